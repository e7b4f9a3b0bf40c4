//! Sequence and random-number throughput, 4096 values per iteration of every benchmark.
//!
//! - `pcg32`: [`Pcg32x8`] (`next_u32x8`, `next_f32x8`) against eight scalar `rand_pcg::Pcg32`
//!   generators producing the same number of values.
//! - `seq`: every generator of `mcsample::seq`, scalar (`seq/scalar/NAME`, indices 0..4096) and
//!   packet (`seq/x8/NAME`, 512 packets of consecutive indices): `independent`, `stratified` and
//!   `latin_hypercube` (4096 strata), `jittered_2d`, `multi_jittered_2d` and `cmj_2d` (64 × 64
//!   grid), `stratified_n3000` and `multi_jittered_2d_48x48` (non-power-of-two sizes, where
//!   `permute` cycle-walks), `sobol` (dimension 2, which runs the matrix loop; `sobol_dim0` and
//!   `sobol_dim1` skip it) and `sobol_2d` (pair 0). Every scalar entry also runs as
//!   `seq/scalar_call/NAME`, with each index passed through `black_box`: LLVM vectorises a plain
//!   loop of the cheap scalar generators by itself, which a renderer calling them one sample at
//!   a time does not get. A 2D point counts as two values, so the 2D entries produce
//!   8192 values and `Throughput::Elements` is always the number of f32 values: the reported
//!   element rate is per value in every entry. Parameters go through `black_box` once per
//!   iteration, so they are run-time values; results are summed as integer bits.
//! - `sobol_vs_burley`: four Sobol dimensions of 1024 indices (4096 values) from
//!   `sobol_burley::sample_4d` and `sobol_burley::sample`, against `mcsample::seq::sobol`
//!   scalar and `seq::sobol` (dimensions 0..4 of 128 packets).
//!
//! `cargo bench --bench sequences`; for the AVX2 build,
//! `RUSTFLAGS="-C target-feature=+avx2,+fma" cargo bench --target-dir target/avx2 --bench sequences`.
//! Criterion takes one regex filter: `cargo bench --bench sequences -- '^(seq|sobol_vs)'`.

use std::hint::black_box;

use criterion::measurement::WallTime;
use criterion::{BenchmarkGroup, Criterion, Throughput, criterion_group, criterion_main};
use glam::Vec2;
use mcsample::rng::Pcg32x8;
use mcsample::seq;
use mcsample::x8::{F32x8, U32x8, Vec2x8};
use rand_core::Rng;
use rand_pcg::Pcg32;
use wide::bytemuck;

/// Values per iteration.
const N: usize = 4096;

const STATES: [u64; 8] = [1, 2, 3, 4, 5, 6, 7, 8];
const STREAMS: [u64; 8] = [11, 12, 13, 14, 15, 16, 17, 18];

fn rng(c: &mut Criterion) {
    let mut g = c.benchmark_group("pcg32");
    g.throughput(Throughput::Elements(N as u64));

    let mut packet = Pcg32x8::new(STATES, STREAMS);
    g.bench_function("x8/next_u32x8", |b| {
        b.iter(|| {
            let mut acc = U32x8::ZERO;
            for _ in 0..N / 8 {
                acc ^= packet.next_u32x8();
            }
            black_box(acc)
        })
    });

    let mut packet = Pcg32x8::new(STATES, STREAMS);
    g.bench_function("x8/next_f32x8", |b| {
        b.iter(|| {
            let mut acc = F32x8::ZERO;
            for _ in 0..N / 8 {
                acc += packet.next_f32x8();
            }
            black_box(acc)
        })
    });

    // One generator, as most code holds it: each value waits for the previous step's multiply.
    let mut single = Pcg32::new(STATES[0], STREAMS[0]);
    g.bench_function("scalar_1x/next_u32", |b| {
        b.iter(|| {
            let mut acc = 0u32;
            for _ in 0..N {
                acc ^= single.next_u32();
            }
            black_box(acc)
        })
    });

    let mut scalars: [Pcg32; 8] = core::array::from_fn(|i| Pcg32::new(STATES[i], STREAMS[i]));
    g.bench_function("scalar_8x/next_u32", |b| {
        b.iter(|| {
            let mut acc = 0u32;
            for _ in 0..N / 8 {
                for s in scalars.iter_mut() {
                    acc ^= s.next_u32();
                }
            }
            black_box(acc)
        })
    });

    let mut scalars: [Pcg32; 8] = core::array::from_fn(|i| Pcg32::new(STATES[i], STREAMS[i]));
    g.bench_function("scalar_8x/next_f32", |b| {
        b.iter(|| {
            let mut acc = 0f32;
            for _ in 0..N / 8 {
                for s in scalars.iter_mut() {
                    acc += (s.next_u32() >> 8) as f32 * (1.0 / 16_777_216.0);
                }
            }
            black_box(acc)
        })
    });

    g.finish();
}

/// Seed of every sequence benchmark: fixed and nonzero.
const SEED: u32 = 0x2545_f491;
/// Strata of `stratified` / `latin_hypercube`: one full round per iteration.
const COUNT: u32 = 4096;
/// Grid of the 2D generators: 64 × 64 = 4096 cells, one full round per iteration.
const NX: u32 = 64;
const NY: u32 = 64;

/// The parameters of a generator call, passed through `black_box` once per iteration so they are
/// run-time values (as in a renderer): the per-call key setup can be hoisted out of the loop but
/// not constant-folded, and `Divisor` cannot be specialised to a known power of two.
#[derive(Clone, Copy)]
struct Params {
    count: u32,
    nx: u32,
    ny: u32,
    dim: u32,
    seed: u32,
}

const PARAMS: Params = Params {
    count: COUNT,
    nx: NX,
    ny: NY,
    dim: 0,
    seed: SEED,
};

/// Lane offsets 0..8 of a packet of consecutive indices.
fn lanes() -> U32x8 {
    U32x8::new([0, 1, 2, 3, 4, 5, 6, 7])
}

/// The bits of a packet of floats, for an integer accumulator.
#[inline(always)]
fn bits8(v: F32x8) -> U32x8 {
    bytemuck::cast(v)
}

/// Scalar 1D generator over indices 0..N: N values. The results are summed as integer bits
/// (wrapping), not as floats, so the accumulator is not a chain of 4-cycle float additions.
fn bench_scalar_1d(
    g: &mut BenchmarkGroup<'_, WallTime>,
    name: &str,
    p: Params,
    f: impl Fn(u32, Params) -> f32,
) {
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function(format!("scalar/{name}"), |b| {
        b.iter(|| {
            let p = black_box(p);
            let mut acc = 0u32;
            for i in 0..N as u32 {
                acc = acc.wrapping_add(f(i, p).to_bits());
            }
            black_box(acc)
        })
    });
    // The same calls on indices LLVM cannot see through, so it cannot vectorise the loop: the
    // scalar function as a renderer calls it, one sample at a time.
    g.bench_function(format!("scalar_call/{name}"), |b| {
        b.iter(|| {
            let p = black_box(p);
            let mut acc = 0u32;
            for i in 0..N as u32 {
                acc = acc.wrapping_add(f(black_box(i), p).to_bits());
            }
            black_box(acc)
        })
    });
}

/// Packet 1D generator over N/8 packets of consecutive indices: N values.
fn bench_x8_1d(
    g: &mut BenchmarkGroup<'_, WallTime>,
    name: &str,
    p: Params,
    f: impl Fn(U32x8, Params) -> F32x8,
) {
    g.throughput(Throughput::Elements(N as u64));
    let lanes = lanes();
    g.bench_function(format!("x8/{name}"), |b| {
        b.iter(|| {
            let p = black_box(p);
            let mut acc = U32x8::ZERO;
            for k in 0..(N / 8) as u32 {
                acc += bits8(f(U32x8::splat(k * 8) + lanes, p));
            }
            black_box(acc)
        })
    });
}

/// Scalar 2D generator over indices 0..N: N points, 2N values.
fn bench_scalar_2d(
    g: &mut BenchmarkGroup<'_, WallTime>,
    name: &str,
    p: Params,
    f: impl Fn(u32, Params) -> Vec2,
) {
    g.throughput(Throughput::Elements(2 * N as u64));
    g.bench_function(format!("scalar/{name}"), |b| {
        b.iter(|| {
            let p = black_box(p);
            let mut acc = 0u32;
            for i in 0..N as u32 {
                let v = f(i, p);
                acc = acc.wrapping_add(v.x.to_bits()).wrapping_add(v.y.to_bits());
            }
            black_box(acc)
        })
    });
    g.bench_function(format!("scalar_call/{name}"), |b| {
        b.iter(|| {
            let p = black_box(p);
            let mut acc = 0u32;
            for i in 0..N as u32 {
                let v = f(black_box(i), p);
                acc = acc.wrapping_add(v.x.to_bits()).wrapping_add(v.y.to_bits());
            }
            black_box(acc)
        })
    });
}

/// Packet 2D generator over N/8 packets of consecutive indices: N points, 2N values.
fn bench_x8_2d(
    g: &mut BenchmarkGroup<'_, WallTime>,
    name: &str,
    p: Params,
    f: impl Fn(U32x8, Params) -> Vec2x8,
) {
    g.throughput(Throughput::Elements(2 * N as u64));
    let lanes = lanes();
    g.bench_function(format!("x8/{name}"), |b| {
        b.iter(|| {
            let p = black_box(p);
            let mut acc = U32x8::ZERO;
            for k in 0..(N / 8) as u32 {
                let v = f(U32x8::splat(k * 8) + lanes, p);
                acc += bits8(v.x) + bits8(v.y);
            }
            black_box(acc)
        })
    });
}

/// Every generator of `mcsample::seq`, scalar and x8, on the same indices.
fn sequences(c: &mut Criterion) {
    let mut g = c.benchmark_group("seq");
    let p = PARAMS;
    let p1 = Params { dim: 1, ..PARAMS };

    bench_scalar_1d(&mut g, "independent", p, |i, p| {
        seq::independent(i, p.dim, p.seed)
    });
    bench_x8_1d(&mut g, "independent", p, |i, p| {
        seq::independent(i, p.dim, p.seed)
    });

    bench_scalar_1d(&mut g, "stratified", p, |i, p| {
        seq::stratified(i, p.count, p.dim, p.seed)
    });
    bench_x8_1d(&mut g, "stratified", p, |i, p| {
        seq::stratified(i, p.count, p.dim, p.seed)
    });

    bench_scalar_1d(&mut g, "latin_hypercube", p1, |i, p| {
        seq::latin_hypercube(i, p.count, p.dim, p.seed)
    });
    bench_x8_1d(&mut g, "latin_hypercube", p1, |i, p| {
        seq::latin_hypercube(i, p.count, p.dim, p.seed)
    });

    // A count that is not a power of two: `permute` cycle-walks (2¹² slots for 3000 strata), and
    // a packet repeats the map until its slowest lane is inside.
    let p3000 = Params {
        count: 3000,
        ..PARAMS
    };
    bench_scalar_1d(&mut g, "stratified_n3000", p3000, |i, p| {
        seq::stratified(i, p.count, p.dim, p.seed)
    });
    bench_x8_1d(&mut g, "stratified_n3000", p3000, |i, p| {
        seq::stratified(i, p.count, p.dim, p.seed)
    });

    bench_scalar_2d(&mut g, "jittered_2d", p, |i, p| {
        seq::jittered_2d(i, p.nx, p.ny, p.dim, p.seed)
    });
    bench_x8_2d(&mut g, "jittered_2d", p, |i, p| {
        seq::jittered_2d(i, p.nx, p.ny, p.dim, p.seed)
    });

    bench_scalar_2d(&mut g, "multi_jittered_2d", p, |i, p| {
        seq::multi_jittered_2d(i, p.nx, p.ny, p.dim, p.seed)
    });
    bench_x8_2d(&mut g, "multi_jittered_2d", p, |i, p| {
        seq::multi_jittered_2d(i, p.nx, p.ny, p.dim, p.seed)
    });

    // A 48 × 48 grid: 2304 cells in 2¹² slots and 48 rows/columns in 2⁶, all cycle-walked.
    let p48 = Params {
        nx: 48,
        ny: 48,
        ..PARAMS
    };
    bench_scalar_2d(&mut g, "multi_jittered_2d_48x48", p48, |i, p| {
        seq::multi_jittered_2d(i, p.nx, p.ny, p.dim, p.seed)
    });
    bench_x8_2d(&mut g, "multi_jittered_2d_48x48", p48, |i, p| {
        seq::multi_jittered_2d(i, p.nx, p.ny, p.dim, p.seed)
    });

    bench_scalar_2d(&mut g, "cmj_2d", p, |i, p| {
        seq::cmj_2d(i, p.nx, p.ny, p.dim, p.seed)
    });
    bench_x8_2d(&mut g, "cmj_2d", p, |i, p| {
        seq::cmj_2d(i, p.nx, p.ny, p.dim, p.seed)
    });

    // Dimension 2 runs the 32-column matrix loop (as does 3); dimension 0 (van der Corput) and 1
    // (Pascal, five shift steps) skip it.
    let p2 = Params { dim: 2, ..PARAMS };
    bench_scalar_1d(&mut g, "sobol", p2, |i, p| seq::sobol(i, p.dim, p.seed));
    bench_x8_1d(&mut g, "sobol", p2, |i, p| seq::sobol(i, p.dim, p.seed));
    bench_scalar_1d(&mut g, "sobol_dim1", p1, |i, p| {
        seq::sobol(i, p.dim, p.seed)
    });
    bench_x8_1d(&mut g, "sobol_dim1", p1, |i, p| {
        seq::sobol(i, p.dim, p.seed)
    });
    bench_scalar_1d(&mut g, "sobol_dim0", p, |i, p| seq::sobol(i, p.dim, p.seed));
    bench_x8_1d(&mut g, "sobol_dim0", p, |i, p| seq::sobol(i, p.dim, p.seed));

    // Pair 0: dimensions 0 and 1, the (0, m, 2)-net.
    bench_scalar_2d(&mut g, "sobol_2d", p, |i, p| {
        seq::sobol_2d(i, p.dim, p.seed)
    });
    bench_x8_2d(&mut g, "sobol_2d", p, |i, p| {
        seq::sobol_2d(i, p.dim, p.seed)
    });

    g.finish();
}

/// Four Sobol dimensions of 1024 consecutive indices (4096 values): `sobol_burley::sample_4d`
/// (its dimension set 0, SSE on x86-64) against `mcsample::seq::sobol`, scalar and x8
/// (dimensions 0..4 of 128 packets).
fn sobol_vs_burley(c: &mut Criterion) {
    const POINTS: u32 = (N / 4) as u32;
    let mut g = c.benchmark_group("sobol_vs_burley");
    g.throughput(Throughput::Elements(N as u64));

    g.bench_function("sobol_burley_sample_4d", |b| {
        b.iter(|| {
            let seed = black_box(SEED);
            let mut acc = 0u32;
            for i in 0..POINTS {
                for v in sobol_burley::sample_4d(i, 0, seed) {
                    acc = acc.wrapping_add(v.to_bits());
                }
            }
            black_box(acc)
        })
    });

    g.bench_function("sobol_burley_sample", |b| {
        b.iter(|| {
            let seed = black_box(SEED);
            let mut acc = 0u32;
            for i in 0..POINTS {
                for d in 0..4 {
                    acc = acc.wrapping_add(sobol_burley::sample(i, d, seed).to_bits());
                }
            }
            black_box(acc)
        })
    });

    g.bench_function("mcsample_scalar_sobol_4d", |b| {
        b.iter(|| {
            let seed = black_box(SEED);
            let mut acc = 0u32;
            for i in 0..POINTS {
                for d in 0..4 {
                    acc = acc.wrapping_add(seq::sobol(i, d, seed).to_bits());
                }
            }
            black_box(acc)
        })
    });

    let lanes = lanes();
    g.bench_function("mcsample_x8_sobol_4d", |b| {
        b.iter(|| {
            let seed = black_box(SEED);
            let mut acc = U32x8::ZERO;
            for k in 0..POINTS / 8 {
                let index = U32x8::splat(k * 8) + lanes;
                for d in 0..4 {
                    acc += bits8(seq::sobol(index, d, seed));
                }
            }
            black_box(acc)
        })
    });

    g.finish();
}

criterion_group!(benches, rng, sequences, sobol_vs_burley);
criterion_main!(benches);
