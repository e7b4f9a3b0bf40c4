//! The width of a call, picked by the type of its argument.
//!
//! Every warp, frame and pdf is one public generic function over [`Point2`] or [`Point3`], as
//! Mitsuba's `warp.h` is one template for scalar and packet values. The argument's type decides
//! the width and the result's types follow:
//!
//! | width | [`Point2`] | [`Point3`] | lane (scalars: pdfs, parameters) |
//! |---|---|---|---|
//! | one f32 sample | [`glam::Vec2`] | [`glam::Vec3`] | `f32` |
//! | eight f32 samples | [`Vec2x8`](crate::x8::Vec2x8) | [`Vec3x8`](crate::x8::Vec3x8) | [`F32x8`](crate::x8::F32x8) |
//! | sixteen f32 samples | [`Vec2x16`](crate::x16::Vec2x16) | [`Vec3x16`](crate::x16::Vec3x16) | [`F32x16`](crate::x16::F32x16) |
//! | the f64 reference | [`glam::DVec2`] | [`glam::DVec3`] | `f64` |
//!
//! The crate's own generic vectors [`V2`] and [`V3`] implement the traits too (for any lane with
//! [`Math`]), so code generic over a lane calls the same functions.
//!
//! ```
//! use glam::{DVec2, Vec2};
//! use mcsample::warp;
//! use mcsample::x8::Vec2x8;
//!
//! let u = Vec2::new(0.3, 0.7);
//! let one = warp::cosine_hemisphere(u); // glam::Vec3
//! let eight = warp::cosine_hemisphere(Vec2x8::splat(u)); // Vec3x8
//! let reference = warp::cosine_hemisphere(DVec2::new(0.3, 0.7)); // glam::DVec3, via libm
//! assert_eq!(eight.lane(5), one);
//! assert!((reference - one.as_dvec3()).length() < 2e-7);
//! ```

use glam::{DVec2, DVec3, Vec2, Vec3};

use crate::lane::{V2, V3};
use crate::math::Math;

/// A 2D point of one width: [`glam::Vec2`], [`Vec2x8`](crate::x8::Vec2x8),
/// [`Vec2x16`](crate::x16::Vec2x16), [`glam::DVec2`], or the generic [`V2<L>`](V2).
pub trait Point2: Copy {
    /// The lane of the width: `f32`, [`F32x8`](crate::x8::F32x8), [`F32x16`](crate::x16::F32x16)
    /// or `f64`.
    type Lane: Math;
    /// The 3D point of the same width.
    type Vec3: Point3<Lane = Self::Lane, Vec2 = Self>;
    /// The components as lanes.
    fn to_lanes(self) -> V2<Self::Lane>;
    /// The point with components `v`.
    fn from_lanes(v: V2<Self::Lane>) -> Self;
}

/// A 3D point or direction of one width: [`glam::Vec3`], [`Vec3x8`](crate::x8::Vec3x8),
/// [`Vec3x16`](crate::x16::Vec3x16), [`glam::DVec3`], or the generic [`V3<L>`](V3).
pub trait Point3: Copy {
    /// The lane of the width: `f32`, [`F32x8`](crate::x8::F32x8), [`F32x16`](crate::x16::F32x16)
    /// or `f64`.
    type Lane: Math;
    /// The 2D point of the same width.
    type Vec2: Point2<Lane = Self::Lane, Vec3 = Self>;
    /// The components as lanes.
    fn to_lanes(self) -> V3<Self::Lane>;
    /// The point with components `v`.
    fn from_lanes(v: V3<Self::Lane>) -> Self;
}

/// One width's pair of public types, converted through the glam conversions of [`V2`]/[`V3`].
macro_rules! width {
    ($v2:ty, $v3:ty, $lane:ty) => {
        impl Point2 for $v2 {
            type Lane = $lane;
            type Vec3 = $v3;
            #[inline(always)]
            fn to_lanes(self) -> V2<$lane> {
                self.into()
            }
            #[inline(always)]
            fn from_lanes(v: V2<$lane>) -> Self {
                v.into()
            }
        }
        impl Point3 for $v3 {
            type Lane = $lane;
            type Vec2 = $v2;
            #[inline(always)]
            fn to_lanes(self) -> V3<$lane> {
                self.into()
            }
            #[inline(always)]
            fn from_lanes(v: V3<$lane>) -> Self {
                v.into()
            }
        }
    };
}

width!(Vec2, Vec3, f32);
width!(DVec2, DVec3, f64);

impl<L: Math> Point2 for V2<L> {
    type Lane = L;
    type Vec3 = V3<L>;
    #[inline(always)]
    fn to_lanes(self) -> V2<L> {
        self
    }
    #[inline(always)]
    fn from_lanes(v: V2<L>) -> Self {
        v
    }
}

impl<L: Math> Point3 for V3<L> {
    type Lane = L;
    type Vec2 = V2<L>;
    #[inline(always)]
    fn to_lanes(self) -> V3<L> {
        self
    }
    #[inline(always)]
    fn from_lanes(v: V3<L>) -> Self {
        v
    }
}
