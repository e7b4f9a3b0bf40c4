//! Square → upper hemisphere (+z): uniform, and cosine-weighted by Malley's method.

use crate::lane::{V2, V3};
use crate::math::Math;
use crate::warp::common::{azimuth_fraction, clamp_u, clamp01};
use crate::warp::disk::{concentric_disk_inverse, concentric_with_one_minus_r};

/// Uniform hemisphere: z = u₀, r = √((1 − z)(1 + z)), φ = 2πu₁. The factored form keeps r
/// accurate near the pole, where 1 − z² would cancel.
#[inline(always)]
pub fn uniform_hemisphere<L: Math>(u: V2<L>) -> V3<L> {
    let u = clamp_u(u);
    let z = u.x;
    let r = ((L::c(1.0) - z) * (L::c(1.0) + z)).max(L::c(0.0)).sqrt();
    let (s, c) = u.y.sincos_2pi();
    V3::new(r * c, r * s, z).nan_where(u.any_nan())
}

#[inline(always)]
pub fn uniform_hemisphere_pdf<L: Math>() -> L {
    L::c(0.5 * core::f64::consts::FRAC_1_PI)
}

/// Inverse: u₀ = z (clamped to [0, 1]), u₁ = azimuth/2π.
#[inline(always)]
pub fn uniform_hemisphere_inverse<L: Math>(w: V3<L>) -> V2<L> {
    V2::new(clamp01(w.z), azimuth_fraction(w.x, w.y)).nan_where(w.any_nan())
}

/// Cosine hemisphere: the concentric disk lifted to the hemisphere, z = √((1 − r)(1 + r)) with
/// 1 − r exact from the map itself, which stays accurate at the rim.
#[inline(always)]
pub fn cosine_hemisphere<L: Math>(u: V2<L>) -> V3<L> {
    let (p, one_minus_r) = concentric_with_one_minus_r(u);
    let z = (one_minus_r * (L::c(2.0) - one_minus_r))
        .max(L::c(0.0))
        .sqrt();
    V3::new(p.x, p.y, z).nan_where(u.any_nan())
}

/// pdf per steradian: cos θ/π for cos θ > 0, else 0 (the rim and below; NaN gives 0).
#[inline(always)]
pub fn cosine_hemisphere_pdf<L: Math>(cos_theta: L) -> L {
    L::select(
        cos_theta.gt(L::c(0.0)),
        cos_theta * L::c(core::f64::consts::FRAC_1_PI),
        L::c(0.0),
    )
}

/// Inverse: the concentric inverse of the direction's (x, y).
#[inline(always)]
pub fn cosine_hemisphere_inverse<L: Math>(w: V3<L>) -> V2<L> {
    concentric_disk_inverse(V2::new(w.x, w.y))
}
