//! The crate's warps beside what a user would otherwise run, in the same criterion groups so that
//! every ratio comes from one run:
//!
//! - per warp: our scalar and x8 forms, the plain glam+std version of the same formula and the
//!   plain `wide::f32x8` version (`examples/report/plain.rs`), on 4096 in-cache points; for the
//!   spherical polygons also our scalar form set up once for all the points ("ours prepared");
//! - the tent one coordinate at a time ("tent 1D"), without the registry pair's joint NaN rule;
//! - random points from an RNG: `Pcg32` with our scalar disk and sphere, `Pcg32x8` with the x8
//!   forms, and rand_distr's `UnitDisc`, `UnitCircle` and `UnitSphere` (rejection and
//!   Marsaglia's method) with the same `Pcg32`;
//! - with `--features rand`, the same through `mcsample::distr` (`rng.sample(UnitDisk)`);
//! - the copy kernel that moves the same bytes (2 floats in, 3 out);
//! - the spherical triangle and rectangle set up for every sample, on 4096 configurations of 0.05
//!   to 2 sr ("polygons"): ours scalar and x8, the textbook versions of `plain.rs` and ports of
//!   pbrt-v4's (`peers/pbrt.rs`), once with the geometry varying from sample to sample and once
//!   with one geometry passed through `black_box` for every sample;
//! - the simple warps in a caller's `#[inline(never)]` loop over structure-of-arrays slices
//!   (`u1`, `u2` in; `x`, `y`, `z` out), ours beside the plain version ("soa");
//! - the same layout on 2²⁴ points, one thread, x8 against x16, beside a copy kernel that moves
//!   the same bytes ("2^24"): the shape of Mitsuba 3's array pass, which
//!   `benches/mitsuba_warps.py` times for its own warps with Dr.Jit's LLVM backend.
//!
//! `cargo bench --bench peers`; for the AVX2 build,
//! `RUSTFLAGS="-C target-feature=+avx2,+fma" cargo bench --target-dir target/avx2 --bench peers`.

mod common;
#[path = "peers/pbrt.rs"]
mod pbrt;
#[path = "../examples/report/plain.rs"]
mod plain;

use std::hint::black_box;

use criterion::measurement::WallTime;
use criterion::{
    BenchmarkGroup, BenchmarkId, Criterion, Throughput, criterion_group, criterion_main,
};
use glam::{DVec3, Vec2, Vec3};
use mcsample::lane::Lane;
use mcsample::rng::Pcg32x8;
use mcsample::verify::registry::{self, Sampler};
use mcsample::warp::{
    SolidAngleRectangle, SolidAngleTriangle, SphericalRectangle, SphericalTriangle, UniformCone,
};
use mcsample::x8::{F32x8, Vec2x8, Vec3x8};
use mcsample::x16::{F32x16, Vec2x16};
use plain::{U8, V8};
use rand_core::Rng;
use rand_distr::{Distribution, UnitCircle, UnitDisc, UnitSphere};
use rand_pcg::Pcg32;
use wide::f32x8;

const N: usize = 4096;

fn points() -> (Vec<Vec2>, Vec<Vec2x8>, Vec<U8>) {
    let (pts, packets) = common::r2_points(N);
    let plain: Vec<U8> = packets
        .iter()
        .map(|p| U8 {
            x: f32x8::new(p.x.to_array()),
            y: f32x8::new(p.y.to_array()),
        })
        .collect();
    (pts, packets, plain)
}

/// The plain packet version of a sampler, where one exists.
fn plain_x8(s: Sampler) -> Option<fn(U8, f32) -> V8> {
    Some(match s {
        Sampler::ConcentricDisk(_) => |u, _| plain::concentric_disk_x8(u),
        Sampler::PolarDisk(_) => |u, _| plain::polar_disk_x8(u),
        Sampler::UniformHemisphere(_) => |u, _| plain::uniform_hemisphere_x8(u),
        Sampler::CosineHemisphere(_) => |u, _| plain::cosine_hemisphere_x8(u),
        Sampler::UniformSphere(_) => |u, _| plain::uniform_sphere_x8(u),
        Sampler::UniformCone(_) => |u, h| plain::uniform_cone_x8(u, f32x8::splat(h)),
        _ => return None,
    })
}

fn warps(c: &mut Criterion) {
    let (pts, packets, plain_packets) = points();
    let mut out = vec![Vec3::ZERO; N];
    let mut out8 = vec![Vec3x8::splat(Vec3::ZERO); N / 8];
    let mut outp = vec![
        V8 {
            x: f32x8::ZERO,
            y: f32x8::ZERO,
            z: f32x8::ZERO
        };
        N / 8
    ];
    for s in registry::registry() {
        let mut g = c.benchmark_group(format!("peers/{}", s.name()));
        g.throughput(Throughput::Elements(N as u64));
        g.bench_function("ours scalar", |b| {
            b.iter(|| {
                s.sample_all(black_box(&pts), &mut out);
                black_box(&out);
            })
        });
        g.bench_function("ours x8", |b| {
            b.iter(|| {
                s.sample_all(black_box(&packets), &mut out8);
                black_box(&out8);
            })
        });
        // The polygons once more, set up once for all the points (`new`, then `sample`): a
        // caller's loop drawing many samples at one shading point.
        match s {
            Sampler::SphericalTriangle(SolidAngleTriangle { v: [a, b, c] }) => {
                let t = SphericalTriangle::new(a, b, c);
                prepared(&mut g, &mut out, &pts, t, |t, u| t.sample(u).0);
            }
            Sampler::SphericalRectangle(SolidAngleRectangle { v: [c0, ex, ey] }) => {
                let r = SphericalRectangle::new(c0, ex, ey);
                prepared(&mut g, &mut out, &pts, r, |r, u| r.sample(u).0);
            }
            _ => {}
        }
        if let Some(f) = plain::loop_for(s) {
            g.bench_function("plain glam", |b| {
                b.iter(|| {
                    f(black_box(&pts), &mut out);
                    black_box(&out);
                })
            });
        }
        if let Some(f) = plain_x8(s) {
            let h = match s {
                Sampler::UniformCone(UniformCone { h }) => h,
                _ => 0.0,
            };
            g.bench_function("plain wide", |b| {
                b.iter(|| {
                    for (o, &u) in outp.iter_mut().zip(black_box(&plain_packets)) {
                        *o = f(u, h);
                    }
                    black_box(&outp);
                })
            });
        }
        g.bench_function("copy", |b| {
            b.iter(|| {
                for (o, u) in out.iter_mut().zip(black_box(&pts)) {
                    *o = Vec3::new(u.x, u.y, u.x);
                }
                black_box(&out);
            })
        });
        g.finish();
    }
}

/// The "ours prepared" entry of a polygon's group: `sample` of a polygon set up once, over all
/// the points.
fn prepared<T: Copy>(
    g: &mut BenchmarkGroup<'_, WallTime>,
    out: &mut [Vec3],
    pts: &[Vec2],
    polygon: T,
    sample: impl Fn(&T, Vec2) -> Vec3,
) {
    g.bench_function("ours prepared", |b| {
        b.iter(|| {
            // A local copy, as a caller would hold it: read through the reference the closure
            // captured, the rectangle's loop could not hoist its loads (66 ns a sample, not 24).
            let polygon = black_box(polygon);
            for (o, &u) in out.iter_mut().zip(black_box(pts)) {
                *o = sample(&polygon, u);
            }
            black_box(&*out);
        })
    });
}

/// One entry of `random_points`: `point` draws one point from the generator per call, and every
/// entry starts from the same `Pcg32::new(7, 11)`.
fn per_call(
    g: &mut BenchmarkGroup<'_, WallTime>,
    out: &mut [[f32; 3]],
    shape: &str,
    name: &str,
    mut point: impl FnMut(&mut Pcg32) -> [f32; 3],
) {
    g.bench_function(BenchmarkId::new(shape, name), |b| {
        let mut rng = Pcg32::new(7, 11);
        b.iter(|| {
            for o in out.iter_mut() {
                *o = point(&mut rng);
            }
            black_box(&*out);
        })
    });
}

/// Points from an RNG: the crate's warps fed by PCG32 against rand_distr's samplers.
fn random_points(c: &mut Criterion) {
    let mut out = vec![[0.0f32; 3]; N];
    let mut g = c.benchmark_group("peers/random points");
    g.throughput(Throughput::Elements(N as u64));
    let to_u = |x: u32| (x >> 8) as f32 * (1.0 / 16_777_216.0);
    let u2 = |rng: &mut Pcg32| Vec2::new(to_u(rng.next_u32()), to_u(rng.next_u32()));
    let flat = |p: Vec2| [p.x, p.y, 0.0];
    per_call(&mut g, &mut out, "disk", "Pcg32 + concentric_disk", |rng| {
        flat(mcsample::warp::concentric_disk(u2(rng)))
    });
    #[cfg(feature = "rand")]
    per_call(
        &mut g,
        &mut out,
        "disk",
        "Pcg32 sample(mcsample::distr::UnitDisk)",
        |rng| flat(rand::RngExt::sample(rng, mcsample::distr::UnitDisk)),
    );
    // The other uniform disk map: with i.i.d. u there is no stratification for the concentric
    // map's low distortion to keep, and the polar map is the cheaper of the two.
    per_call(&mut g, &mut out, "disk", "Pcg32 + polar_disk", |rng| {
        flat(mcsample::warp::polar_disk(u2(rng)))
    });
    per_call(&mut g, &mut out, "disk", "rand_distr UnitDisc", |rng| {
        let [x, y]: [f32; 2] = UnitDisc.sample(rng);
        [x, y, 0.0]
    });
    per_call(
        &mut g,
        &mut out,
        "circle",
        "Pcg32 + polar_disk at r = 1",
        |rng| {
            flat(mcsample::warp::polar_disk(Vec2::new(
                1.0,
                to_u(rng.next_u32()),
            )))
        },
    );
    per_call(&mut g, &mut out, "circle", "rand_distr UnitCircle", |rng| {
        let [x, y]: [f32; 2] = UnitCircle.sample(rng);
        [x, y, 0.0]
    });
    per_call(
        &mut g,
        &mut out,
        "sphere",
        "Pcg32 + uniform_sphere",
        |rng| mcsample::warp::uniform_sphere(u2(rng)).to_array(),
    );
    g.bench_function(
        BenchmarkId::new("sphere", "Pcg32x8 + x8 uniform_sphere"),
        |b| {
            let mut rng =
                Pcg32x8::from_lanes(core::array::from_fn(|i| Pcg32::new(7, 11 + i as u64)));
            b.iter(|| {
                for o in out.chunks_exact_mut(8) {
                    let x = rng.next_f32x8();
                    let u = Vec2x8::new(x, rng.next_f32x8());
                    for (d, w) in o
                        .iter_mut()
                        .zip(mcsample::warp::uniform_sphere(u).to_array())
                    {
                        *d = w.to_array();
                    }
                }
                black_box(&out);
            })
        },
    );
    #[cfg(feature = "rand")]
    per_call(
        &mut g,
        &mut out,
        "sphere",
        "Pcg32 sample(mcsample::distr::UniformSphere)",
        |rng| {
            let w: Vec3 = rand::RngExt::sample(rng, mcsample::distr::UniformSphere);
            w.to_array()
        },
    );
    per_call(&mut g, &mut out, "sphere", "rand_distr UnitSphere", |rng| {
        UnitSphere.sample(rng)
    });
    g.finish();
}

/// The tent alone, one coordinate per call, against the plain version: the registry's tent
/// sampler above is a pair with a joint NaN contract (NaN in either u drops both coordinates),
/// which the plain pair does not have, so this is the warp's own ratio.
fn tent_1d(c: &mut Criterion) {
    let us: Vec<f32> = common::r2_points(N).0.iter().map(|p| p.x).collect();
    let mut out = vec![0.0f32; N];
    let mut g = c.benchmark_group("peers/tent 1D");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function("ours scalar", |b| {
        b.iter(|| {
            for (o, &u) in out.iter_mut().zip(black_box(&us)) {
                *o = mcsample::warp::tent(u);
            }
            black_box(&out);
        })
    });
    g.bench_function("plain glam", |b| {
        b.iter(|| {
            for (o, &u) in out.iter_mut().zip(black_box(&us)) {
                *o = plain::tent(u);
            }
            black_box(&out);
        })
    });
    g.finish();
}

/// A uniform f64 in [0, 1).
fn uniform(rng: &mut Pcg32) -> f64 {
    (rng.next_u64() >> 11) as f64 / (1u64 << 53) as f64
}

/// A unit vector uniform on the sphere.
fn random_unit(rng: &mut Pcg32) -> DVec3 {
    let z: f64 = 2.0 * uniform(rng) - 1.0;
    let phi = std::f64::consts::TAU * uniform(rng);
    let r = (1.0 - z * z).max(0.0).sqrt();
    DVec3::new(r * phi.cos(), r * phi.sin(), z)
}

/// `N` triangles and `N` parallelograms (as corner and two edges) seen from the origin with a
/// solid angle from 0.05 to 2 sr (in f64): centred in a random direction 1 to 3 away, edges up
/// to 2.5 long, the plane tilted up to 80° from facing the origin.
#[allow(clippy::type_complexity)]
fn general_polygons() -> (Vec<[Vec3; 3]>, Vec<[Vec3; 3]>) {
    let mut rng = Pcg32::new(0x5eed, 29);
    let (mut tris, mut rects) = (Vec::with_capacity(N), Vec::with_capacity(N));
    while tris.len() < N || rects.len() < N {
        let dir = random_unit(&mut rng);
        let centre = dir * (1.0 + 2.0 * uniform(&mut rng));
        let normal = loop {
            let n = random_unit(&mut rng);
            if n.dot(-dir) > 80f64.to_radians().cos() {
                break n;
            }
        };
        let (t, b) = normal.any_orthonormal_pair();
        let mut edge = || (t * (uniform(&mut rng) - 0.5) + b * (uniform(&mut rng) - 0.5)) * 5.0;
        let (p, q, r) = (centre + edge(), centre + edge(), centre + edge());
        let in_class = |omega: f64| (0.05..=2.0).contains(&omega);
        let tri = [p.as_vec3(), q.as_vec3(), r.as_vec3()];
        let t64 = SphericalTriangle::<DVec3>::new(p, q, r);
        if tris.len() < N && !t64.by_area() && in_class(t64.solid_angle()) {
            tris.push(tri);
        }
        // A rectangle (orthogonal edges: a skewed parallelogram is sampled by area) turned by a
        // random angle in the plane.
        let turn = std::f64::consts::TAU * uniform(&mut rng);
        let (x, y) = (
            t * turn.cos() + b * turn.sin(),
            b * turn.cos() - t * turn.sin(),
        );
        let (ex, ey) = (
            x * (0.1 + 2.4 * uniform(&mut rng)),
            y * (0.1 + 2.4 * uniform(&mut rng)),
        );
        let corner = centre - (ex + ey) * 0.5;
        let r64 = SphericalRectangle::<DVec3>::new(corner, ex, ey);
        if rects.len() < N && !r64.by_area() && in_class(r64.solid_angle()) {
            rects.push([corner.as_vec3(), ex.as_vec3(), ey.as_vec3()]);
        }
    }
    (tris, rects)
}

/// One entry of `polygons`: `f` over the points, each with its own configuration (`varying`) or
/// each with `cfg[0]` passed through `black_box`. Generic, so that `f` is inlined into the loop
/// as a caller's sampler would be.
fn polygon_entry<U: Copy, T: Copy, O>(
    g: &mut BenchmarkGroup<'_, WallTime>,
    name: &str,
    (us, cfg, out): (&[U], &[T], &mut [O]),
    varying: bool,
    f: impl Fn(U, T) -> O,
) {
    let one = cfg[0];
    g.bench_function(name, |b| {
        b.iter(|| {
            if varying {
                for ((o, &u), &v) in out.iter_mut().zip(black_box(us)).zip(black_box(cfg)) {
                    *o = f(u, v);
                }
            } else {
                for (o, &u) in out.iter_mut().zip(black_box(us)) {
                    *o = f(u, black_box(one));
                }
            }
            black_box(&*out);
        })
    });
}

/// The spherical polygons set up for every sample, ours beside the textbook and pbrt-v4, on
/// geometry varying from sample to sample and on one geometry opaque to the compiler.
fn polygons(c: &mut Criterion) {
    let (pts, packets, _) = points();
    let (tris, rects) = general_polygons();
    let mut out = vec![Vec3::ZERO; N];
    let mut out8 = vec![Vec3x8::splat(Vec3::ZERO); N / 8];
    let pack = |cfg: &[[Vec3; 3]]| -> Vec<[Vec3x8; 3]> {
        cfg.chunks(8)
            .map(|c| {
                [0, 1, 2].map(|k| Vec3x8::from(core::array::from_fn::<Vec3, 8, _>(|i| c[i][k])))
            })
            .collect()
    };
    let (tris8, rects8) = (pack(&tris), pack(&rects));
    for varying in [true, false] {
        let kind = if varying { "varying" } else { "fixed" };
        let mut g = c.benchmark_group(format!("peers/spherical triangle {kind}"));
        g.throughput(Throughput::Elements(N as u64));
        let (p, t) = (&pts[..], &tris[..]);
        polygon_entry(
            &mut g,
            "ours scalar",
            (p, t, &mut out),
            varying,
            |u, [a, b, c]| mcsample::warp::spherical_triangle(u, a, b, c).0,
        );
        polygon_entry(
            &mut g,
            "textbook",
            (p, t, &mut out),
            varying,
            |u, [a, b, c]| plain::spherical_triangle(u, a, b, c).0,
        );
        polygon_entry(
            &mut g,
            "pbrt-v4",
            (p, t, &mut out),
            varying,
            |u: Vec2, [a, b, c]| pbrt::spherical_triangle(u.into(), a, b, c).0,
        );
        polygon_entry(
            &mut g,
            "ours x8",
            (&packets, &tris8, &mut out8),
            varying,
            |u, [a, b, c]| mcsample::warp::spherical_triangle(u, a, b, c).0,
        );
        g.finish();

        let mut g = c.benchmark_group(format!("peers/spherical rectangle {kind}"));
        g.throughput(Throughput::Elements(N as u64));
        let r = &rects[..];
        polygon_entry(
            &mut g,
            "ours scalar",
            (p, r, &mut out),
            varying,
            |u, [c0, x, y]| mcsample::warp::spherical_rectangle(u, c0, x, y).0,
        );
        polygon_entry(
            &mut g,
            "textbook",
            (p, r, &mut out),
            varying,
            |u, [c0, x, y]| plain::spherical_rectangle(u, c0, x, y).0,
        );
        polygon_entry(
            &mut g,
            "pbrt-v4",
            (p, r, &mut out),
            varying,
            |u: Vec2, [c0, x, y]| pbrt::spherical_rectangle(u.into(), c0, x, y).0,
        );
        polygon_entry(
            &mut g,
            "ours x8",
            (&packets, &rects8, &mut out8),
            varying,
            |u, [c0, x, y]| mcsample::warp::spherical_rectangle(u, c0, x, y).0,
        );
        g.finish();
    }
}

/// A caller's loop over structure-of-arrays slices, kept out of line as a renderer's own kernel
/// would be, with the warp inlined into it. Indexed as such loops are written, bounds checks
/// and all.
#[inline(never)]
fn soa_loop(
    f: impl Fn(Vec2) -> Vec3,
    u1: &[f32],
    u2: &[f32],
    (x, y, z): (&mut [f32], &mut [f32], &mut [f32]),
) {
    for i in 0..u1.len() {
        let w = f(Vec2::new(u1[i], u2[i]));
        x[i] = w.x;
        y[i] = w.y;
        z[i] = w.z;
    }
}

/// The simple warps in `soa_loop`: ours against the plain version, one group each.
fn soa(c: &mut Criterion) {
    let (pts, _, _) = points();
    let u1: Vec<f32> = pts.iter().map(|p| p.x).collect();
    let u2: Vec<f32> = pts.iter().map(|p| p.y).collect();
    let (mut x, mut y, mut z) = (vec![0.0f32; N], vec![0.0f32; N], vec![0.0f32; N]);
    let h = 0.5;
    macro_rules! pair {
        ($name:literal, $ours:expr, $plain:expr) => {{
            let mut g = c.benchmark_group(concat!("peers/soa ", $name));
            g.throughput(Throughput::Elements(N as u64));
            g.bench_function("ours scalar", |b| {
                b.iter(|| {
                    soa_loop(
                        $ours,
                        black_box(&u1),
                        black_box(&u2),
                        (&mut x, &mut y, &mut z),
                    );
                    black_box((&x, &y, &z));
                })
            });
            g.bench_function("plain glam", |b| {
                b.iter(|| {
                    soa_loop(
                        $plain,
                        black_box(&u1),
                        black_box(&u2),
                        (&mut x, &mut y, &mut z),
                    );
                    black_box((&x, &y, &z));
                })
            });
            g.finish();
        }};
    }
    pair!(
        "concentric_disk",
        |u| mcsample::warp::concentric_disk(u).extend(0.0),
        |u| plain::concentric_disk(u).extend(0.0)
    );
    pair!(
        "cosine_hemisphere",
        mcsample::warp::cosine_hemisphere,
        plain::cosine_hemisphere
    );
    pair!(
        "uniform_sphere",
        mcsample::warp::uniform_sphere,
        plain::uniform_sphere
    );
    pair!(
        "uniform_cone",
        |u| mcsample::warp::uniform_cone(u, h),
        |u| plain::uniform_cone(u, h)
    );
}

/// 2²⁴ points in structure-of-arrays slices, as Mitsuba's arrays hold them: the whole array
/// pass of each warp in both packet widths, one thread, storing as many outputs as Mitsuba's
/// warp returns (two for the disk and the triangle's barycentrics, three for directions), and
/// a copy kernel that moves the same bytes as the direction warps.
fn large_arrays(c: &mut Criterion) {
    const M: usize = 1 << 24;
    let mut rng = Pcg32::new(7, 11);
    let mut f = || (rng.next_u32() >> 8) as f32 * (1.0 / 16_777_216.0);
    let (u1, u2): (Vec<f32>, Vec<f32>) = (0..M).map(|_| (f(), f())).unzip();
    let (mut x, mut y, mut z) = (vec![0.0f32; M], vec![0.0f32; M], vec![0.0f32; M]);
    let mut g = c.benchmark_group("peers/2^24");
    g.throughput(Throughput::Elements(M as u64)).sample_size(10);
    // One array pass of width $w over lane type $l: `$body` maps the packet `u` to the outputs.
    macro_rules! pass {
        ($name:expr, $l:ty, $v2:ty, $w:literal, |$u:ident| $body:expr) => {
            g.bench_function($name, |b| {
                b.iter(|| {
                    let chunks = u1
                        .chunks_exact($w)
                        .zip(u2.chunks_exact($w))
                        .zip(x.chunks_exact_mut($w))
                        .zip(y.chunks_exact_mut($w))
                        .zip(z.chunks_exact_mut($w));
                    for ((((a, b), ox), oy), oz) in chunks {
                        let load = |s: &[f32]| <$l>::new(core::array::from_fn(|i| s[i]));
                        let $u = <$v2>::new(load(a), load(b));
                        let out: [Option<$l>; 3] = $body;
                        for (o, v) in [ox, oy, oz].into_iter().zip(out) {
                            if let Some(v) = v {
                                o.copy_from_slice(&v.to_array());
                            }
                        }
                    }
                    black_box((&x, &y, &z));
                })
            });
        };
    }
    macro_rules! both {
        ($warp:literal, |$u:ident| $body:expr) => {
            pass!(concat!($warp, " x8"), F32x8, Vec2x8, 8, |$u| $body);
            pass!(concat!($warp, " x16"), F32x16, Vec2x16, 16, |$u| $body);
        };
    }
    both!("copy", |u| [Some(u.x), Some(u.y), Some(u.x)]);
    both!("concentric_disk", |u| {
        let p = mcsample::warp::concentric_disk(u);
        [Some(p.x), Some(p.y), None]
    });
    both!("cosine_hemisphere", |u| {
        let w = mcsample::warp::cosine_hemisphere(u);
        [Some(w.x), Some(w.y), Some(w.z)]
    });
    both!("uniform_sphere", |u| {
        let w = mcsample::warp::uniform_sphere(u);
        [Some(w.x), Some(w.y), Some(w.z)]
    });
    // Mitsuba's cone takes cos θmax = 0.7: h = 1 − 0.7.
    both!("uniform_cone", |u| {
        let w = mcsample::warp::uniform_cone(u, Lane::c(0.3));
        [Some(w.x), Some(w.y), Some(w.z)]
    });
    both!("uniform_triangle", |u| {
        let b = mcsample::warp::uniform_triangle(u);
        [Some(b.x), Some(b.y), None]
    });
    g.finish();
}

criterion_group!(
    benches,
    warps,
    polygons,
    soa,
    tent_1d,
    random_points,
    large_arrays
);
criterion_main!(benches);
