//! The direct-lighting estimator, scalar against x8, per estimate, with a trivial visibility
//! callback: every strategy on one cell of the lecture's grid (Phong n = 100 under a sphere of
//! angular radius 0.2) at 8 + 8 samples per estimate (where optimal MIS fits its weights),
//! independent samples. The x8 group computes eight estimates per call, so the throughputs
//! compare per estimate.
//!
//! `cargo bench --bench direct`; for the AVX2 build,
//! `RUSTFLAGS="-C target-feature=+avx2,+fma" cargo bench --bench direct`.

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use glam::Vec3;
use mcsample::direct::{self, Config, Lights, ShadingPoint, Strategy};
use mcsample::seq::{Generator, Sequence};
use mcsample::verify::direct::grid_scenes;
use mcsample::x8::{F32x8, U32x8, Vec3x8};

/// Estimates per iteration.
const E: u32 = 256;

fn estimator(c: &mut Criterion) {
    let scene = grid_scenes()
        .into_iter()
        .find(|s| s.name == "grid_n100_r0.2")
        .expect("the grid has this cell");
    let lights = Lights::uniform(&scene.lights);
    let material8 = scene.material.splat();
    let config = Config::new(8, 8);
    let n = config.samples();
    let at8 = ShadingPoint {
        p: Vec3x8::splat(scene.at.p),
        n: Vec3x8::splat(scene.at.n),
        wo: Vec3x8::splat(scene.at.wo),
    };
    let mut g = c.benchmark_group("direct");
    g.throughput(Throughput::Elements(u64::from(E)));
    for strategy in Strategy::ALL {
        g.bench_function(BenchmarkId::new(strategy.name(), "scalar"), |b| {
            let mut visible = |_: Vec3, _: Vec3| true;
            b.iter(|| {
                let mut sum = Vec3::ZERO;
                for e in 0..E {
                    let mut s = Sequence {
                        first: e * n,
                        seed: 1,
                        generator: Generator::Independent,
                    };
                    let at = black_box(scene.at);
                    sum += direct::estimate(
                        strategy,
                        &lights,
                        &scene.material,
                        at,
                        config,
                        &mut s,
                        &mut visible,
                    )
                    .radiance;
                }
                black_box(sum)
            })
        });
        g.bench_function(BenchmarkId::new(strategy.name(), "x8"), |b| {
            let mut visible = |m: F32x8, _: Vec3x8, _: Vec3x8| m;
            b.iter(|| {
                let mut sum = Vec3x8::splat(Vec3::ZERO);
                for e in 0..E / 8 {
                    let first = U32x8::new(core::array::from_fn(|i| (e * 8 + i as u32) * n));
                    let mut s = Sequence {
                        first,
                        seed: 1,
                        generator: Generator::Independent,
                    };
                    let at = black_box(at8);
                    let r = direct::estimate(
                        strategy, &lights, &material8, at, config, &mut s, &mut visible,
                    );
                    sum = Vec3x8::from(core::array::from_fn::<Vec3, 8, _>(|i| {
                        sum.lane(i) + r.radiance.lane(i)
                    }));
                }
                black_box(sum)
            })
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10).warm_up_time(std::time::Duration::from_millis(300))
        .measurement_time(std::time::Duration::from_secs(1));
    targets = estimator
}
criterion_main!(benches);
