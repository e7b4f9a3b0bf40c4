//! The triangle's f64 facts: the ray by barycentrics, the silhouette along its edges, and the
//! χ² test on its own parameter square.

use glam::{DVec3, Vec3};
use std::boxed::Box;
use std::vec::Vec;

use super::{ShapeFacts, edge_points, lanes3, light, plane_tolerance};
use crate::lane::{Lanes, V3};
use crate::math::Math;
use crate::scene::{AnyShape, Triangle};
use crate::verify::registry::{Param, TestDomain};
use crate::verify::{Cap, PlanarLight};

impl ShapeFacts for Triangle {
    fn ray(&self, p: DVec3, w: DVec3) -> Option<f64> {
        let w = w.normalize();
        let [a, b, c] = self.v.map(|x| x.as_dvec3());
        let n = (b - a).cross(c - a);
        let t = (a - p).dot(n) / w.dot(n);
        let x = p + w * t;
        let area = n.length_squared();
        let b1 = (x - a).cross(c - a).dot(n) / area;
        let b2 = (b - a).cross(x - a).dot(n) / area;
        let edge = (b - a).length().min((c - a).length()).min((c - b).length());
        let tol = -plane_tolerance(t, w, n, edge);
        (t > 0.0 && b1 >= tol && b2 >= tol && 1.0 - b1 - b2 >= tol).then_some(t)
    }

    fn silhouette(&self, p: DVec3, off: f64) -> Vec<DVec3> {
        edge_points(p, &self.v.map(|x| x.as_dvec3()), off)
    }

    fn angular_size(&self, p: Vec3) -> f64 {
        f64::from((self.v[1] - self.v[0]).length() / (self.v[0] - p).length())
    }

    fn centre(&self) -> Vec3 {
        (self.v[0] + self.v[1] + self.v[2]) / 3.0
    }

    fn cap(&self, p: Vec3) -> Cap {
        Cap::around(&self.v.map(|x| x - p))
    }

    fn planar(&self, p: Vec3) -> Option<(PlanarLight, f64, DVec3)> {
        let [a, b, c] = self.v.map(|x| x - p);
        let n = (b - a).as_dvec3().cross((c - a).as_dvec3());
        Some((
            PlanarLight::triangle(a, b, c),
            0.5 * n.length(),
            n.normalize(),
        ))
    }

    fn surface(&self, x: DVec3) -> (bool, f64, DVec3) {
        let [p0, p1, p2] = self.v.map(|v| v.as_dvec3());
        let n = (p1 - p0).cross(p2 - p0);
        let scale = 1e-6 * (p0.length() + (p1 - p0).length());
        (
            (x - p0).dot(n.normalize()).abs() <= scale,
            0.5 * n.length(),
            n.normalize(),
        )
    }

    fn evidence(&self) -> (Param, TestDomain) {
        let [a, b, c] = self.v;
        (
            Param::Geometry(self.v, Box::new(|v| light(Triangle { v }))),
            TestDomain::Light(PlanarLight::triangle(a, b, c)),
        )
    }

    fn pack<L: Math + Lanes<Scalar = f32>>(s: &[Self]) -> Option<AnyShape<V3<L>>> {
        Some(AnyShape::Triangle(Triangle {
            v: [0, 1, 2].map(|k| lanes3(s, |x| x.v[k])),
        }))
    }
}
