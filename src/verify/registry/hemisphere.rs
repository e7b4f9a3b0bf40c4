//! The hemispheres, uniform and cosine-weighted, tested on the upper half of the sphere.

use glam::{Vec2, Vec3};

use super::{Evidence, Facts, Param, Reads, RoundTrip};
use crate::verify::Cap;
use crate::warp::{CosineHemisphere, UniformHemisphere};

/// u₁ is the azimuth: periodic, and undetermined at the pole u₀ = 1.
impl Evidence for UniformHemisphere {
    fn facts(&self) -> Facts {
        Facts::warp(RoundTrip::azimuth([3e-7; 2]), Param::None, Cap::z(1.0))
    }
    fn determined(&self, u: Vec2, _: Vec3) -> [bool; 2] {
        [true, u.x < 1.0 - 1e-6]
    }
}

/// cos θ decides the pdf; the inverse is the concentric disk's of (x, y).
impl Evidence for CosineHemisphere {
    fn facts(&self) -> Facts {
        Facts::warp(RoundTrip::plain([5e-7; 2]), Param::None, Cap::z(1.0))
    }
    fn reads(&self) -> Reads {
        let inverse = &[0, 1];
        Reads {
            pdf: &[2],
            inverse,
            nan: 3,
        }
    }
}
