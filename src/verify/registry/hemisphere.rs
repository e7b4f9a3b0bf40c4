//! The hemispheres, uniform and cosine-weighted, tested on the upper half of the sphere.

use glam::{Vec2, Vec3};

use super::{Evidence, Facts, Kind, Param, RoundTrip, TestDomain};
use crate::verify::Cap;
use crate::warp::{CosineHemisphere, UniformHemisphere};

/// u₁ is the azimuth: periodic, and undetermined at the pole u₀ = 1.
impl Evidence for UniformHemisphere {
    fn facts(&self) -> Facts {
        Facts {
            kind: Kind::Warp(RoundTrip {
                bound: [3e-7, 3e-7],
                u1_periodic: true,
            }),
            param: Param::None,
            test: TestDomain::Cap(Cap::z(1.0)),
        }
    }
    fn determined(&self, u: Vec2, _: Vec3) -> [bool; 2] {
        [true, u.x < 1.0 - 1e-6]
    }
}

/// cos θ decides the pdf; the inverse is the concentric disk's of (x, y).
impl Evidence for CosineHemisphere {
    fn facts(&self) -> Facts {
        Facts {
            kind: Kind::Warp(RoundTrip {
                bound: [5e-7, 5e-7],
                u1_periodic: false,
            }),
            param: Param::None,
            test: TestDomain::Cap(Cap::z(1.0)),
        }
    }
    fn pdf_reads(&self) -> &'static [usize] {
        &[2]
    }
    fn inverse_reads(&self) -> &'static [usize] {
        &[0, 1]
    }
}
