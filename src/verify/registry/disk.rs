//! The disks: the concentric and the polar map, tested on the disk's equal-area (φ, r²) grid.

use glam::{DVec2, Vec2, Vec3};

use super::{Evidence, Kind, NanPolicy, Sampler};
use crate::verify::{ChiSquare, ChiSquareResult};
use crate::warp::{ConcentricDisk, PolarDisk};

/// The χ² test of planar points (x, y, 0) on the unit disk.
fn on_disk(
    samples: usize,
    sample: &dyn Fn(usize) -> Vec3,
    pdf: &dyn Fn(Vec3) -> f32,
) -> ChiSquareResult {
    ChiSquare::disk().samples(samples).run(
        |i| sample(i).truncate(),
        |p: DVec2| pdf(p.extend(0.0).as_vec3()) as f64,
    )
}

impl Evidence for ConcentricDisk {
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
        Some([5e-7, 5e-7])
    }
    fn chi_square(
        &self,
        samples: usize,
        sample: &dyn Fn(usize) -> Vec3,
        pdf: &dyn Fn(Vec3) -> f32,
    ) -> ChiSquareResult {
        on_disk(samples, sample, pdf)
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

impl Evidence for PolarDisk {
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
        on_disk(samples, sample, pdf)
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
    fn u1_periodic(&self) -> bool {
        true
    }
    /// u₁ is the azimuth, undetermined within 1e-3 of the centre.
    fn determined(&self, _: Vec2, x: Vec3) -> [bool; 2] {
        [true, x.truncate().length() > 1e-3]
    }
}
