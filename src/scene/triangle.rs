//! The triangle: uniform in solid angle through the spherical triangle sampler of
//! [`warp`](crate::warp), which falls back to area sampling where spherical sampling would lose
//! accuracy.

use glam::Vec3;

use super::emitter::Emitter;
use super::select::splat_vec;
use super::shape::{
    AreaPoint, LightSampling, PreparedShape, Shape, ShapeSample, on_shape, planar_point,
    through_bilinear, warped,
};
use crate::lane::V3;
use crate::math::Math;
use crate::point::{Point2, Point3, Split, split_fields};
use crate::warp::plane_dot;
use crate::warp::{
    BilinearTriangle, ProjectedTriangle, SphericalTriangle, uniform_triangle, wide_cross,
};

/// A triangle with vertices `v`, facing the side of its normal (b − a) × (c − a): the side from
/// which the vertices run counter-clockwise. As a light
/// ([`TriangleLight`](super::TriangleLight)) it emits on that side.
///
/// It samples the triangle's solid angle uniformly
/// ([`SphericalTriangle`](crate::warp::SphericalTriangle), Arvo 1995, with the
/// plane and Van Oosterom–Strackee's solid angle in f64): pdf 1/Ω per steradian, within 2e-7 of
/// the f64 value on random triangles near and far, grazing and straddling the horizon. Below
/// [`SPHERICAL_TRIANGLE_MIN_SR`](crate::warp::SPHERICAL_TRIANGLE_MIN_SR) and above
/// [`SPHERICAL_TRIANGLE_MAX_SR`](crate::warp::SPHERICAL_TRIANGLE_MAX_SR) it samples by area and
/// returns the exact converted pdf. `pdf` and `hit` accept directions within the spherical
/// triangle's slack (4.8e-7 + 7.6e-6·√Ω rad in f32) of the silhouette.
///
/// Prepared for [`LightSampling::Bilinear`] with a shading normal, it samples through the
/// bilinear cosine warp ([`BilinearTriangle`]), whose pdf is the spherical one times the
/// bilinear density: at the u′ a sample drew, for the pdf returned with it, and at the
/// direction's spherical inverse for `pdf`. Prepared for
/// [`LightSampling::Projected`], it samples by projected solid angle ([`ProjectedTriangle`]):
/// pdf n·ω / P above the receiver's horizon, 0 (and no
/// distance) below it, unless it falls back to solid angle. Prepared for
/// [`LightSampling::Area`], it samples by area, the pdf converted to solid angle.
///
/// Coincident or collinear vertices, a shading point closer to the plane than 1e-6 of its
/// distance to the nearest vertex (but in the projected mode, whose map has no such limit), and
/// non-finite input give pdf 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Triangle<V: Point3 = Vec3> {
    /// The vertices.
    pub v: [V; 3],
}

split_fields!(Triangle<V: Point3> by V::Lane { v: points });

/// A triangle light: a [`Triangle`] emitting on the side of its normal.
pub type TriangleLight<V = Vec3> = Emitter<Triangle<V>, V>;

impl<V: Point3> TriangleLight<V> {
    /// The triangle (a, b, c), emitting `le`.
    #[inline]
    pub fn new(a: V, b: V, c: V, le: V) -> Self {
        Emitter {
            shape: Triangle { v: [a, b, c] },
            le,
        }
    }
}

impl Triangle<Vec3> {
    /// The same triangle in every lane of width `W`, exactly.
    #[inline]
    pub fn splat<W: Point3>(&self) -> Triangle<W> {
        Triangle {
            v: self.v.map(splat_vec),
        }
    }
}

/// A [`Triangle`] prepared at one shading point.
#[derive(Clone, Copy)]
pub struct PreparedTriangle<V: Point3 = Vec3> {
    map: TriangleMap<V3<V::Lane>>,
    /// The vertices relative to the shading point.
    v: [V3<V::Lane>; 3],
}

/// The map a prepared triangle samples by.
#[derive(Clone, Copy)]
enum TriangleMap<P: Point3> {
    /// The spherical triangle behind the bilinear warp: with equal weights (solid angle) unless
    /// prepared for [`LightSampling::Bilinear`] with a normal.
    Spherical(BilinearTriangle<P>),
    Projected(ProjectedTriangle<P>),
    /// By area in every lane ([`LightSampling::Area`]).
    Area(SphericalTriangle<P>),
}

impl<P: Point3<Lane = L>, L: Math> TriangleMap<P> {
    #[inline(always)]
    fn spherical(&self) -> &SphericalTriangle<P> {
        match self {
            TriangleMap::Spherical(t) => t.spherical(),
            TriangleMap::Projected(t) => t.spherical(),
            TriangleMap::Area(t) => t,
        }
    }
}

impl<V: Point3<Lane = L>, L: Math> Shape<V> for Triangle<V> {
    type Prepared = PreparedTriangle<V>;
    type Half = Triangle<V::Half>;

    #[inline(always)]
    fn halves(&self) -> (Triangle<V::Half>, Triangle<V::Half>) {
        Split::halves(*self)
    }

    #[inline(always)]
    fn at(&self, p: V, n: V, sampling: LightSampling) -> PreparedTriangle<V> {
        let p = p.to_lanes();
        let v = self.v.map(|x| x.to_lanes() - p);
        let map = match sampling {
            LightSampling::Bilinear => {
                TriangleMap::Spherical(BilinearTriangle::new(v[0], v[1], v[2], n.to_lanes()))
            }
            LightSampling::Projected => {
                TriangleMap::Projected(ProjectedTriangle::new(v[0], v[1], v[2], n.to_lanes()))
            }
            LightSampling::Area => {
                TriangleMap::Area(SphericalTriangle::new(v[0], v[1], v[2]).by_area_only())
            }
            _ => TriangleMap::Spherical(BilinearTriangle::new(v[0], v[1], v[2], V3::all(L::ZERO))),
        };
        PreparedTriangle { map, v }
    }

    /// A point uniform on the triangle (the low-distortion map of Heitz 2019), its unit normal
    /// and the area pdf 1/area.
    #[inline]
    fn sample_area(&self, u: V::Vec2) -> AreaPoint<V> {
        let [a, b, c] = self.v.map(|x| x.to_lanes());
        let bary: V3<L> = uniform_triangle(u.to_lanes());
        let x = a.scale(bary.x) + b.scale(bary.y) + c.scale(bary.z);
        let n = wide_cross(b - a, c - a);
        planar_point(x, n, L::TWO)
    }

    /// |(b − a) × (c − a)|/2, the cross product in f64.
    #[inline]
    fn area(&self) -> L {
        let [a, b, c] = self.v.map(|x| x.to_lanes());
        wide_cross(b - a, c - a).length() * L::HALF
    }

    #[inline]
    fn modes(&self) -> &'static [LightSampling] {
        &LightSampling::ALL
    }
}

impl<V: Point3<Lane = L>, L: Math> PreparedTriangle<V> {
    /// The distance h/(wi·n) along unit `wi` to the plane.
    #[inline(always)]
    fn plane_distance(&self, wi: V3<L>) -> L {
        let (h, _) = self.map.spherical().plane();
        let [a, b, c] = self.v;
        let wn = plane_dot(
            [wi.x, wi.y, wi.z],
            [a.x, a.y, a.z],
            [b.x, b.y, b.z],
            [c.x, c.y, c.z],
        );
        h / wn
    }
}

impl<V: Point3<Lane = L>, L: Math> PreparedShape<V> for PreparedTriangle<V> {
    #[inline]
    fn sample(&self, u: V::Vec2) -> ShapeSample<V> {
        let u = u.to_lanes();
        let (wi, kept) = match &self.map {
            TriangleMap::Spherical(t) => {
                let (wi, drawn) = t.sample(u);
                let on = on_shape(t.spherical().pdf(wi), self.plane_distance(wi));
                return through_bilinear(wi, drawn, t.weighted(), on);
            }
            TriangleMap::Projected(t) => t.sample(u),
            TriangleMap::Area(t) => t.sample(u),
        };
        warped(wi, kept, self.eval(V::from_lanes(wi)))
    }

    /// The pdf of unit `wi` by the prepared map (spherical, through the bilinear warp, or
    /// projected) and the distance h/(wi·n) to the plane (wi·n in f64 from the vertices).
    #[inline(always)]
    fn eval(&self, wi: V) -> (L, L) {
        let wi = wi.to_lanes();
        let pdf = match &self.map {
            TriangleMap::Spherical(t) => t.pdf(wi),
            TriangleMap::Projected(t) => t.pdf(wi),
            TriangleMap::Area(t) => t.pdf(wi),
        };
        on_shape(pdf, self.plane_distance(wi))
    }

    /// The distance of `eval`, decided by the spherical pdf where the bilinear density sits on
    /// it (positive wherever it is, so the verdict is the same), by the projected pdf itself.
    #[inline(always)]
    fn dist(&self, wi: V) -> L {
        let wi = wi.to_lanes();
        let pdf = match &self.map {
            TriangleMap::Spherical(t) => t.spherical().pdf(wi),
            TriangleMap::Projected(t) => t.pdf(wi),
            TriangleMap::Area(t) => t.pdf(wi),
        };
        on_shape(pdf, self.plane_distance(wi)).1
    }

    /// The shading point is on the side of the normal.
    #[inline(always)]
    fn front(&self) -> L::Mask {
        self.map.spherical().plane().0.lt(L::ZERO)
    }
}
