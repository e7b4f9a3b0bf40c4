//! The Phong lobe, tested on a cap that holds all but a negligible part of it.

use glam::{Vec2, Vec3};

use super::{Evidence, Kind, NanPolicy, Sampler, on_cap};
use crate::verify::{Cap, ChiSquareResult};
use crate::warp::PhongLobe;

impl Evidence for PhongLobe {
    fn kind(&self) -> Kind {
        Kind::Warp
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
    fn with_param(&self, n: f32) -> Option<Sampler> {
        Some(PhongLobe { n }.into())
    }
    fn with_geometry(&self, _: [Vec3; 3]) -> Option<Sampler> {
        None
    }
    fn roundtrip_bound(&self) -> Option<[f32; 2]> {
        Some([1e-6, 3e-7])
    }
    fn chi_square(
        &self,
        samples: usize,
        sample: &dyn Fn(usize) -> Vec3,
        pdf: &dyn Fn(Vec3) -> f32,
    ) -> ChiSquareResult {
        // A cap holding all but (1 − hs)^(n+1) of the lobe, far below 1/N.
        let hs = match self.n {
            n if n >= 500.0 => 0.06,
            n if n >= 20.0 => 0.8,
            _ => 1.0,
        };
        on_cap(Cap::z(hs), samples, sample, pdf)
    }
    /// cos α decides the pdf.
    fn pdf_reads(&self) -> &'static [usize] {
        &[2]
    }
    fn u1_periodic(&self) -> bool {
        true
    }
    /// u₁ is the azimuth, undetermined at the lobe's axis u₀ = 1.
    fn determined(&self, u: Vec2, _: Vec3) -> [bool; 2] {
        [true, u.x < 1.0 - 1e-6]
    }
}
