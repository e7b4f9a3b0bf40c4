//! `Pcg32x8`'s layout with 32-bit lane operations (AVX2, NEON, wasm and the rest): each 64-bit
//! state is a low and a high [`U32x8`] word.

use super::MULTIPLIER;
use crate::lane::{U32x8, zip_map};

const MUL_LO: u32 = MULTIPLIER as u32;
const MUL_HI: u32 = (MULTIPLIER >> 32) as u32;

/// Eight 64-bit words as their low and high halves.
#[derive(Clone, Copy)]
pub(super) struct Words {
    lo: U32x8,
    hi: U32x8,
}

impl Words {
    pub(super) fn new(x: [u64; 8]) -> Self {
        Self {
            lo: U32x8::new(x.map(|s| s as u32)),
            hi: U32x8::new(x.map(|s| (s >> 32) as u32)),
        }
    }

    pub(super) fn get(&self) -> [u64; 8] {
        let (lo, hi) = (self.lo.to_array(), self.hi.to_array());
        zip_map(hi, lo, |h, l| (u64::from(h) << 32) | u64::from(l))
    }
}

/// The output of every lane's state, then one step of it.
#[inline(always)]
pub(super) fn next(state: &mut Words, inc: &Words) -> U32x8 {
    let Words { lo, hi } = *state;

    // Output XSH RR of the old state: x = s ^ (s >> 18); xsh = (x >> 27) as u32; rot = s >> 59.
    let x_lo = lo ^ ((lo >> 18) | (hi << 14));
    let x_hi = hi ^ (hi >> 18);
    let xsh = (x_lo >> 27) | (x_hi << 5);
    let rot = hi >> 27;
    let left = (U32x8::ZERO - rot) & U32x8::splat(31);
    let out = (xsh >> rot) | (xsh << left);

    // Step: s·M + inc mod 2⁶⁴, with 32-bit halves.
    let (p_lo, p_hi) = lo.mul_keep_low_high(U32x8::splat(MUL_LO));
    let cross = lo * U32x8::splat(MUL_HI) + hi * U32x8::splat(MUL_LO);
    let new_lo = p_lo + inc.lo;
    // Carry out of the low word: the sum wrapped iff it is below an addend.
    let carry = new_lo.simd_lt(inc.lo); // all ones (= −1) where a carry occurred
    state.hi = p_hi + cross + inc.hi - carry;
    state.lo = new_lo;
    out
}
