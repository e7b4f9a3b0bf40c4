//! The uniform triangle's barycentrics, tested on the square through an equal-area map.

use glam::{DVec2, Vec3};

use super::{Evidence, Kind, NanPolicy, Sampler};
use crate::verify::{ChiSquare, ChiSquareResult, square_to_triangle, triangle_to_square};
use crate::warp::UniformTriangle;

impl Evidence for UniformTriangle {
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
        Some([1.2e-7, 1.2e-7])
    }
    fn chi_square(
        &self,
        samples: usize,
        sample: &dyn Fn(usize) -> Vec3,
        pdf: &dyn Fn(Vec3) -> f32,
    ) -> ChiSquareResult {
        ChiSquare::square().samples(samples).run(
            |i| {
                let b = sample(i).as_dvec3();
                triangle_to_square(b.x, b.y)
            },
            // The equal-area map (s, f) = ((b₀+b₁)², b₁/(b₀+b₁)) has Jacobian ½.
            |st: DVec2| 0.5 * pdf(square_to_triangle(st).extend(0.0).as_vec3()) as f64,
        )
    }
    /// The density over (b₀, b₁).
    fn pdf_reads(&self) -> &'static [usize] {
        &[0, 1]
    }
}
