//! Sample sequences: stateless generators of points in [0, 1).
//!
//! # Contract
//!
//! - Every generator is a pure function of `(index, dimension, seed)`: no state, no tables built
//!   at run time, nothing allocated.
//! - Outputs are f32 in [0, 1) with 24 significant bits: the generator's 32-bit value `x` becomes
//!   `(x >> 8) · 2⁻²⁴`, which is never 1.0, including at index 2³² − 1 (whereas `x · 2⁻³²` rounds
//!   to 1.0 for `x ≥ 2³² − 128`).
//! - Each generator is one generic function over the index lane [`U32Lane`](crate::lane::U32Lane): a `u32` index gives
//!   one value (`f32`, or [`glam::Vec2`] for the 2D generators), a [`U32x8`](crate::x8::U32x8)
//!   of indices gives eight ([`F32x8`](crate::x8::F32x8), [`Vec2x8`](crate::x8::Vec2x8)), with
//!   the same scalar `u32` dimension and seed; lane *i* of the packet result equals the scalar
//!   result on lane *i*'s index, bit for bit.
//!
//! # Generators
//!
//! | generator | structure of the first N = count (or nx·ny, or 2ᵐ) indices | RMSE slope, 2D Gaussian |
//! |---|---|---|
//! | [`independent`] | none: a counter-based hash of `(index, dim, seed)` | −0.53 |
//! | [`stratified`], [`latin_hypercube`] | one point per 1/N stratum, in every dimension | −0.60 |
//! | [`jittered_2d`] | one point per cell of the nx × ny grid | −1.02 |
//! | [`multi_jittered_2d`] | jittered, and one point per 1/N stratum of x and of y | −1.05 |
//! | [`cmj_2d`] | the same, with one shared permutation (Kensler) | −0.75 |
//! | [`sobol`], [`sobol_2d`] | dimensions 0 and 1: a (0, m, 2)-net for every N = 2ᵐ | −1.33 |
//!
//! The slopes are of log RMSE against log N on e^{−x²−y²} over N = 16…4096 and 64 seeds, as the
//! report measures them ([`quality::rmse_slope`]); `tests/all/seq/convergence.rs` holds the targets.
//!
//! The stratified families read an index as round ⌊index/N⌋ and position index mod N: each
//! round of N consecutive indices is a complete set, with its own order and jitter. Strata are
//! visited in a hashed order, so any prefix of a round is spread out too. Counts are clamped to
//! [1, [`MAX_STRATA`]] = [1, 2²³] per axis (and nx·ny to 2²³), because finer strata than 2⁻²³
//! cannot each hold a distinct f32 below 1; a count of 0 means 1. Inside those limits a value of
//! stratum s of N is exactly in [s/N, (s+1)/N), not merely up to rounding.
//!
//! The dimension selects an independent pattern; two-dimensional generators take the number of a
//! dimension *pair*, so `sobol_2d(i, d, seed)` is `(sobol(i, 2d, seed), sobol(i, 2d + 1, seed))`.
//!
//! The generators are always inlined: with a constant count or dimension the divisions and key schedules fold away, which an
//! out-of-line call loses (the report measured scalar `stratified` calls 2.7× slower).
//!
//! [`quality`] measures point sets: L2-star discrepancy and the (0, m, 2)-net property.

mod hash;
pub mod quality;
mod samples;
mod sobol;
mod stratify;

pub(crate) use hash::lowbias32;
pub use hash::{hash3, independent};
pub use samples::{Generator, Samples, Sequence};
pub use sobol::{sobol, sobol_2d};
pub use stratify::{
    MAX_STRATA, cmj_2d, jittered_2d, latin_hypercube, multi_jittered_2d, stratified,
};
