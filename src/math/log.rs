//! Natural logarithm, and ln(1 + x) accurate near 0.
//!
//! See [`crate::math`] for the measured error and the special values.

use super::{bits, horner};
use crate::lane::{Lane, Lane32, U32Lane};

/// ln(1 + f) = f + f²·Q(f) for f ∈ [√½ − 1, √2 − 1]. Minimax for relative error: 2^-26.
const LN_Q: [f32; 9] = bits([
    0xbeff_fffc, 0x3eaa_ab04, 0xbe80_027c, 0x3e4c_a43a, 0xbe29_d6cf, 0x3e14_7f14, 0xbe0c_ec36,
    0x3de3_7ee2, 0xbd2b_56a6,
]);
/// ln 2 = LN2_HI + LN2_LO (+ 2^-44). LN2_HI has 16 significant bits, so e·LN2_HI is exact for
/// every exponent |e| ≤ 255.
pub(crate) const LN2_HI: f32 = f32::from_bits(0x3f31_7200);
pub(crate) const LN2_LO: f32 = f32::from_bits(0x35bf_be8e);
/// Bits of √½ (rounded): mantissas are normalised to [√½, √2).
const SQRT_HALF_BITS: u32 = 0x3f35_04f3;
/// 2^-25: below it (in magnitude), ln(1 + x) rounds to x.
const TWO_M25: f32 = f32::from_bits(0x3300_0000);
/// 2²³ + 127: subtracting it from the float with bits `0x4b00_0000 | e_biased` gives e.
const EXP_BIAS_F: f32 = 8_388_735.0;

/// Splits |x| (normal, or 0) into 2^e · m with m ∈ [√½, √2): returns (e as a float, m − 1, the
/// biased exponent e + 127 as an integer lane). Integer steps cannot overflow for any input bits.
#[inline(always)]
fn split<L: Lane32>(x: L) -> (L, L, L::U) {
    let ix = (x.to_bits() & L::U::splat(0x7fff_ffff)) + L::U::splat(0x3f80_0000 - SQRT_HALF_BITS);
    let eb = ix >> 23;
    let m = L::from_bits((ix & L::U::splat(0x007f_ffff)) + L::U::splat(SQRT_HALF_BITS));
    let e = L::from_bits(eb | L::U::splat(0x4b00_0000)) - L::c(EXP_BIAS_F as f64);
    (e, m - L::ONE, eb)
}

/// ln(1 + f) − f = f²·Q(f).
#[inline(always)]
fn tail<L: Lane>(f: L) -> L {
    (f * f) * horner(f, LN_Q)
}

/// e·ln2 + f + t, rounded once: e·LN2_HI is exact, the rounding error of adding f to it is
/// recovered exactly (Fast2Sum: |e·LN2_HI| ≥ |f| unless e = 0, where the sum is exact), and joins
/// the small terms.
#[inline(always)]
fn sum<L: Lane>(e: L, f: L, t: L) -> L {
    let hi = e * L::c(LN2_HI as f64);
    let s = hi + f;
    let err = (hi - s) + f;
    s + e.mul_add(L::c(LN2_LO as f64), t + err)
}

/// ln x. ln 0 = −∞, ln x = NaN for x < 0, ln +∞ = +∞.
#[inline(always)]
pub fn ln<L: Lane32>(x: L) -> L {
    // Subnormals: scale by 2²⁴ first.
    let sub = x.lt(L::c(f32::MIN_POSITIVE as f64));
    let xs = L::select(sub, x * L::c(16_777_216.0), x);
    let (e, f, _) = split(xs);
    let e = e - L::select(sub, L::c(24.0), L::ZERO);
    let r = sum(e, f, tail(f));
    let r = L::select(x.eq(L::c(f64::INFINITY)), x, r);
    let r = L::select(x.eq(L::ZERO), L::c(f64::NEG_INFINITY), r);
    L::select(x.ge(L::ZERO), r, L::c(f64::NAN))
}

/// ln(1 + x). ln_1p(−1) = −∞, NaN for x < −1, +∞ at +∞; tiny x gives x.
#[inline(always)]
pub fn ln_1p<L: Lane32>(x: L) -> L {
    let one = L::ONE;
    let u = one + x;
    // The rounding error of 1 + x, exactly (Fast2Sum with the larger operand first).
    let c = L::select(x.abs().lt(one), x - (u - one), one - (u - x));
    let (e, f, eb) = split(u);
    // e = 0: u = 1 + f and f + c = x exactly, so use x itself.
    let e0 = e.eq(L::ZERO);
    // Otherwise ln(u + c) = ln u + c/u, and c/u = c'/(1 + f) ≈ c'·(1 − f + f²) with c' = c·2^-e
    // (|c'| ≤ 2^-24, so the error of the approximation, c'·f³, stays below 0.1 ulp).
    // 2^(1−e) from bits: (255 − eb) << 23; eb & 0xff keeps NaN bits from underflowing.
    let two_pow = L::from_bits((L::U::splat(255) - (eb & L::U::splat(0xff))) << 23);
    let half_recip = f.mul_add(f.mul_add(L::HALF, L::c(-0.5)), L::HALF);
    let corr = (c * two_pow) * half_recip;
    let v = L::select(e0, x, f);
    let corr = L::select(e0, L::ZERO, corr);
    let r = sum(e, v, tail(v) + corr);
    // x itself for +∞, and for |x| < 2^-25 (where ln(1 + x) rounds to x; this also keeps −0).
    let keep = x.abs().lt(L::c(TWO_M25 as f64)) | x.eq(L::c(f64::INFINITY));
    let r = L::select(keep, x, r);
    let r = L::select(x.eq(L::c(-1.0)), L::c(f64::NEG_INFINITY), r);
    L::select(x.ge(L::c(-1.0)), r, L::c(f64::NAN))
}
