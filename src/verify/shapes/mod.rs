//! What the tests know of each light shape in f64, written once per shape: an independent ray
//! intersection, points just across its silhouette, its angular size and centre, the cap of
//! directions and the parameter square that hold it, and whether a point lies on it. None of it
//! calls the shape's own sampling code, so the scene tests compare the crate against facts it
//! does not share.
//!
//! A shape's facts are its file here, which is also its entry in the registry's evidence: the
//! lights of [`LightSampler`] take their χ² domain and swept parameter from it.

mod disk;
mod rectangle;
mod sphere;
mod triangle;

use glam::{DVec3, Vec3};
use std::vec::Vec;

use super::registry::{LightSampler, Param, Sampler, TestDomain};
use super::{Cap, PlanarLight};
use crate::lane::{Lanes, V3};
use crate::math::Math;
use crate::scene::AnyShape;

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
    /// The registry's evidence for a light of this shape seen from the origin: the parameter the
    /// sweep and the fuzz targets vary, and the domain of its χ² test.
    fn evidence(&self) -> (Param, TestDomain);
    /// Shapes of this kind as one packet shape of lane `L`, lane i shape `i mod shapes.len()`;
    /// `None` if they are not all of one kind, or there are none.
    fn pack<L: Math + Lanes<Scalar = f32>>(shapes: &[Self]) -> Option<AnyShape<V3<L>>>
    where
        Self: Sized;
}

/// The light of `shape` in the registry.
fn light(shape: impl Into<AnyShape>) -> Sampler {
    Sampler::Light(LightSampler(shape.into()))
}

/// Lane i of the packet is `f(shapes[i mod len])` (`shapes` is not empty).
fn lanes3<S, L: Lanes<Scalar = f32>>(shapes: &[S], f: impl Fn(&S) -> Vec3) -> V3<L> {
    V3::new(
        lanes1(shapes, |s| f(s).x),
        lanes1(shapes, |s| f(s).y),
        lanes1(shapes, |s| f(s).z),
    )
}

/// Lane i of the packet is `f(shapes[i mod len])` (`shapes` is not empty).
fn lanes1<S, L: Lanes<Scalar = f32>>(shapes: &[S], f: impl Fn(&S) -> f32) -> L {
    L::from_fn(|i| f(&shapes[i % shapes.len()]))
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
            fn evidence(&self) -> (Param, TestDomain) {
                match self { $(AnyShape::$name(s) => s.evidence(),)* }
            }
            fn pack<L: Math + Lanes<Scalar = f32>>(shapes: &[Self]) -> Option<AnyShape<V3<L>>> {
                match shapes.first()? {
                    $(AnyShape::$name(_) => {
                        let each = shapes
                            .iter()
                            .map(|s| match s { AnyShape::$name(x) => Some(*x), _ => None })
                            .collect::<Option<Vec<_>>>()?;
                        ShapeFacts::pack::<L>(&each)
                    })*
                }
            }
        }
    };
}
crate::scene::with_shapes!(any_shape_facts);
