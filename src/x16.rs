//! The sixteen-wide packet types: sixteen lanes of f32 in structure-of-arrays form, with the same
//! conversions as [`x8`](crate::x8)'s.
//!
//! With AVX-512 an [`F32x16`] is one register. Without it, `wide` runs each operation on two
//! eight-wide halves, and every function still gives, in lane *i*, the scalar result on lane
//! *i*'s input, bit for bit. There the long algorithms run as two eight-wide calls
//! ([`Split`](crate::point::Split)), which keeps their intermediates in registers: the free
//! functions of the spherical, bilinear and projected polygons, the projected cap and the
//! spherical ellipse, a light's `sample`, `pdf` and `hit` at a point, the Phong BSDF, the set-ups
//! of the spherical triangle and rectangle (and so of the bilinear forms built on them) and of a
//! sphere light's projected cap, and the polygons' f64 plane and area terms wherever they run.
//! Everything else runs the sixteen lanes together: the short warps, the other set-ups (the
//! spherical ellipse's, the projected polygons'), the rest of a prepared form's queries
//! (`SphericalTriangle<Vec3x16>`, a light prepared at a point), which would copy their set-up into
//! halves at every query, and the estimator around them.
//!
//! ```
//! use glam::Vec2;
//! use mcsample::warp;
//! use mcsample::x16::Vec2x16;
//!
//! let u = Vec2::new(0.3, 0.7);
//! let sixteen = warp::cosine_hemisphere(Vec2x16::splat(u));
//! assert_eq!(sixteen.lane(13), warp::cosine_hemisphere(u));
//! ```

pub use crate::lane::{F32x16, U32x16};
use crate::lane::{V2, V3, packet_vectors};

/// Sixteen 2D vectors, one per lane.
pub type Vec2x16 = V2<F32x16>;
/// Sixteen 3D vectors, one per lane.
pub type Vec3x16 = V3<F32x16>;

packet_vectors!(F32x16, 16);
