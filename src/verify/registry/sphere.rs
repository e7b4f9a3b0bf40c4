//! The uniform sphere, tested on the whole sphere. u₁ is the azimuth: periodic, and
//! undetermined at both poles.

use glam::{Vec2, Vec3};

use super::{Evidence, Facts, Kind, Param, RoundTrip, TestDomain};
use crate::verify::Cap;
use crate::warp::UniformSphere;

impl Evidence for UniformSphere {
    fn facts(&self) -> Facts {
        Facts {
            kind: Kind::Warp(RoundTrip {
                bound: [3e-7, 3e-7],
                u1_periodic: true,
            }),
            param: Param::None,
            test: TestDomain::Cap(Cap::z(2.0)),
        }
    }
    fn determined(&self, u: Vec2, _: Vec3) -> [bool; 2] {
        [true, u.x > 1e-6 && u.x < 1.0 - 1e-6]
    }
}
