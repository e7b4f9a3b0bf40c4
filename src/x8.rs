//! The public packet types: eight lanes of f32 in structure-of-arrays form.
//!
//! `Vec2x8` and `Vec3x8` are the packet instances of the crate's generic vectors, so their lanes
//! are public fields (`v.x` is an [`F32x8`] holding eight x components).

use glam::{Vec2, Vec3};

pub use crate::lane::{F32x8, U32x8};
use crate::lane::{V2, V3, lane_of, zip_map};
/// Eight 2D vectors, one per lane.
pub type Vec2x8 = V2<F32x8>;
/// Eight 3D vectors, one per lane.
pub type Vec3x8 = V3<F32x8>;

impl Vec2x8 {
    /// Every lane equal to `v`.
    #[inline(always)]
    pub fn splat(v: Vec2) -> Self {
        Self::new(F32x8::splat(v.x), F32x8::splat(v.y))
    }
    /// The eight lanes as glam vectors.
    #[inline]
    pub fn to_array(self) -> [Vec2; 8] {
        zip_map(self.x.to_array(), self.y.to_array(), Vec2::new)
    }
    /// Lane `i` as a glam vector (0 ≤ i < 8; larger i wrap).
    #[inline]
    pub fn lane(self, i: usize) -> Vec2 {
        Vec2::new(
            lane_of(&self.x.to_array(), i),
            lane_of(&self.y.to_array(), i),
        )
    }
}

impl From<[Vec2; 8]> for Vec2x8 {
    #[inline]
    fn from(a: [Vec2; 8]) -> Self {
        Self::new(F32x8::new(a.map(|v| v.x)), F32x8::new(a.map(|v| v.y)))
    }
}

impl Vec3x8 {
    /// Every lane equal to `v`.
    #[inline(always)]
    pub fn splat(v: Vec3) -> Self {
        Self::new(F32x8::splat(v.x), F32x8::splat(v.y), F32x8::splat(v.z))
    }
    /// The eight lanes as glam vectors.
    #[inline]
    pub fn to_array(self) -> [Vec3; 8] {
        let xy = zip_map(self.x.to_array(), self.y.to_array(), |x, y| (x, y));
        zip_map(xy, self.z.to_array(), |(x, y), z| Vec3::new(x, y, z))
    }
    /// Lane `i` as a glam vector (0 ≤ i < 8; larger i wrap).
    #[inline]
    pub fn lane(self, i: usize) -> Vec3 {
        let at = |v: F32x8| lane_of(&v.to_array(), i);
        Vec3::new(at(self.x), at(self.y), at(self.z))
    }
}

impl From<[Vec3; 8]> for Vec3x8 {
    #[inline]
    fn from(a: [Vec3; 8]) -> Self {
        Self::new(
            F32x8::new(a.map(|v| v.x)),
            F32x8::new(a.map(|v| v.y)),
            F32x8::new(a.map(|v| v.z)),
        )
    }
}
