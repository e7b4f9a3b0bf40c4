//! Lambert and the modified Phong BSDF, in the local frame of the shading point (+z along the
//! normal; use [`Frame`](crate::frame::Frame) to get there).
//!
//! Each has `eval(wo, wi)` (the BSDF f, without the cosine), `sample(wo, u)` and `pdf(wo, wi)`
//! per steradian. `sample` returns the pdf function's value at the very direction it returns,
//! so the two agree bit for bit. Either direction at or below the horizon gives f = 0; a
//! sample below the horizon keeps its (non-zero) pdf, so an estimator that divides f by it stays
//! unbiased. NaN gives f = 0 and pdf 0.

use core::f64::consts::PI;

use glam::Vec3;

use crate::frame::Frame;
use crate::lane::{V2, V3};
use crate::math::Math;
use crate::point::{Point2, Point3, by_halves, split_fields};
use crate::warp::dot_wide;
use crate::warp::{
    ONE_MINUS_EPS, cosine_hemisphere, cosine_hemisphere_pdf, phong_lobe, phong_lobe_density,
};

/// A direction drawn from a BSDF, with the BSDF's value there and the pdf per steradian.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BsdfSample<V: Point3> {
    /// The sampled direction (local frame, unit).
    pub wi: V,
    /// `eval(wo, wi)`: 0 below the horizon.
    pub f: V,
    /// `pdf(wo, wi)`, bit for bit; 0 means "drop the sample".
    pub pdf: V::Lane,
}

split_fields!(BsdfSample<V: Point3> by V::Lane { wi: point, f: point, pdf });

/// The Lambertian BSDF f = ρ/π (RGB albedo ρ), sampled by the cosine hemisphere (Malley's
/// method): pdf cos θ/π, so f·cos θ/pdf = ρ exactly.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lambert<V: Point3 = Vec3> {
    /// The albedo ρ (RGB), in [0, 1] for energy conservation.
    pub rho: V,
}

impl<V: Point3<Lane = L>, L: Math> Lambert<V> {
    /// The Lambertian BSDF of albedo `rho`.
    #[inline]
    pub fn new(rho: V) -> Self {
        Self { rho }
    }

    /// f(wo, wi) = ρ/π where both directions are above the horizon, else 0.
    #[inline]
    pub fn eval(&self, wo: V, wi: V) -> V {
        let up = above(wo.to_lanes(), wi.to_lanes());
        let f = self.rho.to_lanes().scale(L::c(1.0 / PI));
        V::from_lanes(V3::select(up, f, V3::all(L::ZERO)))
    }

    /// A cosine-distributed direction, f there and its pdf. u is clamped to [0, 1]².
    #[inline]
    pub fn sample(&self, wo: V, u: V::Vec2) -> BsdfSample<V> {
        let wi = V::from_lanes(cosine_hemisphere(u.to_lanes()));
        BsdfSample {
            wi,
            f: self.eval(wo, wi),
            pdf: self.pdf(wo, wi),
        }
    }

    /// cos θ/π above the horizon, 0 at and below it and for NaN. It does not depend on `wo`.
    #[inline]
    pub fn pdf(&self, _wo: V, wi: V) -> L {
        cosine_hemisphere_pdf(wi)
    }
}

/// The modified Phong BSDF (Lafortune and Willems 1994):
/// f = kd/π + ks·(n + 2)/(2π)·cosⁿα, α the angle between wi and the mirror direction of wo.
/// It conserves energy when kd + ks ≤ 1 (per channel), and reflects exactly kd + ks at normal
/// incidence, where no lobe reaches below the horizon.
///
/// `sample` picks the diffuse lobe with probability P = k̄d/(k̄d + k̄s) (channel means; 1 when
/// both are 0), rescales u₀ to drive the chosen lobe, and draws either the cosine hemisphere or
/// the Phong lobe cosⁿα about the mirror direction; the pdf is the mixture
/// P·cos θ/π + (1 − P)·(n + 1)/(2π)·cosⁿα. n is clamped to [0,
/// [`PHONG_N_MAX`](crate::warp::PHONG_N_MAX)]. A NaN exponent is a NaN parameter: `sample`
/// gives a NaN direction with pdf 0, `pdf` gives 0, and `eval` the diffuse lobe alone.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Phong<V: Point3 = Vec3> {
    /// The diffuse reflectance kd (RGB).
    pub kd: V,
    /// The specular reflectance ks (RGB).
    pub ks: V,
    /// The exponent n.
    pub n: V::Lane,
}

// Sixteen lanes without AVX-512 run as two calls of eight (`point::Split`): the lobe's logarithm
// and exponential spill at width 16.
split_fields!(Phong<V: Point3> by V::Lane { kd: point, ks: point, n });

impl<V: Point3<Lane = L>, L: Math> Phong<V> {
    /// The modified Phong BSDF with reflectances `kd`, `ks` and exponent `n`.
    #[inline]
    pub fn new(kd: V, ks: V, n: L) -> Self {
        Self { kd, ks, n }
    }

    /// The probability of the diffuse lobe.
    #[inline(always)]
    fn diffuse_probability(&self) -> L {
        let mean = |c: V3<L>| (c.x + c.y + c.z) * L::c(1.0 / 3.0);
        let (d, s) = (mean(self.kd.to_lanes()), mean(self.ks.to_lanes()));
        let p = d / (d + s);
        L::select(p.ge(L::ZERO) & p.le(L::ONE), p, L::ONE)
    }

    /// f(wo, wi) where both directions are above the horizon, else 0.
    #[inline]
    pub fn eval(&self, wo: V, wi: V) -> V {
        let f = by_halves(
            (*self, wo.to_lanes(), wi.to_lanes()),
            #[inline(always)]
            |(bsdf, wo, wi)| bsdf.eval_whole(wo, wi),
        );
        V::from_lanes(f)
    }

    /// [`eval`](Self::eval) at the whole width.
    #[inline(always)]
    fn eval_whole(&self, wo: V3<L>, wi: V3<L>) -> V3<L> {
        self.eval_with(wo, wi, lobe_pdf(wo, wi, self.n))
    }

    /// f from the lobe's density at (wo, wi), which `sample` shares with its pdf: it is most of
    /// the cost (a logarithm and an exponential).
    #[inline(always)]
    fn eval_with(&self, wo: V3<L>, wi: V3<L>, lobe: L) -> V3<L> {
        // (n + 2)/(2π)·cosⁿα as the lobe's pdf times (n + 2)/(n + 1): one robust exp-log form.
        let n = self.n.clamp(L::ZERO, L::c(crate::warp::PHONG_N_MAX as f64));
        // A NaN exponent has no lobe (its pdf is 0): no specular term either.
        let spec = L::select(
            lobe.gt(L::ZERO),
            lobe * ((n + L::TWO) / (n + L::ONE)),
            L::ZERO,
        );
        let f = self.kd.to_lanes().scale(L::c(1.0 / PI)) + self.ks.to_lanes().scale(spec);
        V3::select(above(wo, wi), f, V3::all(L::ZERO))
    }

    /// A direction from the mixture of the two lobes, f there and its pdf. u is clamped to
    /// [0, 1]²; NaN gives pdf 0.
    #[inline]
    pub fn sample(&self, wo: V, u: V::Vec2) -> BsdfSample<V> {
        by_halves(
            (*self, wo.to_lanes(), u.to_lanes()),
            #[inline(always)]
            |(bsdf, wo, u)| bsdf.sample_whole(wo, u),
        )
    }

    /// [`sample`](Self::sample) at the whole width.
    #[inline(always)]
    fn sample_whole(&self, wo_l: V3<L>, u: V2<L>) -> BsdfSample<V> {
        let p = self.diffuse_probability();
        let u0 = u.x.clamp(L::ZERO, L::c(ONE_MINUS_EPS as f64));
        let diffuse = u0.lt(p);
        // One u picks the lobe and, rescaled, drives it.
        let v = L::select(diffuse, u0 / p, (u0 - p) / (L::ONE - p));
        let v = V2::new(v.clamp(L::ZERO, L::c(ONE_MINUS_EPS as f64)), u.y);
        let w_diffuse: V3<L> = cosine_hemisphere(v);
        let frame = Frame::from_normal(mirror(wo_l));
        let w_lobe = frame.to_world(phong_lobe(v, self.n));
        let nan = u.any_nan() | self.n.is_nan();
        let wi = V3::select(diffuse, w_diffuse, w_lobe).nan_where(nan);
        // f and pdf are `eval` and `pdf` at wi, sharing the lobe's density: the same bits.
        let lobe = lobe_pdf(wo_l, wi, self.n);
        BsdfSample {
            wi: V::from_lanes(wi),
            f: V::from_lanes(self.eval_with(wo_l, wi, lobe)),
            pdf: self.pdf_with(wo_l, wi, lobe),
        }
    }

    /// The mixture pdf of `sample` at `wi`; 0 for NaN.
    #[inline]
    pub fn pdf(&self, wo: V, wi: V) -> L {
        by_halves(
            (*self, wo.to_lanes(), wi.to_lanes()),
            #[inline(always)]
            |(bsdf, wo, wi)| bsdf.pdf_with(wo, wi, lobe_pdf(wo, wi, bsdf.n)),
        )
    }

    /// The mixture pdf from the lobe's density at (wo, wi).
    #[inline(always)]
    fn pdf_with(&self, wo: V3<L>, wi: V3<L>, lobe: L) -> L {
        let p = self.diffuse_probability();
        let pdf = p.mul_add(cosine_hemisphere_pdf(wi), (L::ONE - p) * lobe);
        // The diffuse part reads z alone: NaN elsewhere, or in n, must still give 0.
        let ok = pdf.is_finite() & !wi.any_nan() & !wo.any_nan() & !self.n.is_nan();
        L::select(ok, pdf, L::ZERO)
    }
}

/// True where both directions are strictly above the horizon (false for NaN).
#[inline(always)]
fn above<L: Math>(wo: V3<L>, wi: V3<L>) -> L::Mask {
    wo.z.gt(L::ZERO) & wi.z.gt(L::ZERO)
}

/// The mirror direction of wo about +z.
#[inline(always)]
fn mirror<L: Math>(wo: V3<L>) -> V3<L> {
    V3::new(-wo.x, -wo.y, wo.z)
}

/// The Phong lobe's density (n+1)/(2π)·cosⁿα about the mirror direction of wo, 0 where
/// cos α ≤ 0 and for NaN.
///
/// The pdf goes with exp(n·ln cos α), so an error δ in ln cos α costs n·δ. Near the peak,
/// ln cos α = ln(1 − t) with t = 1 − cos α = |wi − mirror(wo)|²/2, a sum of squares that keeps
/// its relative precision where cos α itself would round to 1; near the lobe's edge, ln cos α
/// with cos α = wi·mirror(wo) in f64, exact where the f32 dot product would cancel. Both forms
/// are symmetric in wo and wi (swapping them negates the difference's z and the products
/// commute), so f(wo, wi) = f(wi, wo) bit for bit.
#[inline(always)]
fn lobe_pdf<L: Math>(wo: V3<L>, wi: V3<L>, n: L) -> L {
    let d = V3::new(wi.x + wo.x, wi.y + wo.y, wi.z - wo.z);
    let t = L::HALF * d.dot(d);
    let c = dot_wide([wi.x, wi.y, wi.z], [-wo.x, -wo.y, wo.z]);
    // cos α ≤ 1 (rounding, or directions not quite unit, can exceed it): ln cos α ≤ 0.
    let ln_cos = L::select(t.lt(L::HALF), (-t).ln_1p(), c.ln()).min(L::ZERO);
    let p = phong_lobe_density(ln_cos, n);
    L::select(c.gt(L::ZERO) & n.eq(n), p, L::ZERO)
}

/// What the direct-lighting estimator needs of a BSDF, in the local frame: `eval`, `sample` and
/// `pdf` as [`Lambert`] and [`Phong`] define them (f without the cosine; `sample` returns the
/// pdf function's value at its direction, bit for bit).
pub trait Bsdf<V: Point3> {
    /// f(wo, wi).
    fn eval(&self, wo: V, wi: V) -> V;
    /// A direction, f there and its pdf per steradian.
    fn sample(&self, wo: V, u: V::Vec2) -> BsdfSample<V>;
    /// The pdf per steradian of `sample` at `wi`.
    fn pdf(&self, wo: V, wi: V) -> V::Lane;
}

/// The trait forwards to the inherent methods, which stay callable without importing it.
macro_rules! bsdf_trait {
    ($($t:ident),*) => {$(
        impl<V: Point3<Lane = L>, L: Math> Bsdf<V> for $t<V> {
            #[inline]
            fn eval(&self, wo: V, wi: V) -> V {
                $t::eval(self, wo, wi)
            }
            #[inline]
            fn sample(&self, wo: V, u: V::Vec2) -> BsdfSample<V> {
                $t::sample(self, wo, u)
            }
            #[inline]
            fn pdf(&self, wo: V, wi: V) -> L {
                $t::pdf(self, wo, wi)
            }
        }
    )*};
}
bsdf_trait!(Lambert, Phong);
