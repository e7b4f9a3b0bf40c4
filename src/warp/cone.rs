//! Square → cone of directions about +z, uniform in solid angle.
//!
//! The cone is given by h = 1 − cos θmax, never by cos θmax: near the axis cos θmax rounds to 1
//! and loses h entirely (cos θmax = 1 − 1e-7 stored in f32 gives an h that is 19 % wrong).

use crate::lane::{V2, V3};
use crate::math::Math;
use crate::warp::common::{azimuth_fraction, clamp_u, sin_from_one_minus_cos};

/// The largest meaningful h: the whole sphere.
const H_MAX: f64 = 2.0;

/// h = 1 − cos θmax, clamped to [0, 2].
#[inline(always)]
pub fn cone_h_from_cos<L: Math>(cos_max: L) -> L {
    (L::c(1.0) - cos_max).clamp(L::c(0.0), L::c(H_MAX)).canon()
}

/// h from sin²θmax (θmax ≤ π/2), as s²/(1 + √(1 − s²)): exact algebra, no cancellation and no
/// threshold. s² is clamped to [0, 1].
#[inline(always)]
pub fn cone_h_from_sin2<L: Math>(sin2_max: L) -> L {
    let s2 = sin2_max.clamp(L::c(0.0), L::c(1.0));
    (s2 / (L::c(1.0) + (L::c(1.0) - s2).sqrt())).canon()
}

/// t = u₀h is 1 − cos θ; sin θ = √(t(2 − t)); φ = 2πu₁. h is clamped to [0, 2].
#[inline(always)]
pub fn uniform_cone<L: Math>(u: V2<L>, h: L) -> V3<L> {
    let u = clamp_u(u);
    let h = h.clamp(L::c(0.0), L::c(H_MAX));
    let t = u.x * h;
    let sin_theta = sin_from_one_minus_cos(t);
    let (s, c) = u.y.sincos_2pi();
    V3::new(sin_theta * c, sin_theta * s, L::c(1.0) - t).nan_where(u.any_nan() | h.is_nan())
}

/// 1/(2πh) per steradian inside the cone. h ≤ 0 (a degenerate cone) and NaN give 0.
#[inline(always)]
pub fn uniform_cone_pdf<L: Math>(h: L) -> L {
    // NaN must reach the select below as NaN, so it goes in the second operand of min.
    let h = L::c(H_MAX).min(h);
    L::select(
        h.gt(L::c(0.0)),
        L::c(0.5 * core::f64::consts::FRAC_1_PI) / h,
        L::c(0.0),
    )
}

/// Inverse: t = (x² + y²)/(1 + z) (no cancellation near the axis), u₀ = t/h clamped to [0, 1].
#[inline(always)]
pub fn uniform_cone_inverse<L: Math>(w: V3<L>, h: L) -> V2<L> {
    let t = one_minus_z(w);
    let u0 = (t / h).clamp(L::c(0.0), L::c(1.0));
    V2::new(u0, azimuth_fraction(w.x, w.y)).nan_where(w.any_nan() | h.is_nan())
}

/// 1 − z of a unit vector, as (x² + y²)/(1 + z) in the upper half and 1 − z below.
#[inline(always)]
pub(crate) fn one_minus_z<L: Math>(w: V3<L>) -> L {
    let rho2 = w.x.mul_add(w.x, w.y * w.y);
    L::select(w.z.gt(L::c(0.0)), rho2 / (L::c(1.0) + w.z), L::c(1.0) - w.z)
}
