//! The integer lane the generators are written over: `u32` and [`U32x8`].

use crate::x8::{F32x8, U32x8};

/// 2⁻²⁴ as f32 bits: the weight of bit 8 of a 32-bit value in a 24-bit float in [0, 1).
const TWO_POW_M24_BITS: u32 = 0x3380_0000;
/// 1.0f32 as bits.
const ONE_BITS: u32 = 0x3f80_0000;

/// A lane of 32-bit unsigned integers: the operations the sequence generators use, with
/// wrapping arithmetic in both widths.
///
/// Every operation is exact integer arithmetic, and [`to_unit_f32`](U32Lane::to_unit_f32) is
/// exact too, so a generic generator gives the same bits in every lane of a packet as in the
/// scalar form.
pub trait U32Lane: Copy {
    /// The float lane of the same width.
    type F: Copy;
    /// Every lane equal to `x`.
    fn splat(x: u32) -> Self;
    /// Lane-wise `a + b` mod 2³².
    fn wrapping_add(self, b: Self) -> Self;
    /// Lane-wise `a · b` mod 2³².
    fn wrapping_mul(self, b: Self) -> Self;
    /// Lane-wise `a ^ b`.
    fn xor(self, b: Self) -> Self;
    /// Lane-wise `a & b`.
    fn and(self, b: Self) -> Self;
    /// Lane-wise logical shift right by `n < 32`.
    fn shr(self, n: u32) -> Self;
    /// Lane-wise shift left by `n < 32`.
    fn shl(self, n: u32) -> Self;
    /// The float with these bits.
    fn float_from_bits(self) -> Self::F;
    /// `(self >> 8) · 2⁻²⁴`: a 24-bit float in [0, 1), never 1.0.
    ///
    /// Computed exactly, without an int-to-float conversion instruction: the top 23 bits go into
    /// the mantissa of a float in [1, 2), 1 is subtracted (exact), and bit 8 is added as 0 or
    /// 2⁻²⁴ (exact, as the sum has 24 significant bits).
    fn to_unit_f32(self) -> Self::F;
}

impl U32Lane for u32 {
    type F = f32;
    #[inline(always)]
    fn splat(x: u32) -> Self {
        x
    }
    #[inline(always)]
    fn wrapping_add(self, b: Self) -> Self {
        u32::wrapping_add(self, b)
    }
    #[inline(always)]
    fn wrapping_mul(self, b: Self) -> Self {
        u32::wrapping_mul(self, b)
    }
    #[inline(always)]
    fn xor(self, b: Self) -> Self {
        self ^ b
    }
    #[inline(always)]
    fn and(self, b: Self) -> Self {
        self & b
    }
    #[inline(always)]
    fn shr(self, n: u32) -> Self {
        self >> n
    }
    #[inline(always)]
    fn shl(self, n: u32) -> Self {
        self << n
    }
    #[inline(always)]
    fn float_from_bits(self) -> f32 {
        f32::from_bits(self)
    }
    #[inline(always)]
    fn to_unit_f32(self) -> f32 {
        unit_f32(self)
    }
}

impl U32Lane for U32x8 {
    type F = F32x8;
    #[inline(always)]
    fn splat(x: u32) -> Self {
        U32x8::splat(x)
    }
    #[inline(always)]
    fn wrapping_add(self, b: Self) -> Self {
        self + b
    }
    #[inline(always)]
    fn wrapping_mul(self, b: Self) -> Self {
        self * b
    }
    #[inline(always)]
    fn xor(self, b: Self) -> Self {
        self ^ b
    }
    #[inline(always)]
    fn and(self, b: Self) -> Self {
        self & b
    }
    #[inline(always)]
    fn shr(self, n: u32) -> Self {
        self >> n
    }
    #[inline(always)]
    fn shl(self, n: u32) -> Self {
        self << n
    }
    #[inline(always)]
    fn float_from_bits(self) -> F32x8 {
        F32x8::from_bits(self)
    }
    #[inline(always)]
    fn to_unit_f32(self) -> F32x8 {
        unit_f32(self)
    }
}

/// The shared body of [`U32Lane::to_unit_f32`], so both widths run the same operations.
#[inline(always)]
fn unit_f32<U>(x: U) -> U::F
where
    U: U32Lane,
    U::F: core::ops::Sub<Output = U::F> + core::ops::Add<Output = U::F>,
{
    // x >> 9 fills only the 23 mantissa bits, so the xor sets 1.0's exponent above them.
    let hi =
        x.shr(9).xor(U::splat(ONE_BITS)).float_from_bits() - U::splat(ONE_BITS).float_from_bits();
    let lo = x
        .shr(8)
        .and(U::splat(1))
        .wrapping_mul(U::splat(TWO_POW_M24_BITS))
        .float_from_bits();
    hi + lo
}
