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
//! report measures them ([`quality::rmse_slope`]); `tests/seq_convergence.rs` holds the targets.
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
//! [`quality`] measures point sets: L2-star discrepancy and the (0, m, 2)-net property.

mod camera;
mod hash;
pub mod quality;
mod sobol;
mod stratify;

use glam::Vec2;

pub use crate::lane::U32Lane;
pub use camera::PixelFilter;
pub use hash::hash3;
pub use stratify::MAX_STRATA;

/// The `index`-th value of the independent uniform stream `(dim, seed)`: [`hash3`]`(index, dim,
/// seed)` as a 24-bit float in [0, 1).
///
/// Distinct indices give distinct values of the 32-bit hash (it is a bijection of `index` for a
/// fixed `(dim, seed)`), so the 24-bit outputs repeat only where 256 hashes share their top bits.
#[inline]
pub fn independent(index: u32, dim: u32, seed: u32) -> f32 {
    hash::hash3_lane(index, dim, seed).to_unit_f32()
}

/// One point of a stratified set of `count` strata of [0, 1): index i lands in stratum
/// π(i mod count), π a hashed permutation of the round ⌊i/count⌋ and of `(dim, seed)`, with a
/// hashed jitter inside it.
///
/// Each dimension has its own permutation, so reading several dimensions of the same indices gives
/// a Latin hypercube ([`latin_hypercube`] is this function under the name of that property).
/// `count` is clamped to [1, [`MAX_STRATA`]]; every index, including 2³² − 1, gives a value in
/// [0, 1).
#[inline]
pub fn stratified(index: u32, count: u32, dim: u32, seed: u32) -> f32 {
    stratify::stratified(index, count, dim, seed)
}

/// One point of a Latin hypercube of `count` points: dimension `dim` of point `index`. Every
/// dimension is stratified into `count` strata, each visited once per round of `count` indices,
/// with independent permutations per dimension. The same function as [`stratified`].
#[inline]
pub fn latin_hypercube(index: u32, count: u32, dim: u32, seed: u32) -> f32 {
    stratify::stratified(index, count, dim, seed)
}

/// One point of a jittered nx × ny grid: index i visits cell π(i mod nx·ny), π a hashed
/// permutation of the round and of `(dim, seed)`, at a hashed position inside it.
///
/// `dim` numbers dimension pairs. nx is clamped to [1, 2²³] and ny to [1, 2²³/nx].
#[inline]
pub fn jittered_2d(index: u32, nx: u32, ny: u32, dim: u32, seed: u32) -> Vec2 {
    let (x, y) = stratify::jittered_2d(index, nx, ny, dim, seed);
    Vec2::new(x, y)
}

/// One point of a multi-jittered set of nx·ny points (Chiu, Shirley and Wang 1994): jittered on
/// the nx × ny grid, and x and y each one point per 1/(nx·ny) stratum. The fine strata are
/// shuffled by an independent permutation per column and per row, so x and y do not share a
/// pattern.
///
/// `dim` numbers dimension pairs; the grid is clamped as in [`jittered_2d`].
#[inline]
pub fn multi_jittered_2d(index: u32, nx: u32, ny: u32, dim: u32, seed: u32) -> Vec2 {
    let (x, y) = stratify::multi_jittered_2d(index, nx, ny, dim, seed, false);
    Vec2::new(x, y)
}

/// Kensler's correlated multi-jitter (Pixar Technical Memo 13-01, 2013): the structure of
/// [`multi_jittered_2d`], but every column shares one permutation and every row another.
///
/// That makes a cell's fine x-offset a function of its row alone, so the x–y interaction is not
/// stratified: on smooth 2D integrands it converges more slowly than [`multi_jittered_2d`] at
/// large N (the report measures both). Kept because it is the well-known, widely used form.
#[inline]
pub fn cmj_2d(index: u32, nx: u32, ny: u32, dim: u32, seed: u32) -> Vec2 {
    let (x, y) = stratify::multi_jittered_2d(index, nx, ny, dim, seed, true);
    Vec2::new(x, y)
}

/// Owen-scrambled Sobol (Burley 2020): dimension `dim` of point `index`, for `seed`.
///
/// Dimensions 0 and 1 of one seed form a (0, m, 2)-net for every prefix of N = 2ᵐ indices, and
/// every dimension alone is one point per 1/N stratum for such N. Dimensions go in sets of four
/// with independent seeds (padding), so any `dim` works. See the `sobol` module notes in the
/// source for the construction.
#[inline]
pub fn sobol(index: u32, dim: u32, seed: u32) -> f32 {
    sobol::sobol_bits(index, dim, seed).to_unit_f32()
}

/// Dimensions 2·`dim` and 2·`dim` + 1 of [`sobol`]: `sobol_2d(i, 0, seed)` is the net.
#[inline]
pub fn sobol_2d(index: u32, dim: u32, seed: u32) -> Vec2 {
    let d = dim.wrapping_mul(2);
    Vec2::new(sobol(index, d, seed), sobol(index, d.wrapping_add(1), seed))
}

/// One sample of the 5D integral of a pixel (Pharr, CS348b "Monte Carlo II"): a film position,
/// a lens position and a time.
///
/// [`CameraSample::generate`] draws them from three padded Owen-scrambled Sobol pairs keyed by
/// (pixel, seed): film from one pair, lens from another, time from the first dimension of a
/// third. Each pair has its own index shuffle, so no two dimensions share a pattern, and each is a
/// (0, 2)-sequence, so the first 2ᵐ samples of a pixel are stratified in film and in lens.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct CameraSample {
    /// The film position in pixel units: in [pixel, pixel + 1)² for [`PixelFilter::Box`], within
    /// [pixel − ½, pixel + 1½]² for [`PixelFilter::Tent`] (up to f32 rounding of large pixel
    /// coordinates).
    pub film: Vec2,
    /// The lens position on the unit disk (concentric map); scale by the aperture radius.
    pub lens: Vec2,
    /// The time, uniform in [open, close).
    pub time: f32,
}

impl CameraSample {
    /// Sample `index` of `pixel` for `seed`, with film offsets from `filter` and the shutter open
    /// over `shutter = (open, close)`.
    ///
    /// Times are uniform in [open, close) and never equal `close`. A shutter with close ≤ open
    /// gives `open` for every sample (an instantaneous exposure); a NaN or infinite end gives NaN
    /// times, as no uniform time exists. Every index, pixel and seed is valid.
    #[inline]
    pub fn generate(
        pixel: [u32; 2],
        index: u32,
        seed: u32,
        filter: PixelFilter,
        shutter: (f32, f32),
    ) -> Self {
        let (film, lens, time) = camera::camera_sample(pixel, index, seed, filter, shutter);
        Self {
            film: film.into(),
            lens: lens.into(),
            time,
        }
    }
}

/// The packet forms: 8 indices at a time, the same dimension and seed in every lane.
pub mod x8 {
    use super::{PixelFilter, U32Lane, camera, hash, stratify};
    use crate::x8::{F32x8, U32x8, Vec2x8};

    /// [`super::CameraSample`] for 8 indices of one pixel.
    #[derive(Clone, Copy, Debug, PartialEq, Default)]
    pub struct CameraSample {
        /// Film positions in pixel units.
        pub film: Vec2x8,
        /// Lens positions on the unit disk.
        pub lens: Vec2x8,
        /// Times in [open, close).
        pub time: F32x8,
    }

    impl CameraSample {
        /// [`super::CameraSample::generate`] on 8 indices: lane *i* equals the scalar sample of
        /// `index[i]`, bit for bit.
        #[inline]
        pub fn generate(
            pixel: [u32; 2],
            index: U32x8,
            seed: u32,
            filter: PixelFilter,
            shutter: (f32, f32),
        ) -> Self {
            let (film, lens, time) = camera::camera_sample(pixel, index, seed, filter, shutter);
            Self { film, lens, time }
        }
    }

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

    /// [`super::stratified`] on 8 indices, bit for bit.
    #[inline]
    pub fn stratified(index: U32x8, count: u32, dim: u32, seed: u32) -> F32x8 {
        stratify::stratified(index, count, dim, seed)
    }

    /// [`super::latin_hypercube`] on 8 indices, bit for bit.
    #[inline]
    pub fn latin_hypercube(index: U32x8, count: u32, dim: u32, seed: u32) -> F32x8 {
        stratify::stratified(index, count, dim, seed)
    }

    /// [`super::jittered_2d`] on 8 indices, bit for bit.
    #[inline]
    pub fn jittered_2d(index: U32x8, nx: u32, ny: u32, dim: u32, seed: u32) -> Vec2x8 {
        let (x, y) = stratify::jittered_2d(index, nx, ny, dim, seed);
        Vec2x8 { x, y }
    }

    /// [`super::multi_jittered_2d`] on 8 indices, bit for bit.
    #[inline]
    pub fn multi_jittered_2d(index: U32x8, nx: u32, ny: u32, dim: u32, seed: u32) -> Vec2x8 {
        let (x, y) = stratify::multi_jittered_2d(index, nx, ny, dim, seed, false);
        Vec2x8 { x, y }
    }

    /// [`super::cmj_2d`] on 8 indices, bit for bit.
    #[inline]
    pub fn cmj_2d(index: U32x8, nx: u32, ny: u32, dim: u32, seed: u32) -> Vec2x8 {
        let (x, y) = stratify::multi_jittered_2d(index, nx, ny, dim, seed, true);
        Vec2x8 { x, y }
    }

    /// [`super::sobol`] on 8 indices, bit for bit.
    #[inline]
    pub fn sobol(index: U32x8, dim: u32, seed: u32) -> F32x8 {
        super::sobol::sobol_bits(index, dim, seed).to_unit_f32()
    }

    /// [`super::sobol_2d`] on 8 indices, bit for bit.
    #[inline]
    pub fn sobol_2d(index: U32x8, dim: u32, seed: u32) -> Vec2x8 {
        let d = dim.wrapping_mul(2);
        Vec2x8 {
            x: sobol(index, d, seed),
            y: sobol(index, d.wrapping_add(1), seed),
        }
    }
}
