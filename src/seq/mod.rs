//! Sample sequences: stateless generators of points in [0, 1).
//!
//! # Contract
//!
//! - Every generator is a pure function of `(index, dimension, seed)`: no state, no tables built
//!   at run time, nothing allocated.
//! - Outputs are f32 in [0, 1) with 24 significant bits: the generator's 32-bit value `x` becomes
//!   `(x >> 8) · 2⁻²⁴`, which is never 1.0, including at index 2³² − 1 (whereas `x · 2⁻³²` rounds
//!   to 1.0 for `x ≥ 2³² − 128`).
//! - The scalar functions take a `u32` index; their twins in [`x8`] take a
//!   [`U32x8`](crate::x8::U32x8) of indices with the same scalar `u32` dimension and seed, and
//!   lane *i* of the packet result equals the scalar result on lane *i*'s index, bit for bit.
//!   Both are one generic function over [`U32Lane`].
//!
//! # Generators
//!
//! - [`independent`]: a counter-based hash of `(index, dimension, seed)`; every dimension and seed
//!   is an independent-looking uniform stream (plain Monte Carlo, variance ∝ N⁻¹).
//!
//! [`quality`] measures point sets: L2-star discrepancy and the (0, m, 2)-net property.

mod hash;
mod lane;
pub mod quality;

pub use hash::hash3;
pub use lane::U32Lane;

/// The `index`-th value of the independent uniform stream `(dim, seed)`: [`hash3`]`(index, dim,
/// seed)` as a 24-bit float in [0, 1).
///
/// Distinct indices give distinct values of the 32-bit hash (it is a bijection of `index` for a
/// fixed `(dim, seed)`), so the 24-bit outputs repeat only where 256 hashes share their top bits.
#[inline]
pub fn independent(index: u32, dim: u32, seed: u32) -> f32 {
    hash::hash3_lane(index, dim, seed).to_unit_f32()
}

/// The packet forms: 8 indices at a time, the same dimension and seed in every lane.
pub mod x8 {
    use super::{U32Lane, hash};
    use crate::x8::{F32x8, U32x8};

    /// [`super::independent`] on 8 indices: lane *i* equals `independent(index[i], dim, seed)`
    /// bit for bit.
    #[inline]
    pub fn independent(index: U32x8, dim: u32, seed: u32) -> F32x8 {
        hash::hash3_lane(index, dim, seed).to_unit_f32()
    }

    /// [`super::hash3`] on 8 indices.
    #[inline]
    pub fn hash3(index: U32x8, dim: u32, seed: u32) -> U32x8 {
        hash::hash3_lane(index, dim, seed)
    }
}
