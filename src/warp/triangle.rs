//! Square → barycentrics of a uniform point in a triangle, by Heitz's low-distortion map.

use glam::Vec3;

use crate::lane::{V2, V3};
use crate::math::Math;
use crate::point::{Point2, Point3};
use crate::warp::common::clamp_u;
use crate::warp::family::plain_family;

/// Square → barycentrics (b₀, b₁, b₂) of a uniform point in a triangle, by Heitz's
/// low-distortion map (2019), with density [`uniform_triangle_pdf`].
///
/// If u₀ < u₁: b₀ = u₀/2, b₁ = u₁ − b₀; otherwise b₁ = u₁/2, b₀ = u₀ − b₁. No square root, and
/// neighbouring u stay neighbours. b₂ is written as 1 − max(u₀, u₁), which is what 1 − b₀ − b₁ is
/// in exact arithmetic, so b₂ ≥ 0 for every u without rounding luck. u is clamped to [0, 1]²;
/// NaN in either coordinate gives the canonical NaN in all three.
#[inline(always)]
pub fn uniform_triangle<P: Point2<Lane = L>, L: Math>(u: P) -> P::Vec3 {
    let u = u.to_lanes();
    // The clamp's upper bound is the canonical NaN where either coordinate is NaN (min(x, NaN)
    // returns the NaN), so the clamp itself makes both coordinates that NaN: every output below
    // is then arithmetic whose NaN operands are all the canonical NaN, which it propagates
    // whichever operand the hardware returns. One shared select instead of one per output.
    // Elsewhere this is `clamp_u`, bit for bit (min(x, 1) and min(1, x) differ only at NaN).
    let hi = L::select(u.any_nan(), L::c(f64::NAN), L::ONE);
    let clamp = |x: L| L::ZERO.max(x.min(hi));
    let u = V2::new(clamp(u.x), clamp(u.y));
    // Both cases at once: with m = min(u₀, u₁)/2, b₀ = u₀ − m and b₁ = u₁ − m, since the
    // smaller coordinate less half itself is its half exactly (Sterbenz). A min and one product
    // instead of a compare, two products and two selects.
    let m = u.x.min(u.y) * L::HALF;
    let b0 = u.x - m;
    let b1 = u.y - m;
    let b2 = L::ONE - u.x.max(u.y);
    Point3::from_lanes(V3::new(b0, b1, b2))
}

/// Inverse of [`uniform_triangle`]: barycentrics → u, as (b₀ + b₁, 2b₁) if b₀ > b₁, else
/// (2b₀, b₀ + b₁), clamped to [0, 1]². NaN gives NaN.
#[inline(always)]
pub fn uniform_triangle_inverse<P: Point3<Lane = L>, L: Math>(b: P) -> P::Vec2 {
    let b = b.to_lanes();
    let first = b.x.gt(b.y);
    let sum = b.x + b.y;
    let u = V2::new(
        L::select(first, sum, b.x * L::TWO),
        L::select(first, b.y * L::TWO, sum),
    );
    Point2::from_lanes(clamp_u(u).nan_where(b.any_nan()))
}

/// Density of the barycentrics b = (b₀, b₁, b₂) from [`uniform_triangle`], over (b₀, b₁) in the
/// unit square: 2 inside the triangle (b₀, b₁, b₂ ≥ 0, b₀ + b₁ ≤ 1), else 0 (also for NaN). Per
/// unit area of a real triangle, the pdf is 1/area.
#[inline(always)]
pub fn uniform_triangle_pdf<P: Point3<Lane = L>, L: Math>(b: P) -> L {
    let b = b.to_lanes();
    let inside = b.x.ge(L::ZERO) & b.y.ge(L::ZERO) & b.z.ge(L::ZERO) & (b.x + b.y).le(L::ONE);
    L::select(inside, L::TWO, L::ZERO)
}

/// The registry's [`uniform_triangle`]: the barycentrics, with [`uniform_triangle_pdf`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UniformTriangle;

plain_family!(
    UniformTriangle,
    "uniform_triangle",
    uniform_triangle,
    uniform_triangle_pdf,
    uniform_triangle_inverse,
    |x: Vec3| {
        let sum = x.x as f64 + x.y as f64 + x.z as f64;
        x.is_finite() && x.min_element() >= 0.0 && (sum - 1.0).abs() <= 1e-6
    },
);
