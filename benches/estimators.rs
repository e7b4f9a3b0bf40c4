//! Estimator throughput on 4096 in-cache inputs: every two-technique MIS weight, scalar and x8;
//! the N-technique forms; one-sample MIS; and the accumulators (MeanVar, OptimalMis, Reservoir)
//! per pushed value.
//!
//! `cargo bench --bench estimators`; for the AVX2 build,
//! `RUSTFLAGS="-C target-feature=+avx2,+fma" cargo bench --bench estimators`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use mcsample::estimate::MeanVar;
use mcsample::lane::F32x8;
use mcsample::mis::{self, OptimalMis, Reservoir};
use mcsample::verify::mis1d::HEURISTICS;

const N: usize = 4096;

/// (n_f, pdf_f, n_g, pdf_g) with pdfs log-uniform over twelve decades, from a fixed xorshift.
fn quads() -> Vec<[f32; 4]> {
    let mut s = 0x2545_f491_u32;
    let mut next = move || {
        s ^= s << 13;
        s ^= s >> 17;
        s ^= s << 5;
        (s >> 8) as f32 / 16_777_216.0
    };
    (0..N)
        .map(|_| {
            let pdf = |u: f32| 10f32.powf(u * 12.0 - 6.0);
            [1.0 + (next() * 4.0).floor(), pdf(next()), 1.0, pdf(next())]
        })
        .collect()
}

fn weights(c: &mut Criterion) {
    let q = quads();
    let packets: Vec<[F32x8; 4]> = q
        .chunks_exact(8)
        .map(|c| core::array::from_fn(|k| F32x8::new(core::array::from_fn(|i| c[i][k]))))
        .collect();
    let mut out = vec![0f32; N];
    let mut out8 = vec![F32x8::ZERO; N / 8];
    let mut g = c.benchmark_group("mis");
    g.throughput(Throughput::Elements(N as u64));
    for (name, f, fx8, _) in HEURISTICS {
        g.bench_function(BenchmarkId::new("scalar", name), |b| {
            b.iter(|| {
                for (o, x) in out.iter_mut().zip(black_box(&q)) {
                    *o = f(x[0], x[1], x[2], x[3]);
                }
                black_box(&out);
            })
        });
        g.bench_function(BenchmarkId::new("x8", name), |b| {
            b.iter(|| {
                for (o, x) in out8.iter_mut().zip(black_box(&packets)) {
                    *o = fx8(x[0], x[1], x[2], x[3]);
                }
                black_box(&out8);
            })
        });
    }
    g.bench_function(BenchmarkId::new("scalar", "power_n, N = 3"), |b| {
        b.iter(|| {
            for (o, x) in out.iter_mut().zip(black_box(&q)) {
                *o = mis::power_n([x[0], x[2], 1.0], [x[1], x[3], 0.5])[0];
            }
            black_box(&out);
        })
    });
    g.bench_function(BenchmarkId::new("scalar", "one_sample, N = 3"), |b| {
        b.iter(|| {
            for (o, x) in out.iter_mut().zip(black_box(&q)) {
                *o = mis::one_sample([x[0], x[2], 1.0], x[1].fract()).u;
            }
            black_box(&out);
        })
    });
    g.finish();

    let mut g = c.benchmark_group("accumulators");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("MeanVar::push", |b| {
        b.iter(|| {
            let mut acc = MeanVar::new();
            for x in black_box(&q) {
                acc.push(f64::from(x[1]));
            }
            black_box(acc)
        })
    });
    g.bench_function("OptimalMis::push", |b| {
        b.iter(|| {
            let mut acc = OptimalMis::new(1.0, 1.0);
            for x in black_box(&q) {
                acc.push(f64::from(x[0]), f64::from(x[1]), f64::from(x[3]));
            }
            black_box(acc.estimate())
        })
    });
    g.bench_function("Reservoir::push", |b| {
        b.iter(|| {
            let mut r = Reservoir::new(0.37);
            for (i, x) in black_box(&q).iter().enumerate() {
                r.push(i, f64::from(x[1]), f64::from(x[3]));
            }
            black_box(r.chosen())
        })
    });
    g.finish();
}

criterion_group!(benches, weights);
criterion_main!(benches);
