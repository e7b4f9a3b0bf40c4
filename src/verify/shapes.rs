//! What the tests know of each light shape in f64, written once per shape: an independent ray
//! intersection, points just across its silhouette, its angular size and centre, the cap of
//! directions and the parameter square that hold it, and whether a point lies on it. None of it
//! calls the shape's own sampling code, so the scene tests compare the crate against facts it
//! does not share.

use core::f64::consts::PI;

use glam::{DVec3, Vec3};
use std::vec::Vec;

use super::{Cap, PlanarLight};
use crate::scene::{self, AnyShape};
use crate::x8::{F32x8, Vec3x8};

/// The f64 facts of a light shape (scalar f32 geometry), seen from shading point `p`.
pub trait ShapeFacts {
    /// The distance along unit `w` from `p` to the shape, by f64 geometry that shares nothing
    /// with the crate's (the sphere's quadratic, the plane and the disk's radius, barycentrics
    /// for the triangle, (s, t) for the parallelogram), with a tolerance for the f32 rounding of
    /// `w` (8 ulp); `None` for a miss.
    fn ray(&self, p: DVec3, w: DVec3) -> Option<f64>;
    /// Directions just across the silhouette seen from `p`, turned outwards by `off` radians
    /// (0: on it).
    fn silhouette(&self, p: DVec3, off: f64) -> Vec<DVec3>;
    /// The angular size: its radius or an edge over its distance from `p`.
    fn angular_size(&self, p: Vec3) -> f64;
    /// A point inside the shape (the centre, the centroid).
    fn centre(&self) -> Vec3;
    /// A cap of directions from `p` that holds the shape.
    fn cap(&self, p: Vec3) -> Cap;
    /// A planar shape's parameter square (the bounding square for a disk) relative to `p`, the
    /// area of the square's image and the unit normal; `None` for the sphere.
    fn planar(&self, p: Vec3) -> Option<(PlanarLight, f64, DVec3)>;
    /// Whether `x` lies on the surface (to 1e-6 of the shape's scale), the area, and the unit
    /// normal at `x`.
    fn surface(&self, x: DVec3) -> (bool, f64, DVec3);
    /// Eight shapes of this kind as one packet shape, lane i shape i; `None` if they are not all
    /// of one kind.
    fn pack(shapes: &[Self; 8]) -> Option<AnyShape<Vec3x8>>
    where
        Self: Sized;
}

/// Lane i of the packet is `f(shapes[i])`.
fn lanes3<S>(shapes: &[S; 8], f: impl Fn(&S) -> Vec3) -> Vec3x8 {
    Vec3x8::from(core::array::from_fn::<Vec3, 8, _>(|i| f(&shapes[i])))
}

/// Lane i of the packet is `f(shapes[i])`.
fn lanes1<S>(shapes: &[S; 8], f: impl Fn(&S) -> f32) -> F32x8 {
    F32x8::from(core::array::from_fn::<f32, 8, _>(|i| f(&shapes[i])))
}

/// Points along each edge of a convex polygon, turned across the edge's plane through `p` by
/// `off`, away from the centroid.
fn edge_points(p: DVec3, pts: &[DVec3], off: f64) -> Vec<DVec3> {
    let centroid = pts.iter().sum::<DVec3>() / pts.len() as f64;
    let mut out = Vec::new();
    for (i, &a) in pts.iter().enumerate() {
        let b = pts[(i + 1) % pts.len()];
        for k in 1..8 {
            let x = a + (b - a) * (f64::from(k) / 8.0);
            let d = (x - p).normalize();
            let plane = (a - p).cross(b - p).normalize();
            let sign = if plane.dot(centroid - p) > 0.0 {
                -1.0
            } else {
                1.0
            };
            out.push((d + plane * (sign * off)).normalize());
        }
    }
    out
}

/// A round shape's angular size: its radius over its centre's distance from `p`.
fn radius_over_distance(center: Vec3, radius: f32, p: Vec3) -> f64 {
    f64::from(radius / (center - p).length())
}

/// The tolerance of a planar hit for an f32 direction rounded by 8 ulp: it moves the hit by
/// 8εt/|cos θ_l| in the plane, relative to the shortest edge.
fn plane_tolerance(t: f64, w: DVec3, n: DVec3, edge: f64) -> f64 {
    1e-4 + 8.0 * f64::from(f32::EPSILON) * t * n.length() / (w.dot(n).abs() * edge)
}

impl ShapeFacts for scene::Sphere {
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

    fn pack(s: &[Self; 8]) -> Option<AnyShape<Vec3x8>> {
        Some(AnyShape::Sphere(scene::Sphere {
            center: lanes3(s, |x| x.center),
            radius: lanes1(s, |x| x.radius),
        }))
    }
}

impl ShapeFacts for scene::Disk {
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

    fn pack(s: &[Self; 8]) -> Option<AnyShape<Vec3x8>> {
        Some(AnyShape::Disk(scene::Disk {
            center: lanes3(s, |x| x.center),
            normal: lanes3(s, |x| x.normal),
            radius: lanes1(s, |x| x.radius),
        }))
    }
}

impl ShapeFacts for scene::Triangle {
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

    fn pack(s: &[Self; 8]) -> Option<AnyShape<Vec3x8>> {
        Some(AnyShape::Triangle(scene::Triangle {
            v: [0, 1, 2].map(|k| lanes3(s, |x| x.v[k])),
        }))
    }
}

impl ShapeFacts for scene::Rectangle {
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

    fn pack(s: &[Self; 8]) -> Option<AnyShape<Vec3x8>> {
        Some(AnyShape::Rectangle(scene::Rectangle {
            corner: lanes3(s, |x| x.corner),
            ex: lanes3(s, |x| x.ex),
            ey: lanes3(s, |x| x.ey),
        }))
    }
}

/// [`ShapeFacts`] of whichever shape it is, from the scene's one list of shapes.
macro_rules! any_shape_facts {
    ($($name:ident($shape:ident, $prepared:ident)),* $(,)?) => {
        impl ShapeFacts for AnyShape {
            fn ray(&self, p: DVec3, w: DVec3) -> Option<f64> {
                match self { $(AnyShape::$name(s) => s.ray(p, w),)* }
            }
            fn silhouette(&self, p: DVec3, off: f64) -> Vec<DVec3> {
                match self { $(AnyShape::$name(s) => s.silhouette(p, off),)* }
            }
            fn angular_size(&self, p: Vec3) -> f64 {
                match self { $(AnyShape::$name(s) => s.angular_size(p),)* }
            }
            fn centre(&self) -> Vec3 {
                match self { $(AnyShape::$name(s) => s.centre(),)* }
            }
            fn cap(&self, p: Vec3) -> Cap {
                match self { $(AnyShape::$name(s) => s.cap(p),)* }
            }
            fn planar(&self, p: Vec3) -> Option<(PlanarLight, f64, DVec3)> {
                match self { $(AnyShape::$name(s) => s.planar(p),)* }
            }
            fn surface(&self, x: DVec3) -> (bool, f64, DVec3) {
                match self { $(AnyShape::$name(s) => s.surface(x),)* }
            }
            fn pack(shapes: &[Self; 8]) -> Option<AnyShape<Vec3x8>> {
                match shapes[0] {
                    $(AnyShape::$name(first) => {
                        let mut each = [first; 8];
                        for (e, s) in each.iter_mut().zip(shapes) {
                            let AnyShape::$name(x) = s else { return None };
                            *e = *x;
                        }
                        ShapeFacts::pack(&each)
                    })*
                }
            }
        }
    };
}
crate::scene::with_shapes!(any_shape_facts);
