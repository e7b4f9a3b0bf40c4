//! The uniform cone, tested on its cap zoomed onto the whole sphere; its parameter is h. u₁ is
//! the azimuth: periodic, and undetermined on the axis u₀ = 0.

use glam::{Vec2, Vec3};

use std::boxed::Box;

use super::{Evidence, Facts, Kind, Param, RoundTrip, TestDomain};
use crate::verify::Cap;
use crate::warp::UniformCone;

impl Evidence for UniformCone {
    fn facts(&self) -> Facts {
        Facts {
            kind: Kind::Warp(RoundTrip {
                bound: [5e-7, 1.2e-7],
                u1_periodic: true,
            }),
            param: Param::Scalar(self.h, Box::new(|h| UniformCone { h }.into())),
            test: TestDomain::Cap(Cap::z(self.h as f64)),
        }
    }
    fn determined(&self, u: Vec2, _: Vec3) -> [bool; 2] {
        [true, u.x > 1e-6]
    }
}
