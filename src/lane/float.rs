//! Float lanes: [`Lane`] for `f32`, [`F32x8`], [`F32x16`] and the `f64` reference, and the f64
//! packets [`F64x8`] and [`F64x16`] that the f32 packets widen to.

use core::fmt::Debug;
use core::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

use wide::{bytemuck, u32x8, u32x16};

/// Eight f32 lanes (`wide::f32x8`): the packet lane. Masks are `F32x8` values with all bits set
/// or clear. Re-exported as [`crate::x8::F32x8`].
pub type F32x8 = wide::f32x8;

/// Eight f64 lanes (`wide::f64x8`): the packet accumulators (mean and variance, optimal MIS,
/// the RIS reservoir), which sum in f64 as the scalar accumulators do, lane by lane with the same
/// operations. Masks are `F64x8` values with all bits set or clear.
pub type F64x8 = wide::f64x8;

/// Sixteen f32 lanes (`wide::f32x16`): one AVX-512 register, or two [`F32x8`] halves where the
/// build has no AVX-512, which `wide` runs one after the other. Masks are `F32x16` values with
/// all bits set or clear. Re-exported as [`crate::x16::F32x16`].
pub type F32x16 = wide::f32x16;

/// Sixteen f64 lanes, as two [`F64x8`] halves (lanes 0–7 and 8–15): the f64 lane of
/// [`F32x16`]'s width, for its accumulators and the set-up terms computed in f64. Every
/// operation is [`F64x8`]'s on each half, so a lane's value is the same as in the eight-wide
/// packet. Masks are `F64x16` values with all bits set or clear.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct F64x16 {
    /// Lanes 0–7.
    pub lo: F64x8,
    /// Lanes 8–15.
    pub hi: F64x8,
}

/// An [`F32x16`] as its two eight-lane halves, lanes 0..8 and 8..16.
#[cfg(not(target_feature = "avx512f"))]
#[inline(always)]
pub(crate) fn halves16(x: F32x16) -> (F32x8, F32x8) {
    // Without AVX-512 `wide` stores an f32x16 as two f32x8, so this is a move of registers.
    let [lo, hi]: [F32x8; 2] = bytemuck::cast(x);
    (lo, hi)
}

/// The [`F32x16`] whose halves are `lo` and `hi`.
#[cfg(not(target_feature = "avx512f"))]
#[inline(always)]
pub(crate) fn join16(lo: F32x8, hi: F32x8) -> F32x16 {
    bytemuck::cast([lo, hi])
}

/// `F64x16`'s operators, each half by F64x8's.
macro_rules! halves_op {
    ($($tr:ident $f:ident),*) => {$(
        impl $tr for F64x16 {
            type Output = F64x16;
            #[inline(always)]
            fn $f(self, o: F64x16) -> F64x16 {
                F64x16 { lo: $tr::$f(self.lo, o.lo), hi: $tr::$f(self.hi, o.hi) }
            }
        }
    )*};
}
halves_op!(Add add, Sub sub, Mul mul, Div div, BitAnd bitand, BitOr bitor);

impl Neg for F64x16 {
    type Output = F64x16;
    #[inline(always)]
    fn neg(self) -> F64x16 {
        F64x16 {
            lo: -self.lo,
            hi: -self.hi,
        }
    }
}

impl Not for F64x16 {
    type Output = F64x16;
    #[inline(always)]
    fn not(self) -> F64x16 {
        F64x16 {
            lo: !self.lo,
            hi: !self.hi,
        }
    }
}

impl F64x16 {
    /// `f` on each half.
    #[inline(always)]
    fn each(self, f: impl Fn(F64x8) -> F64x8) -> Self {
        F64x16 {
            lo: f(self.lo),
            hi: f(self.hi),
        }
    }
    /// `f` on each half of two packets.
    #[inline(always)]
    fn each2(self, o: Self, f: impl Fn(F64x8, F64x8) -> F64x8) -> Self {
        F64x16 {
            lo: f(self.lo, o.lo),
            hi: f(self.hi, o.hi),
        }
    }
    /// Every lane equal to `x`.
    #[inline(always)]
    pub const fn splat(x: f64) -> Self {
        F64x16 {
            lo: F64x8::new([x; 8]),
            hi: F64x8::new([x; 8]),
        }
    }
}

/// A lane-wise boolean: `bool` for scalar lanes, an all-ones/all-zeros bit pattern for packets.
pub trait Mask:
    Copy + Default + BitAnd<Output = Self> + BitOr<Output = Self> + Not<Output = Self>
{
    /// True if any lane is set.
    fn any(self) -> bool;
    /// True if every lane is set.
    fn all(self) -> bool;
}

impl Mask for bool {
    inline_fns! {
        fn any(self) -> bool { self }
        fn all(self) -> bool { self }
    }
}

impl Mask for F32x8 {
    inline_fns! {
        fn any(self) -> bool { F32x8::any(self) }
        fn all(self) -> bool { F32x8::all(self) }
    }
}

impl Mask for F64x8 {
    inline_fns! {
        fn any(self) -> bool { F64x8::any(self) }
        fn all(self) -> bool { F64x8::all(self) }
    }
}

impl Mask for F32x16 {
    inline_fns! {
        fn any(self) -> bool { F32x16::any(self) }
        fn all(self) -> bool { F32x16::all(self) }
    }
}

impl Mask for F64x16 {
    inline_fns! {
        fn any(self) -> bool { self.lo.any() || self.hi.any() }
        fn all(self) -> bool { self.lo.all() && self.hi.all() }
    }
}

/// A floating-point lane: arithmetic, comparisons to masks, selects and the crate's math.
///
/// Generic code uses only these operations, which is what makes the scalar and packet forms agree
/// bit for bit.
pub trait Lane:
    Copy
    + Default
    + Debug
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The result of a comparison.
    type Mask: Mask;

    /// A constant. Written as `f64` so that the reference instance gets full precision; the f32
    /// instances round it once, at compile time.
    fn c(x: f64) -> Self;
    /// 0 in every lane.
    const ZERO: Self;
    /// 1 in every lane.
    const ONE: Self;
    /// 2 in every lane.
    const TWO: Self;
    /// ½ in every lane.
    const HALF: Self;
    /// The lane's machine epsilon (2⁻²³ for the f32 lanes, 2⁻⁵² for f64): tolerances that
    /// stand for rounding scale with it, so that the f64 reference is not judged by f32's.
    const EPSILON: Self;

    /// `self · b + c`, with one rounding when the build has FMA and two otherwise, the same in
    /// both widths.
    fn mul_add(self, b: Self, c: Self) -> Self;
    /// Correctly rounded square root. Negative input gives NaN: clamp first where rounding can
    /// make a non-negative quantity slightly negative.
    fn sqrt(self) -> Self;
    /// `|self|`, by clearing the sign bit.
    fn abs(self) -> Self;
    /// The magnitude of `self` with the sign bit of `sign`.
    fn copysign(self, sign: Self) -> Self;
    /// `self` with its sign bit flipped where that of `sign` is set: for a `self` whose sign
    /// bit is clear, [`copysign`](Lane::copysign) in one operation fewer. (The default
    /// multiplies by ±1, which is the same but for a NaN `self`.)
    #[inline(always)]
    fn xorsign(self, sign: Self) -> Self {
        self * Self::ONE.copysign(sign)
    }

    /// `self < o`, lane-wise (false where either is NaN, as are the other compares).
    fn lt(self, o: Self) -> Self::Mask;
    /// `self ≤ o`, lane-wise.
    fn le(self, o: Self) -> Self::Mask;
    /// `self > o`, lane-wise.
    fn gt(self, o: Self) -> Self::Mask;
    /// `self ≥ o`, lane-wise.
    fn ge(self, o: Self) -> Self::Mask;
    /// `self == o`, lane-wise.
    fn eq(self, o: Self) -> Self::Mask;

    /// Lane-wise `if m { a } else { b }`.
    fn select(m: Self::Mask, a: Self, b: Self) -> Self;

    /// [`select`](Lane::select) for finite `a` and `b`, except that a result of −0 may come out
    /// as +0.
    ///
    /// The packet forms blend. The scalar f32 form computes a·k + b·(1 − k) with k ∈ {0, 1}, which
    /// is exact (one product is a zero, the other exact): LLVM merges selects on one condition in
    /// a scalar loop into a branch, taken half the time on random input (the concentric disk's
    /// wedge swap, in every per-call loop), where these products cost no prediction.
    #[inline(always)]
    fn select_finite(m: Self::Mask, a: Self, b: Self) -> Self {
        Self::select(m, a, b)
    }

    /// The smaller of the two; if either is NaN, `o`.
    #[inline(always)]
    fn min(self, o: Self) -> Self {
        Self::select(self.lt(o), self, o)
    }
    /// The larger of the two; if either is NaN, `o`.
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        Self::select(self.gt(o), self, o)
    }
    /// `self` limited to `[lo, hi]`; NaN stays NaN.
    #[inline(always)]
    fn clamp(self, lo: Self, hi: Self) -> Self {
        // hi.min(self) is select(self > hi, hi, self), so NaN stays NaN; likewise lo.max(..).
        lo.max(hi.min(self))
    }
    /// True where the lane is NaN.
    #[inline(always)]
    fn is_nan(self) -> Self::Mask {
        !self.eq(self)
    }
    /// NaN replaced by the canonical quiet NaN (bits 0x7fc0_0000 in f32); other values unchanged.
    ///
    /// Which NaN an IEEE operation returns depends on operand order, which the compiler may
    /// commute differently in scalar and packet code. Warps canonicalise what they return, so
    /// NaN outputs are bit-identical in both widths.
    #[inline(always)]
    fn canon(self) -> Self {
        Self::select(self.is_nan(), Self::c(f64::NAN), self)
    }
    /// True where the lane is neither NaN nor infinite.
    #[inline(always)]
    fn is_finite(self) -> Self::Mask {
        self.abs().lt(Self::c(f64::INFINITY))
    }
}

// ---------------------------------------------------------------------------------------------
// f32

/// a·b + c, fused exactly where the packet's `mul_add` is, so that both widths agree bit for bit.
///
/// wide fuses f32x4 and f32x8 on x86 with FMA and on aarch64, and elsewhere computes a·b + c
/// with two roundings. So does this, in scalar instructions:
/// - Without fusion, the plain expression. Lane 0 of an f32x4 gives the same bits, but LLVM
///   does not always see through the splats: it kept shuffles and packed multiplies in the
///   scalar spherical triangle's loop in `benches/peers.rs`.
/// - With fusion and std, std's `mul_add`, the scalar `llvm.fma.f32`: a vector intrinsic left in
///   the caller's loop makes LLVM's loop vectoriser refuse it ("instruction return type cannot be
///   vectorized": seven of nine warp loops stayed scalar in `examples/vectorize.rs`).
/// - With fusion and no std (core has no `mul_add` on stable), lane 0 of wide's f32x4.
#[inline(always)]
fn fma_f32(a: f32, b: f32, c: f32) -> f32 {
    #[cfg(all(
        feature = "std",
        any(
            all(target_feature = "sse2", target_feature = "fma"),
            all(target_arch = "aarch64", target_feature = "neon")
        )
    ))]
    {
        a.mul_add(b, c)
    }
    #[cfg(all(
        not(feature = "std"),
        any(
            all(target_feature = "sse2", target_feature = "fma"),
            all(target_arch = "aarch64", target_feature = "neon")
        )
    ))]
    {
        wide::f32x4::splat(a)
            .mul_add(wide::f32x4::splat(b), wide::f32x4::splat(c))
            .to_array()[0]
    }
    #[cfg(not(any(
        all(target_feature = "sse2", target_feature = "fma"),
        all(target_arch = "aarch64", target_feature = "neon")
    )))]
    {
        a * b + c
    }
}

/// Correctly rounded f32 square root, encoded for the build.
///
/// With std, std's `sqrt`, the scalar `llvm.sqrt.f32`, which LLVM encodes for the target and
/// widens when it vectorises the caller's loop. Without it, on x86, lane 0 of wide's f32x4:
/// libm's `sqrtf` there is an inline-asm `sqrtss`, which LLVM emits as written, never in its VEX
/// form, so that in an AVX build with the upper halves of the ymm registers dirty (the normal
/// state of AVX code) every root pays the SSE/AVX transition (it made the scalar spherical
/// triangle 17× slower). Elsewhere libm's, which uses the hardware instruction where there is one.
#[inline(always)]
fn sqrt_f32(x: f32) -> f32 {
    #[cfg(feature = "std")]
    {
        x.sqrt()
    }
    #[cfg(all(not(feature = "std"), target_feature = "sse"))]
    {
        wide::f32x4::splat(x).sqrt().to_array()[0]
    }
    #[cfg(all(not(feature = "std"), not(target_feature = "sse")))]
    {
        libm::sqrtf(x)
    }
}

/// The correctly rounded square root of an f64, chosen as [`sqrt_f32`] is.
#[inline(always)]
pub(crate) fn sqrt_f64(x: f64) -> f64 {
    #[cfg(feature = "std")]
    {
        x.sqrt()
    }
    #[cfg(all(not(feature = "std"), target_feature = "sse2"))]
    {
        wide::f64x2::splat(x).sqrt().to_array()[0]
    }
    #[cfg(all(not(feature = "std"), not(target_feature = "sse2")))]
    {
        libm::sqrt(x)
    }
}

/// What the two scalar lanes share: their constants, and the compares and select of a lane whose
/// mask is `bool`. The same text for `f32` and `f64`.
macro_rules! scalar_lane {
    () => {
        const ZERO: Self = 0.0;
        const ONE: Self = 1.0;
        const TWO: Self = 2.0;
        const HALF: Self = 0.5;
        const EPSILON: Self = Self::EPSILON;
        inline_fns! {
            fn lt(self, o: Self) -> bool { self < o }
            fn le(self, o: Self) -> bool { self <= o }
            fn gt(self, o: Self) -> bool { self > o }
            fn ge(self, o: Self) -> bool { self >= o }
            fn eq(self, o: Self) -> bool { self == o }
            // The masks of the warps depend on u, so a branch would mispredict half the time;
            // this asks LLVM for a blend instead.
            fn select(m: bool, a: Self, b: Self) -> Self { core::hint::select_unpredictable(m, a, b) }
        }
    };
}

impl Lane for f32 {
    type Mask = bool;

    inline_fns! {
        fn c(x: f64) -> Self { x as f32 }
        fn mul_add(self, b: Self, c: Self) -> Self { fma_f32(self, b, c) }
        fn sqrt(self) -> Self { sqrt_f32(self) }
        fn abs(self) -> Self { f32::from_bits(self.to_bits() & 0x7fff_ffff) }
        fn copysign(self, sign: Self) -> Self {
            f32::from_bits((self.to_bits() & 0x7fff_ffff) | (sign.to_bits() & 0x8000_0000))
        }
        fn xorsign(self, sign: Self) -> Self {
            f32::from_bits(self.to_bits() ^ (sign.to_bits() & 0x8000_0000))
        }
        fn select_finite(m: bool, a: Self, b: Self) -> Self {
            let k = Self::select(m, 1.0, 0.0);
            a * k + b * (1.0 - k)
        }
    }
    scalar_lane!();
}

// ---------------------------------------------------------------------------------------------
// F32x8 and F32x16

/// The f32 packet lanes, one text for both widths: `f32_packet!(F32x8, u32x8, 8)`.
macro_rules! f32_packet {
    ($t:ident, $u:ident, $n:literal) => {
        impl Lane for $t {
            type Mask = $t;
            const ZERO: Self = $t::new([0.0; $n]);
            const ONE: Self = $t::new([1.0; $n]);
            const TWO: Self = $t::new([2.0; $n]);
            const HALF: Self = $t::new([0.5; $n]);
            const EPSILON: Self = $t::new([f32::EPSILON; $n]);

            // On x86, minps and maxps are exactly select(a < b, a, b) and select(a > b, a, b),
            // NaN and signed zeros included (the second operand wins when the compare is false):
            // one instruction instead of a compare and a blend, which SSE2 spells as three.
            // Elsewhere (NEON's min returns NaN, wasm's pmin swaps the operands) the generic
            // selects keep the lanes bit-identical.
            #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
            #[inline(always)]
            fn min(self, o: Self) -> Self {
                self.fast_min(o)
            }
            #[cfg(any(target_arch = "x86", target_arch = "x86_64"))]
            #[inline(always)]
            fn max(self, o: Self) -> Self {
                self.fast_max(o)
            }
            /// One unordered compare, rather than `!(x == x)`.
            #[inline(always)]
            fn is_nan(self) -> $t {
                $t::is_nan(self)
            }

            inline_fns! {
                fn c(x: f64) -> Self { $t::splat(x as f32) }
                fn mul_add(self, b: Self, c: Self) -> Self { $t::mul_add(self, b, c) }
                fn sqrt(self) -> Self { $t::sqrt(self) }
                fn abs(self) -> Self { $t::from_bits($t::to_bits(self) & $u::splat(0x7fff_ffff)) }
            }
            #[inline(always)]
            fn copysign(self, sign: Self) -> Self {
                $t::from_bits(
                    ($t::to_bits(self) & $u::splat(0x7fff_ffff))
                        | ($t::to_bits(sign) & $u::splat(0x8000_0000)),
                )
            }
            #[inline(always)]
            fn xorsign(self, sign: Self) -> Self {
                $t::from_bits($t::to_bits(self) ^ ($t::to_bits(sign) & $u::splat(0x8000_0000)))
            }
            inline_fns! {
                fn lt(self, o: Self) -> $t { self.simd_lt(o) }
                fn le(self, o: Self) -> $t { self.simd_le(o) }
                fn gt(self, o: Self) -> $t { self.simd_gt(o) }
                fn ge(self, o: Self) -> $t { self.simd_ge(o) }
                fn eq(self, o: Self) -> $t { self.simd_eq(o) }
            }
            // With AVX-512 a blend takes its condition from a mask register, so `wide`'s
            // select converts the vector mask first (vpmovd2m, then vblendmps: two operations
            // on the critical path of every select). The masks here are whole lanes of ones or
            // zeros, for which the bitwise select is the same function, and AVX-512 does it in
            // one ternary-logic instruction.
            #[cfg(target_feature = "avx512f")]
            #[inline(always)]
            fn select(m: $t, a: Self, b: Self) -> Self {
                m.bitselect(a, b)
            }
            #[cfg(not(target_feature = "avx512f"))]
            #[inline(always)]
            fn select(m: $t, a: Self, b: Self) -> Self {
                m.select(a, b)
            }
        }
    };
}
f32_packet!(F32x8, u32x8, 8);
f32_packet!(F32x16, u32x16, 16);

// ---------------------------------------------------------------------------------------------
// f64: the reference instance

impl Lane for f64 {
    type Mask = bool;

    #[inline(always)]
    fn c(x: f64) -> Self {
        x
    }
    #[inline(always)]
    fn mul_add(self, b: Self, c: Self) -> Self {
        // The reference wants the exact fused result whatever the build.
        libm::fma(self, b, c)
    }
    inline_fns! {
        fn sqrt(self) -> Self { sqrt_f64(self) }
        // Bit operations, as IEEE defines them: libm's calls are not inlined across crates.
        fn abs(self) -> Self { f64::from_bits(self.to_bits() & !(1 << 63)) }
        fn copysign(self, sign: Self) -> Self {
            f64::from_bits((self.to_bits() & !(1 << 63)) | (sign.to_bits() & (1 << 63)))
        }
    }
    scalar_lane!();
}

// ---------------------------------------------------------------------------------------------
// F64x8: packet accumulators

/// Lane-wise the f64 instance's operations, except `mul_add`, which is unfused here: packet
/// accumulators do not use it.
impl Lane for F64x8 {
    type Mask = F64x8;
    const ZERO: Self = F64x8::new([0.0; 8]);
    const ONE: Self = F64x8::new([1.0; 8]);
    const TWO: Self = F64x8::new([2.0; 8]);
    const HALF: Self = F64x8::new([0.5; 8]);
    const EPSILON: Self = F64x8::new([f64::EPSILON; 8]);

    inline_fns! {
        fn c(x: f64) -> Self { F64x8::splat(x) }
        fn mul_add(self, b: Self, c: Self) -> Self { self * b + c }
        fn sqrt(self) -> Self { F64x8::sqrt(self) }
        fn abs(self) -> Self { F64x8::abs(self) }
        fn copysign(self, sign: Self) -> Self { F64x8::abs(self) | (sign & F64x8::splat(-0.0)) }
        fn lt(self, o: Self) -> F64x8 { self.simd_lt(o) }
        fn le(self, o: Self) -> F64x8 { self.simd_le(o) }
        fn gt(self, o: Self) -> F64x8 { self.simd_gt(o) }
        fn ge(self, o: Self) -> F64x8 { self.simd_ge(o) }
        fn eq(self, o: Self) -> F64x8 { self.simd_eq(o) }
        fn select(m: F64x8, a: Self, b: Self) -> Self { m.select(a, b) }
    }
}

/// [`F64x8`]'s operations on each half.
impl Lane for F64x16 {
    type Mask = F64x16;
    const ZERO: Self = F64x16::splat(0.0);
    const ONE: Self = F64x16::splat(1.0);
    const TWO: Self = F64x16::splat(2.0);
    const HALF: Self = F64x16::splat(0.5);
    const EPSILON: Self = F64x16::splat(f64::EPSILON);

    inline_fns! {
        fn c(x: f64) -> Self { F64x16::splat(x) }
        fn mul_add(self, b: Self, c: Self) -> Self { self * b + c }
        fn sqrt(self) -> Self { self.each(F64x8::sqrt) }
        fn abs(self) -> Self { self.each(F64x8::abs) }
        fn copysign(self, sign: Self) -> Self { self.each2(sign, Lane::copysign) }
        fn lt(self, o: Self) -> F64x16 { self.each2(o, Lane::lt) }
        fn le(self, o: Self) -> F64x16 { self.each2(o, Lane::le) }
        fn gt(self, o: Self) -> F64x16 { self.each2(o, Lane::gt) }
        fn ge(self, o: Self) -> F64x16 { self.each2(o, Lane::ge) }
        fn eq(self, o: Self) -> F64x16 { self.each2(o, Lane::eq) }
        fn select(m: F64x16, a: Self, b: Self) -> Self {
            F64x16 { lo: m.lo.select(a.lo, b.lo), hi: m.hi.select(a.hi, b.hi) }
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Lane by lane

/// A lane read and built one lane at a time: the bridge from a packet to per-lane scalar work
/// (a light choice, an accumulator's final division).
pub trait Lanes: Lane {
    /// The number of lanes.
    const WIDTH: usize;
    /// One lane's value: `f32` or `f64`.
    type Scalar: Copy + Default;
    /// Lane `i` (`i` is reduced modulo the width, so there is no panic path).
    fn lane(self, i: usize) -> Self::Scalar;
    /// The lanes f(0), f(1), ….
    fn from_fn(f: impl FnMut(usize) -> Self::Scalar) -> Self;
}

macro_rules! scalar_lanes {
    ($($t:ty),*) => {$(
        impl Lanes for $t {
            const WIDTH: usize = 1;
            type Scalar = $t;
            inline_fns! {
                fn lane(self, _i: usize) -> $t { self }
                fn from_fn(mut f: impl FnMut(usize) -> $t) -> Self { f(0) }
            }
        }
    )*};
}
scalar_lanes!(f32, f64);

macro_rules! packet_lanes {
    ($($t:ty: $s:ty, $n:literal),*) => {$(
        impl Lanes for $t {
            const WIDTH: usize = $n;
            type Scalar = $s;
            inline_fns! {
                fn lane(self, i: usize) -> $s { super::lane_of(&self.to_array(), i) }
                fn from_fn(f: impl FnMut(usize) -> $s) -> Self { <$t>::new(core::array::from_fn(f)) }
            }
        }
    )*};
}
packet_lanes!(F32x8: f32, 8, F64x8: f64, 8, F32x16: f32, 16);

impl Lanes for F64x16 {
    const WIDTH: usize = 16;
    type Scalar = f64;
    #[inline(always)]
    fn lane(self, i: usize) -> f64 {
        let half = if i & 8 == 0 { self.lo } else { self.hi };
        half.lane(i)
    }
    #[inline(always)]
    fn from_fn(mut f: impl FnMut(usize) -> f64) -> Self {
        let lo = F64x8::from_fn(&mut f);
        F64x16 {
            lo,
            hi: F64x8::from_fn(|i| f(i + 8)),
        }
    }
}

/// A lane and the f64 lane of the same width: `f32` → `f64`, [`F32x8`] → [`F64x8`], [`F32x16`]
/// → [`F64x16`], and `f64` → itself. Accumulators sum in it, and set-up terms that cancel in f32 are computed in it.
/// Widening is exact; narrowing rounds each lane to nearest.
pub trait Widen: Lanes {
    /// The f64 lane of the same width.
    type Wide: Lanes<Scalar = f64>;
    /// Each lane as f64, exactly.
    fn widen(self) -> Self::Wide;
    /// Each lane rounded to this lane's precision.
    fn narrow(w: Self::Wide) -> Self;
    /// The same lanes set, as a mask of this lane.
    fn narrow_mask(m: <Self::Wide as Lane>::Mask) -> Self::Mask;
}

impl Widen for f32 {
    type Wide = f64;
    inline_fns! {
        fn widen(self) -> f64 { f64::from(self) }
        fn narrow(w: f64) -> f32 { w as f32 }
        fn narrow_mask(m: bool) -> bool { m }
    }
}

impl Widen for F32x8 {
    type Wide = F64x8;
    inline_fns! {
        fn widen(self) -> F64x8 { F64x8::from_fn(|i| f64::from(self.lane(i))) }
        fn narrow(w: F64x8) -> F32x8 { F32x8::from_fn(|i| w.lane(i) as f32) }
        fn narrow_mask(m: F64x8) -> F32x8 {
            F32x8::narrow(F64x8::select(m, F64x8::ONE, F64x8::ZERO)).gt(F32x8::ZERO)
        }
    }
}

impl Widen for F32x16 {
    type Wide = F64x16;
    #[inline(always)]
    fn widen(self) -> F64x16 {
        let [lo, hi]: [F32x8; 2] = bytemuck::cast(self);
        F64x16 {
            lo: lo.widen(),
            hi: hi.widen(),
        }
    }
    #[inline(always)]
    fn narrow(w: F64x16) -> F32x16 {
        bytemuck::cast([F32x8::narrow(w.lo), F32x8::narrow(w.hi)])
    }
    #[inline(always)]
    fn narrow_mask(m: F64x16) -> F32x16 {
        bytemuck::cast([F32x8::narrow_mask(m.lo), F32x8::narrow_mask(m.hi)])
    }
}

impl Widen for f64 {
    type Wide = f64;
    inline_fns! {
        fn widen(self) -> f64 { self }
        fn narrow(w: f64) -> f64 { w }
        fn narrow_mask(m: bool) -> bool { m }
    }
}
