//! The scene layer: every light of the registry (seen from the origin) and both BSDFs, on 4096
//! in-cache points.
//!
//! - `first`: a light's first sample at a new shading point, its set-up included
//!   (`light.at(p).sample(u)`, p through `black_box`), as a renderer pays it with one sample per
//!   point;
//! - `further`: each further sample of the light prepared once (`prepared.sample(u)`), as
//!   splitting pays it;
//! - `x8`: eight first samples at once;
//! - `pdf` and `hit` of the prepared light at a direction (a BSDF sample's MIS weight);
//! - `scene_modes`: a further sample of each light prepared for the registry's tilted normal in
//!   every light-sampling mode its shape offers (`light.at_sampling(p, n, mode)`): the modes'
//!   cost over solid angle's, as the report's "Prepared lights" table gives it (the loops keep
//!   direction × pdf, so that the pdf is timed too);
//! - the BSDFs' `sample` and `eval`, scalar and x8; light selection by power.
//!
//! `cargo bench --bench scene`; for the AVX2 build,
//! `RUSTFLAGS="-C target-feature=+avx2,+fma" cargo bench --bench scene`.

mod common;

use std::hint::black_box;

use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};
use glam::Vec3;
use mcsample::scene::{Lambert, Light, Phong, PowerTable, Shape};
use mcsample::verify::registry;
use mcsample::x8::{F32x8, Vec3x8};

const N: usize = 4096;

/// What a timed loop keeps of a light sample: its direction scaled by its pdf, so that the pdf's
/// computation cannot be left out of the time.
#[inline(always)]
fn sampled(s: mcsample::scene::LightSample<Vec3>) -> Vec3 {
    s.wi * s.pdf
}

fn lights(c: &mut Criterion) {
    let (pts, packets) = common::r2_points(N);
    let mut out = vec![Vec3::ZERO; N];
    let mut out8 = vec![Vec3x8::splat(Vec3::ZERO); N / 8];
    let mut g = c.benchmark_group("scene_lights");
    g.throughput(Throughput::Elements(N as u64));
    for s in registry::registry() {
        let Some(light) = s.scene_light() else {
            continue;
        };
        let name = s.name();
        let p = Vec3::ZERO;
        g.bench_function(BenchmarkId::new(&name, "first"), |bn| {
            bn.iter(|| {
                for (o, &u) in out.iter_mut().zip(black_box(&pts)) {
                    *o = sampled(light.at(black_box(p)).sample(u));
                }
                black_box(&out);
            })
        });
        let prepared = light.at(p);
        g.bench_function(BenchmarkId::new(&name, "further"), |bn| {
            bn.iter(|| {
                for (o, &u) in out.iter_mut().zip(black_box(&pts)) {
                    *o = sampled(prepared.sample(u));
                }
                black_box(&out);
            })
        });
        // The packet form through the registry (eight first samples at once).
        g.bench_function(BenchmarkId::new(&name, "x8"), |bn| {
            bn.iter(|| {
                s.sample_all(black_box(&packets), &mut out8);
                black_box(&out8);
            })
        });
        // pdf and hit at the light's own sample directions.
        let dirs: Vec<Vec3> = pts.iter().map(|&u| prepared.sample(u).wi).collect();
        let mut vals = vec![0.0f32; N];
        g.bench_function(BenchmarkId::new(&name, "pdf"), |bn| {
            bn.iter(|| {
                for (o, &w) in vals.iter_mut().zip(black_box(&dirs)) {
                    *o = prepared.pdf(w);
                }
                black_box(&vals);
            })
        });
        g.bench_function(BenchmarkId::new(&name, "hit"), |bn| {
            bn.iter(|| {
                for (o, &w) in vals.iter_mut().zip(black_box(&dirs)) {
                    *o = prepared.hit(w);
                }
                black_box(&vals);
            })
        });
    }
    g.finish();
}

fn modes(c: &mut Criterion) {
    let (pts, _) = common::r2_points(N);
    let mut out = vec![Vec3::ZERO; N];
    let mut g = c.benchmark_group("scene_modes");
    g.throughput(Throughput::Elements(N as u64));
    let (p, n) = (Vec3::ZERO, mcsample::registry::TILTED);
    for s in registry::registry() {
        let Some(light) = s.scene_light() else {
            continue;
        };
        for &mode in light.shape.modes() {
            let prepared = light.at_sampling(p, n, mode);
            g.bench_function(BenchmarkId::new(s.name(), mode.name()), |bn| {
                bn.iter(|| {
                    for (o, &u) in out.iter_mut().zip(black_box(&pts)) {
                        *o = sampled(prepared.sample(u));
                    }
                    black_box(&out);
                })
            });
        }
    }
    g.finish();
}

fn bsdfs(c: &mut Criterion) {
    let (pts, packets) = common::r2_points(N);
    let mut out = vec![Vec3::ZERO; N];
    let mut out8 = vec![Vec3x8::splat(Vec3::ZERO); N / 8];
    let mut g = c.benchmark_group("scene_bsdfs");
    g.throughput(Throughput::Elements(N as u64));
    let wo = Vec3::new(0.5, 0.1, 0.860_232_5);
    let wo8 = Vec3x8::splat(wo);
    let lambert = Lambert::new(Vec3::splat(0.8));
    let lambert8 = Lambert::new(Vec3x8::splat(Vec3::splat(0.8)));
    let phong = Phong::new(Vec3::splat(0.4), Vec3::splat(0.5), 20.0);
    let phong8 = Phong::new(
        Vec3x8::splat(Vec3::splat(0.4)),
        Vec3x8::splat(Vec3::splat(0.5)),
        F32x8::splat(20.0),
    );
    g.bench_function(BenchmarkId::new("lambert", "sample"), |bn| {
        bn.iter(|| {
            for (o, &u) in out.iter_mut().zip(black_box(&pts)) {
                *o = lambert.sample(wo, u).wi;
            }
            black_box(&out);
        })
    });
    g.bench_function(BenchmarkId::new("lambert", "sample_x8"), |bn| {
        bn.iter(|| {
            for (o, &u) in out8.iter_mut().zip(black_box(&packets)) {
                *o = lambert8.sample(wo8, u).wi;
            }
            black_box(&out8);
        })
    });
    g.bench_function(BenchmarkId::new("phong", "sample"), |bn| {
        bn.iter(|| {
            for (o, &u) in out.iter_mut().zip(black_box(&pts)) {
                *o = phong.sample(wo, u).wi;
            }
            black_box(&out);
        })
    });
    g.bench_function(BenchmarkId::new("phong", "sample_x8"), |bn| {
        bn.iter(|| {
            for (o, &u) in out8.iter_mut().zip(black_box(&packets)) {
                *o = phong8.sample(wo8, u).wi;
            }
            black_box(&out8);
        })
    });
    let dirs: Vec<Vec3> = pts.iter().map(|&u| phong.sample(wo, u).wi).collect();
    g.bench_function(BenchmarkId::new("phong", "eval"), |bn| {
        bn.iter(|| {
            for (o, &w) in out.iter_mut().zip(black_box(&dirs)) {
                *o = phong.eval(wo, w);
            }
            black_box(&out);
        })
    });
    g.finish();
}

fn selection(c: &mut Criterion) {
    let (pts, _) = common::r2_points(N);
    let lights: Vec<Light> = registry::registry()
        .iter()
        .filter_map(|s| s.scene_light())
        .collect();
    let mut storage = vec![0.0f32; lights.len()];
    let table = PowerTable::new(&lights, &mut storage);
    let mut idx = vec![0usize; N];
    let mut g = c.benchmark_group("scene_selection");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function(format!("power_{}_lights", lights.len()), |bn| {
        bn.iter(|| {
            for (o, u) in idx.iter_mut().zip(black_box(&pts)) {
                *o = table.select(u.x).index;
            }
            black_box(&idx);
        })
    });
    g.finish();
}

criterion_group!(benches, lights, modes, bsdfs, selection);
criterion_main!(benches);
