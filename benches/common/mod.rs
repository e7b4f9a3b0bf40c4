//! What the warp benches share: their input points.

use glam::Vec2;
use mcsample::x8::Vec2x8;

/// `n` points of the R2 sequence (a fixed low-discrepancy pattern: deterministic, no RNG), as
/// single points and as packets of eight.
pub fn r2_points(n: usize) -> (Vec<Vec2>, Vec<Vec2x8>) {
    let pts: Vec<Vec2> = (0..n)
        .map(|i| {
            let i = i as f64;
            Vec2::new(
                (0.5 + i * 0.754_877_666_246_692_7).fract() as f32,
                (0.5 + i * 0.569_840_290_998_053_2).fract() as f32,
            )
        })
        .collect();
    let packets = pts
        .chunks_exact(8)
        .map(|c| Vec2x8::from(<[Vec2; 8]>::try_from(c).unwrap()))
        .collect();
    (pts, packets)
}
