//! The BSDFs, tested on the sphere of directions: Lambert's hemisphere (cos θ decides its pdf),
//! the whole sphere for a Phong BSDF with a diffuse part, and for a pure sharp Phong lobe the
//! cap about the mirror direction outside which cosⁿα is below e⁻¹⁵ (1 − cos α > 15/n). The
//! Phong BSDF's parameter is its exponent.

use glam::DVec3;

use std::boxed::Box;

use super::{Evidence, Facts, Kind, Param, TestDomain};
use crate::registry::{BsdfLambert, BsdfPhong};
use crate::verify::Cap;

impl Evidence for BsdfLambert {
    fn facts(&self) -> Facts {
        Facts {
            kind: Kind::Bsdf,
            param: Param::None,
            test: TestDomain::Cap(Cap::z(1.0)),
        }
    }
    fn pdf_reads(&self) -> &'static [usize] {
        &[2]
    }
}

impl Evidence for BsdfPhong {
    fn facts(&self) -> Facts {
        let s = *self;
        let cap = if s.kd == 0.0 && s.n >= 100.0 {
            let wo = s.wo.as_dvec3();
            Cap::new(DVec3::new(-wo.x, -wo.y, wo.z), 15.0 / s.n as f64)
        } else {
            Cap::z(2.0)
        };
        Facts {
            kind: Kind::Bsdf,
            param: Param::Scalar(s.n, Box::new(move |n| BsdfPhong { n, ..s }.into())),
            test: TestDomain::Cap(cap),
        }
    }
}
