//! The BSDFs, tested on the sphere of directions: Lambert's hemisphere, the whole sphere for a
//! Phong BSDF with a diffuse part, and for a pure sharp Phong lobe the cap about the mirror
//! direction outside which cosⁿα is below e⁻¹⁵ (1 − cos α > 15/n).

use glam::{DVec3, Vec3};

use super::{Evidence, Kind, NanPolicy, Sampler, on_cap};
use crate::registry::{BsdfLambert, BsdfPhong};
use crate::verify::{Cap, ChiSquareResult};

impl Evidence for BsdfLambert {
    fn kind(&self) -> Kind {
        Kind::Bsdf
    }
    fn nan_policy(&self) -> NanPolicy {
        NanPolicy::NanOut
    }
    fn nan_param(&self) -> bool {
        false
    }
    fn is_proper(&self) -> bool {
        true
    }
    fn with_param(&self, _: f32) -> Option<Sampler> {
        None
    }
    fn with_geometry(&self, _: [Vec3; 3]) -> Option<Sampler> {
        None
    }
    fn roundtrip_bound(&self) -> Option<[f32; 2]> {
        None
    }
    fn chi_square(
        &self,
        samples: usize,
        sample: &dyn Fn(usize) -> Vec3,
        pdf: &dyn Fn(Vec3) -> f32,
    ) -> ChiSquareResult {
        on_cap(Cap::z(1.0), samples, sample, pdf)
    }
    /// cos θ decides the pdf.
    fn pdf_reads(&self) -> &'static [usize] {
        &[2]
    }
}

impl Evidence for BsdfPhong {
    fn kind(&self) -> Kind {
        Kind::Bsdf
    }
    fn nan_policy(&self) -> NanPolicy {
        NanPolicy::NanOut
    }
    fn nan_param(&self) -> bool {
        self.n.is_nan()
    }
    fn is_proper(&self) -> bool {
        !self.n.is_nan()
    }
    /// The exponent.
    fn with_param(&self, n: f32) -> Option<Sampler> {
        Some(BsdfPhong { n, ..*self }.into())
    }
    fn with_geometry(&self, _: [Vec3; 3]) -> Option<Sampler> {
        None
    }
    fn roundtrip_bound(&self) -> Option<[f32; 2]> {
        None
    }
    fn chi_square(
        &self,
        samples: usize,
        sample: &dyn Fn(usize) -> Vec3,
        pdf: &dyn Fn(Vec3) -> f32,
    ) -> ChiSquareResult {
        let cap = if self.kd == 0.0 && self.n >= 100.0 {
            let wo = self.wo.as_dvec3();
            Cap::new(DVec3::new(-wo.x, -wo.y, wo.z), 15.0 / self.n as f64)
        } else {
            Cap::z(2.0)
        };
        on_cap(cap, samples, sample, pdf)
    }
}
