//! Square → unit disk: Shirley–Chiu's concentric map and the polar map. Both are area-preserving
//! up to a constant, so the area pdf is 1/π.

use crate::lane::V2;
use crate::math::Math;
use crate::warp::common::{azimuth_fraction, clamp_u};

/// The concentric map, also returning 1 − r for the radius r of the point.
///
/// Mapping: a = 2u₀ − 1, b = 2u₁ − 1. The larger of |a|, |b| is the radius r; the ratio of the
/// other to it, t ∈ [−1, 1], is the angle in units of π/4 within that quadrant's wedge. One
/// division and selects replace the four-way branch.
///
/// 1 − r comes back because the cosine hemisphere needs it exactly: z = √((1−r)(1+r)) does not
/// cancel near the rim, where √(1 − x² − y²) loses up to 8e-5. It is computed from u, as
/// 1 − |2u − 1| = 2·min(u, 1 − u), since 2u − 1 itself is rounded in f32 for u < ½.
#[inline(always)]
pub(crate) fn concentric_with_one_minus_r<L: Math>(u: V2<L>) -> (V2<L>, L) {
    let u = clamp_u(u);
    let a = u.x.mul_add(L::c(2.0), L::c(-1.0));
    let b = u.y.mul_add(L::c(2.0), L::c(-1.0));
    let a_major = a.abs().gt(b.abs());
    let r = L::select(a_major, a, b);
    let other = L::select(a_major, b, a);
    // At the centre r = 0: t = 0 keeps the result at the origin instead of 0/0.
    let t = L::select(r.eq(L::c(0.0)), L::c(0.0), other / r);
    let (s, c) = t.sincos_pi4();
    // Wedge |a| > |b|: φ = (π/4)t. Otherwise φ = π/2 − (π/4)t, which swaps sin and cos.
    let p = V2::new(r * L::select(a_major, c, s), r * L::select(a_major, s, c));
    let u_major = L::select(a_major, u.x, u.y);
    let one_minus_r = L::c(2.0) * u_major.min(L::c(1.0) - u_major);
    (p, one_minus_r)
}

#[inline(always)]
pub fn concentric_disk<L: Math>(u: V2<L>) -> V2<L> {
    concentric_with_one_minus_r(u).0.nan_where(u.any_nan())
}

/// Inverse of the concentric map. The larger |coordinate| selects the wedge; atan of the ratio of
/// the smaller to it gives t. p = 0 maps to (½, ½).
#[inline(always)]
pub fn concentric_disk_inverse<L: Math>(p: V2<L>) -> V2<L> {
    let x_major = p.x.abs().ge(p.y.abs());
    let major = L::select(x_major, p.x, p.y);
    let minor = L::select(x_major, p.y, p.x);
    let r = p.length_squared().sqrt().copysign(major);
    // atan(minor/major) with |minor| ≤ |major|, written as atan2 so that major = 0 is harmless.
    let phi = (minor * L::c(1.0).copysign(major)).atan2(major.abs());
    let t = phi * L::c(4.0 / core::f64::consts::PI);
    let a = L::select(x_major, r, r * t);
    let b = L::select(x_major, r * t, r);
    // A point a rounding outside the disk would map a rounding outside the square: clamp.
    clamp_u(V2::new(
        a.mul_add(L::c(0.5), L::c(0.5)),
        b.mul_add(L::c(0.5), L::c(0.5)),
    ))
    .nan_where(p.any_nan())
}

/// The polar map: r = √u₀, φ = 2πu₁.
#[inline(always)]
pub fn polar_disk<L: Math>(u: V2<L>) -> V2<L> {
    let u = clamp_u(u);
    let r = u.x.sqrt();
    let (s, c) = u.y.sincos_2pi();
    V2::new(r * c, r * s).nan_where(u.any_nan())
}

/// Inverse of the polar map: u₀ = |p|², u₁ = azimuth/2π in [0, 1).
#[inline(always)]
pub fn polar_disk_inverse<L: Math>(p: V2<L>) -> V2<L> {
    V2::new(p.length_squared(), azimuth_fraction(p.x, p.y)).nan_where(p.any_nan())
}

/// Area pdf of a uniform point in the unit disk: 1/π.
#[inline(always)]
pub fn uniform_disk_pdf<L: Math>() -> L {
    L::c(core::f64::consts::FRAC_1_PI)
}
