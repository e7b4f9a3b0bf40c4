//! The Phong lobe, tested on a cap that holds all but a negligible part of it; its parameter is
//! the exponent, and cos α decides its pdf. u₁ is the azimuth: periodic, and undetermined at
//! the lobe's axis u₀ = 1.

use glam::{Vec2, Vec3};

use std::boxed::Box;

use super::{Evidence, Facts, Kind, Param, RoundTrip, TestDomain};
use crate::verify::Cap;
use crate::warp::PhongLobe;

impl Evidence for PhongLobe {
    fn facts(&self) -> Facts {
        // A cap holding all but (1 − hs)^(n+1) of the lobe, far below 1/N.
        let hs = match self.n {
            n if n >= 500.0 => 0.06,
            n if n >= 20.0 => 0.8,
            _ => 1.0,
        };
        Facts {
            kind: Kind::Warp(RoundTrip {
                bound: [1e-6, 3e-7],
                u1_periodic: true,
            }),
            param: Param::Scalar(self.n, Box::new(|n| PhongLobe { n }.into())),
            test: TestDomain::Cap(Cap::z(hs)),
        }
    }
    fn pdf_reads(&self) -> &'static [usize] {
        &[2]
    }
    fn determined(&self, u: Vec2, _: Vec3) -> [bool; 2] {
        [true, u.x < 1.0 - 1e-6]
    }
}
