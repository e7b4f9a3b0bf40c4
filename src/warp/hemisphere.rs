//! Square → upper hemisphere (+z): uniform, and cosine-weighted by Malley's method.

use glam::Vec3;

use crate::lane::{V2, V3};
use crate::math::Math;
use crate::point::{Point2, Point3};
use crate::warp::common::{azimuth_fraction, clamp_u, clamp01};
use crate::warp::disk::{concentric_disk_inverse, concentric_with_one_minus_r};
use crate::warp::family::is_unit;
use crate::warp::family::plain_family;

/// Square → upper hemisphere (+z), uniform in solid angle (pdf 1/(2π) per steradian,
/// [`uniform_hemisphere_pdf`]).
///
/// z = u₀, r = √((1 − z)(1 + z)), φ = 2πu₁: the factored form keeps r accurate near the pole,
/// where 1 − z² would cancel. u is clamped to [0, 1]²; NaN gives NaN.
#[inline(always)]
pub fn uniform_hemisphere<P: Point2<Lane = L>, L: Math>(u: P) -> P::Vec3 {
    let u = clamp_u(u.to_lanes());
    let z = u.x;
    let r = ((L::ONE - z) * (L::ONE + z)).max(L::ZERO).sqrt();
    let (s, c) = u.y.sincos_2pi_unit();
    Point3::from_lanes(V3::new(r * c, r * s, z).nan_if(u.any_nan()))
}

/// pdf per steradian of [`uniform_hemisphere`] at direction `w`: 1/(2π) for w.z ≥ 0, else 0
/// (also for NaN in any component).
#[inline(always)]
pub fn uniform_hemisphere_pdf<P: Point3<Lane = L>, L: Math>(w: P) -> L {
    let w = w.to_lanes();
    let inside = w.z.ge(L::ZERO) & !w.any_nan();
    L::select(inside, L::c(0.5 * core::f64::consts::FRAC_1_PI), L::ZERO)
}

/// Inverse of [`uniform_hemisphere`] for a unit direction: u = (z, azimuth/2π) in
/// [0, 1] × [0, 1), z clamped to [0, 1]. NaN gives NaN.
#[inline(always)]
pub fn uniform_hemisphere_inverse<P: Point3>(w: P) -> P::Vec2 {
    let w = w.to_lanes();
    Point2::from_lanes(V2::new(clamp01(w.z), azimuth_fraction(w.x, w.y)).nan_where(w.any_nan()))
}

/// Square → upper hemisphere (+z) with pdf cos θ/π per steradian
/// ([`cosine_hemisphere_pdf`]), by Malley's method: the concentric disk lifted by
/// z = √((1 − r)(1 + r)), with 1 − r exact from the map itself so that z stays accurate at the
/// rim.
///
/// u is clamped to [0, 1]²; boundary u gives a finite z ≥ 0; NaN gives NaN. A rim sample can have
/// z = 0 and so pdf 0: callers drop it.
#[inline(always)]
pub fn cosine_hemisphere<P: Point2<Lane = L>, L: Math>(u: P) -> P::Vec3 {
    let u = u.to_lanes();
    let (p, one_minus_r) = concentric_with_one_minus_r(u);
    let z = (one_minus_r * (L::TWO - one_minus_r)).max(L::ZERO).sqrt();
    Point3::from_lanes(V3::new(p.x, p.y, z).nan_if(u.any_nan()))
}

/// pdf per steradian of [`cosine_hemisphere`] at direction `w`: cos θ/π = w.z/π for w.z > 0,
/// else 0 (the rim, below it, and NaN in any component). w.z above 1, from a vector that is not
/// unit, counts as 1, as for [`phong_lobe_pdf`](crate::warp::phong_lobe_pdf), so +∞ gives a
/// finite pdf.
#[inline(always)]
pub fn cosine_hemisphere_pdf<P: Point3<Lane = L>, L: Math>(w: P) -> L {
    let w = w.to_lanes();
    let cos_theta = w.z;
    L::select(
        cos_theta.gt(L::ZERO) & !w.any_nan(),
        cos_theta.min(L::ONE) * L::c(core::f64::consts::FRAC_1_PI),
        L::ZERO,
    )
}

/// Inverse of [`cosine_hemisphere`]: the [`concentric_disk_inverse`] of the direction's (x, y).
#[inline(always)]
pub fn cosine_hemisphere_inverse<P: Point3>(w: P) -> P::Vec2 {
    let w = w.to_lanes();
    Point2::from_lanes(concentric_disk_inverse(V2::new(w.x, w.y)))
}

/// The registry's [`uniform_hemisphere`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UniformHemisphere;

/// The registry's [`cosine_hemisphere`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CosineHemisphere;

plain_family!(
    UniformHemisphere,
    "uniform_hemisphere",
    uniform_hemisphere,
    uniform_hemisphere_pdf,
    uniform_hemisphere_inverse,
    |x: Vec3| is_unit(x) && x.z >= 0.0,
);

plain_family!(
    CosineHemisphere,
    "cosine_hemisphere",
    cosine_hemisphere,
    cosine_hemisphere_pdf,
    cosine_hemisphere_inverse,
    |x: Vec3| is_unit(x) && x.z >= 0.0,
);
