//! The special-value sweep: every sampler of the registry (sample, pdf, inverse), the frame and
//! the sequence generators, in both widths, on the cross product of special u, special
//! parameters and degenerate geometry. It checks the documented bad-input policy:
//!
//! - nothing panics;
//! - u outside the contract but not NaN (negative, 2, ±∞, 1) is clamped: the sample is finite and
//!   in the domain, with a finite pdf ≥ 0, equal bit for bit to the pdf function at the sample;
//! - NaN in u gives canonical NaN in every coordinate (pdf 0), or for the spherical polygons a
//!   dropped sample (pdf 0, a finite point);
//! - degenerate parameters (h ≤ 0, coincident or collinear vertices, a light seen edge-on,
//!   non-finite vertices) give pdf 0, never NaN or ∞;
//! - lane i of every packet result equals the scalar result on lane i's input, bit for bit.
//!
//! The number of cases run is printed and asserted, so a shrinking sweep fails.
//!
//! The sweep runs optimised (opt-level 3) with overflow checks on, from Cargo.toml's test
//! profile, so an integer overflow in the library on these inputs panics here instead of
//! wrapping; `overflow_checks_are_on` fails if that profile loses them.

use crate::common::lanes;
use glam::{Vec2, Vec3};
use mcsample::frame::Frame;
use mcsample::seq;
use mcsample::verify::registry::{self, Kind, SPECIAL_PARAMS, Sampler};

/// The special u coordinates: 0, the smallest subnormal, 1e-30, 2⁻²⁴, ½, 1 − 2⁻²⁴, 1, NaN, −0,
/// −1e-30, 2 and ±∞.
const U_SPECIAL: [f32; 14] = [
    0.0,
    1e-45,
    1e-30,
    5.960_464_5e-8,
    0.5,
    0.999_999_94,
    1.0,
    f32::NAN,
    -0.0,
    -1e-30,
    2.0,
    f32::INFINITY,
    f32::NEG_INFINITY,
    0.3,
];

const CANONICAL_NAN: u32 = 0x7fc0_0000;

fn special_us() -> Vec<Vec2> {
    U_SPECIAL
        .iter()
        .flat_map(|&a| U_SPECIAL.iter().map(move |&b| Vec2::new(a, b)))
        .collect()
}

/// Points and directions that no sampler returns, for the pdfs and inverses.
fn special_points() -> Vec<Vec3> {
    let mut v = vec![
        Vec3::X,
        -Vec3::X,
        Vec3::Y,
        Vec3::Z,
        -Vec3::Z,
        Vec3::ZERO,
        Vec3::new(0.0, 0.0, -0.0),
        Vec3::new(1e-30, 0.0, 1.0),
        Vec3::new(0.6, 0.0, 0.8),
        Vec3::new(1e30, 1e30, 1e30),
        Vec3::new(f32::INFINITY, 0.0, 0.0),
        Vec3::new(0.0, f32::NEG_INFINITY, 1.0),
        Vec3::new(f32::NAN, 0.0, 1.0),
        Vec3::new(0.0, 0.0, f32::NAN),
        // NaN where a pdf reads only above the equator (the cone's 1 − cos θ).
        Vec3::new(0.3, f32::NAN, -0.5),
        Vec3::new(f32::NAN, 0.2, 0.0),
        Vec3::new(0.3, -0.2, 1e-7),
        Vec3::new(-0.3, -0.2, 1.0),
    ];
    v.extend(v.clone().iter().map(|p| p * 0.5));
    v
}

/// Every sampler to sweep: the registry at its parameters, each parametrised one at every
/// special parameter, and each spherical polygon at every degenerate geometry.
fn samplers() -> Vec<Sampler> {
    let mut all = registry::registry();
    // The warps' parameters: the lights' and BSDFs' are fuzzed (`fuzz/fuzz_targets/warps.rs`).
    for s in registry::registry() {
        if matches!(s.kind(), Kind::Warp(_)) && s.has_param() {
            all.extend(SPECIAL_PARAMS.iter().map(|&p| s.with_param(p)));
        }
    }
    let polygons = registry::registry().into_iter().filter(|s| s.is_polygon());
    // One of each kind is enough: the degenerate geometry replaces the registered one.
    for s in polygons.step_by(3) {
        all.extend(
            registry::degenerate_polygons()
                .into_iter()
                .map(|v| s.with_geometry(v)),
        );
    }
    all
}

#[test]
fn every_sampler_on_special_inputs_keeps_the_policy_in_both_widths() {
    let us = special_us();
    let points = special_points();
    let mut cases = 0usize;
    let mut failures = Vec::new();
    for s in samplers() {
        let name = format!("{} {s:?}", s.name());
        // Lanes: sample, then pdf and inverse at the samples and at the special points.
        let f = &mut failures;
        lanes!(f, &format!("{name}: sample lanes"), &us, |u: V2| s
            .sample(u));
        let mut xs: Vec<Vec3> = us.iter().map(|&u| s.sample(u).0).collect();
        xs.extend(&points);
        lanes!(f, &format!("{name}: pdf lanes"), &xs, |x: V3| s.pdf(x));
        lanes!(f, &format!("{name}: inverse lanes"), &xs, |x: V3| s
            .inverse(x));
        cases += 3 * us.len().max(xs.len());

        for &u in &us {
            cases += 1;
            if let Err(e) = s.check_sample(u) {
                failures.push(e);
            }
        }
        for &p in &points {
            cases += 1;
            if let Err(e) = s.check_point(p) {
                failures.push(e);
            }
        }
    }
    eprintln!("sweep: {cases} sampler cases");
    assert!(cases >= 40_000, "only {cases} cases");
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn frames_on_special_normals_keep_the_policy_in_both_widths() {
    let mut normals = special_points();
    normals.extend([
        Vec3::new(0.0, 0.0, -0.999_999_9),
        Vec3::new(1e-20, -1e-20, -1.0),
    ]);
    let vs = special_points();
    let mut cases = 0;
    let pairs: Vec<(Vec3, Vec3)> = normals
        .iter()
        .flat_map(|&n| vs.iter().map(move |&v| (n, v)))
        .collect();
    let mut failures = Vec::new();
    lanes!(&mut failures, "Frame", &pairs, |(n, v): (V3, V3)| {
        let f = Frame::from_normal(n);
        (f.t, f.to_local(v), f.to_world(v))
    });
    assert!(failures.is_empty(), "{}", failures.join("\n"));
    for &(n, v) in &pairs {
        cases += 1;
        let f = Frame::from_normal(n);
        for (what, w) in [
            ("t", f.t),
            ("b", f.b),
            ("local", f.to_local(v)),
            ("world", f.to_world(v)),
        ] {
            let nan_in = n.is_nan() || (what != "t" && what != "b" && v.is_nan());
            if nan_in {
                // NaN reaches every output it touches as the canonical NaN.
                let ok = w
                    .to_array()
                    .iter()
                    .all(|c| !c.is_nan() || c.to_bits() == CANONICAL_NAN);
                assert!(ok, "{what} of n = {n:?}, v = {v:?}: {w:?}");
            } else if n.is_finite() && n.length() <= 1.0 && v.is_finite() && v.length() < 1e3 {
                assert!(w.is_finite(), "{what} of n = {n:?}, v = {v:?}: {w:?}");
            }
        }
    }
    assert!(cases >= 1000, "only {cases} cases");
}

#[test]
fn generators_on_special_indices_and_counts_stay_in_the_unit_interval() {
    let indices = [
        0u32,
        1,
        7,
        255,
        1 << 23,
        1 << 24,
        1 << 31,
        u32::MAX - 1,
        u32::MAX,
    ];
    let counts = [0u32, 1, 2, 3, 1000, 1 << 23, 1 << 24, u32::MAX];
    let dims = [0u32, 1, 3, 4, 1023, u32::MAX];
    let seeds = [0u32, 1, u32::MAX];
    let mut cases = 0;
    let in01 = |x: f32| (0.0..1.0).contains(&x);
    let mut f = Vec::new();
    for &d in &dims {
        for &s in &seeds {
            let one = |i: u32| {
                (
                    seq::independent(i, d, s),
                    seq::sobol(i, d, s),
                    seq::sobol_2d(i, d, s),
                )
            };
            lanes!(&mut f, "sequences", &indices, |i: U| {
                (
                    seq::independent(i, d, s),
                    seq::sobol(i, d, s),
                    seq::sobol_2d(i, d, s),
                )
            });
            for &n in &counts {
                for &m in &counts {
                    let one = |i: u32| {
                        (
                            seq::stratified(i, n, d, s),
                            seq::jittered_2d(i, n, m, d, s),
                            seq::multi_jittered_2d(i, n, m, d, s),
                        )
                    };
                    lanes!(&mut f, "counted sequences", &indices, |i: U| {
                        (
                            seq::stratified(i, n, d, s),
                            seq::jittered_2d(i, n, m, d, s),
                            seq::multi_jittered_2d(i, n, m, d, s),
                        )
                    });
                    for &i in &indices {
                        cases += 1;
                        let (a, p, q) = one(i);
                        let c = seq::cmj_2d(i, n, m, d, s);
                        assert!(
                            in01(a) && [p, q, c].iter().all(|v| in01(v.x) && in01(v.y)),
                            "i {i} n {n} m {m} d {d} s {s}: {a} {p:?} {q:?} {c:?}"
                        );
                    }
                }
                for &i in &indices {
                    let (a, b, c) = one(i);
                    assert!(
                        in01(a) && in01(b) && in01(c.x) && in01(c.y),
                        "i {i} d {d} s {s}"
                    );
                }
            }
        }
    }
    assert!(f.is_empty(), "{}", f.join("\n"));
    assert!(cases >= 10_000, "only {cases} cases");
}

/// The known inconsistency of the spherical polygon samplers (open work: the scene issue asks
/// for it at the warp level). At u = (0, 0) a triangle's sample is its vertex, where the
/// edge-plane inside test of `spherical_triangle_pdf` says 0 and the inverse divides by a
/// rounding-sized cross product; a rectangle's returned pdf differs from
/// `spherical_rectangle_pdf` by rounding on a fraction of samples. Run with `--ignored` to see
/// the cases.
#[test]
#[ignore = "spherical polygon pdf and inverse disagree with the sampler at vertices and edges"]
fn spherical_polygons_pdf_and_inverse_agree_with_the_sampler() {
    let mut failures = Vec::new();
    for s in registry::registry().into_iter().filter(|s| s.is_polygon()) {
        for u in special_us().into_iter().filter(|u| !u.is_nan()) {
            let (x, pdf) = s.sample(u);
            if pdf.to_bits() != s.pdf(x).to_bits() {
                failures.push(format!(
                    "{}: u = {u:?}: pdf {pdf:e} vs pdf(x) {:e}",
                    s.name(),
                    s.pdf(x)
                ));
            }
            let back = s.inverse(x);
            if !back.is_finite() {
                failures.push(format!("{}: u = {u:?}: inverse {back:?}", s.name()));
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{} failures:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// Subnormal cones, found by the `warps` fuzz target: at h = 7.6e-41 the sample's x² + y²
/// rounds in the subnormal range, and a relative margin alone put the cone's own samples outside
/// its support. Wherever 1/(2πh) is finite (h ≥ 4.7e-40), every sample keeps its pdf; below, the
/// cone is degenerate and the pdf is 0, never ∞.
#[test]
fn subnormal_cones_keep_the_pdf_of_their_own_samples() {
    let mut us: Vec<Vec2> = (0..=64)
        .flat_map(|i| (0..=64).map(move |j| Vec2::new(i as f32 / 64.0, j as f32 / 64.0)))
        .collect();
    us.push(Vec2::new(1.0, 0.123));
    for h in [5e-40f32, 1e-39, 3e-39, 1e-38, 2e-38, 1e-37] {
        for &u in &us {
            let w = mcsample::warp::uniform_cone(u, h);
            let pdf = mcsample::warp::uniform_cone_pdf(w, h);
            let want = 0.5 / std::f64::consts::PI / h as f64;
            let err = (pdf as f64 - want).abs() / want;
            assert!(
                err <= 1e-6,
                "h = {h:e}, u = {u:?}, w = {w:?}: pdf {pdf:e}, want {want:e}"
            );
        }
    }
    for h in [7.5691e-41f32, 1e-44, 1e-45] {
        let w = mcsample::warp::uniform_cone(Vec2::new(0.5, 0.5), h);
        assert_eq!(mcsample::warp::uniform_cone_pdf(w, h), 0.0, "h = {h:e}");
    }
}

/// The test profile's overflow checks are what make the sweep find integer overflows in the
/// optimised library: an overflowing add must panic in this build.
#[test]
#[cfg_attr(
    target_family = "wasm",
    ignore = "wasm32-wasip1 aborts on panic, so the panic cannot be caught"
)]
fn overflow_checks_are_on() {
    let x = std::hint::black_box(u32::MAX);
    let overflowed = std::panic::catch_unwind(|| std::hint::black_box(x) + 1);
    assert!(
        overflowed.is_err(),
        "u32::MAX + 1 did not panic: overflow checks are off"
    );
}
