//! Warp throughput: scalar and x8 forms of every sampler of the registry, on 4096 in-cache
//! points and on 2²⁴ points (streaming), beside a copy kernel that moves the same bytes (2 floats
//! in, 3 out).
//!
//! `cargo bench --bench warps`; for the AVX2 build,
//! `RUSTFLAGS="-C target-feature=+avx2,+fma" cargo bench --bench warps`.

mod common;

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use glam::Vec3;
use mcsample::verify::registry;
use mcsample::x8::Vec3x8;

const SMALL: usize = 4096;
const LARGE: usize = 1 << 24;

fn bench_size(c: &mut Criterion, n: usize, label: &str) {
    let (pts, packets) = common::r2_points(n);
    let mut out = vec![Vec3::ZERO; n];
    let mut out8 = vec![Vec3x8::splat(Vec3::ZERO); n / 8];
    let mut g = c.benchmark_group(format!("warps_{label}"));
    g.throughput(Throughput::Elements(n as u64));
    if n == LARGE {
        g.sample_size(10)
            .measurement_time(Duration::from_secs(4))
            .warm_up_time(Duration::from_secs(1));
    }

    // The streaming floor: read 2 floats and write 3 per point, as every Vec2 → Vec3 warp does.
    g.bench_function("copy", |bn| {
        bn.iter(|| {
            for (o, u) in out.iter_mut().zip(black_box(&pts)) {
                *o = Vec3::new(u.x, u.y, u.x);
            }
            black_box(&out);
        })
    });
    g.bench_function("copy_x8", |bn| {
        bn.iter(|| {
            for (o, u) in out8.iter_mut().zip(black_box(&packets)) {
                *o = Vec3x8::new(u.x, u.y, u.x);
            }
            black_box(&out8);
        })
    });

    // Every sampler of the registry, at its registered parameters, through `sample_all`: the
    // dispatch on the sampler is taken once per batch, and the loop runs the warp inlined (a
    // match per point would keep LLVM from vectorising the scalar loop).
    // The lights and BSDFs are not memory-bound: `benches/scene.rs` times them in cache.
    for s in registry::registry()
        .into_iter()
        .filter(|s| n == SMALL || !(s.is_light() || s.is_bsdf()))
    {
        let name = s.name();
        g.bench_function(BenchmarkId::new(&name, "scalar"), |bn| {
            bn.iter(|| {
                s.sample_all(black_box(&pts), &mut out);
                black_box(&out);
            })
        });
        g.bench_function(BenchmarkId::new(&name, "x8"), |bn| {
            bn.iter(|| {
                s.sample_all(black_box(&packets), &mut out8);
                black_box(&out8);
            })
        });
    }
    g.finish();
}

fn warps(c: &mut Criterion) {
    bench_size(c, SMALL, "4096");
    bench_size(c, LARGE, "2^24");
}

criterion_group!(benches, warps);
criterion_main!(benches);
