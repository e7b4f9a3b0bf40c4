//! The shape contract: the geometry of a light, without its emission. A shape is prepared at a
//! shading point; prepared, it samples directions towards itself, evaluates the pdf and the
//! distance of any direction, and says which side of it the point is on. Emission is one layer
//! on top of every shape ([`Emitter`](super::Emitter)).

use crate::lane::Lane;
use crate::math::Math;
use crate::point::Point3;

/// How a prepared light samples its directions, for a receiver whose shading normal it knows.
/// Every shape offers [`SolidAngle`](LightSampling::SolidAngle); a shape prepared with a mode it
/// does not offer (or with the zero normal) samples by solid angle. The report's JSON names the
/// modes `solid_angle`, `bilinear`, `projected` and `area`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[non_exhaustive]
pub enum LightSampling {
    /// Uniform in the solid angle (the sphere's cone, the polygons' spherical maps, the disk's
    /// spherical ellipse; the tiny polygons and disks by area, converted).
    #[default]
    SolidAngle,
    /// The triangle and the rectangle through the bilinear cosine warp
    /// ([`warp::bilinear_triangle`](crate::warp::bilinear_triangle),
    /// [`warp::bilinear_rectangle`](crate::warp::bilinear_rectangle)): approximately
    /// proportional to the receiver's cosine. The sphere and the disk keep solid angle.
    ///
    /// The one mode whose sample's pdf is not the pdf function's bit for bit: a sample returns
    /// the warp's density at the u′ it drew (the density it was drawn with), while the pdf of a
    /// direction takes u′ from the spherical map's inverse, which costs about a second sample.
    /// The two agree to the inverse's round trip times the density's relative slope (within
    /// 2e-4 relative, the 0.01 weight floor allowing slopes up to 100; measured 8.5e-5 at
    /// worst on the crate's test lights, below 2e-5 on all but one), and bit for bit where a light's weights are equal. A MIS
    /// weight sees that difference, and nothing else does: "on the light" is still one verdict.
    Bilinear,
    /// The triangle and the parallelogram by projected solid angle
    /// ([`warp::projected_triangle`](crate::warp::projected_triangle),
    /// [`warp::projected_rectangle`](crate::warp::projected_rectangle)): exactly proportional
    /// to the receiver's cosine over the part above its horizon, so that a Lambertian receiver
    /// under an unoccluded light of constant radiance has no variance. Such a light has pdf 0,
    /// and no distance, in directions below the horizon, except where the polygon falls back
    /// to solid angle (a projected solid angle below
    /// [`PROJECTED_MIN_SR`](crate::warp::PROJECTED_MIN_SR), …). The sphere, from outside, by
    /// its cap's projected solid angle ([`warp::projected_cap`](crate::warp::projected_cap)),
    /// as exact; the disk keeps solid angle.
    Projected,
    /// The triangle and the parallelogram uniformly by area, the pdf converted to solid angle
    /// (what renderers without spherical samplers do), and so is the disk; the sphere keeps its
    /// cone.
    Area,
}

impl LightSampling {
    /// Every mode, in the order of the report.
    pub const ALL: [LightSampling; 4] = [
        LightSampling::SolidAngle,
        LightSampling::Bilinear,
        LightSampling::Projected,
        LightSampling::Area,
    ];

    /// The name the report's JSON uses.
    pub fn name(self) -> &'static str {
        match self {
            LightSampling::SolidAngle => "solid_angle",
            LightSampling::Bilinear => "bilinear",
            LightSampling::Projected => "projected",
            LightSampling::Area => "area",
        }
    }
}

/// A direction towards a shape from a prepared point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShapeSample<V: Point3> {
    /// The unit direction (world space).
    pub wi: V,
    /// The pdf per steradian: [`PreparedShape::eval`] at `wi`, bit for bit, or 0 for a dropped
    /// sample.
    pub pdf: V::Lane,
    /// The distance along `wi` to the shape: [`PreparedShape::eval`]'s at `wi`.
    pub dist: V::Lane,
}

/// A point drawn uniformly by area on a shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AreaPoint<V: Point3> {
    /// The point (world space).
    pub p: V,
    /// The unit normal there: outwards for a sphere, the side a planar shape faces.
    pub n: V,
    /// The pdf per unit area, 1/area; 0 for a degenerate shape or NaN in u.
    pub pdf: V::Lane,
}

/// A light's geometry (sphere, disk, triangle, parallelogram), generic over the width like the
/// warps. What it must give is named here; [`Emitter`](super::Emitter) builds the light's
/// methods from it once.
pub trait Shape<V: Point3>: Copy {
    /// The shape prepared at one shading point.
    type Prepared: PreparedShape<V>;
    /// The shape at the width a light's long queries run at ([`Split`](crate::point::Split)):
    /// the same shape over [`Point3::Half`].
    type Half: Shape<V::Half>;
    /// The shape as its two halves, lanes 0..w/2 and w/2..w (`self` twice where the width runs
    /// whole): [`Split::halves`](crate::point::Split::halves).
    fn halves(&self) -> (Self::Half, Self::Half);
    /// The shape prepared at shading point `p`, with the shading normal `n` (the zero vector for
    /// none), to sample by `sampling` where the shape offers it and by its own sampler (solid
    /// angle) otherwise. Splitting takes several samples at one point and pays the set-up once.
    ///
    /// The shapes mark it `#[inline(always)]`: a prepared packet shape runs to kilobytes, and
    /// inlined where it is stored (the estimator's cache of prepared lights) it is built there;
    /// called, it is built in a temporary and copied, which cost the x8 triangle a fifth of an
    /// estimate.
    fn at(&self, p: V, n: V, sampling: LightSampling) -> Self::Prepared;
    /// A point uniform by area, its normal and the area pdf. u is clamped to [0, 1]²; NaN gives
    /// pdf 0.
    fn sample_area(&self, u: V::Vec2) -> AreaPoint<V>;
    /// The surface area (the sphere's whole surface).
    fn area(&self) -> V::Lane;
    /// The light-sampling modes that change how this shape samples (the others fall back to
    /// [`LightSampling::SolidAngle`]), solid angle first.
    fn modes(&self) -> &'static [LightSampling];
    /// `work` done on the shape prepared at `p` as [`at`](Self::at) prepares it, by reference.
    /// A shape of any kind overrides it to hand over its own variant's prepared form, so that
    /// one query at a point (a light's `sample(p, u)`, `pdf(p, wi)`) never builds, nor moves,
    /// the prepared enum, which is as large as its largest variant.
    #[inline(always)]
    fn with_at<W: AtPoint<V>>(&self, p: V, n: V, sampling: LightSampling, work: W) -> W::Output {
        work.run(&self.at(p, n, sampling))
    }
}

/// Work on a prepared shape of any type: [`Shape::with_at`]'s argument (a closure cannot be
/// generic over the shape it receives).
pub trait AtPoint<V: Point3> {
    /// What the work returns.
    type Output;
    /// The work, on `shape`.
    fn run<P: PreparedShape<V>>(self, shape: &P) -> Self::Output;
    /// Whether the work draws a sample. Work that only asks a pdf or a distance lets a shape
    /// leave out the part of its preparation that only its sampler reads (the disk's table).
    #[inline(always)]
    fn samples(&self) -> bool {
        true
    }
}

/// A shape prepared at a shading point.
pub trait PreparedShape<V: Point3>: Copy {
    /// A direction by the shape's own sampler, with its pdf and distance: the pdf is
    /// [`eval`](Self::eval)'s at the returned direction, bit for bit, or 0 where the sample is
    /// dropped (NaN u, a degenerate shape). One exception: through the bilinear warp with
    /// unequal weights the pdf is the density at the u′ the sample drew, and `eval`'s (at the
    /// spherical inverse of the direction) agrees to the inverse's round trip (see
    /// `through_bilinear`). u is clamped to [0, 1]².
    fn sample(&self, u: V::Vec2) -> ShapeSample<V>;
    /// The pdf per steradian with which [`sample`](Self::sample) returns unit direction `wi`,
    /// and the distance to the shape along it: (pdf, t) with pdf > 0 exactly where t < ∞, from
    /// one test of whether `wi` is on the shape, so the two never disagree.
    fn eval(&self, wi: V) -> (V::Lane, V::Lane);
    /// [`eval`](Self::eval)'s distance alone, bit for bit, for a caller that needs no pdf: a
    /// shape whose pdf costs more than its inside test (a polygon through the bilinear warp)
    /// skips the rest.
    #[inline(always)]
    fn dist(&self, wi: V) -> V::Lane {
        self.eval(wi).1
    }
    /// Where the shading point is on the side the shape faces (outside a sphere, on the side of
    /// a planar shape's normal): the side a one-sided emitter lights.
    fn front(&self) -> <V::Lane as Lane>::Mask;
}

/// The one rule of every shape's `eval`: (pdf, t) where the direction is on the shape (pdf > 0
/// and finite, t > 0 and finite), else (0, ∞), so that pdf > 0 exactly where t < ∞.
#[inline(always)]
pub(crate) fn on_shape<L: Math>(pdf: L, t: L) -> (L, L) {
    let ok = pdf.gt(L::ZERO) & pdf.is_finite() & t.gt(L::ZERO) & t.is_finite();
    (
        L::select(ok, pdf, L::ZERO),
        L::select(ok, t, L::c(f64::INFINITY)),
    )
}

/// The sample of direction `wi` from a spherical polygon's warp, with the shape's (pdf, t) at
/// it: the pdf kept only where the warp kept the sample (its own pdf `kept` > 0), since a
/// dropped sample's stand-in direction may well be on the shape.
#[inline(always)]
pub(crate) fn warped<V: Point3<Lane = L>, L: Math>(
    wi: crate::lane::V3<L>,
    kept: L,
    (pdf, dist): (L, L),
) -> ShapeSample<V> {
    ShapeSample {
        wi: V::from_lanes(wi),
        pdf: L::select(kept.gt(L::ZERO), pdf, L::ZERO),
        dist,
    }
}

/// The sample of direction `wi` from a polygon through the bilinear warp, which drew it with
/// density `drawn`, given `(pdf, t)` of the spherical map alone at `wi` (decided as
/// [`on_shape`]), as [`PreparedShape::dist`] decides "on the light". Where `weighted` (the
/// weights differ) the pdf is `drawn`: the pdf function takes the warp's density at the
/// spherical inverse of `wi`, which costs about one more sample, while the density the sample
/// was drawn with is the one it has, to the warp's f32 rounding; the two agree to the
/// inverse's round trip times the density's slope (measured in the crate's tests), which is
/// all a MIS weight sees of the difference. Elsewhere the warp is the identity and the pdf is
/// the spherical one, bit for bit as `eval`'s.
#[inline(always)]
pub(crate) fn through_bilinear<V: Point3<Lane = L>, L: Math>(
    wi: crate::lane::V3<L>,
    drawn: L,
    weighted: L::Mask,
    (pdf, dist): (L, L),
) -> ShapeSample<V> {
    let pdf = L::select(weighted & pdf.gt(L::ZERO), drawn, pdf);
    warped(wi, drawn, (pdf, dist))
}

/// The area sample of point `x` of a planar shape whose unnormalised normal `n` has length
/// `k`·area (k = 2 for a triangle's edge cross product, 1 for a parallelogram's): pdf 1/area.
#[inline(always)]
pub(crate) fn planar_point<V: Point3<Lane = L>, L: Math>(
    x: crate::lane::V3<L>,
    n: crate::lane::V3<L>,
    k: L,
) -> AreaPoint<V> {
    AreaPoint {
        p: V::from_lanes(x),
        n: V::from_lanes(n.normalize()),
        pdf: k / n.length(),
    }
}
