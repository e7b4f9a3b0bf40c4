//! The spherical polygons as families of the registry ([`Family`]): the spherical triangle and
//! rectangle sampled towards fixed geometry relative to the shading point, and what they share:
//! how they are sampled ([`polygon_size`]) and the rectangle's domain test.

use core::fmt;
use core::hint::black_box;

use glam::Vec3;

use crate::lane::{V2, V3};
use crate::math::Math;
use crate::warp::family::{is_unit, lanes3};
use crate::warp::{
    Family, SPHERICAL_RECTANGLE_MIN_SR, SPHERICAL_TRIANGLE_MIN_SR, spherical_rectangle,
    spherical_rectangle_inverse, spherical_rectangle_pdf, spherical_triangle,
    spherical_triangle_inverse, spherical_triangle_pdf,
};

/// The registry's [`spherical_triangle`](crate::warp::spherical_triangle) towards vertices `v` (relative to the shading point).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolidAngleTriangle {
    /// The vertices.
    pub v: [Vec3; 3],
}

impl SolidAngleTriangle {
    /// How it is sampled, by the solid angle of its sample at u = (½, ½): see [`polygon_size`].
    pub fn size(&self) -> &'static str {
        polygon_size(
            self.sampler::<f32>()(V2::new(0.5, 0.5)).1,
            SPHERICAL_TRIANGLE_MIN_SR,
        )
    }
}

impl Family for SolidAngleTriangle {
    fn name(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "spherical_triangle {}", self.size())
    }
    fn sampler<L: Math>(&self) -> impl Fn(V2<L>) -> (V3<L>, L) + Copy {
        let v = self.v.map(lanes3::<L>);
        // The geometry passes through `black_box` so that a loop over a batch pays the set-up
        // at every sample, as a renderer does when each sample has its own shading point.
        #[inline(always)]
        move |u| {
            let [a, b, c] = black_box(v);
            spherical_triangle(u, a, b, c)
        }
    }
    fn pdf<L: Math>(&self, x: V3<L>) -> L {
        let [a, b, c] = self.v.map(lanes3::<L>);
        spherical_triangle_pdf(x, a, b, c)
    }
    fn inverse<L: Math>(&self, x: V3<L>) -> Option<V2<L>> {
        let [a, b, c] = self.v.map(lanes3::<L>);
        Some(spherical_triangle_inverse(x, a, b, c))
    }
    fn in_domain(&self, x: Vec3) -> bool {
        is_unit(x)
    }
}

/// The registry's [`spherical_rectangle`](crate::warp::spherical_rectangle) towards corner + s·ex + t·ey: `v` is corner, ex, ey.
/// Its sample is the point on the light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolidAngleRectangle {
    /// Corner, ex, ey.
    pub v: [Vec3; 3],
}

impl SolidAngleRectangle {
    /// How it is sampled, by the solid angle of its sample at u = (½, ½): see [`polygon_size`].
    pub fn size(&self) -> &'static str {
        polygon_size(
            self.sampler::<f32>()(V2::new(0.5, 0.5)).1,
            SPHERICAL_RECTANGLE_MIN_SR,
        )
    }
}

impl Family for SolidAngleRectangle {
    fn name(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "spherical_rectangle {}", self.size())
    }
    fn sampler<L: Math>(&self) -> impl Fn(V2<L>) -> (V3<L>, L) + Copy {
        let v = self.v.map(lanes3::<L>);
        // Through `black_box`, as for the triangle: the set-up is paid at every sample.
        #[inline(always)]
        move |u| {
            let [c, ex, ey] = black_box(v);
            spherical_rectangle(u, c, ex, ey)
        }
    }
    fn pdf<L: Math>(&self, x: V3<L>) -> L {
        // The sample is the point on the light; the pdf takes it as it is, so the sample's own
        // pdf and this one are the same function of the same point.
        let [c, ex, ey] = self.v.map(lanes3::<L>);
        spherical_rectangle_pdf(x, c, ex, ey)
    }
    fn inverse<L: Math>(&self, x: V3<L>) -> Option<V2<L>> {
        let [c, ex, ey] = self.v.map(lanes3::<L>);
        Some(spherical_rectangle_inverse(x, c, ex, ey))
    }
    fn in_domain(&self, x: Vec3) -> bool {
        on_parallelogram(x, self.v)
    }
}

/// How a spherical polygon is sampled, from `pdf`, its sample's pdf at u = (½, ½), and the
/// solid angle below which it is sampled by area: "area" below that threshold (or degenerate),
/// "small" up to 0.5 sr, "large" above.
pub fn polygon_size(pdf: f32, min_sr: f32) -> &'static str {
    let omega = 1.0 / pdf as f64;
    if omega.is_nan() || omega < min_sr as f64 {
        "area"
    } else if omega > 0.5 {
        "large"
    } else {
        "small"
    }
}

/// True when `x` lies on the parallelogram corner + s·ex + t·ey (`v` = corner, ex, ey), within
/// 1e-5 of the light's size and distance, in the plane and across it: an f32 point far from the
/// origin is rounded on the scale of its distance, not of the light. In (s, t) that margin is
/// scaled by the conditioning of the edges (1/sin of the angle between them).
pub(crate) fn on_parallelogram(x: Vec3, v: [Vec3; 3]) -> bool {
    let d = x.as_dvec3() - v[0].as_dvec3();
    let (ex, ey) = (v[1].as_dvec3(), v[2].as_dvec3());
    // An orthonormal basis of the plane by Gram–Schmidt, so that the distance from the plane
    // stays exact for edges only a few ulp from parallel, where the Gram system's determinant
    // cancels (found by the `warps` fuzz target: edges 5e-8 rad apart).
    let e1 = ex / ex.length();
    let w = ey - e1 * ey.dot(e1);
    let e2 = w / w.length();
    let (a1, a2) = (d.dot(e1), d.dot(e2));
    let off = (d - e1 * a1 - e2 * a2).length();
    let t = a2 / w.length();
    let s = (a1 - t * ey.dot(e1)) / ex.length();
    let tol = 1e-5 * (ex.length() + ey.length() + v[0].as_dvec3().length());
    // (s, t) move by up to |ey|/area (|ex|/area) per unit of the point's displacement in the
    // plane: 1/|ex| (1/|ey|) for a rectangle, more for a skewed sliver, whose f32 samples,
    // rounded by ε of the point, land far outside a rectangle's margin in (s, t) (found by the
    // `warps` fuzz target: edges 1.3e-5 rad apart).
    let area = ex.length() * w.length();
    let (ms, mt) = (tol * ey.length() / area, tol * ex.length() / area);
    x.is_finite() && (-ms..=1.0 + ms).contains(&s) && (-mt..=1.0 + mt).contains(&t) && off <= tol
}
