//! The triangle and rectangle lights: uniform in solid angle through the spherical polygon
//! samplers of [`warp`](crate::warp), which fall back to area sampling where spherical sampling
//! would lose accuracy.

use core::f64::consts::PI;

use glam::Vec3;

use crate::lane::V3;
use crate::math::Math;
use crate::point::{Point2, Point3};
use crate::scene::{AreaSample, LightSample, area_sample, le_towards, light_sample, on_light};
use crate::warp::{SphericalRectangle, SphericalTriangle, uniform_triangle};
use crate::warp::{cross_wide, plane_dot};

/// A triangle light with vertices `a`, `b`, `c`, emitting radiance `le` on the side of its
/// normal (b − a) × (c − a): the side from which the vertices run counter-clockwise.
///
/// It samples the triangle's solid angle uniformly ([`SphericalTriangle`], Arvo 1995, with the
/// plane and Van Oosterom–Strackee's solid angle in f64): pdf 1/Ω per steradian, within 2e-7 of
/// the f64 value on random triangles near and far, grazing and straddling the horizon. Below
/// [`SPHERICAL_TRIANGLE_MIN_SR`](crate::warp::SPHERICAL_TRIANGLE_MIN_SR) and above
/// [`SPHERICAL_TRIANGLE_MAX_SR`](crate::warp::SPHERICAL_TRIANGLE_MAX_SR) it samples by area and
/// returns the exact converted pdf. `pdf` and `hit` accept directions within the spherical
/// triangle's slack (4.8e-7 + 7.6e-6·√Ω rad in f32) of the silhouette.
///
/// Coincident or collinear vertices, a shading point closer to the plane than 1e-6 of its
/// distance to the nearest vertex, and non-finite input give pdf 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleLight<V: Point3 = Vec3> {
    /// The vertices.
    pub v: [V; 3],
    /// The emitted radiance (RGB).
    pub le: V,
}

/// A [`TriangleLight`] prepared at one shading point: [`TriangleLight::at`].
#[derive(Clone, Copy)]
pub struct PreparedTriangle<V: Point3 = Vec3> {
    tri: SphericalTriangle<V3<V::Lane>>,
    /// The vertices relative to the shading point.
    v: [V3<V::Lane>; 3],
    le: V3<V::Lane>,
}

impl<V: Point3<Lane = L>, L: Math> TriangleLight<V> {
    /// The triangle (a, b, c).
    #[inline]
    pub fn new(a: V, b: V, c: V, le: V) -> Self {
        Self { v: [a, b, c], le }
    }

    /// The light prepared at shading point `p`.
    #[inline]
    pub fn at(&self, p: V) -> PreparedTriangle<V> {
        let p = p.to_lanes();
        let v = self.v.map(|x| x.to_lanes() - p);
        PreparedTriangle {
            tri: SphericalTriangle::new(v[0], v[1], v[2]),
            v,
            le: self.le.to_lanes(),
        }
    }

    super::at_one_point!(PreparedTriangle);

    /// A point uniform on the triangle (the low-distortion map of Heitz 2019), its unit normal,
    /// Le towards `p` and the area pdf 1/area.
    #[inline]
    pub fn sample_area(&self, p: V, u: V::Vec2) -> AreaSample<V> {
        let [a, b, c] = self.v.map(|x| x.to_lanes());
        let bary: V3<L> = uniform_triangle(u.to_lanes());
        let x = a.scale(bary.x) + b.scale(bary.y) + c.scale(bary.z);
        let n = wide_cross(b - a, c - a);
        let pdf = L::TWO / n.length();
        area_sample(p.to_lanes(), x, n.normalize(), pdf, self.le.to_lanes())
    }

    /// The power the light emits, π·area·luminance(Le).
    #[inline]
    pub fn power(&self) -> L {
        let [a, b, c] = self.v.map(|x| x.to_lanes());
        let area = wide_cross(b - a, c - a).length() * L::HALF;
        L::c(PI) * area * super::luminance(self.le.to_lanes())
    }
}

impl<V: Point3<Lane = L>, L: Math> PreparedTriangle<V> {
    /// A direction towards the light, its distance, Le and pdf per steradian (see
    /// [`TriangleLight`]). u is clamped to [0, 1]²; NaN gives the dropped sample (pdf 0).
    #[inline]
    pub fn sample(&self, u: V::Vec2) -> LightSample<V> {
        // The warp's own pdf is 0 for a sample it dropped (NaN u), whose stand-in direction may
        // well be on the light.
        let (wi, kept) = self.tri.sample(u.to_lanes());
        let (pdf, t) = self.eval(wi);
        let pdf = L::select(kept.gt(L::ZERO), pdf, L::ZERO);
        light_sample(wi, t, self.le().to_lanes(), pdf)
    }

    super::from_eval!();

    /// The shading point is on the side of the normal.
    #[inline(always)]
    fn front(&self) -> L::Mask {
        self.tri.plane().0.lt(L::ZERO)
    }

    /// The spherical triangle's pdf of unit `wi` and the distance h/(wi·n) to the plane (wi·n
    /// in f64 from the vertices), together: pdf > 0 exactly where t < ∞.
    #[inline(always)]
    fn eval(&self, wi: V3<L>) -> (L, L) {
        let (h, _) = self.tri.plane();
        let [a, b, c] = self.v;
        let wn = plane_dot(
            [wi.x, wi.y, wi.z],
            [a.x, a.y, a.z],
            [b.x, b.y, b.z],
            [c.x, c.y, c.z],
        );
        on_light(self.tri.pdf(wi), h / wn)
    }
}

/// A parallelogram light `corner + s·ex + t·ey`, s, t ∈ [0, 1], emitting radiance `le` on the
/// side of its normal ex × ey.
///
/// A rectangle (ex ⟂ ey) is sampled uniformly in solid angle ([`SphericalRectangle`], Ureña,
/// Fajardo and King 2013), with the area fallback below
/// [`SPHERICAL_RECTANGLE_MIN_SR`](crate::warp::SPHERICAL_RECTANGLE_MIN_SR). Ureña's map needs a
/// rectangle: a parallelogram whose edges are further than 2e-6 from orthogonal is sampled by
/// area, with its exact converted pdf (or split it into two [`TriangleLight`]s, which are
/// sampled in solid angle).
///
/// A shading point closer to the plane than 1e-6 of its distance to the nearest corner, zero
/// edges and non-finite input give pdf 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RectangleLight<V: Point3 = Vec3> {
    /// The corner.
    pub corner: V,
    /// The first edge.
    pub ex: V,
    /// The second edge (orthogonal to the first for a rectangle).
    pub ey: V,
    /// The emitted radiance (RGB).
    pub le: V,
}

/// A [`RectangleLight`] prepared at one shading point: [`RectangleLight::at`].
#[derive(Clone, Copy)]
pub struct PreparedRectangle<V: Point3 = Vec3> {
    rect: SphericalRectangle<V3<V::Lane>>,
    /// The edges.
    ex: V3<V::Lane>,
    ey: V3<V::Lane>,
    /// corner·(ex × ey), in f64 for the f32 lanes: negative on the emitting side.
    h: V::Lane,
    le: V3<V::Lane>,
}

impl<V: Point3<Lane = L>, L: Math> RectangleLight<V> {
    /// The rectangle `corner + s·ex + t·ey`.
    #[inline]
    pub fn new(corner: V, ex: V, ey: V, le: V) -> Self {
        Self { corner, ex, ey, le }
    }

    /// The light prepared at shading point `p`.
    #[inline]
    pub fn at(&self, p: V) -> PreparedRectangle<V> {
        let corner = self.corner.to_lanes() - p.to_lanes();
        let (ex, ey) = (self.ex.to_lanes(), self.ey.to_lanes());
        PreparedRectangle {
            rect: SphericalRectangle::new(corner, ex, ey),
            ex,
            ey,
            h: normal_dot(corner, ex, ey),
            le: self.le.to_lanes(),
        }
    }

    super::at_one_point!(PreparedRectangle);

    /// A point uniform on the rectangle, its unit normal, Le towards `p` and the area pdf
    /// 1/area.
    #[inline]
    pub fn sample_area(&self, p: V, u: V::Vec2) -> AreaSample<V> {
        let u = u.to_lanes();
        let (c, ex, ey) = (
            self.corner.to_lanes(),
            self.ex.to_lanes(),
            self.ey.to_lanes(),
        );
        let (s, t) = (u.x.clamp(L::ZERO, L::ONE), u.y.clamp(L::ZERO, L::ONE));
        let x = c + ex.scale(s) + ey.scale(t);
        let n = wide_cross(ex, ey);
        let pdf = L::ONE / n.length();
        area_sample(p.to_lanes(), x, n.normalize(), pdf, self.le.to_lanes())
    }

    /// The power the light emits, π·area·luminance(Le).
    #[inline]
    pub fn power(&self) -> L {
        let area = wide_cross(self.ex.to_lanes(), self.ey.to_lanes()).length();
        L::c(PI) * area * super::luminance(self.le.to_lanes())
    }
}

impl<V: Point3<Lane = L>, L: Math> PreparedRectangle<V> {
    /// A direction towards the light, its distance, Le and pdf per steradian (see
    /// [`RectangleLight`]). u is clamped to [0, 1]²; NaN gives the dropped sample (pdf 0).
    #[inline]
    pub fn sample(&self, u: V::Vec2) -> LightSample<V> {
        let (x, kept) = self.rect.sample(u.to_lanes());
        // The point may be far from unit length (a light 1e-22 away): normalise from a scale
        // where its square cannot underflow.
        let wi = x.normalize_scaled();
        let (pdf, t) = self.eval(wi);
        let pdf = L::select(kept.gt(L::ZERO), pdf, L::ZERO);
        light_sample(wi, t, self.le().to_lanes(), pdf)
    }

    super::from_eval!();

    /// The shading point is on the side of the normal.
    #[inline(always)]
    fn front(&self) -> L::Mask {
        self.h.lt(L::ZERO)
    }

    /// The spherical rectangle's pdf of unit `wi` and the distance h/(wi·n) to the plane,
    /// together: pdf > 0 exactly where t < ∞.
    #[inline(always)]
    fn eval(&self, wi: V3<L>) -> (L, L) {
        on_light(self.rect.pdf(wi), self.h / normal_dot(wi, self.ex, self.ey))
    }
}

/// w·(ex × ey), in f64 for the f32 lanes.
#[inline(always)]
fn normal_dot<L: Math>(w: V3<L>, ex: V3<L>, ey: V3<L>) -> L {
    let z = [L::ZERO; 3];
    plane_dot([w.x, w.y, w.z], z, [ex.x, ex.y, ex.z], [ey.x, ey.y, ey.z])
}

/// p × q, in f64 for the f32 lanes.
#[inline(always)]
fn wide_cross<L: Math>(p: V3<L>, q: V3<L>) -> V3<L> {
    let [x, y, z] = cross_wide([p.x, p.y, p.z], [q.x, q.y, q.z]);
    V3::new(x, y, z)
}
