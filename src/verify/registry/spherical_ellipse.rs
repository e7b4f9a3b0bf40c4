//! The disk sampled by solid angle, tested on the cap about its rim.

use glam::{Vec2, Vec3};
use std::boxed::Box;

use super::{Evidence, Facts, Kind, Param, RoundTrip};
use crate::frame::Frame;
use crate::verify::Cap;
use crate::warp::SolidAngleDisk;

/// The radius varies. u₁ is the angle about the cone's axis (periodic), undetermined at the
/// axis itself (u₀ = 0).
impl Evidence for SolidAngleDisk {
    fn facts(&self) -> Facts {
        let (c, n) = (self.c, self.n);
        let r = Param::Scalar(self.r, Box::new(move |r| SolidAngleDisk { c, n, r }.into()));
        Facts::new(
            Kind::Polygon(RoundTrip::azimuth([2e-5, 2e-5])),
            r,
            Cap::around(&rim(self)),
        )
    }
    fn determined(&self, u: Vec2, _: Vec3) -> [bool; 2] {
        [true, u.x > 1e-2]
    }
}

/// Sixteen points of the disk's rim (for the domain of its tests).
pub fn rim(s: &SolidAngleDisk) -> [Vec3; 16] {
    let f = Frame::from_normal(s.n.normalize());
    core::array::from_fn(|i| {
        let a = i as f32 * core::f32::consts::TAU / 16.0;
        s.c + (f.t * a.cos() + f.b * a.sin()) * s.r
    })
}
