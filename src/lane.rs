//! The lane abstraction: every algorithm in the crate is written once over [`Lane`] (and
//! [`Math`](crate::math::Math), which adds the transcendental functions).
//!
//! Three instances exist:
//!
//! - `f32`: the scalar form that the glam-facing API uses;
//! - [`F32x8`]: the 8-wide packet form;
//! - `f64`: the reference instance. Its transcendental functions delegate to libm, so it measures
//!   the error of the f32 polynomials rather than repeating it.
//!
//! The f32 and F32x8 instances are built so that lane *i* of a packet computation equals the scalar
//! computation on lane *i*'s inputs, bit for bit:
//!
//! - `+ − × ÷` and `sqrt` are IEEE operations, correctly rounded in both widths;
//! - [`Lane::mul_add`] is fused in both widths exactly when the build has FMA (the scalar form goes
//!   through lane 0 of a `wide::f32x4`, which wide fuses under the same condition as `f32x8`);
//! - `min`, `max` and `clamp` are written as compare-and-select, so NaN handling does not depend on
//!   which min/max instruction a target has;
//! - conversions between floats and integers use bit tricks on integer-valued floats, never a
//!   platform conversion whose out-of-range behaviour differs between widths.

use core::fmt::Debug;
use core::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

/// Eight f32 lanes (`wide::f32x8`): the packet lane. Masks are `F32x8` values with all bits set
/// or clear. Re-exported as [`crate::x8::F32x8`].
pub type F32x8 = wide::f32x8;
/// Eight u32 lanes (`wide::u32x8`), the bits of an [`F32x8`]. Re-exported as
/// [`crate::x8::U32x8`].
pub type U32x8 = wide::u32x8;

/// A lane-wise boolean: `bool` for scalar lanes, an all-ones/all-zeros bit pattern for packets.
pub trait Mask: Copy + BitAnd<Output = Self> + BitOr<Output = Self> + Not<Output = Self> {
    /// True if any lane is set.
    fn any(self) -> bool;
    /// True if every lane is set.
    fn all(self) -> bool;
}

impl Mask for bool {
    #[inline(always)]
    fn any(self) -> bool {
        self
    }
    #[inline(always)]
    fn all(self) -> bool {
        self
    }
}

impl Mask for F32x8 {
    #[inline(always)]
    fn any(self) -> bool {
        F32x8::any(self)
    }
    #[inline(always)]
    fn all(self) -> bool {
        F32x8::all(self)
    }
}

/// A floating-point lane: arithmetic, comparisons to masks, selects and the crate's math.
///
/// Generic code uses only these operations, which is what makes the scalar and packet forms agree
/// bit for bit.
pub trait Lane:
    Copy
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

    fn lt(self, o: Self) -> Self::Mask;
    fn le(self, o: Self) -> Self::Mask;
    fn gt(self, o: Self) -> Self::Mask;
    fn ge(self, o: Self) -> Self::Mask;
    fn eq(self, o: Self) -> Self::Mask;

    /// Lane-wise `if m { a } else { b }`.
    fn select(m: Self::Mask, a: Self, b: Self) -> Self;

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
        let m = Self::select(self.gt(hi), hi, self);
        Self::select(m.lt(lo), lo, m)
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

/// Lanes of IEEE single precision, with access to their bits: the instances that run the crate's
/// own polynomials.
pub trait Lane32: Lane {
    /// The integer lane of the same width.
    type U: Copy
        + Add<Output = Self::U>
        + Sub<Output = Self::U>
        + BitAnd<Output = Self::U>
        + BitOr<Output = Self::U>;
    fn to_bits(self) -> Self::U;
    fn from_bits(u: Self::U) -> Self;
    fn u(x: u32) -> Self::U;
    fn shl(u: Self::U, n: u32) -> Self::U;
    fn shr(u: Self::U, n: u32) -> Self::U;
}

// ---------------------------------------------------------------------------------------------
// f32

#[inline(always)]
fn fma_f32(a: f32, b: f32, c: f32) -> f32 {
    // wide fuses f32x4 and f32x8 under the same condition, so lane 0 of an f32x4 is the scalar
    // twin of a packet FMA (one vfmadd…ss with FMA, a multiply and an add without).
    wide::f32x4::splat(a)
        .mul_add(wide::f32x4::splat(b), wide::f32x4::splat(c))
        .to_array()[0]
}

impl Lane for f32 {
    type Mask = bool;

    #[inline(always)]
    fn c(x: f64) -> Self {
        x as f32
    }
    #[inline(always)]
    fn mul_add(self, b: Self, c: Self) -> Self {
        fma_f32(self, b, c)
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        libm::sqrtf(self)
    }
    #[inline(always)]
    fn abs(self) -> Self {
        f32::from_bits(self.to_bits() & 0x7fff_ffff)
    }
    #[inline(always)]
    fn copysign(self, sign: Self) -> Self {
        f32::from_bits((self.to_bits() & 0x7fff_ffff) | (sign.to_bits() & 0x8000_0000))
    }
    #[inline(always)]
    fn lt(self, o: Self) -> bool {
        self < o
    }
    #[inline(always)]
    fn le(self, o: Self) -> bool {
        self <= o
    }
    #[inline(always)]
    fn gt(self, o: Self) -> bool {
        self > o
    }
    #[inline(always)]
    fn ge(self, o: Self) -> bool {
        self >= o
    }
    #[inline(always)]
    fn eq(self, o: Self) -> bool {
        self == o
    }
    #[inline(always)]
    fn select(m: bool, a: Self, b: Self) -> Self {
        if m { a } else { b }
    }
}

impl Lane32 for f32 {
    type U = u32;
    #[inline(always)]
    fn to_bits(self) -> u32 {
        f32::to_bits(self)
    }
    #[inline(always)]
    fn from_bits(u: u32) -> Self {
        f32::from_bits(u)
    }
    #[inline(always)]
    fn u(x: u32) -> u32 {
        x
    }
    #[inline(always)]
    fn shl(u: u32, n: u32) -> u32 {
        u << n
    }
    #[inline(always)]
    fn shr(u: u32, n: u32) -> u32 {
        u >> n
    }
}

// ---------------------------------------------------------------------------------------------
// F32x8

impl Lane for F32x8 {
    type Mask = F32x8;

    #[inline(always)]
    fn c(x: f64) -> Self {
        F32x8::splat(x as f32)
    }
    #[inline(always)]
    fn mul_add(self, b: Self, c: Self) -> Self {
        F32x8::mul_add(self, b, c)
    }
    #[inline(always)]
    fn sqrt(self) -> Self {
        F32x8::sqrt(self)
    }
    #[inline(always)]
    fn abs(self) -> Self {
        F32x8::from_bits(F32x8::to_bits(self) & U32x8::splat(0x7fff_ffff))
    }
    #[inline(always)]
    fn copysign(self, sign: Self) -> Self {
        F32x8::from_bits(
            (F32x8::to_bits(self) & U32x8::splat(0x7fff_ffff))
                | (F32x8::to_bits(sign) & U32x8::splat(0x8000_0000)),
        )
    }
    #[inline(always)]
    fn lt(self, o: Self) -> F32x8 {
        self.simd_lt(o)
    }
    #[inline(always)]
    fn le(self, o: Self) -> F32x8 {
        self.simd_le(o)
    }
    #[inline(always)]
    fn gt(self, o: Self) -> F32x8 {
        self.simd_gt(o)
    }
    #[inline(always)]
    fn ge(self, o: Self) -> F32x8 {
        self.simd_ge(o)
    }
    #[inline(always)]
    fn eq(self, o: Self) -> F32x8 {
        self.simd_eq(o)
    }
    #[inline(always)]
    fn select(m: F32x8, a: Self, b: Self) -> Self {
        m.select(a, b)
    }
}

impl Lane32 for F32x8 {
    type U = U32x8;
    #[inline(always)]
    fn to_bits(self) -> U32x8 {
        F32x8::to_bits(self)
    }
    #[inline(always)]
    fn from_bits(u: U32x8) -> Self {
        F32x8::from_bits(u)
    }
    #[inline(always)]
    fn u(x: u32) -> U32x8 {
        U32x8::splat(x)
    }
    #[inline(always)]
    fn shl(u: U32x8, n: u32) -> U32x8 {
        u << n
    }
    #[inline(always)]
    fn shr(u: U32x8, n: u32) -> U32x8 {
        u >> n
    }
}

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
    #[inline(always)]
    fn sqrt(self) -> Self {
        libm::sqrt(self)
    }
    #[inline(always)]
    fn abs(self) -> Self {
        libm::fabs(self)
    }
    #[inline(always)]
    fn copysign(self, sign: Self) -> Self {
        libm::copysign(self, sign)
    }
    #[inline(always)]
    fn lt(self, o: Self) -> bool {
        self < o
    }
    #[inline(always)]
    fn le(self, o: Self) -> bool {
        self <= o
    }
    #[inline(always)]
    fn gt(self, o: Self) -> bool {
        self > o
    }
    #[inline(always)]
    fn ge(self, o: Self) -> bool {
        self >= o
    }
    #[inline(always)]
    fn eq(self, o: Self) -> bool {
        self == o
    }
    #[inline(always)]
    fn select(m: bool, a: Self, b: Self) -> Self {
        if m { a } else { b }
    }
}

// ---------------------------------------------------------------------------------------------
// Vectors of lanes

/// A 2D vector whose components are lanes: `V2<f32>` is one point, `V2<F32x8>` eight.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct V2<L> {
    pub x: L,
    pub y: L,
}

/// A 3D vector whose components are lanes, stored as structure-of-arrays.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct V3<L> {
    pub x: L,
    pub y: L,
    pub z: L,
}

impl<L: Lane> V2<L> {
    #[inline(always)]
    pub fn new(x: L, y: L) -> Self {
        Self { x, y }
    }
    #[inline(always)]
    pub fn dot(self, o: Self) -> L {
        self.x.mul_add(o.x, self.y * o.y)
    }
    #[inline(always)]
    pub fn length_squared(self) -> L {
        self.dot(self)
    }
    /// Lane-wise select of whole vectors.
    #[inline(always)]
    pub fn select(m: L::Mask, a: Self, b: Self) -> Self {
        Self::new(L::select(m, a.x, b.x), L::select(m, a.y, b.y))
    }
    /// Every NaN component replaced by the canonical NaN ([`Lane::canon`]).
    #[inline(always)]
    pub fn canon(self) -> Self {
        Self::new(self.x.canon(), self.y.canon())
    }
    /// True where any component is NaN.
    #[inline(always)]
    pub fn any_nan(self) -> L::Mask {
        self.x.is_nan() | self.y.is_nan()
    }
    /// Every component the canonical NaN where `m` is set or the component is NaN: how a warp
    /// makes NaN input give NaN in every coordinate, not just in those the NaN reached.
    #[inline(always)]
    pub fn nan_where(self, m: L::Mask) -> Self {
        let nan = L::c(f64::NAN);
        Self::new(
            L::select(m | self.x.is_nan(), nan, self.x),
            L::select(m | self.y.is_nan(), nan, self.y),
        )
    }
}

impl<L: Lane> V3<L> {
    #[inline(always)]
    pub fn new(x: L, y: L, z: L) -> Self {
        Self { x, y, z }
    }
    /// The vector with every component equal to `v`.
    #[inline(always)]
    pub fn all(v: L) -> Self {
        Self::new(v, v, v)
    }
    #[inline(always)]
    pub fn dot(self, o: Self) -> L {
        self.x.mul_add(o.x, self.y.mul_add(o.y, self.z * o.z))
    }
    #[inline(always)]
    pub fn cross(self, o: Self) -> Self {
        Self::new(
            self.y.mul_add(o.z, -(self.z * o.y)),
            self.z.mul_add(o.x, -(self.x * o.z)),
            self.x.mul_add(o.y, -(self.y * o.x)),
        )
    }
    #[inline(always)]
    pub fn length_squared(self) -> L {
        self.dot(self)
    }
    #[inline(always)]
    pub fn length(self) -> L {
        self.dot(self).sqrt()
    }
    /// `self / |self|` by true division (no approximate reciprocal). The zero vector gives NaN
    /// components; callers guard it.
    #[inline(always)]
    pub fn normalize(self) -> Self {
        let len = self.length();
        Self::new(self.x / len, self.y / len, self.z / len)
    }
    #[inline(always)]
    pub fn scale(self, s: L) -> Self {
        Self::new(self.x * s, self.y * s, self.z * s)
    }
    /// Lane-wise select of whole vectors.
    #[inline(always)]
    pub fn select(m: L::Mask, a: Self, b: Self) -> Self {
        Self::new(
            L::select(m, a.x, b.x),
            L::select(m, a.y, b.y),
            L::select(m, a.z, b.z),
        )
    }
    /// Every NaN component replaced by the canonical NaN ([`Lane::canon`]).
    #[inline(always)]
    pub fn canon(self) -> Self {
        Self::new(self.x.canon(), self.y.canon(), self.z.canon())
    }
    /// True where any component is NaN.
    #[inline(always)]
    pub fn any_nan(self) -> L::Mask {
        self.x.is_nan() | self.y.is_nan() | self.z.is_nan()
    }
    /// Every component the canonical NaN where `m` is set or the component is NaN (see
    /// [`V2::nan_where`]).
    #[inline(always)]
    pub fn nan_where(self, m: L::Mask) -> Self {
        let nan = L::c(f64::NAN);
        Self::new(
            L::select(m | self.x.is_nan(), nan, self.x),
            L::select(m | self.y.is_nan(), nan, self.y),
            L::select(m | self.z.is_nan(), nan, self.z),
        )
    }
}

impl<L: Lane> Add for V3<L> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Self::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}
impl<L: Lane> Sub for V3<L> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Self::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}
impl<L: Lane> Neg for V3<L> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Self::new(-self.x, -self.y, -self.z)
    }
}
impl<L: Lane> Add for V2<L> {
    type Output = Self;
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Self::new(self.x + o.x, self.y + o.y)
    }
}
impl<L: Lane> Sub for V2<L> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Self::new(self.x - o.x, self.y - o.y)
    }
}

impl From<glam::Vec2> for V2<f32> {
    #[inline(always)]
    fn from(v: glam::Vec2) -> Self {
        Self::new(v.x, v.y)
    }
}
impl From<V2<f32>> for glam::Vec2 {
    #[inline(always)]
    fn from(v: V2<f32>) -> Self {
        glam::Vec2::new(v.x, v.y)
    }
}
impl From<glam::Vec3> for V3<f32> {
    #[inline(always)]
    fn from(v: glam::Vec3) -> Self {
        Self::new(v.x, v.y, v.z)
    }
}
impl From<V3<f32>> for glam::Vec3 {
    #[inline(always)]
    fn from(v: V3<f32>) -> Self {
        glam::Vec3::new(v.x, v.y, v.z)
    }
}
impl From<glam::DVec2> for V2<f64> {
    #[inline(always)]
    fn from(v: glam::DVec2) -> Self {
        Self::new(v.x, v.y)
    }
}
impl From<V2<f64>> for glam::DVec2 {
    #[inline(always)]
    fn from(v: V2<f64>) -> Self {
        glam::DVec2::new(v.x, v.y)
    }
}
impl From<glam::DVec3> for V3<f64> {
    #[inline(always)]
    fn from(v: glam::DVec3) -> Self {
        Self::new(v.x, v.y, v.z)
    }
}
impl From<V3<f64>> for glam::DVec3 {
    #[inline(always)]
    fn from(v: V3<f64>) -> Self {
        glam::DVec3::new(v.x, v.y, v.z)
    }
}
