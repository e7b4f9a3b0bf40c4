//! sin and cos: a general-argument form with Cody–Waite reduction to a kernel in radians, and a
//! form in turns with exact reduction to the kernel in eighths of a turn that `sincos_pi4` is.
//!
//! See [`crate::math`] for domains and measured errors.

use super::{MAGIC, bits, fast_two_diff, horner, round_small};
use crate::lane::{Lane, Lane32, U32Lane};

// ---------------------------------------------------------------------------------------------
// Kernel in radians, |r| ≤ π/4 (plus a few ulp): sin r = r + r³·S(r²), cos r = 1 + r²·C(r²).
// Minimax for relative error, coefficients fitted with the f32 rounding of the lower ones
// fixed (max relative error of the polynomials themselves: 2^-26.6 for sin, 2^-33 for cos).

const SIN_R: [f32; 3] = bits([0xbe2a_aaaa, 0x3c08_8571, 0xb94d_0ae0]);
const COS_R: [f32; 4] = [
    -0.5,
    f32::from_bits(0x3d2a_aaa5),
    f32::from_bits(0xbab6_0614),
    f32::from_bits(0x37cc_f406),
];

/// sin and cos of r + lo, where lo is below half an ulp of r: sin takes lo·cos r into account
/// (for r just above ½, sin r lies in the binade below r, where half an ulp of r is a whole ulp
/// of the result); for cos, lo·sin r stays below 0.4 ulp and is dropped.
#[inline(always)]
fn kernel_rad<L: Lane>(r: L, lo: L) -> (L, L) {
    let z = r * r;
    let c = z.mul_add(horner(z, COS_R), L::ONE);
    let s = (r * z).mul_add(horner(z, SIN_R), lo * c) + r;
    (s, c)
}

// ---------------------------------------------------------------------------------------------
// Kernel in eighths of a turn, t ∈ [−1, 1]: sin(πt/4) = t·(A1 + t²·S(t²)) with A1 = π/4 carried as
// two f32 (so that π/4 is never rounded: the leading term would otherwise cost half an ulp), and
// cos(πt/4) = 1 + t²·C(t²). Polynomial error (relative): 2^-27.9 for sin, 2^-31 for cos.
// A1_HI is π/4 rounded down, so that A1_LO > 0 and t = −0 gives sin = −0.

const A1_HI: f32 = f32::from_bits(0x3f49_0fda);
const A1_LO: f32 = f32::from_bits(0x3322_2169);
const SIN_T: [f32; 4] = [
    A1_LO,
    f32::from_bits(0xbda5_5ddf),
    f32::from_bits(0x3b23_2fd6),
    f32::from_bits(0xb816_dae7),
];
const COS_T: [f32; 4] = bits([0xbe9d_e9e6, 0x3c81_e0d8, 0xb9aa_d95b, 0x366a_7bf7]);

/// The same polynomials in v = t/2 (quarter turns): the coefficient of v^k is scaled by 2^k,
/// exactly, so the results are those of the t-kernel at t = 2v, bit for bit.
// Evaluated into constants only: an index out of range there is a compile error, not a
// run-time panic, and the loop bounds keep every index in range.
#[allow(clippy::indexing_slicing)]
const fn scale_pow2<const N: usize>(p: [f32; N], first: f32, step: f32) -> [f32; N] {
    let mut out = p;
    let mut s = first;
    let mut i = 0;
    while i < N {
        out[i] = p[i] * s;
        s *= step;
        i += 1;
    }
    out
}
const A1_HI_V: f32 = A1_HI * 2.0;
const SIN_V: [f32; 4] = scale_pow2(SIN_T, 2.0, 4.0);
const COS_V: [f32; 4] = scale_pow2(COS_T, 4.0, 4.0);

#[inline(always)]
fn kernel_eighths<L: Lane>(t: L, a1_hi: f32, sp: [f32; 4], cp: [f32; 4]) -> (L, L) {
    let z = t * t;
    let s = t.mul_add(L::c(a1_hi as f64), t * horner(z, sp));
    let c = z.mul_add(horner(z, cp), L::ONE);
    (s, c)
}

// ---------------------------------------------------------------------------------------------
// General argument

/// π/2 = C1 + C2 + C3 + C4 (+ 2^-68.7). C1, C2 and C3 have 12 significant bits, so j·Ck is exact
/// for |j| < 2¹², with or without FMA.
const PIO2_C1: f32 = f32::from_bits(0x3fc9_1000);
const PIO2_C2: f32 = f32::from_bits(0xb695_7000);
const PIO2_C3: f32 = f32::from_bits(0xb06f_5000);
const PIO2_C4: f32 = f32::from_bits(0x298c_234c);
const FRAC_2_PI: f32 = f32::from_bits(0x3f22_f983);
/// 2²²: the end of the range where sin_cos reduces at all.
const LIMIT: f32 = 4_194_304.0;

/// Multiplies by ±1.0 built from a sign bit: `s` has only bit 31 possibly set.
#[inline(always)]
fn flip<L: Lane32>(x: L, s: L::U) -> L {
    x * L::from_bits(s | L::U::splat(0x3f80_0000))
}

/// sin x and cos x.
///
/// Cody–Waite reduction by π/2, see [`crate::math`] for the domain of the error bound.
#[inline(always)]
pub fn sin_cos<L: Lane32>(x: L) -> (L, L) {
    // Beyond 2²² the quadrant no longer fits the magic-number rounding (and an ulp of x is half a
    // radian): give (±0, 1) there, NaN for ±∞.
    let x = L::select(x.abs().le(L::c(LIMIT as f64)), x, x * L::ZERO);
    // t = MAGIC + j with j = round(x·2/π); its low bits are those of j.
    let t = x.mul_add(L::c(FRAC_2_PI as f64), L::c(MAGIC as f64));
    let j = t - L::c(MAGIC as f64);
    // r = x − j·(C1 + C2 + C3 + C4). For |j| < 2¹² (the domain of the error bound) j·C1, j·C2 and
    // j·C3 are exact, and so is x − j·C1, with or without FMA. The next two subtractions are exact
    // when r is small, where it matters most; otherwise their rounding errors are recovered
    // (Fast2Sum) and added to the j·C4 term, so that r is rounded once and its remainder lo goes
    // to the kernel. (Fast2Sum needs |r2| ≥ |j·C3|; below that, |r3| < 2^-17 and the lost bits
    // are far below its ulp.)
    let r1 = j.mul_add(L::c(-PIO2_C1 as f64), x);
    let (r2, e2) = fast_two_diff(r1, j * L::c(PIO2_C2 as f64));
    let (r3, e3) = fast_two_diff(r2, j * L::c(PIO2_C3 as f64));
    let lo = j.mul_add(L::c(-PIO2_C4 as f64), e2 + e3);
    let r = r3 + lo;
    let lo = lo - (r - r3);
    let (s, c) = kernel_rad(r, lo);

    let tb = t.to_bits();
    // Quadrant j mod 4: odd swaps sin and cos; sin is negated for j ≡ 2, 3, cos for j ≡ 1, 2.
    let odd = L::from_bits(((tb & L::U::splat(1)) << 31) | L::U::splat(0x3f80_0000)).lt(L::ZERO);
    let sin_sign = (tb & L::U::splat(2)) << 30;
    let cos_sign = (((tb & L::U::splat(3)) + L::U::splat(1)) & L::U::splat(2)) << 30;
    let sn = flip(L::select(odd, c, s), sin_sign);
    let cs = flip(L::select(odd, s, c), cos_sign);
    // sin(±0) = ±0 (the reduction turns −0 into +0).
    (L::select(x.eq(L::ZERO), x, sn), cs)
}

/// sin 2πu and cos 2πu, with exact reduction in u.
#[inline(always)]
pub fn sincos_2pi<L: Lane32>(u: L) -> (L, L) {
    // r = u − round(u) ∈ [−½, ½], exact. |u| ≥ 2²³ is an integer already.
    let a = u.abs();
    let two23 = L::c(8_388_608.0);
    let ra = (a + two23) - two23;
    let rnd = L::select(a.lt(two23), ra.copysign(u), u);
    quarter_turns(u - rnd)
}

/// [`sincos_2pi`] for u ∈ [0, 1], the warps' clamped u, bit for bit, in two fewer operations.
///
/// With u ∈ [0, 1] there is no turn to remove: q = round(4u) ∈ {0, …, 4} and f = 4u − q are
/// exact, and f is the f of [`sincos_2pi`] (which takes q − 4 for u > ½). The rotation by q
/// quarter turns is that by d = q − 2 followed by a half turn, so cos(qπ/2) = |d| − 1 and
/// sin(qπ/2) = d|d| − 2d: the same exact values, signed zeros included, as the general form's.
/// At u = −0, which a clamp can leave, f is −0 in both.
#[inline(always)]
pub fn sincos_2pi_unit<L: Lane32>(u: L) -> (L, L) {
    let u4 = u * L::c(4.0);
    let q = round_small(u4);
    let (s, c) = kernel_eighths(u4 - q, A1_HI_V, SIN_V, COS_V);
    let d = q - L::TWO;
    let ad = d.abs();
    rotate(s, c, ad - L::ONE, d * ad - (d + d))
}

/// sin 2πr and cos 2πr for r ∈ [−½, ½].
#[inline(always)]
fn quarter_turns<L: Lane32>(r: L) -> (L, L) {
    // r = (q + f)/4 with q = round(4r) ∈ {−2, …, 2} and f ∈ [−½, ½], both exact.
    let r4 = r * L::c(4.0);
    let q = round_small(r4);
    let (s, c) = kernel_eighths(r4 - q, A1_HI_V, SIN_V, COS_V);
    // Rotate (s, c) by q quarter turns with cos(qπ/2) = 1 − |q| and sin(qπ/2) = q(2 − |q|),
    // written 2q − q|q| so that q = −2 gives +0, not −0. One of the two is 0 and the other ±1,
    // so every product and sum below is exact: this is the quadrant swap without selects, which
    // the scalar form would otherwise compile to a branch taken half the time. At exact quarter
    // turns f = +0, s = +0, and the sums give +0, never −0.
    let aq = q.abs();
    rotate(s, c, L::ONE - aq, (q + q) - q * aq)
}

/// (s, c) rotated by the angle whose cosine and sine are cq, sq ∈ {0, ±1}: exact.
#[inline(always)]
fn rotate<L: Lane32>(s: L, c: L, cq: L, sq: L) -> (L, L) {
    (s * cq + c * sq, c * cq - s * sq)
}

/// sin(πt/4) and cos(πt/4) for t ∈ [−1, 1], with no range reduction.
#[inline(always)]
pub fn sincos_pi4<L: Lane32>(t: L) -> (L, L) {
    kernel_eighths(t, A1_HI, SIN_T, COS_T)
}
