//! Camera samples: the lecture's 5D pixel integral (film x, y; lens u, v; time t) from padded
//! Owen-scrambled Sobol pairs, written once over the lanes.

use super::hash::{hash3, lowbias32};
use super::sobol::sobol_bits;
use crate::lane::U32Lane;
use crate::lane::V2;
use crate::math::Math;
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

/// Generic body of the camera samplers: (film, lens, time).
#[inline(always)]
pub(crate) fn camera_sample<U, L>(
    pixel: [u32; 2],
    index: U,
    seed: u32,
    filter: PixelFilter,
    shutter: (f32, f32),
) -> (V2<L>, V2<L>, L)
where
    U: U32Lane<F = L>,
    L: Math,
{
    let [film_seed, lens_seed, time_seed] = pair_seeds(pixel, seed);
    let uniform = |dim: u32, s: u32| sobol_bits(index, dim, s).to_unit_f32();
    let u = V2::new(uniform(0, film_seed), uniform(1, film_seed));
    let (px, py) = (L::c(pixel[0] as f64), L::c(pixel[1] as f64));
    let film = match filter {
        PixelFilter::Box => V2::new(px + u.x, py + u.y),
        PixelFilter::Tent => {
            let half = L::c(0.5);
            V2::new(px + half + tent(u.x), py + half + tent(u.y))
        }
    };
    let lens = concentric_disk(V2::new(uniform(0, lens_seed), uniform(1, lens_seed)));
    // open·(1 − u) + close·u cannot overflow; rounding may land it on `close` or a hair below
    // `open`, which the selects move back inside [open, close). NaN terms fail both compares.
    let (open, close, last) = shutter_terms(shutter.0, shutter.1);
    let (open, close, last) = (L::c(open as f64), L::c(close as f64), L::c(last as f64));
    let t = uniform(0, time_seed);
    let time = open * (L::c(1.0) - t) + close * t;
    let time = L::select(time.ge(close), last, time);
    let time = L::select(time.lt(open), open, time);
    (film, lens, time)
}
