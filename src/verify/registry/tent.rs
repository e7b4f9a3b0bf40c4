//! The pair of tents, tested on the square [−1, 1]² mapped onto the unit square.

use glam::{DVec2, Vec3};

use super::{Evidence, Kind, NanPolicy, Sampler};
use crate::verify::{ChiSquare, ChiSquareResult};
use crate::warp::TentPair;

impl Evidence for TentPair {
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
                let x = sample(i).as_dvec3();
                DVec2::new((x.x + 1.0) / 2.0, (x.y + 1.0) / 2.0)
            },
            |p: DVec2| 4.0 * pdf((2.0 * p - 1.0).as_vec2().extend(0.0)) as f64,
        )
    }
    fn pdf_reads(&self) -> &'static [usize] {
        &[0, 1]
    }
    fn inverse_reads(&self) -> &'static [usize] {
        &[0, 1]
    }
    fn nan_coords(&self) -> usize {
        2
    }
}
