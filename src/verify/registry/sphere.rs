//! The uniform sphere, tested on the whole sphere.

use glam::{Vec2, Vec3};

use super::{Evidence, Facts, Param, RoundTrip};
use crate::verify::Cap;
use crate::warp::UniformSphere;

/// u₁ is the azimuth: periodic, and undetermined at both poles.
impl Evidence for UniformSphere {
    fn facts(&self) -> Facts {
        Facts::warp(RoundTrip::azimuth([3e-7; 2]), Param::None, Cap::z(2.0))
    }
    fn determined(&self, u: Vec2, _: Vec3) -> [bool; 2] {
        [true, u.x > 1e-6 && u.x < 1.0 - 1e-6]
    }
}
