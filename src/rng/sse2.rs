//! `Pcg32x8`'s layout for x86-64 without AVX2. SSE2 has no 32-bit lane multiply and no per-lane
//! shift, which the 32-bit-halves layout needs (`wide` emulates both one lane at a time there).
//! It does have `pmuludq`, a 32×32→64 multiply in each 64-bit lane, and a 64-bit shift by a
//! count held in a register. So each 64-bit state is a 64-bit lane, two to a register:
//! - the step s·M + inc takes three `pmuludq`: s_lo·M_lo whole, and the cross terms
//!   s_lo·M_hi + s_hi·M_lo, of which only the low 32 bits matter, shifted up by 32;
//! - the rotation of the 32-bit xsh by `rot` is the low half of the 64-bit word xsh:xsh shifted
//!   right by `rot`, one shift per lane, since the count register is shared by both lanes.

use safe_arch::{
    add_i64_m128i, bitxor_m128i, cast_to_m128_from_m128i, cast_to_m128d_from_m128i,
    cast_to_m128i_from_m128, cast_to_m128i_from_m128d, copy_replace_low_f64_m128d, m128i,
    mul_widen_u32_odd_m128i, set_splat_i64_m128i, shl_imm_u64_m128i, shr_all_u64_m128i,
    shr_imm_u64_m128i, shuffle_abi_f32_all_m128, shuffle_ai_f32_all_m128i, unpack_high_i64_m128i,
};
use wide::bytemuck;

use super::MULTIPLIER;
use crate::lane::U32x8;

/// Eight 64-bit words, lanes 2j and 2j + 1 in register j.
#[derive(Clone, Copy)]
pub(super) struct Words([m128i; 4]);

impl Words {
    pub(super) fn new(x: [u64; 8]) -> Self {
        let [x0, x1, x2, x3, x4, x5, x6, x7] = x;
        Self([[x0, x1], [x2, x3], [x4, x5], [x6, x7]].map(bytemuck::cast))
    }

    pub(super) fn get(&self) -> [u64; 8] {
        bytemuck::cast(self.0)
    }
}

/// The output of every lane's state (in the low 32 bits of its 64-bit lane), then one step of it.
#[inline(always)]
fn next_pair(s: &mut m128i, inc: m128i) -> m128i {
    let m_lo = set_splat_i64_m128i(i64::from(MULTIPLIER as u32));
    let m_hi = set_splat_i64_m128i((MULTIPLIER >> 32) as i64);
    let old = *s;

    // Output XSH RR: xsh = ((s ^ (s >> 18)) >> 27) as u32, rot = s >> 59.
    let xsh = shr_imm_u64_m128i::<27>(bitxor_m128i(old, shr_imm_u64_m128i::<18>(old)));
    // xsh:xsh in each lane (dwords 0, 0, 2, 2): its right shift by rot < 32 has
    // xsh.rotate_right(rot) in the low half.
    let doubled = shuffle_ai_f32_all_m128i::<0b10_10_00_00>(xsh);
    let rot = shr_imm_u64_m128i::<59>(old);
    let by_lane0 = shr_all_u64_m128i(doubled, rot);
    let by_lane1 = shr_all_u64_m128i(doubled, unpack_high_i64_m128i(rot, rot));
    let out = cast_to_m128i_from_m128d(copy_replace_low_f64_m128d(
        cast_to_m128d_from_m128i(by_lane1),
        cast_to_m128d_from_m128i(by_lane0),
    ));

    // Step: s·M + inc mod 2⁶⁴. pmuludq reads the low 32 bits of each lane.
    let low = mul_widen_u32_odd_m128i(old, m_lo);
    let cross = add_i64_m128i(
        mul_widen_u32_odd_m128i(old, m_hi),
        mul_widen_u32_odd_m128i(shr_imm_u64_m128i::<32>(old), m_lo),
    );
    *s = add_i64_m128i(add_i64_m128i(low, shl_imm_u64_m128i::<32>(cross)), inc);
    out
}

/// The output of every lane's state, then one step of it.
#[inline(always)]
pub(super) fn next(state: &mut Words, inc: &Words) -> U32x8 {
    let [s0, s1, s2, s3] = &mut state.0;
    let [i0, i1, i2, i3] = inc.0;
    let out = [
        next_pair(s0, i0),
        next_pair(s1, i1),
        next_pair(s2, i2),
        next_pair(s3, i3),
    ];
    // The low dwords (0 and 2) of two registers make four lanes.
    let low_dwords = |a: m128i, b: m128i| {
        cast_to_m128i_from_m128(shuffle_abi_f32_all_m128::<0b10_00_10_00>(
            cast_to_m128_from_m128i(a),
            cast_to_m128_from_m128i(b),
        ))
    };
    bytemuck::cast([low_dwords(out[0], out[1]), low_dwords(out[2], out[3])])
}
