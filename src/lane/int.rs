//! The 32-bit integer lane, `u32`, [`U32x8`] and [`U32x16`], that the sequence generators are
//! written over, and [`Lane32`]: the f32 lanes with access to their bits in it.

use core::fmt::Debug;
use core::ops::{Add, BitAnd, BitOr, BitXor, Shl, Shr, Sub};

use wide::{bytemuck, i32x8, i32x16};

use super::float::{F32x8, F32x16, Lane};
use super::vector::V2;

/// Eight u32 lanes (`wide::u32x8`), the bits of an [`F32x8`]. Re-exported as
/// [`crate::x8::U32x8`].
pub type U32x8 = wide::u32x8;

/// Sixteen u32 lanes (`wide::u32x16`), the bits of an [`F32x16`]. Re-exported as
/// [`crate::x16::U32x16`].
pub type U32x16 = wide::u32x16;

/// 2⁻²⁴: the weight of bit 8 of a 32-bit value in a 24-bit float in [0, 1).
const TWO_POW_M24: f32 = 1.0 / 16_777_216.0;

/// A lane of 32-bit unsigned integers: the bits of a float lane, and the operations the sequence
/// generators use, with wrapping arithmetic in both widths.
///
/// Shifts are the operators `>>` and `<<` (also callable as `.shr(n)`, `.shl(n)`), logical, for
/// n < 32. The operators `+ − & |` are the plain ones (for `u32`, `+` and `−` are checked in debug
/// builds): bit manipulation of floats uses them where no overflow can occur; the generators use
/// the `wrapping_*` methods.
///
/// Every operation is exact integer arithmetic, and [`to_unit_f32`](U32Lane::to_unit_f32) is
/// exact too, so a generic generator gives the same bits in every lane of a packet as in the
/// scalar form.
pub trait U32Lane:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + BitAnd<Output = Self>
    + BitOr<Output = Self>
    + BitXor<Output = Self>
    + Shr<u32, Output = Self>
    + Shl<u32, Output = Self>
{
    /// The float lane of the same width.
    type F: Lane;
    /// The public 2D vector of the same width: [`glam::Vec2`] for `u32`,
    /// [`Vec2x8`](crate::x8::Vec2x8) for [`U32x8`]. Two-dimensional generators return it.
    type Vec2: Copy + Debug + PartialEq + Default + From<V2<Self::F>>;
    /// Every lane equal to `x`.
    fn splat(x: u32) -> Self;
    /// Lane-wise `a + b` mod 2³².
    fn wrapping_add(self, b: Self) -> Self;
    /// Lane-wise `a − b` mod 2³².
    fn wrapping_sub(self, b: Self) -> Self;
    /// Lane-wise `a · b` mod 2³².
    fn wrapping_mul(self, b: Self) -> Self;
    /// Lane-wise logical `self >> N` for a constant N in 0..32: a shift by an immediate in
    /// packets. Use it for every constant count; `>>` is for counts known at run time.
    fn shr_by<const N: i32>(self) -> Self;
    /// Lane-wise `self << N` for a constant N in 0..32, as [`shr_by`](U32Lane::shr_by).
    fn shl_by<const N: i32>(self) -> Self;
    /// Lane-wise `a ^ b`.
    #[inline(always)]
    fn xor(self, b: Self) -> Self {
        self ^ b
    }
    /// Lane-wise `a & b`.
    #[inline(always)]
    fn and(self, b: Self) -> Self {
        self & b
    }
    /// (⌊self/d⌋, self mod d), lane-wise, for d ≥ 1: the hardware divide in scalar code, a
    /// multiply by a precomputed reciprocal in packets (exact in both, so the results agree).
    fn div_rem(self, d: u32) -> (Self, Self);
    /// `f` of each lane: for table lookups, which packets cannot do in their registers.
    fn map(self, f: impl Fn(u32) -> u32) -> Self;
    /// The high word of the 64-bit product `a · b`.
    fn mul_hi(self, b: Self) -> Self;
    /// All ones where `self > b` (unsigned), zero elsewhere.
    fn gt_mask(self, b: Self) -> Self;
    /// All ones where bit 31 is set, zero elsewhere (an arithmetic shift right by 31).
    fn top_bit_mask(self) -> Self;
    /// `self` where `mask` is all ones, `other` where it is zero (`mask` from a `*_mask` method).
    fn select(mask: Self, a: Self, b: Self) -> Self;
    /// True if any lane is nonzero.
    fn any_nonzero(self) -> bool;
    /// The bits in reverse order, lane-wise.
    fn reverse_bits(self) -> Self;
    /// `self / den` as the correctly rounded f32 quotient, for `self, den < 2²⁴`, where both
    /// convert to f32 exactly (larger values are rounded to nearest before dividing).
    fn ratio(self, den: u32) -> Self::F;
    /// `(self >> 8) · 2⁻²⁴`: a 24-bit float in [0, 1), never 1.0.
    ///
    /// Exact in both widths: `self >> 8` is below 2²⁴, so its conversion to f32 (through i32,
    /// one instruction for a packet) is exact, and so is the scaling by a power of two.
    fn to_unit_f32(self) -> Self::F;
}

impl U32Lane for u32 {
    type F = f32;
    type Vec2 = glam::Vec2;
    #[inline(always)]
    fn shr_by<const N: i32>(self) -> Self {
        self >> N
    }
    #[inline(always)]
    fn shl_by<const N: i32>(self) -> Self {
        self << N
    }
    inline_fns! {
        fn splat(x: u32) -> Self { x }
        fn wrapping_add(self, b: Self) -> Self { u32::wrapping_add(self, b) }
        fn wrapping_sub(self, b: Self) -> Self { u32::wrapping_sub(self, b) }
        fn wrapping_mul(self, b: Self) -> Self { u32::wrapping_mul(self, b) }
        fn div_rem(self, d: u32) -> (Self, Self) {
            // Total: a divisor of 0 is taken as 1 (callers pass counts clamped to at least 1).
            let d = d.max(1);
            #[allow(clippy::integer_division)]
            (self / d, self % d)
        }
        fn map(self, f: impl Fn(u32) -> u32) -> Self { f(self) }
        fn mul_hi(self, b: Self) -> Self { ((self as u64 * b as u64) >> 32) as u32 }
        fn gt_mask(self, b: Self) -> Self { 0u32.wrapping_sub((self > b) as u32) }
        fn top_bit_mask(self) -> Self { ((self as i32) >> 31) as u32 }
        fn select(mask: Self, a: Self, b: Self) -> Self { (a & mask) | (b & !mask) }
        fn any_nonzero(self) -> bool { self != 0 }
        fn reverse_bits(self) -> Self { u32::reverse_bits(self) }
    }
    #[inline(always)]
    fn ratio(self, den: u32) -> f32 {
        // Through i32, like the packet's conversion instruction: exact below 2²⁴.
        (self as i32) as f32 / (den as i32) as f32
    }
    #[inline(always)]
    fn to_unit_f32(self) -> f32 {
        ((self >> 8) as i32) as f32 * TWO_POW_M24
    }
}

impl U32Lane for U32x8 {
    type F = F32x8;
    type Vec2 = V2<F32x8>;
    #[inline(always)]
    fn shr_by<const N: i32>(self) -> Self {
        imm::shr::<N>(self)
    }
    #[inline(always)]
    fn shl_by<const N: i32>(self) -> Self {
        imm::shl::<N>(self)
    }
    inline_fns! {
        fn splat(x: u32) -> Self { U32x8::splat(x) }
        fn wrapping_add(self, b: Self) -> Self { self + b }
        fn wrapping_sub(self, b: Self) -> Self { self - b }
        fn wrapping_mul(self, b: Self) -> Self { mul_x8(self, b) }
        fn div_rem(self, d: u32) -> (Self, Self) { Divisor::new(d).div_rem(self) }
        fn map(self, f: impl Fn(u32) -> u32) -> Self { U32x8::new(self.to_array().map(f)) }
        fn mul_hi(self, b: Self) -> Self { self.mul_keep_high(b) }
        fn gt_mask(self, b: Self) -> Self { self.simd_gt(b) }
        fn top_bit_mask(self) -> Self { imm::sar31(self) }
        fn select(mask: Self, a: Self, b: Self) -> Self { mask.select(a, b) }
        fn any_nonzero(self) -> bool { self != U32x8::ZERO }
        fn reverse_bits(self) -> Self { reverse_bits_x8(self) }
        fn ratio(self, den: u32) -> F32x8 {
            bytemuck::cast::<U32x8, i32x8>(self).round_float() / F32x8::splat((den as i32) as f32)
        }
        fn to_unit_f32(self) -> F32x8 {
            F32x8::from_i32x8(bytemuck::cast::<U32x8, i32x8>(imm::shr::<8>(self))) * F32x8::splat(TWO_POW_M24)
        }
    }
}

/// The sixteen-wide lane. With AVX-512 its operations are `wide`'s, one instruction each, but for
/// the table lookups, byte shuffles and the high product, which go through two eight-wide halves.
/// Without AVX-512 `wide` splits every operation into halves anyway, and these take the halves
/// through [`U32x8`]'s own operations, with the immediate shifts and the SSE2 multiply that
/// `wide`'s eight-wide operators lack.
impl U32Lane for U32x16 {
    type F = F32x16;
    type Vec2 = V2<F32x16>;
    #[inline(always)]
    fn shr_by<const N: i32>(self) -> Self {
        #[cfg(target_feature = "avx512f")]
        return self >> N as u32;
        #[cfg(not(target_feature = "avx512f"))]
        return halves(self, U32x8::shr_by::<N>);
    }
    #[inline(always)]
    fn shl_by<const N: i32>(self) -> Self {
        #[cfg(target_feature = "avx512f")]
        return self << N as u32;
        #[cfg(not(target_feature = "avx512f"))]
        return halves(self, U32x8::shl_by::<N>);
    }
    #[inline(always)]
    fn wrapping_mul(self, b: Self) -> Self {
        #[cfg(target_feature = "avx512f")]
        return self * b;
        #[cfg(not(target_feature = "avx512f"))]
        return halves2(self, b, U32x8::wrapping_mul);
    }
    #[inline(always)]
    fn top_bit_mask(self) -> Self {
        #[cfg(target_feature = "avx512f")]
        return bytemuck::cast(bytemuck::cast::<U32x16, i32x16>(self) >> 31);
        #[cfg(not(target_feature = "avx512f"))]
        return halves(self, U32x8::top_bit_mask);
    }
    inline_fns! {
        fn splat(x: u32) -> Self { U32x16::splat(x) }
        fn wrapping_add(self, b: Self) -> Self { self + b }
        fn wrapping_sub(self, b: Self) -> Self { self - b }
        fn div_rem(self, d: u32) -> (Self, Self) { Divisor::new(d).div_rem(self) }
        fn map(self, f: impl Fn(u32) -> u32) -> Self { U32x16::new(self.to_array().map(f)) }
        fn mul_hi(self, b: Self) -> Self { halves2(self, b, U32x8::mul_hi) }
        fn gt_mask(self, b: Self) -> Self { self.simd_gt(b) }
        fn select(mask: Self, a: Self, b: Self) -> Self { mask.select(a, b) }
        fn any_nonzero(self) -> bool { self != U32x16::ZERO }
        fn reverse_bits(self) -> Self { halves(self, U32x8::reverse_bits) }
        fn ratio(self, den: u32) -> F32x16 {
            bytemuck::cast::<U32x16, i32x16>(self).round_float() / F32x16::splat((den as i32) as f32)
        }
        fn to_unit_f32(self) -> F32x16 {
            F32x16::from_i32x16(bytemuck::cast::<U32x16, i32x16>(self.shr_by::<8>()))
                * F32x16::splat(TWO_POW_M24)
        }
    }
}

/// `f` on each eight-wide half of a sixteen-wide lane.
#[inline(always)]
fn halves(x: U32x16, f: impl Fn(U32x8) -> U32x8) -> U32x16 {
    let [a, b]: [U32x8; 2] = bytemuck::cast(x);
    bytemuck::cast([f(a), f(b)])
}

/// `f` on each eight-wide half of two sixteen-wide lanes.
#[inline(always)]
fn halves2(x: U32x16, y: U32x16, f: impl Fn(U32x8, U32x8) -> U32x8) -> U32x16 {
    let [a, b]: [U32x8; 2] = bytemuck::cast(x);
    let [c, d]: [U32x8; 2] = bytemuck::cast(y);
    bytemuck::cast([f(a, c), f(b, d)])
}

/// Shifts of a packet by a constant. `wide`'s shift operators take the count in a register, and
/// on x86 build that register through memory: a store the load cannot always forward from, a
/// stall of a dozen cycles per shift in the hash chains of the sequences. The immediate forms
/// take the count in the instruction.
#[cfg(target_arch = "x86_64")]
mod imm {
    use super::U32x8;
    use wide::bytemuck::cast;

    #[cfg(not(target_feature = "avx2"))]
    use safe_arch::{m128i, shl_imm_u32_m128i, shr_imm_i32_m128i, shr_imm_u32_m128i};
    #[cfg(target_feature = "avx2")]
    use safe_arch::{shl_imm_u32_m256i, shr_imm_i32_m256i, shr_imm_u32_m256i};

    /// One AVX2 register, or two SSE2 registers each shifted alike.
    macro_rules! by {
        ($avx2:expr, $sse2:expr, $x:expr) => {{
            #[cfg(target_feature = "avx2")]
            let r: U32x8 = cast($avx2(cast($x)));
            #[cfg(not(target_feature = "avx2"))]
            let r: U32x8 = {
                let [a, b]: [m128i; 2] = cast($x);
                cast([$sse2(a), $sse2(b)])
            };
            r
        }};
    }

    #[inline(always)]
    pub(super) fn shr<const N: i32>(x: U32x8) -> U32x8 {
        by!(shr_imm_u32_m256i::<N>, shr_imm_u32_m128i::<N>, x)
    }

    #[inline(always)]
    pub(super) fn shl<const N: i32>(x: U32x8) -> U32x8 {
        by!(shl_imm_u32_m256i::<N>, shl_imm_u32_m128i::<N>, x)
    }

    /// The arithmetic shift by 31: each lane's top bit copied through the lane.
    #[inline(always)]
    pub(super) fn sar31(x: U32x8) -> U32x8 {
        by!(shr_imm_i32_m256i::<31>, shr_imm_i32_m128i::<31>, x)
    }
}

/// Shifts of a packet by a constant, where `wide`'s operators take it as it comes.
#[cfg(not(target_arch = "x86_64"))]
mod imm {
    use super::U32x8;
    use wide::{bytemuck::cast, i32x8};

    #[inline(always)]
    pub(super) fn shr<const N: i32>(x: U32x8) -> U32x8 {
        x >> N as u32
    }

    #[inline(always)]
    pub(super) fn shl<const N: i32>(x: U32x8) -> U32x8 {
        x << N as u32
    }

    #[inline(always)]
    pub(super) fn sar31(x: U32x8) -> U32x8 {
        cast(cast::<U32x8, i32x8>(x) >> 31)
    }
}

/// Lane-wise a·b mod 2³². The 32-bit lane multiply `pmulld` is SSE4.1, and without it `wide`
/// multiplies one lane at a time through memory. SSE2's `pmuludq` multiplies lanes 0 and 2 into
/// 64-bit products; a second one on the words shifted down takes lanes 1 and 3, and two shuffles
/// and an interleave gather the four low halves: seven instructions per four lanes, in registers.
#[cfg(all(target_arch = "x86_64", not(target_feature = "sse4.1")))]
#[inline(always)]
fn mul_x8(a: U32x8, b: U32x8) -> U32x8 {
    use safe_arch::{
        m128i, mul_widen_u32_odd_m128i, shr_imm_u64_m128i, shuffle_ai_f32_all_m128i,
        unpack_low_i32_m128i,
    };
    let four = |a: m128i, b: m128i| {
        let even = mul_widen_u32_odd_m128i(a, b);
        let odd = mul_widen_u32_odd_m128i(shr_imm_u64_m128i::<32>(a), shr_imm_u64_m128i::<32>(b));
        // The low words of the two products (dwords 0 and 2) to the bottom, then interleaved.
        unpack_low_i32_m128i(
            shuffle_ai_f32_all_m128i::<0b00_00_10_00>(even),
            shuffle_ai_f32_all_m128i::<0b00_00_10_00>(odd),
        )
    };
    let [a0, a1]: [m128i; 2] = bytemuck::cast(a);
    let [b0, b1]: [m128i; 2] = bytemuck::cast(b);
    bytemuck::cast([four(a0, b0), four(a1, b1)])
}

/// Lane-wise a·b mod 2³², `wide`'s multiply where the target has a 32-bit lane multiply.
#[cfg(not(all(target_arch = "x86_64", not(target_feature = "sse4.1"))))]
#[inline(always)]
fn mul_x8(a: U32x8, b: U32x8) -> U32x8 {
    a * b
}

/// Bit reversal of each lane with AVX2: one byte shuffle reverses the bytes of each lane, and two
/// 16-entry lookups (also byte shuffles) reverse the bits of each byte from its two nibbles. Seven
/// instructions instead of the twenty-odd of the shift-and-mask form.
#[cfg(target_feature = "avx2")]
#[inline(always)]
fn reverse_bits_x8(x: U32x8) -> U32x8 {
    use wide::u8x32;
    // Evaluated into a constant: an index out of range is a compile error, not a run-time panic,
    // and the divisor is the constant 4.
    #[allow(clippy::indexing_slicing, clippy::integer_division)]
    const fn tables() -> ([u8; 32], [u8; 32], [u8; 32]) {
        let (mut bytes, mut low, mut high) = ([0u8; 32], [0u8; 32], [0u8; 32]);
        let mut i = 0;
        while i < 32 {
            // The shuffle indexes within each 16-byte half.
            bytes[i] = ((i % 16) / 4 * 4 + 3 - i % 4) as u8;
            let nibble = (i % 16) as u8;
            let reversed = nibble.reverse_bits() >> 4;
            low[i] = reversed << 4; // the low nibble goes to the top
            high[i] = reversed;
            i += 1;
        }
        (bytes, low, high)
    }
    const TABLES: ([u8; 32], [u8; 32], [u8; 32]) = tables();
    let swapped: U32x8 = bytemuck::cast(
        bytemuck::cast::<U32x8, u8x32>(x).swizzle_half_relaxed(u8x32::from(TABLES.0)),
    );
    let nibbles = U32x8::splat(0x0f0f_0f0f);
    let low = bytemuck::cast::<U32x8, u8x32>(swapped & nibbles);
    let high = bytemuck::cast::<U32x8, u8x32>(imm::shr::<4>(swapped) & nibbles);
    bytemuck::cast(
        u8x32::from(TABLES.1).swizzle_half_relaxed(low)
            | u8x32::from(TABLES.2).swizzle_half_relaxed(high),
    )
}

/// Bit reversal of each lane without byte shuffles: swap halves, then bytes, nibbles, pairs and
/// single bits.
#[cfg(not(target_feature = "avx2"))]
#[inline(always)]
fn reverse_bits_x8(x: U32x8) -> U32x8 {
    use imm::{shl, shr};
    let x = shr::<16>(x) | shl::<16>(x);
    let x = (shr::<8>(x) & U32x8::splat(0x00ff_00ff)) | shl::<8>(x & U32x8::splat(0x00ff_00ff));
    let x = (shr::<4>(x) & U32x8::splat(0x0f0f_0f0f)) | shl::<4>(x & U32x8::splat(0x0f0f_0f0f));
    let x = (shr::<2>(x) & U32x8::splat(0x3333_3333)) | shl::<2>(x & U32x8::splat(0x3333_3333));
    (shr::<1>(x) & U32x8::splat(0x5555_5555)) | shl::<1>(x & U32x8::splat(0x5555_5555))
}

/// Unsigned division of a lane by a scalar d ≥ 1 through a precomputed multiplier (Granlund and
/// Montgomery, "Division by invariant integers using multiplication", PLDI 1994, §4): with
/// l = ⌈log₂ d⌉ and m = ⌊2³²(2ˡ − d)/d⌋ + 1, q = (t + ((n − t) >> 1)) >> (l − 1), t = mulhi(m, n),
/// is ⌊n/d⌋ for every 32-bit n (d = 1 uses shifts 0 and 0).
#[derive(Clone, Copy, Debug)]
struct Divisor {
    d: u32,
    m: u32,
    shift1: u32,
    shift2: u32,
}

impl Divisor {
    /// The divisor `d` (0 is taken as 1: callers pass counts clamped to at least 1).
    #[inline(always)]
    fn new(d: u32) -> Self {
        let d = d.max(1);
        let l = 32 - (d - 1).leading_zeros(); // ⌈log₂ d⌉
        // d ≥ 1, just above.
        #[allow(clippy::integer_division)]
        let m = ((((1u64 << l) - d as u64) << 32) / d as u64 + 1) as u32;
        Self {
            d,
            m,
            shift1: l.min(1),
            shift2: l.saturating_sub(1),
        }
    }

    /// (⌊n/d⌋, n mod d), lane-wise.
    #[inline(always)]
    fn div_rem<U: U32Lane>(self, n: U) -> (U, U) {
        let t = n.mul_hi(U::splat(self.m));
        let q = t
            .wrapping_add(n.wrapping_sub(t).shr(self.shift1))
            .shr(self.shift2);
        (q, n.wrapping_sub(q.wrapping_mul(U::splat(self.d))))
    }
}

// ---------------------------------------------------------------------------------------------
// The bits of the float lanes

/// Lanes of IEEE single precision, with access to their bits: the instances that run the crate's
/// own polynomials.
pub trait Lane32: Lane {
    /// The integer lane of the same width.
    type U: U32Lane;
    /// The bits of each lane.
    fn to_bits(self) -> Self::U;
    /// The lanes whose bits are `u`.
    fn from_bits(u: Self::U) -> Self;
}

impl Lane32 for f32 {
    type U = u32;
    inline_fns! {
        fn to_bits(self) -> u32 { f32::to_bits(self) }
        fn from_bits(u: u32) -> Self { f32::from_bits(u) }
    }
}

impl Lane32 for F32x8 {
    type U = U32x8;
    inline_fns! {
        fn to_bits(self) -> U32x8 { F32x8::to_bits(self) }
        fn from_bits(u: U32x8) -> Self { F32x8::from_bits(u) }
    }
}

impl Lane32 for F32x16 {
    type U = U32x16;
    inline_fns! {
        fn to_bits(self) -> U32x16 { F32x16::to_bits(self) }
        fn from_bits(u: U32x16) -> Self { F32x16::from_bits(u) }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn divisor_matches_division() {
        let ds = [
            1u32,
            2,
            3,
            5,
            7,
            10,
            641,
            1000,
            1 << 23,
            (1 << 31) + 1,
            u32::MAX,
        ];
        let mut x = 0x1234_5678u32;
        for &d in &ds {
            let div = Divisor::new(d);
            for k in 0..20_000u32 {
                x = x.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
                for n in [
                    x,
                    k,
                    u32::MAX - k,
                    d.wrapping_mul(k),
                    d.wrapping_mul(k).wrapping_sub(1),
                ] {
                    assert_eq!(div.div_rem::<u32>(n), (n / d, n % d), "{n} / {d}");
                }
            }
        }
    }

    #[test]
    fn packet_products_are_the_scalar_products_in_every_lane() {
        // Carries out of every bit position, the words with the top bit set that a signed
        // multiply would get wrong, and lanes 1 and 3 that the second pmuludq computes.
        let mut x = 0x9e37_79b9u32;
        let mut next = || {
            x ^= x << 13;
            x ^= x >> 17;
            x ^= x << 5;
            x
        };
        for _ in 0..10_000 {
            let a: [u32; 8] = core::array::from_fn(|i| match i {
                0 => u32::MAX,
                5 => 0x8000_0001,
                _ => next(),
            });
            let b: [u32; 8] = core::array::from_fn(|_| next());
            let p = U32x8::new(a).wrapping_mul(U32x8::new(b)).to_array();
            for i in 0..8 {
                assert_eq!(
                    p[i],
                    a[i].wrapping_mul(b[i]),
                    "lane {i}: {} · {}",
                    a[i],
                    b[i]
                );
            }
        }
    }
}
