//! Square → unit sphere, uniform by area.

use crate::lane::{V2, V3};
use crate::math::Math;
use crate::warp::common::{azimuth_fraction, clamp_u};

/// z = 1 − 2u₀, r = 2√(u₀(1 − u₀)), φ = 2πu₁. The product form keeps r right near the poles:
/// at u₀ = 1e-8, √(1 − z²) gives 0 where the true radius is 2e-4.
#[inline(always)]
pub fn uniform_sphere<L: Math>(u: V2<L>) -> V3<L> {
    let u = clamp_u(u);
    let z = u.x.mul_add(L::c(-2.0), L::c(1.0));
    let r = L::c(2.0) * (u.x * (L::c(1.0) - u.x)).max(L::c(0.0)).sqrt();
    let (s, c) = u.y.sincos_2pi();
    V3::new(r * c, r * s, z).nan_where(u.any_nan())
}

#[inline(always)]
pub fn uniform_sphere_pdf<L: Math>() -> L {
    L::c(0.25 * core::f64::consts::FRAC_1_PI)
}

/// Inverse: u₀ = (1 − z)/2, with 1 − z computed as (x² + y²)/(1 + z) in the upper half, where
/// the subtraction would cancel.
#[inline(always)]
pub fn uniform_sphere_inverse<L: Math>(w: V3<L>) -> V2<L> {
    let rho2 = w.x.mul_add(w.x, w.y * w.y);
    let one_minus_z = L::select(w.z.gt(L::c(0.0)), rho2 / (L::c(1.0) + w.z), L::c(1.0) - w.z);
    let u0 = (one_minus_z * L::c(0.5)).clamp(L::c(0.0), L::c(1.0));
    V2::new(u0, azimuth_fraction(w.x, w.y)).nan_where(w.any_nan())
}
