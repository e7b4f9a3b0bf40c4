//! The BSDFs, tested on the sphere of directions.

use glam::DVec3;
use std::boxed::Box;

use super::{Evidence, Facts, Kind, Param, Reads};
use crate::registry::{BsdfLambert, BsdfPhong};
use crate::verify::Cap;

/// Tested on the hemisphere; cos θ decides the pdf.
impl Evidence for BsdfLambert {
    fn facts(&self) -> Facts {
        Facts::new(Kind::Bsdf, Param::None, Cap::z(1.0))
    }
    fn reads(&self) -> Reads {
        Reads {
            pdf: &[2],
            ..Reads::ALL
        }
    }
}

/// The exponent varies. Tested on the whole sphere with a diffuse part, and for a pure sharp
/// lobe on the cap about the mirror direction outside which cosⁿα is below e⁻³⁰
/// (1 − cos α > 30/n): a share (1 − 30/n)ⁿ⁺¹ < 1e-13 of the samples falls outside, where one
/// in 10⁶ fails the test (at 15/n the share, 3e-7, did so for some seeds).
impl Evidence for BsdfPhong {
    fn facts(&self) -> Facts {
        let s = *self;
        let cap = if s.kd == 0.0 && s.n >= 100.0 {
            let wo = s.wo.as_dvec3();
            Cap::new(DVec3::new(-wo.x, -wo.y, wo.z), 30.0 / s.n as f64)
        } else {
            Cap::z(2.0)
        };
        let n = Param::Scalar(s.n, Box::new(move |n| BsdfPhong { n, ..s }.into()));
        Facts::new(Kind::Bsdf, n, cap)
    }
}
