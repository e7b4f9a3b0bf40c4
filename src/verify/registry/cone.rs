//! The uniform cone, tested on its cap zoomed onto the whole sphere.

use glam::{Vec2, Vec3};

use super::{Evidence, Kind, NanPolicy, Sampler, on_cap};
use crate::verify::{Cap, ChiSquareResult};
use crate::warp::UniformCone;

impl Evidence for UniformCone {
    fn kind(&self) -> Kind {
        Kind::Warp
    }
    fn nan_policy(&self) -> NanPolicy {
        NanPolicy::NanOut
    }
    fn nan_param(&self) -> bool {
        self.h.is_nan()
    }
    /// h ≤ 0 is a degenerate cone.
    fn is_proper(&self) -> bool {
        self.h > 0.0
    }
    fn with_param(&self, h: f32) -> Option<Sampler> {
        Some(UniformCone { h }.into())
    }
    fn with_geometry(&self, _: [Vec3; 3]) -> Option<Sampler> {
        None
    }
    fn roundtrip_bound(&self) -> Option<[f32; 2]> {
        Some([5e-7, 1.2e-7])
    }
    fn chi_square(
        &self,
        samples: usize,
        sample: &dyn Fn(usize) -> Vec3,
        pdf: &dyn Fn(Vec3) -> f32,
    ) -> ChiSquareResult {
        on_cap(Cap::z(self.h as f64), samples, sample, pdf)
    }
    fn u1_periodic(&self) -> bool {
        true
    }
    /// u₁ is the azimuth, undetermined on the axis u₀ = 0.
    fn determined(&self, u: Vec2, _: Vec3) -> [bool; 2] {
        [true, u.x > 1e-6]
    }
}
