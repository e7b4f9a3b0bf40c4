//! The lights, seen from the origin: the sphere and the disk on a cap of directions that holds
//! them, the triangle and the rectangle on their own parameter squares.

use glam::{Vec2, Vec3};
use std::vec::Vec;

use super::{Evidence, Kind, NanPolicy, Sampler, on_cap, on_light};
use crate::registry::LightSampler;
use crate::verify::{Cap, ChiSquareResult, PlanarLight};
use crate::warp::Family;

impl LightSampler {
    /// The cap of directions that holds every sample: the cone of a sphere seen from outside
    /// (2 % wider), a cap 20 % wider than a disk's rim or a polygon's vertices.
    fn cap(&self) -> Cap {
        match *self {
            LightSampler::Sphere { center, radius } => {
                let c = center.as_dvec3();
                let s2 = (radius as f64 / c.length()).powi(2);
                if s2 < 1.0 {
                    // 50/49 of the cone: its edge then falls on the edge of the χ² grid's
                    // last row of 50, where no cell straddles the discontinuity.
                    Cap::new(c, 50.0 / 49.0 * s2 / (1.0 + (1.0 - s2).sqrt()))
                } else {
                    Cap::z(2.0)
                }
            }
            LightSampler::Disk {
                center,
                normal,
                radius,
            } => {
                let (t, b) = normal.normalize().any_orthonormal_pair();
                let rim: Vec<Vec3> = (0..64)
                    .map(|k| {
                        let (sn, cs) = (k as f32 * core::f32::consts::TAU / 64.0).sin_cos();
                        center + (t * cs + b * sn) * radius
                    })
                    .collect();
                Cap::around(&rim)
            }
            LightSampler::Triangle { v } => Cap::around(&v),
            LightSampler::Rectangle { v: [c, ex, ey] } => {
                Cap::around(&[c, c + ex, c + ey, c + ex + ey])
            }
        }
    }
}

impl Evidence for LightSampler {
    fn kind(&self) -> Kind {
        Kind::Light
    }
    fn nan_policy(&self) -> NanPolicy {
        NanPolicy::ZeroPdf
    }
    fn nan_param(&self) -> bool {
        false
    }
    /// Proper when it is sampled at all: the sampler, not the pdf function, decides (they
    /// disagree at the edges of huge or grazing lights, see `check_sample`).
    fn is_proper(&self) -> bool {
        self.sampler::<f32>()(Vec2::splat(0.5).into()).1 > 0.0
    }
    /// The radius of the sphere and the disk.
    fn with_param(&self, radius: f32) -> Option<Sampler> {
        match *self {
            LightSampler::Sphere { center, .. } => Some(LightSampler::Sphere { center, radius }),
            LightSampler::Disk { center, normal, .. } => Some(LightSampler::Disk {
                center,
                normal,
                radius,
            }),
            LightSampler::Triangle { .. } | LightSampler::Rectangle { .. } => None,
        }
        .map(Sampler::Light)
    }
    /// The vertices of the triangle, the corner and edges of the rectangle.
    fn with_geometry(&self, v: [Vec3; 3]) -> Option<Sampler> {
        match self {
            LightSampler::Triangle { .. } => Some(LightSampler::Triangle { v }),
            LightSampler::Rectangle { .. } => Some(LightSampler::Rectangle { v }),
            LightSampler::Sphere { .. } | LightSampler::Disk { .. } => None,
        }
        .map(Sampler::Light)
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
        match *self {
            LightSampler::Triangle { v: [a, b, c] } => {
                on_light(PlanarLight::triangle(a, b, c), samples, sample, pdf)
            }
            LightSampler::Rectangle { v: [c, ex, ey] } => {
                on_light(PlanarLight::parallelogram(c, ex, ey), samples, sample, pdf)
            }
            LightSampler::Sphere { .. } | LightSampler::Disk { .. } => {
                on_cap(self.cap(), samples, sample, pdf)
            }
        }
    }
}
