//! The report's sequences table: per generator, scalar, x8 and x16 ns per value, the RMS L2-star
//! discrepancy of 1024 points over 32 seeds, and the RMSE slopes on the Gaussian and the disk
//! indicator over N = 16…4096.

use std::hint::black_box;
use std::time::Instant;

use glam::Vec2;
use mcsample::camera::{CameraSample, PixelFilter};
use mcsample::rng::{Pcg32x8, Pcg32x16};
use mcsample::seq::{self, quality};
use mcsample::x8::{F32x8, U32x8};
use mcsample::x16::{F32x16, U32x16};
use rand_core::Rng;
use rand_pcg::Pcg32;

pub struct SeqRow {
    pub name: &'static str,
    /// A plain loop of scalar calls over consecutive indices (LLVM may vectorise it).
    pub scalar_ns: f64,
    /// Scalar calls one at a time, on indices LLVM cannot see through.
    pub scalar_call_ns: f64,
    pub x8_ns: f64,
    pub x16_ns: f64,
    pub l2_star_1024: f64,
    pub slope_gaussian: f64,
    pub slope_disk: f64,
}

/// Values per timed batch (in cache).
const BATCH: u32 = 4096;

/// The grid nx × ny = N = 2ᵏ of the 2D stratified generators: nx = 2^⌈k/2⌉.
fn grid(n: u32) -> (u32, u32) {
    let k = n.trailing_zeros();
    (1 << k.div_ceil(2), 1 << (k / 2))
}

/// A generator: a 2D point set for the quality measures, and batch kernels for timing that write
/// `BATCH` f32 values (scalar) or `BATCH / 8` and `BATCH / 16` packets, inlined over the batch.
struct Generator {
    name: &'static str,
    points: fn(u32, u32, u32) -> Vec2,
    scalar: fn(&mut [f32], bool),
    packet: Packets,
}

/// The eight- and sixteen-wide batch kernels of a generator.
type Packets = (fn(&mut [F32x8]), fn(&mut [F32x16]));

/// A generator's packet kernels, written once: `$body` fills `$out` (a slice of packets) and
/// names the index packet k as `$lanes(k)`, at both widths.
macro_rules! packets {
    (|$out:ident, $lanes:ident| $body:block) => {
        (
            |$out: &mut [F32x8]| {
                let $lanes = lanes;
                $body
            },
            |$out: &mut [F32x16]| {
                let $lanes = lanes16;
                $body
            },
        )
    };
}

const SEED: u32 = 0x5eed;

/// Index i for a scalar kernel. Opaque indices pass through `black_box`, so LLVM cannot
/// vectorise the loop: that measures the scalar function as a renderer calls it, one sample at a
/// time, while plain indices measure a bulk loop, which LLVM turns into vector code by itself.
fn index(i: usize, opaque: bool) -> u32 {
    if opaque {
        black_box(i as u32)
    } else {
        i as u32
    }
}

/// Index packets 8k..8k+8.
fn lanes(k: usize) -> U32x8 {
    let b = 8 * k as u32;
    U32x8::new([b, b + 1, b + 2, b + 3, b + 4, b + 5, b + 6, b + 7])
}

/// Index packets 16k..16k+16.
fn lanes16(k: usize) -> U32x16 {
    let b = 16 * k as u32;
    U32x16::new(core::array::from_fn(|i| b + i as u32))
}

/// A generator on a grid, from its scalar and packet forms: the quality columns use an nx × ny = N
/// grid, the timings a 64 × 32 grid, two values per index.
macro_rules! grid_generator {
    ($name:literal, $scalar:path, $packet:path) => {
        Generator {
            name: $name,
            points: |i, n, s| {
                let (nx, ny) = grid(n);
                $scalar(i, nx, ny, 0, s)
            },
            scalar: |out, opaque| {
                for (i, o) in out.chunks_exact_mut(2).enumerate() {
                    let p = $scalar(index(i, opaque), 64, 32, 0, SEED);
                    (o[0], o[1]) = (p.x, p.y);
                }
            },
            packet: packets!(|out, lanes| {
                for (k, o) in out.chunks_exact_mut(2).enumerate() {
                    let p = $packet(lanes(k), 64, 32, 0, SEED);
                    (o[0], o[1]) = (p.x, p.y);
                }
            }),
        }
    };
}

/// 1D generators write one value per index; 2D ones two values per index (x then y).
fn generators() -> Vec<Generator> {
    vec![
        Generator {
            name: "independent",
            points: |i, _, s| Vec2::new(seq::independent(i, 0, s), seq::independent(i, 1, s)),
            scalar: |out, opaque| {
                for (i, o) in out.iter_mut().enumerate() {
                    let i = index(i, opaque);
                    *o = seq::independent(i, 0, SEED);
                }
            },
            packet: packets!(|out, lanes| {
                for (k, o) in out.iter_mut().enumerate() {
                    *o = seq::independent(lanes(k), 0, SEED);
                }
            }),
        },
        Generator {
            name: "stratified",
            points: |i, n, s| Vec2::new(seq::stratified(i, n, 0, s), seq::stratified(i, n, 1, s)),
            scalar: |out, opaque| {
                for (i, o) in out.iter_mut().enumerate() {
                    let i = index(i, opaque);
                    *o = seq::stratified(i, BATCH, 0, SEED);
                }
            },
            packet: packets!(|out, lanes| {
                for (k, o) in out.iter_mut().enumerate() {
                    *o = seq::stratified(lanes(k), BATCH, 0, SEED);
                }
            }),
        },
        Generator {
            name: "latin_hypercube",
            points: |i, n, s| {
                Vec2::new(
                    seq::latin_hypercube(i, n, 0, s),
                    seq::latin_hypercube(i, n, 1, s),
                )
            },
            scalar: |out, opaque| {
                for (i, o) in out.iter_mut().enumerate() {
                    let i = index(i, opaque);
                    *o = seq::latin_hypercube(i, BATCH, 1, SEED);
                }
            },
            packet: packets!(|out, lanes| {
                for (k, o) in out.iter_mut().enumerate() {
                    *o = seq::latin_hypercube(lanes(k), BATCH, 1, SEED);
                }
            }),
        },
        grid_generator!("jittered_2d", seq::jittered_2d, seq::jittered_2d),
        grid_generator!(
            "multi_jittered_2d",
            seq::multi_jittered_2d,
            seq::multi_jittered_2d
        ),
        grid_generator!("cmj_2d", seq::cmj_2d, seq::cmj_2d),
        Generator {
            // Dimensions 0–3 in turn, as a 4D consumer reads them: 0 and 1 skip the matrix loop.
            name: "sobol (dims 0-3)",
            points: |i, _, s| Vec2::new(seq::sobol(i, 0, s), seq::sobol(i, 1, s)),
            scalar: |out, opaque| {
                for (i, o) in out.chunks_exact_mut(4).enumerate() {
                    let i = index(i, opaque);
                    for (d, v) in o.iter_mut().enumerate() {
                        *v = seq::sobol(i, d as u32, SEED);
                    }
                }
            },
            packet: packets!(|out, lanes| {
                for (k, o) in out.chunks_exact_mut(4).enumerate() {
                    for (d, v) in o.iter_mut().enumerate() {
                        *v = seq::sobol(lanes(k), d as u32, SEED);
                    }
                }
            }),
        },
        Generator {
            name: "sobol_2d",
            points: |i, _, s| seq::sobol_2d(i, 0, s),
            scalar: |out, opaque| {
                for (i, o) in out.chunks_exact_mut(2).enumerate() {
                    let i = index(i, opaque);
                    let p = seq::sobol_2d(i, 0, SEED);
                    (o[0], o[1]) = (p.x, p.y);
                }
            },
            packet: packets!(|out, lanes| {
                for (k, o) in out.chunks_exact_mut(2).enumerate() {
                    let p = seq::sobol_2d(lanes(k), 0, SEED);
                    (o[0], o[1]) = (p.x, p.y);
                }
            }),
        },
        Generator {
            // Five values per sample: film x, y, lens x, y, time.
            name: "camera_sample (5 values)",
            points: |i, _, s| {
                CameraSample::generate([0, 0], i, s, PixelFilter::Box, (0.0, 1.0)).film
            },
            scalar: |out, opaque| {
                for (i, o) in out.chunks_exact_mut(5).enumerate() {
                    let i = index(i, opaque);
                    let c = CameraSample::generate([3, 4], i, SEED, PixelFilter::Tent, (0.0, 1.0));
                    o.copy_from_slice(&[c.film.x, c.film.y, c.lens.x, c.lens.y, c.time]);
                }
            },
            packet: packets!(|out, lanes| {
                for (k, o) in out.chunks_exact_mut(5).enumerate() {
                    let c = CameraSample::generate(
                        [3, 4],
                        lanes(k),
                        SEED,
                        PixelFilter::Tent,
                        (0.0, 1.0),
                    );
                    o.copy_from_slice(&[c.film.x, c.film.y, c.lens.x, c.lens.y, c.time]);
                }
            }),
        },
    ]
}

/// Median ns per value of the scalar and packet kernels, interleaved in one run: the scalar loop,
/// the scalar calls, x8 and x16.
fn time_kernels(
    quick: bool,
    values: usize,
    mut scalar: impl FnMut(&mut [f32], bool),
    (mut packet, mut packet16): (impl FnMut(&mut [F32x8]), impl FnMut(&mut [F32x16])),
) -> [f64; 4] {
    let mut out = vec![0f32; values];
    let mut out8 = vec![F32x8::ZERO; values / 8];
    let mut out16 = vec![F32x16::ZERO; values / 16];
    let runs = if quick { 9 } else { 41 };
    let target = if quick { 2e-4 } else { 2e-3 };
    let mut reps = 1usize;
    loop {
        let t = Instant::now();
        for _ in 0..reps {
            scalar(black_box(&mut out), false);
        }
        if t.elapsed().as_secs_f64() > target / 4.0 {
            break;
        }
        reps *= 2;
    }
    let (mut ts, mut tc, mut tp, mut tq) = (vec![], vec![], vec![], vec![]);
    for _ in 0..runs {
        let t = Instant::now();
        for _ in 0..reps {
            scalar(black_box(&mut out), false);
        }
        ts.push(t.elapsed().as_secs_f64());
        let t = Instant::now();
        for _ in 0..reps {
            scalar(black_box(&mut out), true);
        }
        tc.push(t.elapsed().as_secs_f64());
        let t = Instant::now();
        for _ in 0..reps {
            packet(black_box(&mut out8));
        }
        tp.push(t.elapsed().as_secs_f64());
        let t = Instant::now();
        for _ in 0..reps {
            packet16(black_box(&mut out16));
        }
        tq.push(t.elapsed().as_secs_f64());
    }
    let med = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2] * 1e9 / (reps * values) as f64
    };
    [med(&mut ts), med(&mut tc), med(&mut tp), med(&mut tq)]
}

/// RMS over 32 seeds of the L2-star discrepancy of the first 1024 points.
fn l2_star_1024(points: fn(u32, u32, u32) -> Vec2) -> f64 {
    let n = 1024;
    let ms: f64 = (0..32)
        .map(|s| {
            let set: Vec<Vec2> = (0..n).map(|i| points(i, n, s)).collect();
            quality::l2_star_discrepancy(&set).powi(2)
        })
        .sum();
    (ms / 32.0).sqrt()
}

fn row(
    quick: bool,
    name: &'static str,
    points: fn(u32, u32, u32) -> Vec2,
    [scalar_ns, scalar_call_ns, x8_ns, x16_ns]: [f64; 4],
) -> SeqRow {
    let seeds = if quick { 16 } else { 64 };
    SeqRow {
        name,
        scalar_ns,
        scalar_call_ns,
        x8_ns,
        x16_ns,
        l2_star_1024: l2_star_1024(points),
        slope_gaussian: quality::rmse_slope(
            points,
            quality::gaussian,
            quality::GAUSSIAN_INTEGRAL,
            4..=12,
            seeds,
        ),
        slope_disk: quality::rmse_slope(
            points,
            quality::disk_indicator,
            quality::DISK_INTEGRAL,
            4..=12,
            seeds,
        ),
    }
}

/// Consecutive pairs of one PCG32 stream per seed, for the quality columns of the RNG row.
fn pcg_points(i: u32, _n: u32, s: u32) -> Vec2 {
    let mut rng = Pcg32::new(s as u64, 0x0a02_bdbf_7bb3_c0a7);
    rng.advance(2 * i as u64);
    let f = |x: u32| (x >> 8) as f32 / 16_777_216.0;
    Vec2::new(f(rng.next_u32()), f(rng.next_u32()))
}

pub fn sequences(quick: bool) -> Vec<SeqRow> {
    let mut rows = vec![];
    for g in generators() {
        // A camera sample is 5 values: 512 samples, or 64 packets of 8, or 32 of 16.
        let values = if g.name.starts_with("camera") {
            5 * 512
        } else {
            BATCH as usize
        };
        let times = time_kernels(quick, values, g.scalar, g.packet);
        rows.push(row(quick, g.name, g.points, times));
    }
    // The packet RNG against eight rand_pcg streams, per value.
    let mut scalars: [Pcg32; 8] = std::array::from_fn(|i| Pcg32::new(i as u64, 7 + i as u64));
    let mut packet = Pcg32x8::new(
        std::array::from_fn(|i| i as u64),
        std::array::from_fn(|i| 7 + i as u64),
    );
    let mut packet16 = Pcg32x16::new(
        std::array::from_fn(|i| i as u64),
        std::array::from_fn(|i| 7 + i as u64),
    );
    let times = time_kernels(
        quick,
        BATCH as usize,
        |out, _| {
            for o in out.chunks_exact_mut(8) {
                for (v, s) in o.iter_mut().zip(scalars.iter_mut()) {
                    *v = (s.next_u32() >> 8) as f32 / 16_777_216.0;
                }
            }
        },
        (
            |out: &mut [F32x8]| {
                for o in out.iter_mut() {
                    *o = packet.next_f32x8();
                }
            },
            |out: &mut [F32x16]| {
                for o in out.iter_mut() {
                    *o = packet16.next_f32x16();
                }
            },
        ),
    );
    rows.push(row(
        quick,
        "pcg32 (8 × rand_pcg | Pcg32x8 | Pcg32x16)",
        pcg_points,
        times,
    ));
    rows
}

/// Per generator (and the PCG32 stream), the RMSE of the N-point estimate of the Gaussian's
/// integral for N = 16…4096, over the same seeds as the slopes: the curves of the RMSE plot.
pub fn rmse_curves(quick: bool) -> Vec<(&'static str, Vec<(f64, f64)>)> {
    let seeds = if quick { 16 } else { 64 };
    type Family = (&'static str, fn(u32, u32, u32) -> Vec2);
    let mut families: Vec<Family> = generators().iter().map(|g| (g.name, g.points)).collect();
    families.push(("pcg32", pcg_points));
    families
        .into_iter()
        .map(|(name, points)| {
            let curve = (4..=12)
                .map(|k| {
                    let n = 1u32 << k;
                    let e = quality::rmse(
                        points,
                        quality::gaussian,
                        quality::GAUSSIAN_INTEGRAL,
                        n,
                        seeds,
                    );
                    (f64::from(n), e)
                })
                .collect();
            (name, curve)
        })
        .collect()
}
