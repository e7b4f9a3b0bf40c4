//! Four-quadrant arctangent.
//!
//! See [`crate::math`] for the measured error and the special values.

use super::{bits, horner};
use crate::lane::Lane32;

/// atan t = t + t³·P(t²) for |t| ≤ ½. Minimax for relative error: 2^-27.5.
const ATAN_P: [f32; 5] = bits([
    0xbeaa_aa89, 0x3e4c_bd83, 0xbe11_24d9, 0x3dcf_fdca, 0xbd51_ed42,
]);
/// 2¹²⁶: above it, both operands are scaled by ¼ so that their sum cannot overflow.
const TWO_126: f32 = f32::from_bits(0x7e80_0000);
/// π/4 = PIO4_HI + PIO4_LO (+ 2^-48). PIO4_HI has 22 significant bits, so k·PIO4_HI is exact for
/// the integers k ≤ 4 used here.
pub(crate) const PIO4_HI: f32 = f32::from_bits(0x3f49_0fdc);
pub(crate) const PIO4_LO: f32 = f32::from_bits(0xb3ae_ef4c);

/// atan2(y, x) in [−π, π].
#[inline(always)]
pub fn atan2<L: Lane32>(y: L, x: L) -> L {
    let inf = L::c(f64::INFINITY);
    let ax = x.abs();
    let ay = y.abs();
    // NaN compares false, so a NaN in x lands in mx and a NaN in y in mn: the quotient is NaN.
    let swap = ay.gt(ax);
    let mut mn = L::select(swap, ax, ay);
    let mut mx = L::select(swap, ay, ax);
    // Keep mn + mx finite: a common power-of-two scale does not change the ratio.
    let sc = L::select(mx.gt(L::c(TWO_126 as f64)), L::c(0.25), L::ONE);
    mn = mn * sc;
    mx = mx * sc;
    // Both infinite: the ratio is taken as 1 (atan2(±∞, ±∞) = ±π/4, ±3π/4).
    let both_inf = mn.eq(inf) & mx.eq(inf);
    mn = L::select(both_inf, L::ONE, mn);
    mx = L::select(both_inf, L::ONE, mx);

    // mn/mx ∈ [0, 1]. Above ½, use atan(mn/mx) = π/4 + atan((mn − mx)/(mn + mx)), with one
    // division either way; mn − mx is exact there (Sterbenz), and the quotient is in (−⅓, 0].
    let big = mn.gt(mx * L::HALF);
    let num = L::select(big, mn - mx, mn);
    let den = L::select(big, mn + mx, mx);
    // (0, 0): 0/0 would be NaN; 0/1 gives 0, and the signs below give IEEE's ±0 and ±π.
    let den = L::select(den.eq(L::ZERO), L::ONE, den);
    let t = num / den;

    // angle = k·π/4 + p, then π/2 − angle if swapped, then π − angle if x is negative (by its
    // sign bit, so that x = −0 gives π like IEEE atan2). The sign is applied to t (atan is odd),
    // and k·(π/4)_lo joins the small terms of the polynomial, so that the sum is rounded twice:
    // once adding t, once adding k·(π/4)_hi.
    let one = L::ONE;
    let xneg = one.copysign(x).lt(L::ZERO);
    let mut k = L::select(big, one, L::ZERO);
    let mut t = t;
    k = L::select(swap, L::TWO - k, k);
    t = L::select(swap, -t, t);
    k = L::select(xneg, L::c(4.0) - k, k);
    t = L::select(xneg, -t, t);
    let z = t * t;
    let small = (t * z).mul_add(horner(z, ATAN_P), k * L::c(PIO4_LO as f64));
    let a = k.mul_add(L::c(PIO4_HI as f64), t + small);
    a.copysign(y)
}
