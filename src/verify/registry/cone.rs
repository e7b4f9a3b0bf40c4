//! The uniform cone, tested on its cap zoomed onto the whole sphere.

use glam::{Vec2, Vec3};
use std::boxed::Box;

use super::{Evidence, Facts, Param, RoundTrip};
use crate::verify::Cap;
use crate::warp::UniformCone;

/// h varies; u₁ is the azimuth: periodic, and undetermined on the axis u₀ = 0.
impl Evidence for UniformCone {
    fn facts(&self) -> Facts {
        let h = Param::Scalar(self.h, Box::new(|h| UniformCone { h }.into()));
        Facts::warp(RoundTrip::azimuth([5e-7, 1.2e-7]), h, Cap::z(self.h as f64))
    }
    fn determined(&self, u: Vec2, _: Vec3) -> [bool; 2] {
        [true, u.x > 1e-6]
    }
}
