//! The parallelogram: uniform in solid angle through the spherical rectangle sampler of
//! [`warp`](crate::warp) where it is a rectangle, by area otherwise.

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
use crate::warp::{
    BilinearRectangle, ProjectedRectangle, SphericalRectangle, plane_dot, wide_cross,
};

/// A parallelogram `corner + s·ex + t·ey`, s, t ∈ [0, 1], facing the side of its normal ex × ey.
/// As a light ([`RectangleLight`](super::RectangleLight)) it emits on that side.
///
/// A rectangle (ex ⟂ ey) is sampled uniformly in solid angle
/// ([`SphericalRectangle`](crate::warp::SphericalRectangle), Ureña,
/// Fajardo and King 2013), with the area fallback below
/// [`SPHERICAL_RECTANGLE_MIN_SR`](crate::warp::SPHERICAL_RECTANGLE_MIN_SR). Ureña's map needs a
/// rectangle: a parallelogram whose edges are further than 2e-6 from orthogonal is sampled by
/// area, with its exact converted pdf (or split it into two [`Triangle`](super::Triangle)s,
/// which are sampled in solid angle).
///
/// Prepared for [`LightSampling::Bilinear`] with a shading normal, a rectangle sampled in solid
/// angle samples through the bilinear cosine warp ([`BilinearRectangle`]); one sampled by area
/// keeps area sampling. Prepared for [`LightSampling::Projected`], any parallelogram samples by
/// projected solid angle ([`ProjectedRectangle`]): pdf n·ω / P above the receiver's horizon, 0
/// (and no distance) below it, unless it falls back to solid angle. Prepared for
/// [`LightSampling::Area`], it samples by area, the pdf converted to solid angle.
///
/// A shading point closer to the plane than 1e-6 of its distance to the nearest corner (but in
/// the projected mode, whose map has no such limit), zero edges and non-finite input give pdf
/// 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rectangle<V: Point3 = Vec3> {
    /// The corner.
    pub corner: V,
    /// The first edge.
    pub ex: V,
    /// The second edge (orthogonal to the first for a rectangle).
    pub ey: V,
}

split_fields!(Rectangle<V: Point3> by V::Lane { corner: point, ex: point, ey: point });

/// A parallelogram light: a [`Rectangle`] emitting on the side of its normal.
pub type RectangleLight<V = Vec3> = Emitter<Rectangle<V>, V>;

impl<V: Point3> RectangleLight<V> {
    /// The parallelogram `corner + s·ex + t·ey`, emitting `le`.
    #[inline]
    pub fn new(corner: V, ex: V, ey: V, le: V) -> Self {
        Emitter {
            shape: Rectangle { corner, ex, ey },
            le,
        }
    }
}

impl Rectangle<Vec3> {
    /// The same parallelogram in every lane of width `W`, exactly.
    #[inline]
    pub fn splat<W: Point3>(&self) -> Rectangle<W> {
        Rectangle {
            corner: splat_vec(self.corner),
            ex: splat_vec(self.ex),
            ey: splat_vec(self.ey),
        }
    }
}

/// A [`Rectangle`] prepared at one shading point.
#[derive(Clone, Copy)]
pub struct PreparedRectangle<V: Point3 = Vec3> {
    map: RectangleMap<V3<V::Lane>>,
    /// The edges.
    ex: V3<V::Lane>,
    ey: V3<V::Lane>,
    /// corner·(ex × ey), in f64 for the f32 lanes: negative on the side the normal faces.
    h: V::Lane,
}

/// The map a prepared rectangle samples by.
#[derive(Clone, Copy)]
enum RectangleMap<P: Point3> {
    /// The spherical rectangle behind the bilinear warp: with equal weights (solid angle)
    /// unless prepared for [`LightSampling::Bilinear`] with a normal.
    Spherical(BilinearRectangle<P>),
    Projected(ProjectedRectangle<P>),
    /// By area in every lane ([`LightSampling::Area`]).
    Area(SphericalRectangle<P>),
}

impl<V: Point3<Lane = L>, L: Math> Shape<V> for Rectangle<V> {
    type Prepared = PreparedRectangle<V>;
    type Half = Rectangle<V::Half>;

    #[inline(always)]
    fn halves(&self) -> (Rectangle<V::Half>, Rectangle<V::Half>) {
        Split::halves(*self)
    }

    #[inline(always)]
    fn at(&self, p: V, n: V, sampling: LightSampling) -> PreparedRectangle<V> {
        let corner = self.corner.to_lanes() - p.to_lanes();
        let (ex, ey) = (self.ex.to_lanes(), self.ey.to_lanes());
        let map = match sampling {
            LightSampling::Bilinear => {
                RectangleMap::Spherical(BilinearRectangle::new(corner, ex, ey, n.to_lanes()))
            }
            LightSampling::Projected => {
                RectangleMap::Projected(ProjectedRectangle::new(corner, ex, ey, n.to_lanes()))
            }
            LightSampling::Area => {
                RectangleMap::Area(SphericalRectangle::new(corner, ex, ey).by_area_only())
            }
            _ => RectangleMap::Spherical(BilinearRectangle::new(corner, ex, ey, V3::all(L::ZERO))),
        };
        PreparedRectangle {
            map,
            ex,
            ey,
            h: normal_dot(corner, ex, ey),
        }
    }

    /// A point uniform on the parallelogram, its unit normal and the area pdf 1/area.
    #[inline]
    fn sample_area(&self, u: V::Vec2) -> AreaPoint<V> {
        let u = u.to_lanes();
        let (c, ex, ey) = (
            self.corner.to_lanes(),
            self.ex.to_lanes(),
            self.ey.to_lanes(),
        );
        let (s, t) = (u.x.clamp(L::ZERO, L::ONE), u.y.clamp(L::ZERO, L::ONE));
        let x = c + ex.scale(s) + ey.scale(t);
        let n = wide_cross(ex, ey);
        planar_point(x, n, L::ONE)
    }

    /// |ex × ey|, the cross product in f64.
    #[inline]
    fn area(&self) -> L {
        wide_cross(self.ex.to_lanes(), self.ey.to_lanes()).length()
    }

    #[inline]
    fn modes(&self) -> &'static [LightSampling] {
        &LightSampling::ALL
    }
}

impl<V: Point3<Lane = L>, L: Math> PreparedShape<V> for PreparedRectangle<V> {
    #[inline]
    fn sample(&self, u: V::Vec2) -> ShapeSample<V> {
        let u = u.to_lanes();
        // The spherical map's point may be far from unit length (a light 1e-22 away):
        // normalise from a scale where its square cannot underflow.
        let (x, kept) = match &self.map {
            RectangleMap::Spherical(r) => {
                let (x, drawn) = r.sample(u);
                let wi = x.normalize_scaled();
                let t = self.h / normal_dot(wi, self.ex, self.ey);
                let on = on_shape(r.spherical().pdf(wi), t);
                return through_bilinear(wi, drawn, r.weighted(), on);
            }
            RectangleMap::Projected(r) => r.sample(u),
            RectangleMap::Area(r) => r.sample(u),
        };
        let wi = x.normalize_scaled();
        warped(wi, kept, self.eval(V::from_lanes(wi)))
    }

    /// The pdf of unit `wi` by the prepared map (spherical, through the bilinear warp, or
    /// projected) and the distance h/(wi·n) to the plane.
    #[inline(always)]
    fn eval(&self, wi: V) -> (L, L) {
        let wi = wi.to_lanes();
        let pdf = match &self.map {
            RectangleMap::Spherical(r) => r.pdf(wi),
            RectangleMap::Projected(r) => r.pdf(wi),
            RectangleMap::Area(r) => r.pdf(wi),
        };
        on_shape(pdf, self.h / normal_dot(wi, self.ex, self.ey))
    }

    /// The distance of `eval`, decided as the triangle's.
    #[inline(always)]
    fn dist(&self, wi: V) -> L {
        let wi = wi.to_lanes();
        let pdf = match &self.map {
            RectangleMap::Spherical(r) => r.spherical().pdf(wi),
            RectangleMap::Projected(r) => r.pdf(wi),
            RectangleMap::Area(r) => r.pdf(wi),
        };
        on_shape(pdf, self.h / normal_dot(wi, self.ex, self.ey)).1
    }

    /// The shading point is on the side of the normal.
    #[inline(always)]
    fn front(&self) -> L::Mask {
        self.h.lt(L::ZERO)
    }
}

/// w·(ex × ey), in f64 for the f32 lanes.
#[inline(always)]
fn normal_dot<L: Math>(w: V3<L>, ex: V3<L>, ey: V3<L>) -> L {
    let z = [L::ZERO; 3];
    plane_dot([w.x, w.y, w.z], z, [ex.x, ex.y, ex.z], [ey.x, ey.y, ey.z])
}
