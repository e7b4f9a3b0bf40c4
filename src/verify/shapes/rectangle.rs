//! The parallelogram's f64 facts: the ray by (s, t) from the Gram system, the silhouette along
//! its edges, and the χ² test on its own parameter square.

use glam::{DVec3, Vec3};
use std::boxed::Box;
use std::vec::Vec;

use super::{ShapeFacts, edge_points, lanes3, light, plane_tolerance};
use crate::lane::{Lanes, V3};
use crate::math::Math;
use crate::scene::{AnyShape, Rectangle};
use crate::verify::registry::{Param, TestDomain};
use crate::verify::{Cap, PlanarLight};

impl ShapeFacts for Rectangle {
    fn ray(&self, p: DVec3, w: DVec3) -> Option<f64> {
        let w = w.normalize();
        let (c, ex, ey) = (
            self.corner.as_dvec3(),
            self.ex.as_dvec3(),
            self.ey.as_dvec3(),
        );
        let n = ex.cross(ey);
        let t = (c - p).dot(n) / w.dot(n);
        let x = p + w * t - c;
        // (s, u) from the 2×2 Gram system: the edges of a parallelogram need not be orthogonal.
        let (xx, xy, yy) = (ex.dot(ex), ex.dot(ey), ey.dot(ey));
        let (dx, dy) = (x.dot(ex), x.dot(ey));
        let det = xx * yy - xy * xy;
        let (s, u) = ((dx * yy - dy * xy) / det, (dy * xx - dx * xy) / det);
        let tol = plane_tolerance(t, w, n, ex.length().min(ey.length()));
        (t > 0.0 && (-tol..=1.0 + tol).contains(&s) && (-tol..=1.0 + tol).contains(&u)).then_some(t)
    }

    fn silhouette(&self, p: DVec3, off: f64) -> Vec<DVec3> {
        let (c0, ex, ey) = (
            self.corner.as_dvec3(),
            self.ex.as_dvec3(),
            self.ey.as_dvec3(),
        );
        edge_points(p, &[c0, c0 + ex, c0 + ex + ey, c0 + ey], off)
    }

    fn angular_size(&self, p: Vec3) -> f64 {
        f64::from(self.ex.length() / (self.corner - p).length())
    }

    fn centre(&self) -> Vec3 {
        self.corner + (self.ex + self.ey) * 0.5
    }

    fn cap(&self, p: Vec3) -> Cap {
        let c0 = self.corner - p;
        Cap::around(&[c0, c0 + self.ex, c0 + self.ey, c0 + self.ex + self.ey])
    }

    fn planar(&self, p: Vec3) -> Option<(PlanarLight, f64, DVec3)> {
        let n = self.ex.as_dvec3().cross(self.ey.as_dvec3());
        Some((
            PlanarLight::parallelogram(self.corner - p, self.ex, self.ey),
            n.length(),
            n.normalize(),
        ))
    }

    fn surface(&self, x: DVec3) -> (bool, f64, DVec3) {
        let n = self.ex.as_dvec3().cross(self.ey.as_dvec3());
        let scale = 1e-6 * f64::from(self.corner.length() + self.ex.length());
        (
            (x - self.corner.as_dvec3()).dot(n.normalize()).abs() <= scale,
            n.length(),
            n.normalize(),
        )
    }

    fn evidence(&self) -> (Param, TestDomain) {
        let rebuild = |[corner, ex, ey]: [Vec3; 3]| light(Rectangle { corner, ex, ey });
        (
            Param::Geometry([self.corner, self.ex, self.ey], Box::new(rebuild)),
            TestDomain::Light(PlanarLight::parallelogram(self.corner, self.ex, self.ey)),
        )
    }

    fn pack<L: Math + Lanes<Scalar = f32>>(s: &[Self]) -> Option<AnyShape<V3<L>>> {
        Some(AnyShape::Rectangle(Rectangle {
            corner: lanes3(s, |x| x.corner),
            ex: lanes3(s, |x| x.ex),
            ey: lanes3(s, |x| x.ey),
        }))
    }
}
