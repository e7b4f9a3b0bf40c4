//! Square → Phong lobe cosⁿα about +z, pdf (n+1)/(2π)·cosⁿα per steradian.

use core::fmt;

use glam::Vec3;

use crate::lane::{V2, V3};
use crate::math::Math;
use crate::point::{Point2, Point3};
use crate::warp::Family;
use crate::warp::common::{azimuth_fraction, clamp_u, one_minus_z, sin_from_one_minus_cos};
use crate::warp::family::{is_unit, lane, with_pdf};

/// Exponents are clamped to [0, `PHONG_N_MAX`]. A lobe sharper than this is a mirror: route it
/// with a specular flag, not through a pdf of 10¹⁹.
pub const PHONG_N_MAX: f32 = 1.0e20;

#[inline(always)]
fn clamp_n<L: Math>(n: L) -> L {
    n.clamp(L::ZERO, L::c(PHONG_N_MAX as f64))
}

/// Square → Phong lobe about +z, pdf (n+1)/(2π)·cosⁿα per steradian ([`phong_lobe_pdf`]).
///
/// t = 1 − cos α = −expm1(ln(u₀)/(n+1)), sin α = √(t(2 − t)), φ = 2πu₁. The naive
/// cos α = u₀^{1/(n+1)} rounds to 1 for most u₀ when n is large (157 distinct directions from
/// 1e5 samples at n = 1e6); expm1 keeps t, and with it sin α, to full relative precision.
///
/// u is clamped to [0, 1]² and n to [0, [`PHONG_N_MAX`]]; u₀ = 0 gives a horizon direction
/// (pdf 0); NaN in u or n gives NaN.
#[inline(always)]
pub fn phong_lobe<P: Point2<Lane = L>, L: Math>(u: P, n: L) -> P::Vec3 {
    let u = clamp_u(u.to_lanes());
    let n = clamp_n(n);
    let t = -(u.x.ln() / (n + L::ONE)).exp_m1();
    let sin_a = sin_from_one_minus_cos(t);
    let (s, c) = u.y.sincos_2pi_unit();
    let w = V3::new(sin_a * c, sin_a * s, L::ONE - t);
    Point3::from_lanes(w.nan_where(u.any_nan() | n.is_nan()))
}

/// pdf per steradian of [`phong_lobe`] at direction `w` of the lobe's frame (+z the lobe's
/// axis): (n+1)/(2π)·exp(n·ln cos α) with cos α = w.z, for cos α > 0, else 0.
///
/// The horizon is outside the support, which makes n = 0 agree with the open hemisphere. NaN in
/// `w` or `n` gives 0. cos α above 1, which rounding can produce from a slightly long vector,
/// counts as 1.
#[inline(always)]
pub fn phong_lobe_pdf<P: Point3<Lane = L>, L: Math>(w: P, n: L) -> L {
    let w = w.to_lanes();
    let cos_alpha = w.z;
    let p = phong_lobe_density(cos_alpha.min(L::ONE).ln(), n);
    L::select(cos_alpha.gt(L::ZERO) & n.eq(n) & !w.any_nan(), p, L::ZERO)
}

/// (n+1)/(2π)·exp(n·ln cos α) from ln cos α, n clamped: the one formula of the lobe's density,
/// for [`phong_lobe_pdf`] and for the Phong BSDF, which forms ln cos α its own way.
#[inline(always)]
pub(crate) fn phong_lobe_density<L: Math>(ln_cos: L, n: L) -> L {
    let n = clamp_n(n);
    (n + L::ONE) * L::c(0.5 * core::f64::consts::FRAC_1_PI) * (n * ln_cos).exp()
}

/// Inverse of [`phong_lobe`]: u₀ = cos^{n+1}α = exp((n+1)·ln(1 − t)) with t = 1 − cos α taken
/// from x² + y², so directions near the axis keep their precision; u₁ = azimuth/2π. Below the
/// horizon u₀ = 0. NaN gives NaN.
#[inline(always)]
pub fn phong_lobe_inverse<P: Point3<Lane = L>, L: Math>(w: P, n: L) -> P::Vec2 {
    let w = w.to_lanes();
    let n = clamp_n(n);
    let t = one_minus_z(w);
    let u0 = ((n + L::ONE) * (-t).ln_1p()).exp();
    let u0 = L::select(w.z.gt(L::ZERO), u0.min(L::ONE), L::ZERO);
    let u = V2::new(u0, azimuth_fraction(w.x, w.y));
    Point2::from_lanes(u.nan_where(w.any_nan() | n.is_nan()))
}

/// The registry's [`phong_lobe`] with exponent n.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhongLobe {
    /// The exponent.
    pub n: f32,
}

impl Family for PhongLobe {
    fn name(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "phong_lobe n={}", self.n)
    }
    fn sampler<L: Math>(&self) -> impl Fn(V2<L>) -> (V3<L>, L) + Copy {
        let n = lane(self.n);
        with_pdf(move |u| phong_lobe(u, n), move |w| phong_lobe_pdf(w, n))
    }
    fn pdf<L: Math>(&self, x: V3<L>) -> L {
        phong_lobe_pdf(x, lane(self.n))
    }
    fn inverse<L: Math>(&self, x: V3<L>) -> Option<V2<L>> {
        Some(phong_lobe_inverse(x, lane(self.n)))
    }
    fn in_domain(&self, x: Vec3) -> bool {
        is_unit(x) && x.z >= 0.0
    }
}
