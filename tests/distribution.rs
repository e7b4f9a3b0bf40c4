//! Distribution: χ² goodness of fit of every warp against its own pdf (Jakob's χ² test from
//! Mitsuba: equal-area bins, expected counts integrated from the pdf, cells expecting fewer than
//! 5 pooled), with a Šidák correction over all of them, negative controls that must be rejected,
//! and ∫pdf = 1 by a quadrature independent of the harness.
//!
//! Narrow lobes and small lights are zoomed before binning: a cap of directions about an axis,
//! 1 − cos θ ∈ [0, hs], is stretched onto the whole sphere by z' = 1 − 2(1 − cos θ)/hs with the
//! azimuth kept. The stretch is equal-area up to the constant 2/hs, so the pdf per steradian of
//! the zoomed samples is pdf·hs/2, and 101 rows of cells resolve the lobe instead of one. A sample
//! outside the cap counts as outside the domain and fails the test.

mod common;

use std::f64::consts::PI;

use common::TestRng;
use glam::{DVec2, DVec3, Vec2, Vec3};
use mcsample::verify::{
    Cap, ChiSquare, ChiSquareResult, PlanarLight, sidak_alpha, square_to_triangle,
    triangle_to_square,
};
use mcsample::warp;

/// The u sequence: pairs of 24-bit floats in [0, 1) from the shared test generator.
fn u_seq(seed: u64) -> impl FnMut(usize) -> Vec2 {
    let mut rng = TestRng::new(seed);
    move |_| rng.u2()
}

/// χ² on a zoomed cap (see [`Cap`]) of an f32 sampler against an f32 pdf.
fn cap_test(
    cap: Cap,
    sample: impl FnMut(usize) -> Vec3,
    pdf: impl Fn(Vec3) -> f32,
    ires: usize,
) -> ChiSquareResult {
    cap.test(ChiSquare::sphere().ires(ires), sample, |w: DVec3| {
        pdf(w.as_vec3()) as f64
    })
}

/// The spherical polygons under test: (name, vertices, zoom cap). Sizes: a large light (≈1 sr),
/// a small one just above the spherical-sampling threshold, and one below it (area sampling).
fn triangles() -> Vec<(&'static str, [Vec3; 3])> {
    let tri = |s: f32, d: f32| {
        [
            Vec3::new(-0.6 * s, -0.4 * s, d),
            Vec3::new(0.7 * s, -0.3 * s, d + 0.2 * s),
            Vec3::new(0.1 * s, 0.8 * s, d - 0.1 * s),
        ]
    };
    vec![
        ("spherical_triangle large", tri(1.0, 1.0)),
        ("spherical_triangle small", tri(0.01, 1.0)),
        ("spherical_triangle area-sampled", tri(1e-3, 1.0)),
        ("spherical_triangle wide", tri(4.0, 0.3)),
    ]
}

fn rectangles() -> Vec<(&'static str, [Vec3; 3])> {
    let rect = |s: f32, d: f32| {
        [
            Vec3::new(-0.4 * s, -0.7 * s, d),
            Vec3::new(1.1 * s, 0.0, 0.3 * s),
            Vec3::new(0.0, 0.8 * s, 0.0),
        ]
    };
    vec![
        ("spherical_rectangle large", rect(1.0, 1.0)),
        ("spherical_rectangle small", rect(0.2, 1.0)),
        ("spherical_rectangle area-sampled", rect(0.05, 1.0)),
    ]
}

fn positive_cases() -> Vec<(String, ChiSquareResult)> {
    let inv_pi = 1.0 / PI;
    let mut out: Vec<(String, ChiSquareResult)> = Vec::new();
    let mut push = |name: &str, r: ChiSquareResult| out.push((name.to_string(), r));

    let mut u = u_seq(1);
    push(
        "concentric_disk",
        ChiSquare::disk().run(|i| warp::concentric_disk(u(i)), |_: DVec2| inv_pi),
    );
    let mut u = u_seq(2);
    push(
        "polar_disk",
        ChiSquare::disk().run(|i| warp::polar_disk(u(i)), |_: DVec2| inv_pi),
    );

    let hemi = Cap::z(1.0);
    let mut u = u_seq(3);
    // The support includes the horizon z = 0 (u₀ = 0), which the zoom puts on the bottom row's
    // edge: the test pdf must keep it.
    push(
        "uniform_hemisphere",
        cap_test(
            hemi,
            |i| warp::uniform_hemisphere(u(i)),
            warp::uniform_hemisphere_pdf,
            6,
        ),
    );
    let mut u = u_seq(4);
    push(
        "cosine_hemisphere",
        cap_test(
            hemi,
            |i| warp::cosine_hemisphere(u(i)),
            |w| warp::cosine_hemisphere_pdf(w.z),
            6,
        ),
    );
    let mut u = u_seq(5);
    push(
        "uniform_sphere",
        cap_test(
            Cap::z(2.0),
            |i| warp::uniform_sphere(u(i)),
            warp::uniform_sphere_pdf,
            6,
        ),
    );

    for (k, h) in [0.3f32, 1e-3].into_iter().enumerate() {
        let mut u = u_seq(10 + k as u64);
        push(
            &format!("uniform_cone h={h}"),
            cap_test(
                Cap::z(h as f64),
                |i| warp::uniform_cone(u(i), h),
                |w| warp::uniform_cone_pdf(w, h),
                6,
            ),
        );
    }
    for (k, (n, hs)) in [(1.0f32, 1.0), (20.0, 0.8), (500.0, 0.06)]
        .into_iter()
        .enumerate()
    {
        let mut u = u_seq(20 + k as u64);
        push(
            &format!("phong_lobe n={n}"),
            cap_test(
                Cap::z(hs),
                |i| warp::phong_lobe(u(i), n),
                |w| warp::phong_lobe_pdf(w.z, n),
                6,
            ),
        );
    }

    // Barycentrics mapped to the square by the equal-area (s, f) = ((b0+b1)², b1/(b0+b1)), so
    // that the triangle's diagonal edge becomes the square's boundary. Density 2 on the triangle
    // is 2·½ = 1 on the square.
    let mut u = u_seq(30);
    push(
        "uniform_triangle",
        ChiSquare::square().run(
            |i| {
                let b = warp::uniform_triangle(u(i)).as_dvec3();
                triangle_to_square(b.x, b.y)
            },
            |st: DVec2| 0.5 * warp::uniform_triangle_pdf(square_to_triangle(st).as_vec2()) as f64,
        ),
    );
    // Two independent tents, as a 2D density (1 − |x|)(1 − |y|) on [−1, 1]², scaled to the square.
    let mut u = u_seq(31);
    push(
        "tent",
        ChiSquare::square().run(
            |i| {
                let v = u(i);
                DVec2::new(
                    (warp::tent(v.x) as f64 + 1.0) / 2.0,
                    (warp::tent(v.y) as f64 + 1.0) / 2.0,
                )
            },
            |p: DVec2| {
                4.0 * warp::tent_pdf((2.0 * p.x - 1.0) as f32) as f64
                    * warp::tent_pdf((2.0 * p.y - 1.0) as f32) as f64
            },
        ),
    );

    for (k, (name, [a, b, c])) in triangles().into_iter().enumerate() {
        let mut u = u_seq(40 + k as u64);
        push(
            name,
            PlanarLight::triangle(a, b, c).test(
                ChiSquare::square(),
                |i| warp::spherical_triangle(u(i), a, b, c).0,
                |w| warp::spherical_triangle_pdf(w.as_vec3(), a, b, c) as f64,
            ),
        );
    }
    for (k, (name, [s, ex, ey])) in rectangles().into_iter().enumerate() {
        let mut u = u_seq(50 + k as u64);
        push(
            name,
            PlanarLight::parallelogram(s, ex, ey).test(
                ChiSquare::square(),
                |i| warp::spherical_rectangle(u(i), s, ex, ey).0,
                |w| warp::spherical_rectangle_pdf(w.as_vec3(), s, ex, ey) as f64,
            ),
        );
    }
    out
}

/// Every warp passes at the Šidák-corrected level α = 0.01 over all of them.
#[test]
fn every_warp_passes_chi_square() {
    let cases = positive_cases();
    let threshold = sidak_alpha(0.01, cases.len());
    let mut failures = Vec::new();
    for (name, r) in &cases {
        println!(
            "{name:40} p = {:.4}  dof = {}  ∫pdf = {:.6}",
            r.p_value, r.dof, r.pdf_integral
        );
        if !r.passes(threshold) {
            failures.push(format!("{name}: {r}"));
        }
    }
    assert!(
        failures.is_empty(),
        "threshold {threshold:.2e}; failed:\n{}",
        failures.join("\n")
    );
}

/// The samples of the sampled pdf must agree with the pdf function: the spherical polygon
/// samplers return a pdf with each sample, and it must be the pdf function's value there.
#[test]
fn returned_pdf_equals_pdf_function() {
    let mut u = u_seq(60);
    let mut worst = 0.0f64;
    for (name, [a, b, c]) in triangles() {
        for i in 0..20_000 {
            let (w, p) = warp::spherical_triangle(u(i), a, b, c);
            let q = warp::spherical_triangle_pdf(w, a, b, c);
            // At the polygon's boundary the inside test can round either way.
            if q == 0.0 {
                continue;
            }
            let rel = ((p - q) / q).abs() as f64;
            worst = worst.max(rel);
            assert!(
                rel < 1e-6,
                "{name}: sample pdf {p} vs pdf function {q} at {w}"
            );
        }
    }
    for (name, [s, ex, ey]) in rectangles() {
        for i in 0..20_000 {
            let (pt, p) = warp::spherical_rectangle(u(i), s, ex, ey);
            let q = warp::spherical_rectangle_pdf(pt.normalize(), s, ex, ey);
            if q == 0.0 {
                continue;
            }
            let rel = ((p - q) / q).abs() as f64;
            assert!(
                rel < 1e-5,
                "{name}: sample pdf {p} vs pdf function {q} at {pt}"
            );
        }
    }
    println!("worst relative difference {worst:e}");
}

/// The test must reject broken samplers: a goodness-of-fit test that has never rejected anything
/// proves nothing, so each control here is a known-broken sampler or pdf that must fail.
#[test]
fn negative_controls_are_rejected() {
    let inv_pi = 1.0 / PI;
    let threshold = sidak_alpha(0.01, 20);

    // The disk with r = u instead of √u.
    let mut u = u_seq(70);
    let r = ChiSquare::disk().run(
        |i| {
            let v = u(i);
            warp::polar_disk(Vec2::new(v.x * v.x, v.y))
        },
        |_: DVec2| inv_pi,
    );
    assert!(
        !r.passes(threshold) && r.p_value < 1e-9,
        "r = u accepted: {r}"
    );

    // A pdf scaled by 1.05.
    let mut u = u_seq(71);
    let r = cap_test(
        Cap::z(1.0),
        |i| warp::cosine_hemisphere(u(i)),
        |w| 1.05 * warp::cosine_hemisphere_pdf(w.z),
        6,
    );
    assert!(
        !r.passes(threshold) && r.p_value < 1e-9,
        "pdf × 1.05 accepted: {r}"
    );

    // Cosine-weighted samples against the uniform pdf.
    let mut u = u_seq(72);
    let r = cap_test(
        Cap::z(1.0),
        |i| warp::cosine_hemisphere(u(i)),
        warp::uniform_hemisphere_pdf,
        6,
    );
    assert!(
        !r.passes(threshold) && r.p_value < 1e-9,
        "cosine vs uniform accepted: {r}"
    );

    // A Phong lobe sampled with the naive exponent n instead of n + 1 (a subtle error).
    let mut u = u_seq(73);
    let r = cap_test(
        Cap::z(0.8),
        |i| warp::phong_lobe(u(i), 19.0),
        |w| warp::phong_lobe_pdf(w.z, 20.0),
        6,
    );
    assert!(!r.passes(threshold), "phong with n − 1 accepted: {r}");

    // Spherical triangle samples against the pdf of the same triangle with one vertex moved by
    // 2 % of an edge: the pdf level and its support shift slightly.
    let [a, b, c] = triangles()[0].1;
    let moved = c + (b - a) * 0.02;
    let mut u = u_seq(74);
    let r = PlanarLight::triangle(a, b, c).test(
        ChiSquare::square(),
        |i| warp::spherical_triangle(u(i), a, b, c).0,
        |w| warp::spherical_triangle_pdf(w.as_vec3(), a, b, moved) as f64,
    );
    assert!(
        !r.passes(threshold),
        "triangle against a moved vertex's pdf accepted: {r}"
    );

    // Barycentrics from the √u₀ map with its outputs swapped for u₀ > ½: every point still lies
    // in the triangle, but the density is not uniform.
    let mut u = u_seq(75);
    let r = ChiSquare::square().run(
        |i| {
            let v = u(i);
            let r = (v.x as f64).sqrt();
            let (b0, b1) = (1.0 - r, r * v.y as f64);
            let (b0, b1) = if v.x > 0.5 { (b1, b0) } else { (b0, b1) };
            triangle_to_square(b0, b1)
        },
        |_: DVec2| 1.0,
    );
    assert!(
        !r.passes(threshold),
        "a non-uniform triangle map accepted: {r}"
    );
}

/// ∫pdf = 1 over each warp's domain, by a midpoint rule on a fine equal-area grid of the cap
/// (independent of the χ² harness's trapezoid rule).
#[test]
fn every_pdf_integrates_to_one() {
    fn integrate(cap: Cap, pdf: impl Fn(Vec3) -> f32, n: usize) -> f64 {
        let mut sum = 0.0;
        for i in 0..n {
            let zp = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
            let rp = ((1.0 - zp) * (1.0 + zp)).sqrt();
            for j in 0..n {
                let phi = 2.0 * PI * (j as f64 + 0.5) / n as f64;
                let (w, k) = cap.unzoom(DVec3::new(rp * phi.cos(), rp * phi.sin(), zp));
                sum += pdf(w.as_vec3()) as f64 * k;
            }
        }
        sum * 4.0 * PI / (n * n) as f64
    }
    let mut cases: Vec<(String, f64, f64)> = vec![
        (
            "uniform_hemisphere".into(),
            integrate(Cap::z(1.0), warp::uniform_hemisphere_pdf, 1000),
            1e-6,
        ),
        (
            "cosine_hemisphere".into(),
            integrate(Cap::z(1.0), |w| warp::cosine_hemisphere_pdf(w.z), 1000),
            1e-5,
        ),
        (
            "uniform_sphere".into(),
            integrate(Cap::z(2.0), warp::uniform_sphere_pdf, 1000),
            1e-6,
        ),
        (
            "uniform_cone h=1e-3".into(),
            integrate(Cap::z(1e-3), |w| warp::uniform_cone_pdf(w, 1e-3), 1000),
            1e-5,
        ),
    ];
    for n in [0.0f32, 1.0, 20.0, 500.0] {
        // The lobe lives within 1 − cos α < 40/n of the axis; beyond, cosⁿ is below e⁻⁴⁰.
        let hs = if n < 40.0 { 1.0 } else { 40.0 / n as f64 };
        cases.push((
            format!("phong_lobe n={n}"),
            integrate(Cap::z(hs), |w| warp::phong_lobe_pdf(w.z, n), 5000),
            1e-5,
        ));
    }
    for (name, [a, b, c]) in triangles() {
        let cap = Cap::around(&[a, b, c]);
        cases.push((
            name.into(),
            integrate(cap, |w| warp::spherical_triangle_pdf(w, a, b, c), 3000),
            3e-3,
        ));
    }
    for (name, [s, ex, ey]) in rectangles() {
        let cap = Cap::around(&[s, s + ex, s + ey, s + ex + ey]);
        cases.push((
            name.into(),
            integrate(cap, |w| warp::spherical_rectangle_pdf(w, s, ex, ey), 3000),
            3e-3,
        ));
    }
    // Planar: the disk and triangle densities on their squares, the tent on [−1, 1].
    let m = 4000;
    let mut tri = 0.0;
    let mut tent = 0.0;
    for i in 0..m {
        let x = (i as f64 + 0.5) / m as f64;
        tent += warp::tent_pdf((2.0 * x - 1.0) as f32) as f64 * 2.0 / m as f64;
        for j in 0..m {
            let y = (j as f64 + 0.5) / m as f64;
            tri += warp::uniform_triangle_pdf(DVec2::new(x, y).as_vec2()) as f64;
        }
    }
    cases.push(("uniform_triangle".into(), tri / (m * m) as f64, 1e-3));
    cases.push(("tent".into(), tent, 1e-6));
    // The unit disk's pdf over the square [−1, 1]² by the midpoint rule: cells cut by the rim
    // leave an error of the order of the cell size, 1e-3.
    let k = 2000;
    let cell = 2.0 / k as f64;
    let disk: f64 = (0..k * k)
        .map(|i| {
            let x = -1.0 + (i % k) as f64 * cell + cell / 2.0;
            let y = -1.0 + (i / k) as f64 * cell + cell / 2.0;
            warp::uniform_disk_pdf(Vec2::new(x as f32, y as f32)) as f64
        })
        .sum::<f64>()
        * cell
        * cell;
    cases.push(("uniform_disk".into(), disk, 1e-3));

    let bad: Vec<String> = cases
        .iter()
        .filter(|(_, v, tol)| (v - 1.0).abs().partial_cmp(tol) != Some(std::cmp::Ordering::Less))
        .map(|(n, v, tol)| format!("{n}: ∫pdf = {v} (tolerance {tol})"))
        .collect();
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}
