//! The sphere's f64 facts: the ray by its quadratic, the silhouette as the cone's rim, and
//! the χ² test on the cap that holds it.

use core::f64::consts::PI;

use glam::{DVec3, Vec3};
use std::boxed::Box;
use std::vec::Vec;

use super::{ShapeFacts, lanes1, lanes3, light, radius_over_distance};
use crate::lane::{Lanes, V3};
use crate::math::Math;
use crate::scene::{AnyShape, Sphere};
use crate::verify::registry::{Param, TestDomain};
use crate::verify::{Cap, PlanarLight};

impl ShapeFacts for Sphere {
    fn ray(&self, p: DVec3, w: DVec3) -> Option<f64> {
        // The f32 direction is unit to 6e-8; the quadratic assumes exactly 1, and near the
        // silhouette b² − c would amplify the difference a thousandfold.
        let w = w.normalize();
        let oc = p - self.center.as_dvec3();
        let r = f64::from(self.radius);
        let b = oc.dot(w);
        let c = oc.dot(oc) - r * r;
        let disc = b * b - c;
        if disc < 0.0 {
            return None;
        }
        let (t0, t1) = (-b - disc.sqrt(), -b + disc.sqrt());
        // A point on the surface has a root at 0 (up to rounding): skip it.
        let eps = 1e-9 * (oc.length() + r);
        [t0, t1].into_iter().find(|&t| t > eps)
    }

    fn silhouette(&self, p: DVec3, off: f64) -> Vec<DVec3> {
        let d = self.center.as_dvec3() - p;
        let (axis, dist) = (d.normalize(), d.length());
        let theta = (f64::from(self.radius) / dist).asin() + off;
        let (t, b) = axis.any_orthonormal_pair();
        (0..16)
            .map(|k| {
                let phi = f64::from(k) * PI / 8.0;
                axis * theta.cos() + (t * phi.cos() + b * phi.sin()) * theta.sin()
            })
            .collect()
    }

    fn angular_size(&self, p: Vec3) -> f64 {
        radius_over_distance(self.center, self.radius, p)
    }

    fn centre(&self) -> Vec3 {
        self.center
    }

    fn cap(&self, p: Vec3) -> Cap {
        let d = (self.center - p).as_dvec3();
        let s2 = (f64::from(self.radius) / d.length()).powi(2);
        if s2 < 1.0 {
            Cap::new(d, 1.05 * s2 / (1.0 + (1.0 - s2).sqrt()) + 1e-12)
        } else {
            Cap::z(2.0)
        }
    }

    fn planar(&self, _p: Vec3) -> Option<(PlanarLight, f64, DVec3)> {
        None
    }

    fn surface(&self, x: DVec3) -> (bool, f64, DVec3) {
        let r = f64::from(self.radius);
        let d = x - self.center.as_dvec3();
        (
            (d.length() - r).abs() <= 1e-6 * (r + f64::from(self.center.length())),
            4.0 * PI * r * r,
            d.normalize(),
        )
    }

    fn evidence(&self) -> (Param, TestDomain) {
        let center = self.center;
        // The cap 2 % wider than the sphere: its edge then falls on the edge of the χ² grid's
        // last row of 50, where no cell straddles the discontinuity.
        let c = center.as_dvec3();
        let s2 = (f64::from(self.radius) / c.length()).powi(2);
        let cap = if s2 < 1.0 {
            Cap::new(c, 50.0 / 49.0 * s2 / (1.0 + (1.0 - s2).sqrt()))
        } else {
            Cap::z(2.0)
        };
        let rebuild = move |radius| light(Sphere { center, radius });
        (
            Param::Scalar(self.radius, Box::new(rebuild)),
            TestDomain::Cap(cap),
        )
    }

    fn pack<L: Math + Lanes<Scalar = f32>>(s: &[Self]) -> Option<AnyShape<V3<L>>> {
        Some(AnyShape::Sphere(Sphere {
            center: lanes3(s, |x| x.center),
            radius: lanes1(s, |x| x.radius),
        }))
    }
}
