//! [0, 1) → tent on [−1, 1] with pdf 1 − |x|: the pixel-filter warp.

use crate::math::Math;
use crate::warp::common::clamp01;

/// [0, 1) → [−1, 1] with pdf 1 − |x| (the tent pixel filter, [`tent_pdf`]), by inverting each
/// half on its own: u < ½ gives x = √(2u) − 1, otherwise x = 1 − √(2(1 − u)).
///
/// u is clamped to [0, 1]; NaN gives NaN.
#[inline(always)]
pub fn tent<L: Math>(u: L) -> L {
    let u = clamp01(u);
    let left = u.lt(L::c(0.5));
    let v = L::select(left, u, L::c(1.0) - u);
    let x = L::c(1.0) - (v * L::c(2.0)).sqrt();
    L::select(left, -x, x).canon()
}

/// pdf of [`tent`]: 1 − |x| on [−1, 1], else 0 (also for NaN).
#[inline(always)]
pub fn tent_pdf<L: Math>(x: L) -> L {
    let p = L::c(1.0) - x.abs();
    L::select(p.gt(L::c(0.0)), p, L::c(0.0))
}

/// Inverse of [`tent`]: u = (1 + x)²/2 for x < 0, else 1 − (1 − x)²/2. x is clamped to [−1, 1];
/// NaN gives NaN.
#[inline(always)]
pub fn tent_inverse<L: Math>(x: L) -> L {
    let x = x.clamp(L::c(-1.0), L::c(1.0));
    let d = L::c(1.0) - x.abs();
    let half_d2 = d * d * L::c(0.5);
    L::select(x.lt(L::c(0.0)), half_d2, L::c(1.0) - half_d2).canon()
}
