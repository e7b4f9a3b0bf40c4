//! Camera samples: the 5D integral of a pixel (film x, y; lens u, v; time t) from padded
//! Owen-scrambled Sobol pairs, shaped by the warps (Pharr, CS348b "Monte Carlo II").
//!
//! This module stands on [`seq`](crate::seq) and [`warp`](crate::warp), as pbrt keeps its
//! camera samples in the sampler layer above both. [`CameraSample`] is written once over the
//! index lane: `CameraSample<u32>` (the default) is one sample, `CameraSample<U32x8>`
//! eight.

use crate::lane::{U32Lane, V2};
use crate::math::Math;
use crate::seq::{hash3, lowbias32, sobol};
use crate::warp::{concentric_disk, tent};

/// The pixel reconstruction filter that film offsets are drawn from (importance sampling the
/// filter, so every sample has weight 1).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum PixelFilter {
    /// Uniform over the pixel: film = pixel + u, u ∈ [0, 1)².
    #[default]
    Box,
    /// The separable tent of radius 1 pixel around the pixel centre: film = pixel + ½ + tent(u)
    /// per axis, in [pixel − ½, pixel + 1½].
    Tent,
}

/// The three independent Sobol pair seeds of a pixel: film, lens, time. Each pair has its own
/// index shuffle, so the pairs are padded (decorrelated) while each stays a (0, 2)-sequence.
#[inline(always)]
fn pair_seeds(pixel: [u32; 2], seed: u32) -> [u32; 3] {
    let key = hash3(pixel[0], pixel[1], seed);
    [1u32, 2, 3].map(|k| lowbias32(key ^ k.wrapping_mul(0x9e37_79b9)))
}

/// (base, weight of the close time, last time below close) of a shutter, decided once in scalar.
/// NaN or infinite ends give NaN times; a shutter with close ≤ open gives `open` for every sample.
#[inline(always)]
fn shutter_terms(open: f32, close: f32) -> (f32, f32, f32) {
    if !(open.is_finite() && close.is_finite()) {
        (f32::NAN, f32::NAN, f32::NAN)
    } else if close > open {
        (open, close, close.next_down())
    } else {
        (open, open, open)
    }
}

/// One sample of the 5D integral of a pixel (Pharr, CS348b "Monte Carlo II"): a film position,
/// a lens position and a time, for one index (`I = u32`, the default) or eight
/// (`I = U32x8`).
///
/// [`CameraSample::generate`] draws them from three padded Owen-scrambled Sobol pairs keyed by
/// (pixel, seed): film from one pair, lens from another, time from the first dimension of a
/// third. Each pair has its own index shuffle, so no two dimensions share a pattern, and each is a
/// (0, 2)-sequence, so the first 2ᵐ samples of a pixel are stratified in film and in lens.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub struct CameraSample<I: U32Lane = u32> {
    /// The film position in pixel units: in [pixel, pixel + 1)² for [`PixelFilter::Box`], within
    /// [pixel − ½, pixel + 1½]² for [`PixelFilter::Tent`] (up to f32 rounding of large pixel
    /// coordinates).
    pub film: I::Vec2,
    /// The lens position on the unit disk (concentric map); scale by the aperture radius.
    pub lens: I::Vec2,
    /// The time, uniform in [open, close).
    pub time: I::F,
}

impl<I: U32Lane<F = L>, L: Math> CameraSample<I> {
    /// Sample `index` of `pixel` for `seed`, with film offsets from `filter` and the shutter open
    /// over `shutter = (open, close)`. With eight indices, lane *i* equals the sample of
    /// `index[i]`, bit for bit.
    ///
    /// Times are uniform in [open, close) and never equal `close`. A shutter with close ≤ open
    /// gives `open` for every sample (an instantaneous exposure); a NaN or infinite end gives NaN
    /// times, as no uniform time exists. Every index, pixel and seed is valid.
    ///
    /// Always inlined: with a constant pixel, seed and shutter, the per-pixel seeds and shutter
    /// terms fold away (as an out-of-line call, the report measured 16.8 ns a sample, not 9.0).
    #[inline(always)]
    pub fn generate(
        pixel: [u32; 2],
        index: I,
        seed: u32,
        filter: PixelFilter,
        shutter: (f32, f32),
    ) -> Self {
        let [film_seed, lens_seed, time_seed] = pair_seeds(pixel, seed);
        let u = V2::new(sobol(index, 0, film_seed), sobol(index, 1, film_seed));
        let (px, py) = (L::c(pixel[0] as f64), L::c(pixel[1] as f64));
        let film = match filter {
            PixelFilter::Box => V2::new(px + u.x, py + u.y),
            PixelFilter::Tent => {
                let half = L::HALF;
                V2::new(px + half + tent(u.x), py + half + tent(u.y))
            }
        };
        let lens = concentric_disk(V2::new(
            sobol(index, 0, lens_seed),
            sobol(index, 1, lens_seed),
        ));
        // open·(1 − u) + close·u cannot overflow; rounding may land it on `close` or a hair below
        // `open`, which the selects move back inside [open, close). NaN terms fail both compares.
        let (open, close, last) = shutter_terms(shutter.0, shutter.1);
        let (open, close, last) = (L::c(open as f64), L::c(close as f64), L::c(last as f64));
        let t = sobol(index, 0, time_seed);
        let time = open * (L::ONE - t) + close * t;
        let time = L::select(time.ge(close), last, time);
        let time = L::select(time.lt(open), open, time);
        Self {
            film: film.into(),
            lens: lens.into(),
            time,
        }
    }
}
