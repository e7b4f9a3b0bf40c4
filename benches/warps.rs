//! Warp throughput: scalar and x8 forms of every warp, on 4096 in-cache points and on 2²⁴
//! points (streaming), beside a copy kernel that moves the same bytes (2 floats in, 3 out).
//!
//! `cargo bench --bench warps`; for the AVX2 build,
//! `RUSTFLAGS="-C target-feature=+avx2,+fma" cargo bench --bench warps`.

use std::hint::black_box;
use std::time::Duration;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use glam::{Vec2, Vec3};
use mcsample::warp;
use mcsample::x8::{F32x8, Vec2x8, Vec3x8};

const SMALL: usize = 4096;
const LARGE: usize = 1 << 24;

fn inputs(n: usize) -> (Vec<Vec2>, Vec<Vec2x8>) {
    // A fixed low-discrepancy-ish pattern (R2 sequence): deterministic, no RNG dependency.
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

/// Warps under test: name, scalar closure, packet closure. The triangle and rectangle are a
/// mid-sized light one unit away.
macro_rules! for_each_warp {
    ($m:ident) => {{
        let a = Vec3::new(-0.3, -0.2, 1.0);
        let b = Vec3::new(0.4, -0.1, 1.1);
        let c = Vec3::new(0.0, 0.5, 0.9);
        let (a8, b8, c8) = (Vec3x8::splat(a), Vec3x8::splat(b), Vec3x8::splat(c));
        let ex = Vec3::new(0.6, 0.0, 0.0);
        let ey = Vec3::new(0.0, 0.5, 0.0);
        let (ex8, ey8) = (Vec3x8::splat(ex), Vec3x8::splat(ey));
        let h = 0.3f32;
        let h8 = F32x8::splat(h);
        let n = 20.0f32;
        let n8 = F32x8::splat(n);
        $m!(
            "concentric_disk",
            |u: Vec2| {
                let p = warp::concentric_disk(u);
                Vec3::new(p.x, p.y, 0.0)
            },
            |u: Vec2x8| {
                let p = warp::x8::concentric_disk(u);
                Vec3x8::new(p.x, p.y, F32x8::ZERO)
            }
        );
        $m!(
            "polar_disk",
            |u: Vec2| {
                let p = warp::polar_disk(u);
                Vec3::new(p.x, p.y, 0.0)
            },
            |u: Vec2x8| {
                let p = warp::x8::polar_disk(u);
                Vec3x8::new(p.x, p.y, F32x8::ZERO)
            }
        );
        $m!(
            "uniform_hemisphere",
            warp::uniform_hemisphere,
            warp::x8::uniform_hemisphere
        );
        $m!(
            "cosine_hemisphere",
            warp::cosine_hemisphere,
            warp::x8::cosine_hemisphere
        );
        $m!(
            "uniform_sphere",
            warp::uniform_sphere,
            warp::x8::uniform_sphere
        );
        $m!("uniform_cone", |u| warp::uniform_cone(u, h), |u| {
            warp::x8::uniform_cone(u, h8)
        });
        $m!("phong_lobe", |u| warp::phong_lobe(u, n), |u| {
            warp::x8::phong_lobe(u, n8)
        });
        $m!(
            "uniform_triangle",
            warp::uniform_triangle,
            warp::x8::uniform_triangle
        );
        $m!(
            "spherical_triangle",
            |u| warp::spherical_triangle(u, a, b, c).0,
            |u| warp::x8::spherical_triangle(u, a8, b8, c8).0
        );
        $m!(
            "spherical_rectangle",
            |u| warp::spherical_rectangle(u, a, ex, ey).0,
            |u| warp::x8::spherical_rectangle(u, a8, ex8, ey8).0
        );
        $m!(
            "tent",
            |u: Vec2| Vec3::new(warp::tent(u.x), warp::tent(u.y), 0.0),
            |u: Vec2x8| Vec3x8::new(warp::x8::tent(u.x), warp::x8::tent(u.y), F32x8::ZERO)
        );
    }};
}

fn bench_size(c: &mut Criterion, n: usize, label: &str) {
    let (pts, packets) = inputs(n);
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

    macro_rules! one {
        ($name:expr, $scalar:expr, $packet:expr) => {{
            let f = $scalar;
            g.bench_function(BenchmarkId::new($name, "scalar"), |bn| {
                bn.iter(|| {
                    for (o, &u) in out.iter_mut().zip(black_box(&pts)) {
                        *o = f(u);
                    }
                    black_box(&out);
                })
            });
            let f8 = $packet;
            g.bench_function(BenchmarkId::new($name, "x8"), |bn| {
                bn.iter(|| {
                    for (o, &u) in out8.iter_mut().zip(black_box(&packets)) {
                        *o = f8(u);
                    }
                    black_box(&out8);
                })
            });
        }};
    }
    for_each_warp!(one);
    g.finish();
}

fn warps(c: &mut Criterion) {
    bench_size(c, SMALL, "4096");
    bench_size(c, LARGE, "2^24");
}

criterion_group!(benches, warps);
criterion_main!(benches);
