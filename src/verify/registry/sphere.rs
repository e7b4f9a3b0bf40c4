//! The uniform sphere, tested on the whole sphere.

use glam::{Vec2, Vec3};

use super::{Evidence, Kind, NanPolicy, Sampler, on_cap};
use crate::verify::{Cap, ChiSquareResult};
use crate::warp::UniformSphere;

impl Evidence for UniformSphere {
    fn kind(&self) -> Kind {
        Kind::Warp
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
        Some([3e-7, 3e-7])
    }
    fn chi_square(
        &self,
        samples: usize,
        sample: &dyn Fn(usize) -> Vec3,
        pdf: &dyn Fn(Vec3) -> f32,
    ) -> ChiSquareResult {
        on_cap(Cap::z(2.0), samples, sample, pdf)
    }
    fn u1_periodic(&self) -> bool {
        true
    }
    /// u₁ is the azimuth, undetermined at both poles.
    fn determined(&self, u: Vec2, _: Vec3) -> [bool; 2] {
        [true, u.x > 1e-6 && u.x < 1.0 - 1e-6]
    }
}
