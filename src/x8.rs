//! The public packet types: eight lanes of f32 in structure-of-arrays form.
//!
//! `Vec2x8` and `Vec3x8` are the packet instances of the crate's generic vectors, so their lanes
//! are public fields (`v.x` is an [`F32x8`] holding eight x components).

pub use crate::lane::{F32x8, U32x8};
use crate::lane::{V2, V3};

/// Eight 2D vectors, one per lane.
pub type Vec2x8 = V2<F32x8>;
/// Eight 3D vectors, one per lane.
pub type Vec3x8 = V3<F32x8>;

/// The glam-facing conversions of one packet width, the same text for eight and sixteen lanes:
/// `packet_vectors!(F32x8, 8)`.
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

packet_vectors!(F32x8, 8);
