//! The lights, seen from the origin: the sphere and the disk tested on a cap of directions that
//! holds them, the triangle and the rectangle on their own parameter squares. The sphere's and
//! the disk's parameter is the radius, the polygons' their geometry.

use glam::Vec3;
use std::vec::Vec;

use std::boxed::Box;

use super::{Evidence, Facts, Kind, Param, Sampler, TestDomain};
use crate::registry::LightSampler;
use crate::verify::{Cap, PlanarLight};

/// The cap of directions that holds every sample of a sphere seen from outside, 2 % wider: its
/// edge then falls on the edge of the χ² grid's last row of 50, where no cell straddles the
/// discontinuity.
fn sphere_cap(center: Vec3, radius: f32) -> Cap {
    let c = center.as_dvec3();
    let s2 = (radius as f64 / c.length()).powi(2);
    if s2 < 1.0 {
        Cap::new(c, 50.0 / 49.0 * s2 / (1.0 + (1.0 - s2).sqrt()))
    } else {
        Cap::z(2.0)
    }
}

/// The cap of directions that holds every sample of a disk, 20 % wider than its rim.
fn disk_cap(center: Vec3, normal: Vec3, radius: f32) -> Cap {
    let (t, b) = normal.normalize().any_orthonormal_pair();
    let rim: Vec<Vec3> = (0..64)
        .map(|k| {
            let (sn, cs) = (k as f32 * core::f32::consts::TAU / 64.0).sin_cos();
            center + (t * cs + b * sn) * radius
        })
        .collect();
    Cap::around(&rim)
}

impl Evidence for LightSampler {
    fn facts(&self) -> Facts {
        let light = |l: LightSampler| Sampler::Light(l);
        let (param, test) = match *self {
            LightSampler::Sphere { center, radius } => (
                Param::Scalar(
                    radius,
                    Box::new(move |radius| light(LightSampler::Sphere { center, radius })),
                ),
                TestDomain::Cap(sphere_cap(center, radius)),
            ),
            LightSampler::Disk {
                center,
                normal,
                radius,
            } => (
                Param::Scalar(
                    radius,
                    Box::new(move |radius| {
                        light(LightSampler::Disk {
                            center,
                            normal,
                            radius,
                        })
                    }),
                ),
                TestDomain::Cap(disk_cap(center, normal, radius)),
            ),
            LightSampler::Triangle { v } => (
                Param::Geometry(v, Box::new(move |v| light(LightSampler::Triangle { v }))),
                TestDomain::Light(PlanarLight::triangle(v[0], v[1], v[2])),
            ),
            LightSampler::Rectangle { v } => (
                Param::Geometry(v, Box::new(move |v| light(LightSampler::Rectangle { v }))),
                TestDomain::Light(PlanarLight::parallelogram(v[0], v[1], v[2])),
            ),
        };
        Facts::new(Kind::Light, param, test)
    }
}
