//! The crate's own transcendental functions: sin/cos (three forms), atan2, asin/acos, ln, ln_1p,
//! exp and exp_m1, written once over [`Lane32`](crate::lane::Lane32).
//!
//! They are reached through the [`Math`] trait (`x.sin_cos()`, `y.atan2(x)`, …). The `f32` and
//! [`F32x8`] instances run these polynomials; the `f64` instance delegates to
//! libm and is the reference the errors below are measured against.
//!
//! # Bit-for-bit agreement of the widths
//!
//! Every function is one generic body that uses only [`Lane`]/[`Lane32`](crate::lane::Lane32)
//! operations: IEEE `+ − × ÷ √`, [`Lane::mul_add`] (fused in both widths exactly when the build
//! has FMA), compares and selects, and bit operations on the integer lane. There are no branches
//! on values and no platform float↔int conversions (integers come from the bits of a float after
//! adding `1.5·2²³`). So within one build, lane *i* of a packet result equals the scalar result for
//! lane *i*'s input, bit for bit, NaN for NaN; `tests/all/math.rs` checks it on 2¹⁶ inputs per
//! function. Builds with and without FMA give different bits (both within the table).
//!
//! # Error
//!
//! ulp error = |f32 result − f64 reference| / ulp(reference rounded to f32), with ulp(v) = 2^(e−23)
//! for |v| in [2^e, 2^(e+1)) and 2^-149 for subnormal v. The reference is f64 std (`f64::sin`,
//! …); for `sincos_2pi` it is f64 sin/cos of the exactly reduced argument (u − round(u), then
//! quarter turns), i.e. the true sin 2πu of the f32 u, so that exact zeros are exact zeros.
//! The measure is relative everywhere, including near the zeros of sin and cos: inside the stated
//! domains the f32 result carries even a tiny value to within the bound (no absolute-error
//! convention is needed). A result equal to the rounded reference counts 0 (that is how ±∞ and
//! overflow compare).
//!
//! Measured maxima. "All" means every f32 of the domain (the ignored `exhaustive_*` tests of
//! `tests/all/math.rs`); `atan2` was measured on 2³⁰ pairs (random angles and radii over 2^±120,
//! random bit patterns, sweeps along x = ±1 and y = ±1, and pairs near the switch points). The
//! default build is x86-64 without FMA; the second column is `-C target-feature=+avx2,+fma`.
//!
//! | function | domain of the bound | ulp, default | ulp, +avx2,+fma | measured over |
//! |---|---|---|---|---|
//! | `sin_cos` (sin) | \|x\| ≤ 6433 | 1.47 | 1.21 | all f32 |
//! | `sin_cos` (cos) | \|x\| ≤ 6433 | 1.46 | 1.21 | all f32 |
//! | `sincos_2pi` (sin) | every finite u | 1.68 | 1.00 | all f32 with \|u\| ≤ 2²⁴ (beyond, u is an integer) |
//! | `sincos_2pi` (cos) | every finite u | 1.65 | 0.88 | same |
//! | `sincos_pi4` (sin) | t ∈ [−1, 1] | 1.68 | 1.00 | all f32 |
//! | `sincos_pi4` (cos) | t ∈ [−1, 1] | 1.13 | 0.88 | all f32 |
//! | `atan2` | all (y, x) | 1.60 | 1.60 | 2³⁰ pairs (max seen 1.58) |
//! | `asin` | [−1, 1] | 1.94 | 1.90 | all f32 |
//! | `acos` | [−1, 1] | 1.14 | 1.12 | all f32 |
//! | `ln` | (0, +∞), subnormals included | 1.02 | 0.99 | all f32 |
//! | `ln_1p` | (−1, +∞) | 1.07 | 1.06 | all f32 |
//! | `exp` | every finite x (subnormal results included) | 1.01 | 1.04 | all f32 |
//! | `exp_m1` | every finite x | 1.35 | 1.33 | all f32 |
//!
//! Where the extra error comes from: without FMA, a product rounds before it is added, and where
//! the result lies in the binade below the product (sin(πt/4) just under ½ while (π/4)·t is just
//! over), that rounding is worth a whole ulp of the result (`sincos_2pi`, `sincos_pi4`). `asin`
//! above ½ inherits half an ulp of √((1−|x|)/2). `atan2` inherits the rounding of its quotient.
//!
//! # Domains and special values
//!
//! - `sin_cos(x)`: the bound holds for |x| ≤ 6433 (quadrant index below 2¹², where the 4-part
//!   π/2 reduction is exact). For 6433 < |x| ≤ 2²² the result is finite, in [−1, 1], with an absolute
//!   error below |x|·2^-24 (half an ulp of x; far smaller with FMA). For |x| > 2²² (where an ulp of
//!   x is at least half a radian) the result is (±0, 1). sin(±0) = ±0. ±∞ and NaN give NaN.
//! - `sincos_2pi(u)`: the reduction is exact for every finite u. Integers give exactly (+0, 1),
//!   half-integers (+0, −1), quarter turns (±1, +0). sin is odd and cos even in u, bit for bit,
//!   except that the exact zeros of sin are +0 for either sign of u (u = −0 gives (+0, 1)).
//!   ±∞ and NaN give NaN.
//! - `sincos_pi4(t)`: no range reduction; outside [−1, 1] the polynomials are evaluated as they
//!   are (not sin and cos, and not guaranteed finite for huge t). sin(±0) = ±0; NaN gives NaN.
//! - `atan2(y, x)` follows IEEE/C: atan2(±0, +0) = ±0, atan2(±0, −0) = ±π, atan2(±0, x<0) = ±π,
//!   atan2(y≠0, ±0) = ±π/2, atan2(±∞, +∞) = ±π/4, atan2(±∞, −∞) = ±3π/4, atan2(±∞, finite) =
//!   ±π/2, atan2(finite, +∞) = ±0, atan2(finite, −∞) = ±π (the sign is y's). NaN in either
//!   argument gives NaN. Never NaN otherwise, including at (0, 0).
//! - `asin`, `acos`: NaN for |x| > 1 (±∞ included) and NaN. asin(±0) = ±0, asin(±1) = ±π/2,
//!   acos(1) = +0, acos(−1) = π (all as rounded f32).
//! - `ln`: ln(±0) = −∞, ln(x < 0) = NaN (−∞ included), ln(+∞) = +∞, ln(1) = +0, NaN gives NaN.
//!   Subnormal inputs are scaled by 2²⁴ first and stay within the bound.
//! - `ln_1p`: ln_1p(−1) = −∞, NaN below −1 (−∞ included), ln_1p(+∞) = +∞, and x itself for
//!   |x| < 2^-25 (±0 and subnormals included). NaN gives NaN.
//! - `exp`: +∞ from 88.72284 on (the first f32 whose eˣ rounds past `f32::MAX`; 88.72283 is
//!   finite); results below 2^-126 are subnormal, scaled in two steps and rounded once; +0 for
//!   x ≤ −103.98 (and at −∞); exp(±0) = 1. NaN gives NaN.
//! - `exp_m1`: x itself for |x| < 2^-25 (±0 and subnormals included); exactly −1 for x ≤ −17.4
//!   (and at −∞); +∞ from 88.72284 on. NaN gives NaN.
//!
//! # Methods and cost
//!
//! Coefficients are minimax fits for relative error with the f32 rounding of each coefficient
//! taken into account. Counts are lane operations per call (`mul_add` is one FMA with +fma, a
//! multiply and an add without); bit operations include `abs` (1) and `copysign` (3).
//!
//! | function | method | ops | of which mul_add | div/sqrt |
//! |---|---|---|---|---|
//! | `sin_cos` | j = round(2x/π); r = x − j·π/2 with a 4-part Cody–Waite constant (three 12-bit parts and an f32 tail, so j·C₁, j·C₂, j·C₃ are exact without FMA for \|j\| < 2¹²) and Fast2Sum to round r once and keep its remainder; degree-7 sin and degree-8 cos in r; quadrant from the bits of j | ~49 | 10 | — |
//! | `sincos_2pi` | r = u − round(u), q = round(4r), f = 4r − q (all exact); the `sincos_pi4` polynomials with coefficients scaled to quarter turns; the quadrant by an exact rotation (products with 0 and ±1), not selects; `sincos_2pi_unit` for u ∈ [0, 1] rotates by q = round(4u) ∈ {0, …, 4} quarter turns with no reduction | ~38 (~31 unit) | 8 | — |
//! | `sincos_pi4` | degree-7 sin with π/4 split in two f32, degree-8 cos | 10 | 8 | — |
//! | `atan2` | t = min/max, or (min − max)/(min + max) above ½ (one division either way); degree-11 odd polynomial on \|t\| ≤ ½; octant fix as k·π/4 ± atan t with π/4 in two parts | ~49 | 6 | 1 div |
//! | `asin` / `acos` | degree-11 odd polynomial on [0, ½]; above ½ the half-angle form with √((1−\|x\|)/2) | ~22 / ~26 | 6 / 7 | 1 sqrt |
//! | `ln` | exponent and mantissa in [√½, √2) from the bits; ln(1+f) = f + f²·Q(f), degree 10; e·ln2 in two parts with Fast2Sum | ~36 | 9 | — |
//! | `ln_1p` | u = 1 + x and its exact rounding error c; the `ln` kernel on x itself when u has exponent 0, else on u plus c/u ≈ c·2^-e·(1 − f + f²) | ~53 | 12 | — |
//! | `exp` | n = round(x·log₂e); r = x − n·ln2 (two parts); degree-6 expm1(r); 2ⁿ from bits in two factors | ~25 | 7 | — |
//! | `exp_m1` | as exp, keeping r's rounding error; 2·(2ⁿ⁻¹·(r + small) + (2ⁿ⁻¹ − ½)) | ~27 | 9 | — |
pub mod asin;
pub mod atan;
pub mod exp;
pub mod log;
pub mod trig;

use crate::lane::{F32x8, F32x16, Lane, Widen, inline_fns};

/// The transcendental functions of a lane: the crate's own polynomials for `f32`, [`F32x8`] and
/// [`F32x16`],
/// libm for the `f64` reference. Warps are generic over `L: Math`.
pub trait Math: Widen {
    /// The lane a long algorithm runs at: half this width where the build runs this width as two
    /// halves ([`F32x8`] for [`F32x16`] without AVX-512), else `Self`
    /// ([`Split`](crate::point::Split)).
    type Half: Math;
    /// True where the width runs as two halves.
    const SPLIT: bool;
    /// Lanes 0..w/2 and w/2..w; where the width runs whole, `self` twice.
    fn halves(self) -> (Self::Half, Self::Half);
    /// The lane whose halves are `lo` and `hi`; where the width runs whole, `lo`.
    fn join(lo: Self::Half, hi: Self::Half) -> Self;
    /// A mask's halves, lane for lane as [`halves`](Self::halves).
    fn mask_halves(m: Self::Mask) -> (<Self::Half as Lane>::Mask, <Self::Half as Lane>::Mask);
    /// The mask whose halves are `lo` and `hi`, as [`join`](Self::join).
    fn mask_join(lo: <Self::Half as Lane>::Mask, hi: <Self::Half as Lane>::Mask) -> Self::Mask;
    /// sin and cos, within the table's bound for |x| ≤ 6433.
    fn sin_cos(self) -> (Self, Self);
    /// sin and cos of 2π·self, with exact range reduction in `self`.
    fn sincos_2pi(self) -> (Self, Self);
    /// [`sincos_2pi`](Math::sincos_2pi) for self ∈ [0, 1] (the warps' clamped u), bit for bit,
    /// without the reduction that larger arguments need. Outside [0, 1] it is not the same
    /// function: call `sincos_2pi` there.
    fn sincos_2pi_unit(self) -> (Self, Self);
    /// sin and cos of (π/4)·self for self in [−1, 1], with no range reduction.
    fn sincos_pi4(self) -> (Self, Self);
    /// Four-quadrant arctangent of `self / x`, in [−π, π].
    fn atan2(self, x: Self) -> Self;
    /// asin on [−1, 1]; NaN outside.
    fn asin(self) -> Self;
    /// acos on [−1, 1]; NaN outside.
    fn acos(self) -> Self;
    /// Natural logarithm.
    fn ln(self) -> Self;
    /// e^self.
    fn exp(self) -> Self;
    /// ln(1 + self), accurate near 0.
    fn ln_1p(self) -> Self;
    /// e^self − 1, accurate near 0.
    fn exp_m1(self) -> Self;
}

/// The f32 lanes run the same generic polynomials, which is what makes them agree bit for bit.
macro_rules! own_math {
    ($t:ty, $halves:ident) => {
        impl Math for $t {
            $halves!($t);
            inline_fns! {
                fn sin_cos(self) -> (Self, Self) { trig::sin_cos(self) }
                fn sincos_2pi(self) -> (Self, Self) { trig::sincos_2pi(self) }
                fn sincos_2pi_unit(self) -> (Self, Self) { trig::sincos_2pi_unit(self) }
                fn sincos_pi4(self) -> (Self, Self) { trig::sincos_pi4(self) }
                fn atan2(self, x: Self) -> Self { atan::atan2(self, x) }
                fn asin(self) -> Self { asin::asin(self) }
                fn acos(self) -> Self { asin::acos(self) }
                fn ln(self) -> Self { log::ln(self) }
                fn exp(self) -> Self { exp::exp(self) }
                fn ln_1p(self) -> Self { log::ln_1p(self) }
                fn exp_m1(self) -> Self { exp::exp_m1(self) }
            }
        }
    };
}

/// [`Math`]'s halves for a width that runs whole.
macro_rules! whole {
    ($t:ty) => {
        type Half = $t;
        const SPLIT: bool = false;
        inline_fns! {
            fn halves(self) -> ($t, $t) { (self, self) }
            fn join(lo: $t, _hi: $t) -> $t { lo }
            fn mask_halves(m: <$t as Lane>::Mask) -> (<$t as Lane>::Mask, <$t as Lane>::Mask) {
                (m, m)
            }
            fn mask_join(lo: <$t as Lane>::Mask, _hi: <$t as Lane>::Mask) -> <$t as Lane>::Mask {
                lo
            }
        }
    };
}
/// [`F32x16`]'s halves without AVX-512: two [`F32x8`], which is how `wide` stores it.
#[cfg(not(target_feature = "avx512f"))]
macro_rules! halves16 {
    ($t:ty) => {
        type Half = F32x8;
        const SPLIT: bool = true;
        inline_fns! {
            fn halves(self) -> (F32x8, F32x8) { crate::lane::halves16(self) }
            fn join(lo: F32x8, hi: F32x8) -> F32x16 { crate::lane::join16(lo, hi) }
            // The packets' masks are lanes of all-ones or zero bits: they split as lanes do.
            fn mask_halves(m: F32x16) -> (F32x8, F32x8) { crate::lane::halves16(m) }
            fn mask_join(lo: F32x8, hi: F32x8) -> F32x16 { crate::lane::join16(lo, hi) }
        }
    };
}
/// With AVX-512 an [`F32x16`] is one register and runs whole.
#[cfg(target_feature = "avx512f")]
macro_rules! halves16 {
    ($t:ty) => {
        whole!($t);
    };
}

own_math!(f32, whole);
own_math!(F32x8, whole);
own_math!(F32x16, halves16);

/// The reference instance: libm in f64.
impl Math for f64 {
    whole!(f64);
    #[inline(always)]
    fn sin_cos(self) -> (Self, Self) {
        libm::sincos(self)
    }
    #[inline]
    fn sincos_2pi(self) -> (Self, Self) {
        // Reduce exactly in u before scaling, as the f32 instances do, so that u = 1 gives
        // exactly (0, 1) in the reference too.
        let r = self - libm::round(self);
        libm::sincos(core::f64::consts::TAU * r)
    }
    #[inline]
    fn sincos_2pi_unit(self) -> (Self, Self) {
        self.sincos_2pi()
    }
    inline_fns! {
        fn sincos_pi4(self) -> (Self, Self) { libm::sincos(core::f64::consts::FRAC_PI_4 * self) }
        fn atan2(self, x: Self) -> Self { libm::atan2(self, x) }
        fn asin(self) -> Self { libm::asin(self) }
        fn acos(self) -> Self { libm::acos(self) }
        fn ln(self) -> Self { libm::log(self) }
        fn exp(self) -> Self { libm::exp(self) }
        fn ln_1p(self) -> Self { libm::log1p(self) }
        fn exp_m1(self) -> Self { libm::expm1(self) }
    }
}

/// `1.5 · 2²³`: adding and subtracting it rounds an f32 with |x| ≤ 2²² to the nearest integer
/// (ties to even), and the bits of `x + MAGIC` are `0x4b40_0000 + round(x)`.
pub(crate) const MAGIC: f32 = 12_582_912.0;
/// The bits of [`MAGIC`].
pub(crate) const MAGIC_BITS: u32 = 0x4b40_0000;

/// Fast2Sum for a difference (Dekker): `(d, e)` with d = fl(a − b) and d + e = a − b exactly,
/// provided |a| ≥ |b| (or the subtraction is exact).
#[inline(always)]
pub(crate) fn fast_two_diff<L: Lane>(a: L, b: L) -> (L, L) {
    let d = a - b;
    (d, (a - d) - b)
}

/// f32 coefficients written as their bit patterns, so that the polynomial evaluated is exactly
/// the one whose error was measured: a decimal literal would be rounded by the parser.
// Evaluated into constants only: an index out of range there is a compile error, not a
// run-time panic, and the loop bounds keep every index in range.
#[allow(clippy::indexing_slicing)]
pub(crate) const fn bits<const N: usize>(b: [u32; N]) -> [f32; N] {
    let mut out = [0.0; N];
    let mut i = 0;
    while i < N {
        out[i] = f32::from_bits(b[i]);
        i += 1;
    }
    out
}

/// `p[0] + x·(p[1] + x·(p[2] + …))` by Horner's rule with [`Lane::mul_add`].
///
/// The coefficients are f32 values, so `L::c` converts them exactly.
#[inline(always)]
pub(crate) fn horner<L: Lane, const N: usize>(x: L, p: [f32; N]) -> L {
    let mut coefficients = p.iter().rev();
    let Some(&last) = coefficients.next() else {
        return L::ZERO;
    };
    let mut acc = L::c(last as f64);
    for &c in coefficients {
        acc = acc.mul_add(x, L::c(c as f64));
    }
    acc
}

/// `round(x)` (ties to even) for |x| ≤ 2²², by the magic-number add. Beyond that the result is
/// not the nearest integer (for −2²³ < x < −2²² not even an integer): callers bound |x| first.
#[inline(always)]
pub(crate) fn round_small<L: Lane>(x: L) -> L {
    (x + L::c(MAGIC as f64)) - L::c(MAGIC as f64)
}
