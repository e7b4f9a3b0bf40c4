//! The public packet types: eight lanes of f32 in structure-of-arrays form.
//!
//! `Vec2x8` and `Vec3x8` are the packet instances of the crate's generic vectors, so their lanes
//! are public fields (`v.x` is an [`F32x8`] holding eight x components).

pub use crate::lane::{F32x8, U32x8};
use crate::lane::{V2, V3, packet_vectors};

/// Eight 2D vectors, one per lane.
pub type Vec2x8 = V2<F32x8>;
/// Eight 3D vectors, one per lane.
pub type Vec3x8 = V3<F32x8>;

packet_vectors!(F32x8, 8);
