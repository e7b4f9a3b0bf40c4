//! The scene that direct illumination needs, and nothing more: four lights (sphere, disk,
//! triangle, rectangle), light selection over a borrowed slice, and two BSDFs (Lambert and
//! modified Phong). There is no geometry engine: visibility is the caller's.
//!
//! # Lights
//!
//! Every light offers, at a shading point p:
//!
//! - `sample(p, u)` → [`LightSample`]: a unit direction towards the light, the distance to the
//!   point it reaches, the radiance Le that arrives from it, and the pdf per steradian;
//! - `sample_area(p, u)` → [`AreaSample`]: a point on the light, its normal, Le towards p and
//!   the pdf per unit area;
//! - `pdf(p, wi)`: the solid-angle pdf of `sample`, in closed form with no ray cast. For every
//!   kept sample (pdf > 0) it returns the same number, bit for bit, that `sample` returned: the
//!   sampler computes its pdf by the same function at the very direction it returns (a dropped
//!   sample, pdf 0, stands at +z, which may well be on the light);
//! - `hit(p, wi)`: the distance along `wi` to the light, ∞ for a miss. It decides "hit" by the
//!   same test as `pdf`, so the two never disagree on whether a direction is on the light, and
//!   a sample's distance is `hit` at its direction;
//! - `at(p)`: the light prepared at p (solid angle, frames, arcs), with `sample(u)`, `pdf(wi)`
//!   and `hit(wi)`. Splitting takes several samples at one point and pays the set-up once. The
//!   unprepared methods are `at(p)` followed by one call: there is one algorithm.
//!
//! Directions and pdfs are in world space, per steradian unless named "area". Lights emit on
//! one side, the side their normal points to (outwards for the sphere), with constant radiance
//! `le` (RGB). Le is 0 from behind; the pdf is geometric and does not look at the side.
//!
//! # Where f32 cannot see a light's edge
//!
//! A unit f32 direction is resolved to about 6e-8 rad, and world-space rounding moves a sample
//! by a few of those. A sample placed exactly on a light's silhouette can therefore land just
//! outside it. `pdf` and `hit` accept directions within a slack of a few ε·(1 + angular size)
//! outside the silhouette (documented per light), so every sample keeps its pdf and its hit; a
//! direction farther out gets pdf 0 and ∞. For a sphere light 1e-2 rad across the band is 5e-5
//! of its solid angle; for the tiniest lights (a sphere with sin²θmax = 1e-12 spans 2e-6 rad)
//! it widens what a BSDF-sampled ray can hit by a large part of the light, an f32 limit that
//! the f64 instance, whose slack scales with its own ε, does not share.
//!
//! # Choosing a light
//!
//! [`Light`] puts the four kinds in one slice. [`PowerTable`] chooses in proportion to power
//! (π·area·luminance(Le)) from a cumulative table in storage the caller provides, and
//! [`LightChoice::uniform`] with equal probability; either returns the index, its probability
//! and u rescaled to drive the chosen light's sampler. The probability enters every pdf an
//! estimator sees: [`LightSample::chosen_with`] for light samples, and `pmf(i)·pdf(p, wi)` for a
//! BSDF sample whose ray `hit`s light i.
//!
//! # Widths
//!
//! Each light and BSDF is generic over the width like the warps: `SphereLight<Vec3>` (the
//! default), `SphereLight<Vec3x8>` (eight lights, lane by lane, bit for bit the scalar ones) and
//! `SphereLight<DVec3>`, the f64 reference.
//!
//! # Bad input
//!
//! Nothing panics. A degenerate light (zero radius or area, non-finite geometry), a shading point
//! in a planar light's plane, and NaN in p, u or wi give pdf 0, distance ∞ and Le 0, with a finite
//! direction; callers drop samples with pdf 0.

/// The unprepared methods of a light, `sample(p, u)`, `pdf(p, wi)` and `hit(p, wi)`: the light
/// prepared at `p` (`at(p)`) and one call of its method, so that each light has one algorithm.
macro_rules! at_one_point {
    ($prepared:ident) => {
        #[doc = concat!("[`", stringify!($prepared), "::sample`] at shading point `p`.")]
        #[inline]
        pub fn sample(&self, p: V, u: V::Vec2) -> LightSample<V> {
            self.at(p).sample(u)
        }

        /// The pdf per steradian of `sample` at `p` in unit direction `wi`.
        #[inline]
        pub fn pdf(&self, p: V, wi: V) -> L {
            self.at(p).pdf(wi)
        }

        /// The distance from `p` along unit `wi` to the light, ∞ for a miss.
        #[inline]
        pub fn hit(&self, p: V, wi: V) -> L {
            self.at(p).hit(wi)
        }
    };
}
use at_one_point;

/// The methods every prepared light derives from its one `eval(wi) -> (pdf, t)` and its
/// `front()` (the shading point is on the emitting side): `pdf`, `hit`, both at once, and `le`,
/// so that the four lights answer these questions by one rule.
macro_rules! from_eval {
    () => {
        /// The pdf per steradian with which `sample` returns unit direction `wi` (the function
        /// the sampler itself calls); 0 off the light, for a degenerate light and for NaN.
        #[inline]
        pub fn pdf(&self, wi: V) -> L {
            self.eval(wi.to_lanes()).0
        }

        /// The distance along unit `wi` to the light, ∞ for a miss, decided by the same test as
        /// `pdf`.
        #[inline]
        pub fn hit(&self, wi: V) -> L {
            self.eval(wi.to_lanes()).1
        }

        /// `pdf` and `hit` at `wi` from one evaluation, as a BSDF sample's MIS weight and its
        /// shadow ray need both.
        #[inline]
        pub fn pdf_hit(&self, wi: V) -> (L, L) {
            self.eval(wi.to_lanes())
        }

        /// The radiance that arrives from every direction on the light: Le where the shading
        /// point is on the emitting side, else 0. Directions off the light (`hit` = ∞) receive
        /// nothing.
        #[inline]
        pub fn le(&self) -> V {
            V::from_lanes(le_towards(self.front(), self.le))
        }
    };
}
use from_eval;

mod bsdf;
mod disk;
mod polygon;
mod select;
mod sphere;

pub use bsdf::{Bsdf, BsdfSample, Lambert, Phong};
pub use disk::{DiskLight, PreparedDisk};
pub use polygon::{PreparedRectangle, PreparedTriangle, RectangleLight, TriangleLight};
pub use select::{Light, LightChoice, PowerTable, PreparedLight, luminance};
pub use sphere::{PreparedSphere, SphereLight};

use crate::lane::V3;
use crate::math::Math;
use crate::point::Point3;

/// A direction towards a light, from [`SphereLight::sample`] and the other lights' `sample`.
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
    /// The pdf per steradian, the light's `pdf` at `wi` bit for bit; 0 means "drop the sample".
    pub pdf: V::Lane,
}

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

/// Le where `front`, else 0: a light's radiance towards a point on its emitting side. NaN in Le
/// comes out as the canonical quiet NaN, so both widths return the same bits (a signalling NaN
/// came out quieted in one width and not in the other; found by the `lights` fuzz target).
#[inline(always)]
fn le_towards<L: Math>(front: L::Mask, le: V3<L>) -> V3<L> {
    let le = V3::new(le.x.canon(), le.y.canon(), le.z.canon());
    V3::select(front, le, V3::all(L::ZERO))
}

/// The sample of direction `wi` with its pdf and distance, or the dropped sample (+z, pdf 0,
/// distance ∞, Le 0) where the pdf is 0 or not finite.
#[inline(always)]
fn light_sample<V: Point3<Lane = L>, L: Math>(
    wi: V3<L>,
    dist: L,
    le: V3<L>,
    pdf: L,
) -> LightSample<V> {
    let ok = pdf.gt(L::ZERO) & pdf.is_finite() & dist.is_finite();
    LightSample {
        wi: V::from_lanes(V3::select(ok, wi, V3::new(L::ZERO, L::ZERO, L::ONE))),
        dist: L::select(ok, dist, L::c(f64::INFINITY)),
        le: V::from_lanes(le_towards(ok, le)),
        pdf: L::select(ok, pdf, L::ZERO),
    }
}

/// The area sample of point `x`, with unit normal `n` and area pdf `pdf`, seen from `p`: Le
/// where `p` is on the side `n` points to. A pdf that is 0 or not finite, or a NaN point, gives
/// the dropped sample (the origin, +z, Le 0, pdf 0).
#[inline(always)]
fn area_sample<V: Point3<Lane = L>, L: Math>(
    p: V3<L>,
    x: V3<L>,
    n: V3<L>,
    pdf: L,
    le: V3<L>,
) -> AreaSample<V> {
    let ok = pdf.gt(L::ZERO) & pdf.is_finite() & !x.any_nan() & !n.any_nan();
    let front = (p - x).dot(n).gt(L::ZERO) & ok;
    AreaSample {
        p: V::from_lanes(V3::select(ok, x, V3::all(L::ZERO))),
        n: V::from_lanes(V3::select(ok, n, V3::new(L::ZERO, L::ZERO, L::ONE))),
        le: V::from_lanes(le_towards(front, le)),
        pdf: L::select(ok, pdf, L::ZERO),
    }
}

/// The one rule of every light's `eval`: (pdf, t) where the direction is on the light (pdf > 0
/// and finite, t > 0 and finite), else (0, ∞), so that pdf > 0 exactly where t < ∞.
#[inline(always)]
fn on_light<L: Math>(pdf: L, t: L) -> (L, L) {
    let ok = pdf.gt(L::ZERO) & pdf.is_finite() & t.gt(L::ZERO) & t.is_finite();
    (
        L::select(ok, pdf, L::ZERO),
        L::select(ok, t, L::c(f64::INFINITY)),
    )
}
