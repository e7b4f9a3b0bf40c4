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

use std::f64::consts::PI;

use crate::common::TestRng;
use glam::{DVec2, DVec3, Vec2, Vec3};
use mcsample::verify::registry::{self, Sampler};
use mcsample::verify::{
    Cap, ChiSquare, ChiSquareResult, PlanarLight, sidak_alpha, triangle_to_square,
};
use mcsample::warp;
use mcsample::x8::{F32x8, Vec3x8};

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

/// The samplers under test: the registry, plus a wide triangle (4 sr-class, one vertex near the
/// horizon) that stresses the spherical map where its arcs are long.
fn samplers() -> Vec<Sampler> {
    let mut all = registry::registry();
    let wide = [
        Vec3::new(-2.4, -1.6, 0.3),
        Vec3::new(2.8, -1.2, 1.1),
        Vec3::new(0.4, 3.2, -0.1),
    ];
    all.push(warp::SolidAngleTriangle { v: wide }.into());
    all
}

/// The spherical polygons among [`samplers`].
fn polygons() -> Vec<Sampler> {
    samplers().into_iter().filter(|s| s.is_polygon()).collect()
}

/// 10⁶ u pairs of the shared test generator, as the indexable sequence the χ² harness reads.
fn u_table(seed: u64) -> impl Fn(usize) -> Vec2 {
    let mut rng = TestRng::new(seed);
    let us: Vec<Vec2> = (0..1_000_000).map(|_| rng.u2()).collect();
    move |i| us[i]
}

fn positive_cases() -> Vec<(String, ChiSquareResult)> {
    samplers()
        .into_iter()
        .enumerate()
        .map(|(k, s)| (s.name(), s.chi_square(1_000_000, u_table(k as u64 + 1))))
        .collect()
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
    for s in polygons() {
        for i in 0..20_000 {
            let (x, p) = s.sample(u(i));
            let q = s.pdf(x);
            // At the polygon's boundary the inside test can round either way.
            if q == 0.0 {
                continue;
            }
            let rel = ((p - q) / q).abs() as f64;
            worst = worst.max(rel);
            // The rectangle's pdf function recomputes Ω from the direction's frame: 1e-5.
            let tol = if matches!(s, Sampler::SphericalRectangle(_)) {
                1e-5
            } else {
                1e-6
            };
            assert!(
                rel < tol,
                "{}: sample pdf {p} vs pdf function {q} at {x}",
                s.name()
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
        |w| 1.05 * warp::cosine_hemisphere_pdf(w),
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
        |w| warp::phong_lobe_pdf(w, 20.0),
        6,
    );
    assert!(!r.passes(threshold), "phong with n − 1 accepted: {r}");

    // Spherical triangle samples against the pdf of the same triangle with one vertex moved by
    // 2 % of an edge: the pdf level and its support shift slightly.
    let Sampler::SphericalTriangle(warp::SolidAngleTriangle { v: [a, b, c] }) = polygons()[0]
    else {
        unreachable!()
    };
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
    // The midpoint rule on the zoomed cap, eight azimuths per pdf call: the packet pdf is the
    // scalar pdf lane by lane (warp::lanes), and a fifth of its time.
    fn integrate(cap: Cap, pdf: impl Fn(Vec3x8) -> F32x8, n: usize) -> f64 {
        assert_eq!(n % 8, 0);
        let azimuths: Vec<(f64, f64)> = (0..n)
            .map(|j| (2.0 * PI * (j as f64 + 0.5) / n as f64).sin_cos())
            .collect();
        let mut sum = 0.0;
        for i in 0..n {
            let zp = 1.0 - 2.0 * (i as f64 + 0.5) / n as f64;
            for phis in azimuths.chunks_exact(8) {
                let at: [(DVec3, f64); 8] = std::array::from_fn(|j| cap.unzoom_polar(zp, phis[j]));
                let p = pdf(Vec3x8::from(at.map(|(w, _)| w.as_vec3()))).to_array();
                sum += (0..8).map(|j| p[j] as f64 * at[j].1).sum::<f64>();
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
            integrate(Cap::z(1.0), warp::cosine_hemisphere_pdf, 1000),
            1e-5,
        ),
        (
            "uniform_sphere".into(),
            integrate(Cap::z(2.0), warp::uniform_sphere_pdf, 1000),
            1e-6,
        ),
        (
            "uniform_cone h=1e-3".into(),
            integrate(
                Cap::z(1e-3),
                |w| warp::uniform_cone_pdf(w, F32x8::splat(1e-3)),
                1000,
            ),
            1e-5,
        ),
    ];
    for n in [0.0f32, 1.0, 20.0, 500.0] {
        // The lobe lives within 1 − cos α < 40/n of the axis; beyond, cosⁿ is below e⁻⁴⁰.
        let hs = if n < 40.0 { 1.0 } else { 40.0 / n as f64 };
        cases.push((
            format!("phong_lobe n={n}"),
            integrate(
                Cap::z(hs),
                |w| warp::phong_lobe_pdf(w, F32x8::splat(n)),
                5000,
            ),
            1e-5,
        ));
    }
    for s in polygons() {
        let cap = match s {
            Sampler::SphericalTriangle(warp::SolidAngleTriangle { v })
            | Sampler::BilinearTriangle(warp::CosineTriangle { v, .. })
            | Sampler::ProjectedTriangle(warp::ProjectedSolidAngleTriangle { v, .. }) => {
                Cap::around(&v)
            }
            Sampler::SphericalRectangle(warp::SolidAngleRectangle { v: [c, ex, ey] })
            | Sampler::BilinearRectangle(warp::CosineRectangle { v: [c, ex, ey], .. })
            | Sampler::ProjectedRectangle(warp::ProjectedSolidAngleRectangle {
                v: [c, ex, ey],
                ..
            }) => Cap::around(&[c, c + ex, c + ey, c + ex + ey]),
            Sampler::ProjectedHexagon(warp::ProjectedSolidAngleHexagon { v, .. }) => {
                Cap::around(&warp::hexagon(v))
            }
            Sampler::ProjectedCap(warp::ProjectedSolidAngleCap { c, r, .. }) => {
                let s2 = (r as f64 / c.as_dvec3().length()).powi(2);
                Cap::new(c.as_dvec3(), (1.2 * warp::cone_h_from_sin2(s2)).min(2.0))
            }
            Sampler::SphericalEllipse(d) => Cap::around(&registry::disk_rim(&d)),
            _ => unreachable!(),
        };
        // 1504² directions leave the polygons within 6e-4 of 1, but the two tiny lights sampled
        // by area at 2.6e-3 and 2.1e-3; those take 3000².
        let n = if s.name().ends_with(" area") {
            3000
        } else {
            1504
        };
        cases.push((s.name(), integrate(cap, |w| s.pdf(w), n), 3e-3));
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
            tri += warp::uniform_triangle_pdf(DVec3::new(x, y, 1.0 - x - y).as_vec3()) as f64;
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

#[test]
fn registry_chi_square_rejects_a_sampler_with_the_wrong_pdf() {
    // Negative controls through the same domains and binning as `every_warp_passes_chi_square`: each sampler's
    // samples judged by a pdf that is slightly or grossly wrong.
    let hexagon = |n| warp::ProjectedSolidAngleHexagon {
        v: mcsample::registry::hexagon_axes(1.0),
        n,
    };
    let controls: [(Sampler, Sampler); 5] = [
        (
            warp::UniformCone { h: 0.3 }.into(),
            warp::UniformCone { h: 0.25 }.into(),
        ),
        (
            warp::CosineHemisphere.into(),
            warp::UniformHemisphere.into(),
        ),
        (
            warp::PhongLobe { n: 20.0 }.into(),
            warp::PhongLobe { n: 22.0 }.into(),
        ),
        (warp::PolarDisk.into(), warp::TentPair.into()),
        // On the fan's square: the cosine of a normal tilted by 37° where the samples follow
        // the normal's own.
        (
            hexagon(mcsample::registry::TILTED).into(),
            hexagon(Vec3::Z).into(),
        ),
    ];
    for (k, (s, judge)) in controls.into_iter().enumerate() {
        let r = s.chi_square_against(&judge, 200_000, u_table(99 + k as u64));
        assert!(
            r.p_value < 1e-6,
            "{} judged by {} accepted: {r}",
            s.name(),
            judge.name()
        );
    }
}
