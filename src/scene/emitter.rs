//! Emission, written once over every [`Shape`]: a light is a shape with a constant radiance Le on
//! the side it faces. The emitter turns the shape's directions into light samples, its points
//! into area samples, and its area into power.

use core::f64::consts::PI;

use glam::Vec3;

use super::luminance;
use super::shape::{AtPoint, LightSampling, PreparedShape, Shape};
use crate::lane::V3;
use crate::math::Math;
use crate::point::{Point3, Split, by_halves, halves2, halves3, split_fields};

/// A light: the shape `S` emitting radiance `le` (RGB) on the side it faces (outwards for the
/// sphere, the normal's side for planar shapes), 0 behind. [`SphereLight`](super::SphereLight),
/// [`DiskLight`](super::DiskLight), [`TriangleLight`](super::TriangleLight),
/// [`RectangleLight`](super::RectangleLight) and [`Light`](super::Light) (any of them) are this
/// type with their shape.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Emitter<S, V: Point3 = Vec3> {
    /// The geometry.
    pub shape: S,
    /// The emitted radiance (RGB).
    pub le: V,
}

impl<S: Shape<V>, V: Point3> Split for Emitter<S, V> {
    type Half = Emitter<S::Half, V::Half>;
    const SPLIT: bool = <V::Lane as Math>::SPLIT;
    #[inline(always)]
    fn halves(self) -> (Self::Half, Self::Half) {
        let ((s0, s1), (le0, le1)) = (self.shape.halves(), halves3(self.le));
        (
            Emitter { shape: s0, le: le0 },
            Emitter { shape: s1, le: le1 },
        )
    }
}

/// An [`Emitter`] prepared at one shading point: [`Emitter::at`].
#[derive(Clone, Copy)]
pub struct PreparedEmitter<P, V: Point3 = Vec3> {
    pub(super) shape: P,
    pub(super) le: V3<V::Lane>,
}

/// A direction towards a light, from a light's `sample`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSample<V: Point3> {
    /// The unit direction from the shading point towards the light (world space).
    pub wi: V,
    /// The distance along `wi` to the point of the light: the light's `hit` at `wi`. ∞ where the
    /// sample is dropped.
    pub dist: V::Lane,
    /// The radiance arriving along `wi`: the light's Le, or 0 from behind or for a dropped
    /// sample.
    pub le: V,
    /// The pdf per steradian, the light's `pdf` at `wi` bit for bit (in
    /// [`LightSampling::Bilinear`](super::LightSampling::Bilinear), to the spherical inverse's
    /// round trip); 0 means "drop the sample".
    pub pdf: V::Lane,
}

split_fields!(LightSample<V: Point3> by V::Lane { wi: point, dist, le: point, pdf });

/// A point on a light, drawn uniformly by area, from `sample_area`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AreaSample<V: Point3> {
    /// The point on the light (world space).
    pub p: V,
    /// The light's unit normal at `p`.
    pub n: V,
    /// The radiance leaving `p` towards the shading point: Le on the emitting side, else 0.
    pub le: V,
    /// The pdf per unit area, 1/area; 0 for a degenerate light or NaN in u.
    pub pdf: V::Lane,
}

impl<S: Shape<V>, V: Point3<Lane = L>, L: Math> Emitter<S, V> {
    /// The light prepared at shading point `p`, without a shading normal.
    #[inline]
    pub fn at(&self, p: V) -> PreparedEmitter<S::Prepared, V> {
        self.at_normal(p, V::from_lanes(V3::all(L::ZERO)))
    }

    /// The light prepared at shading point `p` with shading normal `n` (zero for none), sampled
    /// by solid angle.
    #[inline]
    pub fn at_normal(&self, p: V, n: V) -> PreparedEmitter<S::Prepared, V> {
        self.at_sampling(p, n, LightSampling::SolidAngle)
    }

    /// The light prepared at shading point `p` for a receiver with unit shading normal `n`
    /// (zero for none), sampled by `sampling` where its shape offers that mode, by solid angle
    /// otherwise ([`LightSampling`]).
    #[inline]
    pub fn at_sampling(
        &self,
        p: V,
        n: V,
        sampling: LightSampling,
    ) -> PreparedEmitter<S::Prepared, V> {
        PreparedEmitter {
            shape: self.shape.at(p, n, sampling),
            le: self.le.to_lanes(),
        }
    }

    /// [`PreparedEmitter::sample`] at shading point `p`.
    #[inline]
    pub fn sample(&self, p: V, u: V::Vec2) -> LightSample<V> {
        self.once_at(p, Query::Sample(u))
    }

    /// The pdf per steradian of `sample` at `p` in unit direction `wi`.
    #[inline]
    pub fn pdf(&self, p: V, wi: V) -> L {
        self.once_at(p, Query::Pdf(wi)).pdf
    }

    /// The distance from `p` along unit `wi` to the light, ∞ for a miss.
    #[inline]
    pub fn hit(&self, p: V, wi: V) -> L {
        self.once_at(p, Query::Hit(wi)).dist
    }

    /// One query of the light prepared at `p` (no normal, by solid angle), the prepared shape
    /// kept where it is built ([`Shape::with_at`]); sixteen lanes without AVX-512 as two calls
    /// of eight ([`Split`]), since a light's set-up at width 16 spills.
    #[inline(always)]
    fn once_at(&self, p: V, query: Query<V>) -> LightSample<V> {
        by_halves(
            (*self, p.to_lanes(), query),
            #[inline(always)]
            |(light, p, query)| light.whole_at(Point3::from_lanes(p), query),
        )
    }

    /// [`once_at`](Self::once_at) at the whole width.
    #[inline(always)]
    fn whole_at(&self, p: V, query: Query<V>) -> LightSample<V> {
        let zero = V::from_lanes(V3::all(L::ZERO));
        let work = Once {
            query,
            le: self.le.to_lanes(),
        };
        self.shape.with_at(p, zero, LightSampling::SolidAngle, work)
    }

    /// A point uniform on the light by area, its normal, Le towards `p` (0 where the point faces
    /// away from `p`) and the area pdf 1/area. A pdf that is 0 or not finite, or a NaN point,
    /// gives the dropped sample (the origin, +z, Le 0, pdf 0).
    #[inline]
    pub fn sample_area(&self, p: V, u: V::Vec2) -> AreaSample<V> {
        let a = self.shape.sample_area(u);
        let (x, n, pdf) = (a.p.to_lanes(), a.n.to_lanes(), a.pdf);
        let ok = pdf.gt(L::ZERO) & pdf.is_finite() & !x.any_nan() & !n.any_nan();
        let front = (p.to_lanes() - x).dot(n).gt(L::ZERO) & ok;
        AreaSample {
            p: V::from_lanes(V3::select(ok, x, V3::all(L::ZERO))),
            n: V::from_lanes(V3::select(ok, n, V3::new(L::ZERO, L::ZERO, L::ONE))),
            le: V::from_lanes(le_towards(front, self.le.to_lanes())),
            pdf: L::select(ok, pdf, L::ZERO),
        }
    }

    /// The power the light emits, π·area·luminance(Le).
    #[inline]
    pub fn power(&self) -> L {
        L::c(PI) * self.shape.area() * luminance(self.le)
    }
}

impl<P: PreparedShape<V>, V: Point3<Lane = L>, L: Math> PreparedEmitter<P, V> {
    /// A direction towards the light by its shape's sampler, the distance, Le and the pdf per
    /// steradian. u is clamped to [0, 1]²; NaN gives the dropped sample (+z, pdf 0, distance ∞,
    /// Le 0).
    #[inline]
    pub fn sample(&self, u: V::Vec2) -> LightSample<V> {
        light_sample(&self.shape, self.le, u)
    }

    /// The pdf per steradian with which `sample` returns unit direction `wi`; 0 off the light,
    /// for a degenerate light and for NaN.
    #[inline]
    pub fn pdf(&self, wi: V) -> L {
        self.shape.eval(wi).0
    }

    /// The distance along unit `wi` to the light, ∞ for a miss, decided by the same test as
    /// `pdf`.
    #[inline]
    pub fn hit(&self, wi: V) -> L {
        self.shape.dist(wi)
    }

    /// `pdf` and `hit` at `wi` from one evaluation, as a BSDF sample's MIS weight and its shadow
    /// ray need both.
    #[inline]
    pub fn pdf_hit(&self, wi: V) -> (L, L) {
        self.shape.eval(wi)
    }

    /// The radiance that arrives from every direction on the light: Le where the shading point
    /// is on the emitting side, else 0. Directions off the light (`hit` = ∞) receive nothing.
    #[inline]
    pub fn le(&self) -> V {
        V::from_lanes(le_towards(self.shape.front(), self.le))
    }

    /// The prepared shape.
    #[inline]
    pub fn shape(&self) -> &P {
        &self.shape
    }
}

/// [`PreparedEmitter::sample`] of `shape` with radiance `le`.
#[inline(always)]
fn light_sample<P: PreparedShape<V>, V: Point3<Lane = L>, L: Math>(
    shape: &P,
    le: V3<L>,
    u: V::Vec2,
) -> LightSample<V> {
    let s = shape.sample(u);
    let (wi, dist, pdf) = (s.wi.to_lanes(), s.dist, s.pdf);
    let ok = pdf.gt(L::ZERO) & pdf.is_finite() & dist.is_finite();
    let le = le_towards(shape.front(), le);
    LightSample {
        wi: V::from_lanes(V3::select(ok, wi, V3::new(L::ZERO, L::ZERO, L::ONE))),
        dist: L::select(ok, dist, L::c(f64::INFINITY)),
        le: V::from_lanes(V3::select(ok, le, V3::all(L::ZERO))),
        pdf: L::select(ok, pdf, L::ZERO),
    }
}

/// What [`Emitter`]'s queries at a point ask of the light prepared there: a sample, or the pdf
/// (answered in `pdf`, the rest 0) or the distance (in `dist`) of a direction.
#[derive(Clone, Copy)]
enum Query<V: Point3> {
    Sample(V::Vec2),
    Pdf(V),
    Hit(V),
}

impl<V: Point3> Split for Query<V> {
    type Half = Query<V::Half>;
    const SPLIT: bool = <V::Lane as Math>::SPLIT;
    #[inline(always)]
    fn halves(self) -> (Query<V::Half>, Query<V::Half>) {
        match self {
            Query::Sample(u) => {
                let (lo, hi) = halves2::<V>(u);
                (Query::Sample(lo), Query::Sample(hi))
            }
            Query::Pdf(w) => {
                let (lo, hi) = halves3(w);
                (Query::Pdf(lo), Query::Pdf(hi))
            }
            Query::Hit(w) => {
                let (lo, hi) = halves3(w);
                (Query::Hit(lo), Query::Hit(hi))
            }
        }
    }
}

/// A [`Query`] with the light's radiance, as work on the prepared shape.
struct Once<V: Point3> {
    query: Query<V>,
    le: V3<V::Lane>,
}

impl<V: Point3<Lane = L>, L: Math> AtPoint<V> for Once<V> {
    type Output = LightSample<V>;
    #[inline(always)]
    fn samples(&self) -> bool {
        matches!(self.query, Query::Sample(_))
    }
    #[inline(always)]
    fn run<P: PreparedShape<V>>(self, shape: &P) -> LightSample<V> {
        let zero = V::from_lanes(V3::all(L::ZERO));
        let none = LightSample {
            wi: zero,
            dist: L::ZERO,
            le: zero,
            pdf: L::ZERO,
        };
        match self.query {
            Query::Sample(u) => light_sample(shape, self.le, u),
            Query::Pdf(wi) => LightSample {
                pdf: shape.eval(wi).0,
                ..none
            },
            Query::Hit(wi) => LightSample {
                dist: shape.dist(wi),
                ..none
            },
        }
    }
}

/// Le where `front`, else 0. NaN in Le comes out as the canonical quiet NaN, so both widths
/// return the same bits.
#[inline(always)]
fn le_towards<L: Math>(front: L::Mask, le: V3<L>) -> V3<L> {
    let le = V3::new(le.x.canon(), le.y.canon(), le.z.canon());
    V3::select(front, le, V3::all(L::ZERO))
}

impl<V: Point3<Lane = L>, L: Math> LightSample<V> {
    /// The same sample with its pdf multiplied by a selection probability: what an estimator
    /// that chose the light at random must divide by.
    #[inline]
    pub fn chosen_with(self, pmf: L) -> Self {
        Self {
            pdf: self.pdf * pmf,
            ..self
        }
    }
}
