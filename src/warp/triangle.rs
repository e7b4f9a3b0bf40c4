//! Square → barycentrics of a uniform point in a triangle, by Heitz's low-distortion map.

use crate::lane::{V2, V3};
use crate::math::Math;
use crate::warp::common::clamp_u;

/// If u₀ < u₁: b₀ = u₀/2, b₁ = u₁ − b₀; otherwise b₁ = u₁/2, b₀ = u₀ − b₁. No square root, and
/// neighbouring u stay neighbours. b₂ is written as 1 − max(u₀, u₁), which is what b₀ + b₁ is in
/// exact arithmetic, so b₂ ≥ 0 without rounding luck.
#[inline(always)]
pub fn uniform_triangle<L: Math>(u: V2<L>) -> V3<L> {
    let u = clamp_u(u);
    let first = u.x.lt(u.y);
    let half0 = u.x * L::c(0.5);
    let half1 = u.y * L::c(0.5);
    let b0 = L::select(first, half0, u.x - half1);
    let b1 = L::select(first, u.y - half0, half1);
    let b2 = L::c(1.0) - u.x.max(u.y);
    V3::new(b0, b1, b2).nan_where(u.any_nan())
}

/// Inverse: (b₀ + b₁, 2b₁) if b₀ > b₁, else (2b₀, b₀ + b₁). Clamped to [0, 1].
#[inline(always)]
pub fn uniform_triangle_inverse<L: Math>(b: V3<L>) -> V2<L> {
    let first = b.x.gt(b.y);
    let sum = b.x + b.y;
    let u = V2::new(
        L::select(first, sum, b.x * L::c(2.0)),
        L::select(first, b.y * L::c(2.0), sum),
    );
    clamp_u(u).nan_where(b.any_nan())
}

/// Density of the barycentrics (b₀, b₁) over the unit square: 2 inside the triangle b₀ + b₁ ≤ 1,
/// b₀, b₁ ≥ 0, else 0. (Per unit area of a real triangle the pdf is 1/area.)
#[inline(always)]
pub fn uniform_triangle_pdf<L: Math>(b: V2<L>) -> L {
    let inside = b.x.ge(L::c(0.0)) & b.y.ge(L::c(0.0)) & (b.x + b.y).le(L::c(1.0));
    L::select(inside, L::c(2.0), L::c(0.0))
}
