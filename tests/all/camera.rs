//! `camera::CameraSample`: packets equal scalars, film/lens/time ranges and stratification, the
//! filters' moments, decorrelated dimensions and pixels (with controls), and the documented
//! shutter edge cases.

use crate::common::lanes;
use glam::Vec2;
use mcsample::camera::{CameraSample, PixelFilter};
use mcsample::seq::{
    self,
    quality::{is_elementary_net, net_violation},
};

const SHUTTER: (f32, f32) = (0.25, 0.75);

fn sample(pixel: [u32; 2], i: u32, seed: u32, filter: PixelFilter) -> CameraSample {
    CameraSample::generate(pixel, i, seed, filter, SHUTTER)
}

#[test]
fn packets_equal_scalars_bit_for_bit() {
    let indices: Vec<u32> = (0..1024).chain([u32::MAX, u32::MAX - 7, 1 << 31]).collect();
    let shutters = [
        SHUTTER,
        (0.0, 1.0),
        (-3e38, 3e38),
        (1.0, 1.0),
        (2.0, 1.0),
        (f32::NAN, 1.0),
        (0.0, f32::INFINITY),
    ];
    let pixels = [[0, 0], [1919, 1079], [u32::MAX, 7], [1 << 24, 3]];
    let mut f = Vec::new();
    for (k, &shutter) in shutters.iter().enumerate() {
        for &pixel in &pixels {
            for filter in [PixelFilter::Box, PixelFilter::Tent] {
                let seed = 17 * k as u32;
                lanes!(
                    &mut f,
                    &format!("{pixel:?} {filter:?} {shutter:?}"),
                    &indices,
                    |i: U| {
                        let s = CameraSample::<U>::generate(pixel, i, seed, filter, shutter);
                        (s.film, s.lens, s.time)
                    }
                );
            }
        }
    }
    assert!(f.is_empty(), "{}", f.join("\n"));
}

#[test]
fn box_film_offsets_are_nets_inside_the_pixel() {
    // Pixel (0, 0) keeps all 24 bits of the offset; elsewhere pixel + offset is rounded to the
    // f32 grid of the pixel coordinate (2⁻²¹ at pixel 5), which can move a point across a fine
    // cell edge, so there the check is the coarser 2^8 net.
    for (pixel, ms) in [
        ([0u32, 0], [4, 8, 12]),
        ([5, 9], [2, 4, 8]),
        ([2, 3], [2, 4, 8]),
    ] {
        for seed in [0, 1, 2] {
            for m in ms {
                let offsets: Vec<Vec2> = (0..1u32 << m)
                    .map(|i| {
                        let s = sample(pixel, i, seed, PixelFilter::Box);
                        s.film - Vec2::new(pixel[0] as f32, pixel[1] as f32)
                    })
                    .collect();
                assert_eq!(
                    net_violation(&offsets, m),
                    None,
                    "{pixel:?} seed {seed} 2^{m}"
                );
            }
        }
    }
}

#[test]
fn times_are_stratified_and_below_close() {
    let n = 1u32 << 10;
    let mut count = vec![0u32; n as usize];
    for i in 0..n {
        let t = sample([3, 4], i, 9, PixelFilter::Box).time;
        assert!((SHUTTER.0..SHUTTER.1).contains(&t), "time {t}");
        let u = (t as f64 - 0.25) / 0.5;
        count[(u * n as f64) as usize] += 1;
    }
    assert!(count.iter().all(|&c| c == 1), "not one time per stratum");
    // The close time is never reached, even with the widest shutter and the last indices.
    for i in (0..4096).map(|k| u32::MAX - k) {
        for shutter in [(0.0, 1.0), (-3e38, 3e38), (1.0, 1.0 + f32::EPSILON)] {
            let t = CameraSample::generate([1, 1], i, 3, PixelFilter::Box, shutter).time;
            assert!(t >= shutter.0 && t < shutter.1, "{t} for {shutter:?}");
        }
    }
}

#[test]
fn shutter_edge_cases_are_as_documented() {
    for i in [0u32, 1, 99, u32::MAX] {
        let time = |shutter| CameraSample::generate([2, 2], i, 4, PixelFilter::Tent, shutter).time;
        assert_eq!(time((1.0, 1.0)), 1.0, "instantaneous");
        assert_eq!(time((2.0, 1.0)), 2.0, "close before open");
        assert!(time((f32::NAN, 1.0)).is_nan());
        assert!(time((0.0, f32::NAN)).is_nan());
        assert!(time((0.0, f32::INFINITY)).is_nan());
        assert!(time((f32::NEG_INFINITY, 0.0)).is_nan());
        // A NaN shutter does not touch the film and lens.
        let s = CameraSample::generate([2, 2], i, 4, PixelFilter::Tent, (f32::NAN, 1.0));
        assert!(s.film.is_finite() && s.lens.is_finite());
    }
}

/// Mean and variance of the film offset from the pixel centre along x, and the mean r² of the
/// lens, over 4096 samples.
fn moments(filter: PixelFilter) -> (f64, f64, f64) {
    let n = 4096;
    let (mut m, mut m2, mut r2) = (0.0, 0.0, 0.0);
    for i in 0..n {
        let s = sample([10, 20], i, 5, filter);
        let d = s.film.x as f64 - 10.5;
        m += d;
        m2 += d * d;
        r2 += s.lens.length_squared() as f64;
        assert!(s.lens.length() <= 1.0 + 1e-6);
    }
    let n = n as f64;
    (m / n, m2 / n - (m / n).powi(2), r2 / n)
}

#[test]
fn filters_and_lens_have_the_right_moments() {
    // Box: variance 1/12; tent of radius 1: variance 1/6; uniform disk: E[r²] = ½. Stratified
    // sampling makes the estimates far tighter than these tolerances, which still separate 1/12
    // from 1/6.
    let (mean, var, r2) = moments(PixelFilter::Box);
    assert!(
        mean.abs() < 1e-3 && (var - 1.0 / 12.0).abs() < 1e-3,
        "box {mean} {var}"
    );
    assert!((r2 - 0.5).abs() < 1e-3, "lens E[r²] = {r2}");
    let (mean, var, _) = moments(PixelFilter::Tent);
    assert!(
        mean.abs() < 1e-3 && (var - 1.0 / 6.0).abs() < 1e-3,
        "tent {mean} {var}"
    );
    for i in 0..4096 {
        let f = sample([10, 20], i, 5, PixelFilter::Tent).film;
        assert!(
            (9.5..=11.5).contains(&f.x) && (19.5..=21.5).contains(&f.y),
            "{f}"
        );
    }
}

/// The correlation of two sequences of values.
fn correlation(a: &[f32], b: &[f32]) -> f64 {
    let n = a.len() as f64;
    let mean = |v: &[f32]| v.iter().map(|&x| x as f64).sum::<f64>() / n;
    let (ma, mb) = (mean(a), mean(b));
    let cov: f64 = a
        .iter()
        .zip(b)
        .map(|(&x, &y)| (x as f64 - ma) * (y as f64 - mb))
        .sum();
    let var = |v: &[f32], m: f64| v.iter().map(|&x| (x as f64 - m).powi(2)).sum::<f64>();
    cov / (var(a, ma) * var(b, mb)).sqrt()
}

#[test]
fn dimensions_and_pixels_are_decorrelated() {
    let n = 4096;
    let samples: Vec<CameraSample> = (0..n)
        .map(|i| sample([7, 7], i, 1, PixelFilter::Box))
        .collect();
    let dims: [Vec<f32>; 5] = [
        samples.iter().map(|s| s.film.x).collect(),
        samples.iter().map(|s| s.film.y).collect(),
        samples.iter().map(|s| s.lens.x).collect(),
        samples.iter().map(|s| s.lens.y).collect(),
        samples.iter().map(|s| s.time).collect(),
    ];
    // Independent dimensions: |ρ| ~ 1/√N ≈ 0.016; 4/√N leaves room for 10 pairs.
    let bound = 4.0 / (n as f64).sqrt();
    for a in 0..5 {
        for b in a + 1..5 {
            let r = correlation(&dims[a], &dims[b]);
            assert!(r.abs() < bound, "dims {a} and {b}: ρ = {r:.4}");
        }
    }
    // Neighbouring pixels do not repeat each other's pattern.
    let next: Vec<f32> = (0..n)
        .map(|i| sample([8, 7], i, 1, PixelFilter::Box).film.x)
        .collect();
    let r = correlation(&dims[0], &next);
    assert!(r.abs() < bound, "pixels (7,7) and (8,7): ρ = {r:.4}");

    // Control: the same Sobol pair read twice (what unpadded dimensions would give) is caught.
    let film: Vec<f32> = (0..n).map(|i| seq::sobol_2d(i, 0, 1).x).collect();
    let lens: Vec<f32> = (0..n)
        .map(|i| 2.0 * seq::sobol_2d(i, 0, 1).x - 1.0)
        .collect();
    assert!(correlation(&film, &lens).abs() > bound);
}

#[test]
fn lens_prefix_is_stratified_before_the_disk_map() {
    // The lens pair is a (0, 2)-sequence before the concentric map; the map is measure-preserving
    // and monotone per quadrant, so stratification survives. Checked through the inverse map on
    // the first 2^8 samples, whose cells are far wider than the inverse's rounding.
    let m = 8;
    let squares: Vec<Vec2> = (0..1u32 << m)
        .map(|i| {
            let lens = sample([0, 0], i, 2, PixelFilter::Box).lens;
            mcsample::warp::concentric_disk_inverse(lens).clamp(Vec2::ZERO, Vec2::splat(0.999_999))
        })
        .collect();
    assert!(is_elementary_net(&squares, m), "lens pair is not a net");
}
