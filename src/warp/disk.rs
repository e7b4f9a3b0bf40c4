//! Square → unit disk: Shirley–Chiu's concentric map and the polar map. Both are area-preserving
//! up to a constant, so the area pdf is 1/π.

use glam::Vec3;

use crate::lane::{V2, V3};
use crate::math::Math;
use crate::point::Point2;
use crate::warp::common::{azimuth_fraction, clamp_u};
use crate::warp::family::plain_family;

/// The concentric map, also returning 1 − r for the radius r of the point.
///
/// Mapping: a = 2u₀ − 1, b = 2u₁ − 1. The larger of |a|, |b| is the radius r; the ratio of the
/// other to it, t ∈ [−1, 1], is the angle in units of π/4 within that quadrant's wedge.
///
/// Written in the first octant: r = max(|a|, |b|) and |t| = min(|a|, |b|)/r, and the signs of a
/// and b go back on at the end (x has a's, y has b's, in every wedge). This is the textbook
/// map's arithmetic, bit for bit, since sin is odd and cos even in |t|; but where the textbook
/// picks r and the other coordinate with a select on the wedge, which LLVM compiles to a branch
/// taken half the time in a scalar loop, min and max pick them here, and the sin/cos swap of
/// the wedge |b| ≥ |a| (and the choice of the major u below) is exact arithmetic.
///
/// 1 − r comes back because the cosine hemisphere needs it exactly: z = √((1−r)(1+r)) does not
/// cancel near the rim, where √(1 − x² − y²) loses up to 8e-5. It is computed from u, as
/// 1 − |2u − 1| = 2·min(u, 1 − u), since 2u − 1 itself is rounded in f32 for u < ½.
#[inline(always)]
pub(crate) fn concentric_with_one_minus_r<L: Math>(u: V2<L>) -> (V2<L>, L) {
    let u = clamp_u(u);
    let a = u.x.mul_add(L::TWO, L::c(-1.0));
    let b = u.y.mul_add(L::TWO, L::c(-1.0));
    let (abs_a, abs_b) = (a.abs(), b.abs());
    let a_major = abs_a.gt(abs_b);
    let r = abs_a.max(abs_b);
    let minor = abs_a.min(abs_b);
    // At the centre r = 0: t = 0 keeps the result at the origin instead of 0/0. A select rather
    // than a division by max(r, least normal): the same bits, and LLVM pairs the sine and cosine
    // polynomials of the scalar per-call loop only with the select.
    let t = L::select(r.eq(L::ZERO), L::ZERO, minor / r);
    let (s, c) = t.sincos_pi4();
    // Wedge |a| > |b|: φ = (π/4)t. Otherwise φ = π/2 − (π/4)t, which swaps sin and cos. s ≥ +0
    // and c > 0 are finite and never −0, so `select_finite` gives the selects' bits without
    // their branch. r ≥ 0, so flipping its sign bit by a's and b's is copysign.
    let p = V2::new(
        r.xorsign(a) * L::select_finite(a_major, c, s),
        r.xorsign(b) * L::select_finite(a_major, s, c),
    );
    // The same condition picks the major u. Where u_major is −0 the scalar form may give +0,
    // and z = √((1−r)(1+r)) clamps its ±0 product to +0 either way.
    let u_major = L::select_finite(a_major, u.x, u.y);
    let one_minus_r = L::TWO * u_major.min(L::ONE - u_major);
    (p, one_minus_r)
}

/// Square → unit disk by Shirley and Chiu's concentric map (area pdf 1/π, [`uniform_disk_pdf`]).
///
/// Concentric squares of u become concentric circles, so strata stay compact. u is clamped to
/// [0, 1]²; (½, ½) ↦ (0, 0) exactly; NaN in either coordinate gives NaN in both.
#[inline(always)]
pub fn concentric_disk<P: Point2>(u: P) -> P {
    let u = u.to_lanes();
    P::from_lanes(concentric_with_one_minus_r(u).0.nan_if(u.any_nan()))
}

/// Inverse of [`concentric_disk`]: disk point → u ∈ [0, 1]², within 3e-7 in f32.
///
/// The larger |coordinate| selects the wedge; atan of the ratio of the smaller to it gives t.
/// p = 0 maps to (½, ½). Points outside the disk map as if radially scaled onto the square's
/// boundary (clamped to [0, 1]²); NaN gives NaN.
#[inline(always)]
pub fn concentric_disk_inverse<P: Point2<Lane = L>, L: Math>(p: P) -> P {
    let p = p.to_lanes();
    let x_major = p.x.abs().ge(p.y.abs());
    let major = L::select(x_major, p.x, p.y);
    let minor = L::select(x_major, p.y, p.x);
    let r = p.length_squared().sqrt().copysign(major);
    // atan(minor/major) with |minor| ≤ |major|, written as atan2 so that major = 0 is harmless.
    let phi = (minor * L::ONE.copysign(major)).atan2(major.abs());
    let t = phi * L::c(4.0 / core::f64::consts::PI);
    let a = L::select(x_major, r, r * t);
    let b = L::select(x_major, r * t, r);
    // A point a rounding outside the disk would map a rounding outside the square: clamp.
    let u = clamp_u(V2::new(
        a.mul_add(L::HALF, L::HALF),
        b.mul_add(L::HALF, L::HALF),
    ));
    P::from_lanes(u.nan_where(p.any_nan()))
}

/// Square → unit disk by the polar map r = √u₀, φ = 2πu₁ (area pdf 1/π, [`uniform_disk_pdf`]).
///
/// u is clamped to [0, 1]²; NaN in either coordinate gives NaN in both.
#[inline(always)]
pub fn polar_disk<P: Point2<Lane = L>, L: Math>(u: P) -> P {
    let u = clamp_u(u.to_lanes());
    let r = u.x.sqrt();
    let (s, c) = u.y.sincos_2pi_unit();
    P::from_lanes(V2::new(r * c, r * s).nan_if(u.any_nan()))
}

/// Inverse of [`polar_disk`]: u₀ = |p|², at most 1 (a rim point that rounding put a few ulp
/// outside comes back as 1), u₁ = azimuth/2π in [0, 1). NaN gives NaN.
#[inline(always)]
pub fn polar_disk_inverse<P: Point2<Lane = L>, L: Math>(p: P) -> P {
    let p = p.to_lanes();
    let u0 = p.length_squared().min(L::ONE);
    P::from_lanes(V2::new(u0, azimuth_fraction(p.x, p.y)).nan_where(p.any_nan()))
}

/// Area pdf of [`concentric_disk`] and [`polar_disk`] at `p`: 1/π inside the unit disk, 0
/// outside it and for NaN.
///
/// "Inside" is |p|² ≤ 1 + 2⁻²⁰, so that rim points, whose rounded radius can exceed 1 by a few
/// ulp, keep their pdf: every point either map returns gets 1/π.
#[inline(always)]
pub fn uniform_disk_pdf<P: Point2<Lane = L>, L: Math>(p: P) -> L {
    let inside = p
        .to_lanes()
        .length_squared()
        .le(L::c(1.0 + 1.0 / 1_048_576.0));
    L::select(inside, L::c(core::f64::consts::FRAC_1_PI), L::ZERO)
}

/// The registry's [`concentric_disk`]: (x, y, 0) with [`uniform_disk_pdf`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConcentricDisk;

/// The registry's [`polar_disk`]: (x, y, 0) with [`uniform_disk_pdf`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PolarDisk;

/// The concentric map's point as the registry's 3D sample (x, y, 0).
#[inline(always)]
fn concentric_3d<L: Math>(u: V2<L>) -> V3<L> {
    let p = concentric_disk(u);
    V3::new(p.x, p.y, L::ZERO)
}

/// The polar map's point as the registry's 3D sample (x, y, 0).
#[inline(always)]
fn polar_3d<L: Math>(u: V2<L>) -> V3<L> {
    let p = polar_disk(u);
    V3::new(p.x, p.y, L::ZERO)
}

/// The concentric inverse of the registry's 3D sample.
#[inline(always)]
fn concentric_of<L: Math>(x: V3<L>) -> V2<L> {
    concentric_disk_inverse(V2::new(x.x, x.y))
}

/// The polar inverse of the registry's 3D sample.
#[inline(always)]
fn polar_of<L: Math>(x: V3<L>) -> V2<L> {
    polar_disk_inverse(V2::new(x.x, x.y))
}

/// The disk pdf of a point widened to (x, y, 0): 0 off the plane.
#[inline(always)]
fn disk_pdf<L: Math>(x: V3<L>) -> L {
    L::select(
        x.z.eq(L::ZERO),
        uniform_disk_pdf(V2::new(x.x, x.y)),
        L::ZERO,
    )
}

/// (x, y, 0) with |(x, y)| ≤ 1 up to rounding.
fn in_disk(x: Vec3) -> bool {
    x.is_finite() && x.z == 0.0 && x.truncate().as_dvec2().length_squared() <= 1.0 + 1e-6
}

plain_family!(
    ConcentricDisk,
    "concentric_disk",
    concentric_3d,
    disk_pdf,
    concentric_of,
    in_disk
);
plain_family!(
    PolarDisk, "polar_disk", polar_3d, disk_pdf, polar_of, in_disk
);
