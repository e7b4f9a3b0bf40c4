//! asin and acos on [−1, 1].
//!
//! See [`crate::math`] for the measured error and the special values.

use super::atan::{PIO4_HI, PIO4_LO};
use super::{bits, horner};
use crate::lane::Lane32;

/// asin s = s + s³·P(s²) for s ∈ [0, ½]. Minimax for relative error: 2^-27.6.
const ASIN_P: [f32; 5] = bits([
    0x3e2a_aae4, 0x3d99_8102, 0x3d3a_3ddd, 0x3cc6_1f14, 0x3d2c_ae49,
]);

/// For a = |x|: `(w, big)` with w = asin a when a ≤ ½, and w = asin √((1 − a)/2) when a > ½
/// (`big`), so that asin a = π/2 − 2w there. NaN for a > 1 (the square root of a negative) and
/// for NaN.
#[inline(always)]
fn core<L: Lane32>(a: L) -> (L, L::Mask) {
    let big = a.gt(L::HALF);
    // 1 − a is exact for a ∈ [½, 1] (Sterbenz), and so is the halving.
    let h = (L::ONE - a) * L::HALF;
    let z = L::select(big, h, a * a);
    let s = L::select(big, h.sqrt(), a);
    let w = (s * z).mul_add(horner(z, ASIN_P), s);
    (w, big)
}

/// asin x for x ∈ [−1, 1]; NaN outside.
#[inline(always)]
pub fn asin<L: Lane32>(x: L) -> L {
    let (w, big) = core(x.abs());
    // big: π/2 − 2w = 2·((π/4)_hi − w) + 2·(π/4)_lo. (π/4)_hi − w ∈ [0.26, 0.53] rounds to a
    // quarter of an ulp of the result; rounding 2w ≈ 1 instead would cost a whole one.
    let d = L::select(big, L::c(PIO4_HI as f64) - w, w);
    let k = L::select(big, L::TWO, L::ONE);
    let lo = L::select(big, L::c(2.0 * PIO4_LO as f64), L::ZERO);
    d.mul_add(k, lo).copysign(x)
}

/// acos x for x ∈ [−1, 1]; NaN outside.
#[inline(always)]
pub fn acos<L: Lane32>(x: L) -> L {
    let (w, big) = core(x.abs());
    // |x| ≤ ½: π/2 − asin x. x > ½: 2w. x < −½: π − 2w. As k·π/4 + v:
    let neg = x.lt(L::ZERO);
    let k = L::select(big, L::select(neg, L::c(4.0), L::ZERO), L::TWO);
    // v = 2w·sign(x) when big, −w·sign(x) otherwise.
    let v = L::select(big, w * L::TWO, w).copysign(L::select(big, x, -x));
    k.mul_add(L::c(PIO4_HI as f64), k.mul_add(L::c(PIO4_LO as f64), v))
}
