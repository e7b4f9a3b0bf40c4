//! The Phong lobe, tested on a cap that holds all but (1 − hs)^(n+1) of it, far below 1/N.

use glam::{Vec2, Vec3};
use std::boxed::Box;

use super::{Evidence, Facts, Param, Reads, RoundTrip};
use crate::verify::Cap;
use crate::warp::PhongLobe;

/// The exponent varies, and cos α decides the pdf; u₁ is the azimuth: periodic, and
/// undetermined at the lobe's axis u₀ = 1.
impl Evidence for PhongLobe {
    fn facts(&self) -> Facts {
        let hs = match self.n {
            n if n >= 500.0 => 0.06,
            n if n >= 20.0 => 0.8,
            _ => 1.0,
        };
        let n = Param::Scalar(self.n, Box::new(|n| PhongLobe { n }.into()));
        Facts::warp(RoundTrip::azimuth([1e-6, 3e-7]), n, Cap::z(hs))
    }
    fn determined(&self, u: Vec2, _: Vec3) -> [bool; 2] {
        [true, u.x < 1.0 - 1e-6]
    }
    fn reads(&self) -> Reads {
        Reads {
            pdf: &[2],
            ..Reads::ALL
        }
    }
}
