//! The spherical rectangle, tested on the rectangle's own parameter square.

use glam::{Vec2, Vec3};

use super::{Evidence, Kind, NanPolicy, Sampler, on_light};
use crate::verify::{ChiSquareResult, PlanarLight};
use crate::warp::{Family, SolidAngleRectangle};

impl Evidence for SolidAngleRectangle {
    fn kind(&self) -> Kind {
        Kind::Polygon
    }
    fn nan_policy(&self) -> NanPolicy {
        NanPolicy::ZeroPdf
    }
    fn nan_param(&self) -> bool {
        false
    }
    /// Proper when it is sampled at all, as for the triangle.
    fn is_proper(&self) -> bool {
        self.sampler::<f32>()(Vec2::splat(0.5).into()).1 > 0.0
    }
    fn with_param(&self, _: f32) -> Option<Sampler> {
        None
    }
    fn with_geometry(&self, v: [Vec3; 3]) -> Option<Sampler> {
        Some(SolidAngleRectangle { v }.into())
    }
    /// Sampled by area, as for the triangle; Ureña's map forms Ω as Σγ − 2π, which cancels as
    /// the rectangle shrinks (1.5e-5 in u₀ at 0.035 sr).
    fn roundtrip_bound(&self) -> Option<[f32; 2]> {
        Some(match self.size() {
            "area" => [1.5e-4, 1.5e-4],
            _ => [2e-6, 5e-7],
        })
    }
    fn chi_square(
        &self,
        samples: usize,
        sample: &dyn Fn(usize) -> Vec3,
        pdf: &dyn Fn(Vec3) -> f32,
    ) -> ChiSquareResult {
        let [c, ex, ey] = self.v;
        on_light(PlanarLight::parallelogram(c, ex, ey), samples, sample, pdf)
    }
    /// A degenerate rectangle returns its corner as the point (documented), NaN corner included.
    fn is_corner(&self, x: Vec3) -> bool {
        x.to_array()
            .iter()
            .zip(self.v[0].to_array())
            .all(|(a, b)| a.to_bits() == b.to_bits())
    }
}
