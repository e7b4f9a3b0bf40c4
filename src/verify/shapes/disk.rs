//! The disk's f64 facts: the ray by its plane and radius, the silhouette from rim tangents, the
//! bounding square as its parameter square, and the χ² test on the cap that holds it.

use core::f64::consts::PI;

use glam::{DVec3, Vec3};
use std::boxed::Box;
use std::vec::Vec;

use super::{ShapeFacts, lanes1, lanes3, light, radius_over_distance};
use crate::lane::{Lanes, V3};
use crate::math::Math;
use crate::scene::{AnyShape, Disk};
use crate::verify::registry::{Param, TestDomain};
use crate::verify::{Cap, PlanarLight};

impl ShapeFacts for Disk {
    fn ray(&self, p: DVec3, w: DVec3) -> Option<f64> {
        let w = w.normalize();
        let n = self.normal.as_dvec3().normalize();
        let t = (self.center.as_dvec3() - p).dot(n) / w.dot(n);
        let x = p + w * t;
        let r = f64::from(self.radius);
        let tol = 1e-6 * r + 8.0 * f64::from(f32::EPSILON) * t / w.dot(n).abs();
        (t > 0.0 && (x - self.center.as_dvec3()).length() <= r + tol).then_some(t)
    }

    fn angular_size(&self, p: Vec3) -> f64 {
        radius_over_distance(self.center, self.radius, p)
    }

    fn centre(&self) -> Vec3 {
        self.center
    }

    fn silhouette(&self, p: DVec3, off: f64) -> Vec<DVec3> {
        // Rim points turned across the silhouette: the plane through the shading point and the
        // rim's tangent line at the point is the silhouette's great circle there.
        let n = self.normal.as_dvec3().normalize();
        let (t, b) = n.any_orthonormal_pair();
        let c = self.center.as_dvec3();
        (0..48)
            .map(|k| {
                let phi = f64::from(k) * PI / 24.0;
                let x = c + (t * phi.cos() + b * phi.sin()) * f64::from(self.radius);
                let tangent = b * phi.cos() - t * phi.sin();
                let plane = (x - p).cross(tangent).normalize();
                let sign = if plane.dot(c - p) > 0.0 { -1.0 } else { 1.0 };
                ((x - p).normalize() + plane * (sign * off)).normalize()
            })
            .collect()
    }

    fn cap(&self, p: Vec3) -> Cap {
        let (t, b) = self.normal.normalize().any_orthonormal_pair();
        let rim: Vec<Vec3> = (0..64)
            .map(|k| {
                let (sn, cs) = (k as f32 * core::f32::consts::TAU / 64.0).sin_cos();
                self.center - p + (t * cs + b * sn) * self.radius
            })
            .collect();
        Cap::around(&rim)
    }

    fn planar(&self, p: Vec3) -> Option<(PlanarLight, f64, DVec3)> {
        let (t, b) = self.normal.normalize().any_orthonormal_pair();
        let r = self.radius;
        let corner = self.center - p - (t + b) * r;
        Some((
            PlanarLight::parallelogram(corner, t * (2.0 * r), b * (2.0 * r)),
            4.0 * f64::from(r).powi(2),
            self.normal.as_dvec3().normalize(),
        ))
    }

    fn surface(&self, x: DVec3) -> (bool, f64, DVec3) {
        let n = self.normal.as_dvec3().normalize();
        let d = x - self.center.as_dvec3();
        let r = f64::from(self.radius);
        let scale = 1e-6 * (r + f64::from(self.center.length()));
        (
            d.dot(n).abs() <= scale && d.length() <= r + scale,
            PI * r * r,
            n,
        )
    }

    fn evidence(&self) -> (Param, TestDomain) {
        let (center, normal) = (self.center, self.normal);
        let rebuild = move |radius| {
            light(Disk {
                center,
                normal,
                radius,
            })
        };
        // The cap 20 % wider than the rim, seen from the origin.
        (
            Param::Scalar(self.radius, Box::new(rebuild)),
            TestDomain::Cap(self.cap(Vec3::ZERO)),
        )
    }

    fn pack<L: Math + Lanes<Scalar = f32>>(s: &[Self]) -> Option<AnyShape<V3<L>>> {
        Some(AnyShape::Disk(Disk {
            center: lanes3(s, |x| x.center),
            normal: lanes3(s, |x| x.normal),
            radius: lanes1(s, |x| x.radius),
        }))
    }
}
