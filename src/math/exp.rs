//! exp, and exp(x) − 1 accurate near 0.
//!
//! See [`crate::math`] for the measured error and the special values.

use super::log::{LN2_HI, LN2_LO};
use super::{MAGIC, MAGIC_BITS, bits, fast_two_diff, horner};
use crate::lane::{Lane, Lane32, U32Lane};

/// expm1 r = r + r²·Q(r) for |r| ≤ ln2/2 (plus a little). Minimax for relative error: 2^-26.1.
const EXPM1_Q: [f32; 5] = bits([
    0x3eff_ffff, 0x3e2a_aa55, 0x3d2a_abcc, 0x3c09_15ff, 0x3ab5_64ec,
]);
const LOG2_E: f32 = f32::from_bits(0x3fb8_aa3b);
const TWO_M64: f32 = f32::from_bits(0x1f80_0000);
/// 2^-25: below it (in magnitude), eˣ − 1 rounds to x.
const TWO_M25: f32 = f32::from_bits(0x3300_0000);

/// (n, r, r_lo, bits of MAGIC + n) with x = n·ln2 + r + r_lo, n = round(x·log2 e),
/// |r| ≤ ln2/2 + a little, and r_lo the rounding error of r (up to the error of n·LN2_LO, ~2^-60).
/// Needs |x| ≤ 2²¹ or so for n to be the rounded value; callers clamp far less than that.
#[inline(always)]
fn reduce<L: Lane32>(x: L) -> (L, L, L, L::U) {
    let t = x.mul_add(L::c(LOG2_E as f64), L::c(MAGIC as f64));
    let n = t - L::c(MAGIC as f64);
    // x − n·LN2_HI is exact (n·LN2_HI is, and the two are close).
    let r_hi = n.mul_add(L::c(-LN2_HI as f64), x);
    let (r, r_lo) = fast_two_diff(r_hi, n * L::c(LN2_LO as f64));
    (n, r, r_lo, t.to_bits())
}

#[inline(always)]
fn expm1_poly<L: Lane>(r: L) -> L {
    (r * r).mul_add(horner(r, EXPM1_Q), r)
}

/// 2^k from the bits of MAGIC + k (an integer-valued float) for k ∈ [−126, 127].
#[inline(always)]
fn pow2<L: Lane32>(tb: L::U) -> L {
    L::from_bits((tb - L::U::splat(MAGIC_BITS - 127)) << 23)
}

/// eˣ. Overflows to +∞ above 88.72283; results below 2^-126 are subnormal, correctly scaled
/// (one rounding), and 0 below about −103.97.
#[inline(always)]
pub fn exp<L: Lane32>(x: L) -> L {
    // Clamp (NaN stays NaN, and its bits cannot underflow the integer steps below): eˣ is +∞
    // at 89 and 0 at −104 already.
    let xc = x.clamp(L::c(-104.0), L::c(89.0));
    let (n, r, _, _) = reduce(xc);
    let y = L::ONE + expm1_poly(r);
    // 2ⁿ in two factors so that n = 128 and n < −126 work: 2^(n−1)·2 for n > 0,
    // 2^(n+64)·2^-64 otherwise (the second product rounds once, also to a subnormal).
    let pos = n.gt(L::ZERO);
    let d = L::select(pos, L::ONE, L::c(-64.0));
    let s1 = pow2::<L>((n - d + L::c(MAGIC as f64)).to_bits());
    let s2 = L::select(pos, L::TWO, L::c(TWO_M64 as f64));
    (y * s1) * s2
}

/// eˣ − 1. −1 for x below about −17.3, +∞ above 88.72283; x itself for |x| < 2^-25.
#[inline(always)]
pub fn exp_m1<L: Lane32>(x: L) -> L {
    let xc = x.clamp(L::c(-32.0), L::c(89.0));
    let (_, r, r_lo, tb) = reduce(xc);
    // expm1(r + r_lo) = r + small with small = r_lo + r²·Q(r) (the first-order term of r_lo is
    // enough: it is below half an ulp of r; keeping it matters where eˣ − 1 cancels, n = 1).
    let small = (r * r).mul_add(horner(r, EXPM1_Q), r_lo);
    // eˣ − 1 = 2ⁿ(1 + r + small) − 1 = 2·((s·r + (s − ½)) + s·small) with s = 2^(n−1): s·r and
    // s − ½ (n ≤ 24) are exact, and so is their sum for n = 0 and n = 1, where the result is
    // smallest; n = 0 gives r + small rounded once; n = 128 still fits.
    let s = pow2::<L>(tb - L::U::splat(1));
    let y = s.mul_add(small, s.mul_add(r, s - L::HALF)) * L::TWO;
    // Tiny x (and ±0, and subnormals, which the halving above would round): x itself.
    L::select(x.abs().lt(L::c(TWO_M25 as f64)), x, y)
}
