//! Vectors whose components are lanes, and their conversions to glam's types.

use core::ops::{Add, Neg, Sub};

use super::float::{Lane, Mask};

/// A 2D vector whose components are lanes: `V2<f32>` is one point, `V2<F32x8>` eight.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct V2<L> {
    /// The x components.
    pub x: L,
    /// The y components.
    pub y: L,
}

/// A 3D vector whose components are lanes, stored as structure-of-arrays.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct V3<L> {
    /// The x components.
    pub x: L,
    /// The y components.
    pub y: L,
    /// The z components.
    pub z: L,
}

impl<L: Lane> V2<L> {
    /// The vector (x, y).
    #[inline(always)]
    pub fn new(x: L, y: L) -> Self {
        Self { x, y }
    }
    /// x·o.x + y·o.y, with one [`Lane::mul_add`].
    #[inline(always)]
    pub fn dot(self, o: Self) -> L {
        self.x.mul_add(o.x, self.y * o.y)
    }
    /// x² + y².
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
        Self::new(nan_where(m, self.x), nan_where(m, self.y))
    }
    /// Every component the canonical NaN where `m` is set; for warps whose outputs are NaN only
    /// where an input is, so that `m` (the inputs' NaN) is the whole story. One mask for every
    /// component lets the blend share its constant: two instructions a component in SSE2, where
    /// [`V2::nan_where`] takes five.
    #[inline(always)]
    pub fn nan_if(self, m: L::Mask) -> Self {
        let nan = L::c(f64::NAN);
        Self::new(L::select(m, nan, self.x), L::select(m, nan, self.y))
    }
}

impl<L: Lane> V3<L> {
    /// The vector (x, y, z).
    #[inline(always)]
    pub fn new(x: L, y: L, z: L) -> Self {
        Self { x, y, z }
    }
    /// The vector with every component equal to `v`.
    #[inline(always)]
    pub fn all(v: L) -> Self {
        Self::new(v, v, v)
    }
    /// The dot product, with two [`Lane::mul_add`]s.
    #[inline(always)]
    pub fn dot(self, o: Self) -> L {
        self.x.mul_add(o.x, self.y.mul_add(o.y, self.z * o.z))
    }
    /// The cross product, each component a product minus a product with one [`Lane::mul_add`].
    #[inline(always)]
    pub fn cross(self, o: Self) -> Self {
        Self::new(
            self.y.mul_add(o.z, -(self.z * o.y)),
            self.z.mul_add(o.x, -(self.x * o.z)),
            self.x.mul_add(o.y, -(self.y * o.x)),
        )
    }
    /// |self|².
    #[inline(always)]
    pub fn length_squared(self) -> L {
        self.dot(self)
    }
    /// |self|, a correctly rounded square root of [`length_squared`](Self::length_squared).
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
    /// [`normalize`](Self::normalize) of the vector first divided by its largest component's
    /// magnitude, so that its squared length can neither overflow nor fall into the subnormals
    /// (where `normalize` of a vector 1e-22 long is 1e-3 off unit). Zero, a subnormal largest
    /// component, ±∞ and NaN give NaN components.
    #[inline(always)]
    pub fn normalize_scaled(self) -> Self {
        self.scale(L::ONE / self.largest()).normalize()
    }
    /// `self`, or, in the lanes whose largest component's magnitude lies outside [2⁻⁴⁰, 2⁴⁰],
    /// `self` divided by it: a vector whose squared length neither overflows nor reaches the
    /// subnormals, for a caller that needs only its direction (n·ω/|ω|) and would rather not
    /// pay `normalize`'s divisions. The division happens only where some lane needs it. Zero,
    /// a subnormal largest component and ±∞ give NaN components, as in
    /// [`normalize_scaled`](Self::normalize_scaled).
    #[inline(always)]
    pub fn in_square_range(self) -> Self {
        let m = self.x.abs().max(self.y.abs()).max(self.z.abs());
        let extreme = m.lt(L::c(9.094947017729282e-13)) | m.gt(L::c(1.099511627776e12));
        if extreme.any() {
            Self::select(extreme, self.scale(L::ONE / self.largest()), self)
        } else {
            self
        }
    }
    /// The largest component's magnitude, or NaN where it is zero or subnormal.
    #[inline(always)]
    fn largest(self) -> L {
        let m = self.x.abs().max(self.y.abs()).max(self.z.abs());
        L::select(m.ge(L::c(f32::MIN_POSITIVE as f64)), m, L::c(f64::NAN))
    }
    /// Every component times `s`.
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
        Self::new(
            nan_where(m, self.x),
            nan_where(m, self.y),
            nan_where(m, self.z),
        )
    }
    /// Every component the canonical NaN where `m` is set (see [`V2::nan_if`]).
    #[inline(always)]
    pub fn nan_if(self, m: L::Mask) -> Self {
        let nan = L::c(f64::NAN);
        Self::new(
            L::select(m, nan, self.x),
            L::select(m, nan, self.y),
            L::select(m, nan, self.z),
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

/// Conversions between glam's vectors of one precision and the vectors of that scalar lane.
macro_rules! glam_conversions {
    ($v2:ty, $v3:ty, $lane:ty) => {
        impl From<$v2> for V2<$lane> {
            #[inline(always)]
            fn from(v: $v2) -> Self {
                Self::new(v.x, v.y)
            }
        }
        impl From<V2<$lane>> for $v2 {
            #[inline(always)]
            fn from(v: V2<$lane>) -> Self {
                <$v2>::new(v.x, v.y)
            }
        }
        impl From<$v3> for V3<$lane> {
            #[inline(always)]
            fn from(v: $v3) -> Self {
                Self::new(v.x, v.y, v.z)
            }
        }
        impl From<V3<$lane>> for $v3 {
            #[inline(always)]
            fn from(v: V3<$lane>) -> Self {
                <$v3>::new(v.x, v.y, v.z)
            }
        }
    };
}

glam_conversions!(glam::Vec2, glam::Vec3, f32);
glam_conversions!(glam::DVec2, glam::DVec3, f64);

/// The canonical NaN where `m` is set or `x` is NaN, else `x`.
#[inline(always)]
fn nan_where<L: Lane>(m: L::Mask, x: L) -> L {
    L::select(m | x.is_nan(), L::c(f64::NAN), x)
}

/// The glam-facing conversions of one packet width's vectors (`splat`, `to_array`, `lane`,
/// `From` an array of glam vectors), the same text for eight and sixteen lanes, invoked by
/// `x8` and `x16`: `packet_vectors!(F32x8, 8)`.
macro_rules! packet_vectors {
    ($f:ident, $n:literal) => {
        impl V2<$f> {
            /// Every lane equal to `v`.
            #[inline(always)]
            pub fn splat(v: glam::Vec2) -> Self {
                Self::new($f::splat(v.x), $f::splat(v.y))
            }
            /// The lanes as glam vectors.
            #[inline]
            pub fn to_array(self) -> [glam::Vec2; $n] {
                $crate::lane::zip_map(self.x.to_array(), self.y.to_array(), glam::Vec2::new)
            }
            /// Lane `i` as a glam vector (i below the width; larger i wrap).
            #[inline]
            pub fn lane(self, i: usize) -> glam::Vec2 {
                let at = |v: $f| $crate::lane::lane_of(&v.to_array(), i);
                glam::Vec2::new(at(self.x), at(self.y))
            }
        }

        impl From<[glam::Vec2; $n]> for V2<$f> {
            #[inline]
            fn from(a: [glam::Vec2; $n]) -> Self {
                Self::new($f::new(a.map(|v| v.x)), $f::new(a.map(|v| v.y)))
            }
        }

        impl V3<$f> {
            /// Every lane equal to `v`.
            #[inline(always)]
            pub fn splat(v: glam::Vec3) -> Self {
                Self::new($f::splat(v.x), $f::splat(v.y), $f::splat(v.z))
            }
            /// The lanes as glam vectors.
            #[inline]
            pub fn to_array(self) -> [glam::Vec3; $n] {
                let xy = $crate::lane::zip_map(self.x.to_array(), self.y.to_array(), |x, y| (x, y));
                $crate::lane::zip_map(xy, self.z.to_array(), |(x, y), z| glam::Vec3::new(x, y, z))
            }
            /// Lane `i` as a glam vector (i below the width; larger i wrap).
            #[inline]
            pub fn lane(self, i: usize) -> glam::Vec3 {
                let at = |v: $f| $crate::lane::lane_of(&v.to_array(), i);
                glam::Vec3::new(at(self.x), at(self.y), at(self.z))
            }
        }

        impl From<[glam::Vec3; $n]> for V3<$f> {
            #[inline]
            fn from(a: [glam::Vec3; $n]) -> Self {
                Self::new(
                    $f::new(a.map(|v| v.x)),
                    $f::new(a.map(|v| v.y)),
                    $f::new(a.map(|v| v.z)),
                )
            }
        }
    };
}
pub(crate) use packet_vectors;
