//! The spherical triangle, tested on the triangle's own parameter square.

use glam::{Vec2, Vec3};

use super::{Evidence, Kind, NanPolicy, Sampler, on_light};
use crate::verify::{ChiSquareResult, PlanarLight};
use crate::warp::{Family, SolidAngleTriangle};

impl Evidence for SolidAngleTriangle {
    fn kind(&self) -> Kind {
        Kind::Polygon
    }
    fn nan_policy(&self) -> NanPolicy {
        NanPolicy::ZeroPdf
    }
    fn nan_param(&self) -> bool {
        false
    }
    /// Proper when it is sampled at all: the sampler, not the pdf function, decides (they
    /// disagree at the edges of huge or grazing triangles).
    fn is_proper(&self) -> bool {
        self.sampler::<f32>()(Vec2::splat(0.5).into()).1 > 0.0
    }
    fn with_param(&self, _: f32) -> Option<Sampler> {
        None
    }
    fn with_geometry(&self, v: [Vec3; 3]) -> Option<Sampler> {
        Some(SolidAngleTriangle { v }.into())
    }
    /// Sampled by area, the map resolves only the f32 direction grid over the light
    /// (6e-8/√Ω: 1e-4 at 5e-7 sr).
    fn roundtrip_bound(&self) -> Option<[f32; 2]> {
        Some(match self.size() {
            "area" => [1.5e-4, 1.5e-4],
            _ => [4e-6, 1.5e-6],
        })
    }
    fn chi_square(
        &self,
        samples: usize,
        sample: &dyn Fn(usize) -> Vec3,
        pdf: &dyn Fn(Vec3) -> f32,
    ) -> ChiSquareResult {
        let [a, b, c] = self.v;
        on_light(PlanarLight::triangle(a, b, c), samples, sample, pdf)
    }
    /// u₀ is undetermined at the apex B (u₁ → 0).
    fn determined(&self, u: Vec2, _: Vec3) -> [bool; 2] {
        [u.y > 1e-3, true]
    }
}
