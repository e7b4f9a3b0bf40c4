//! Evidence driven by the registry of samplers (`mcsample::verify::registry`): every registered
//! sampler, at every registered parameter, gets the same checks, so a new sampler is covered by
//! adding it there.
//!
//! - the packet form equals the scalar form bit for bit (sample, pdf, inverse);
//! - the f32 sample is within 2e-6 of the f64 instance of the same code (directions and points
//!   of the unit domains; for the light-sized rectangle, relative to its distance), and its pdf
//!   within 1e-5 relative of the f64 pdf at the same point;
//! - inverse(sample(u)) returns u within the sampler's stated tolerance;
//! - χ² of 2·10⁵ samples against the pdf passes at the Šidák-corrected level, and a sampler
//!   tested against the wrong pdf is rejected.

use glam::{Vec2, Vec3};
use mcsample::verify::registry::{self, Sampler};
use mcsample::verify::{check_lanes, sidak_alpha};
use mcsample::x8::{Vec2x8, Vec3x8};

/// Interior u on a stratified grid with a hashed jitter, plus the lines where maps change branch.
fn interior_us(n: usize) -> Vec<Vec2> {
    let mut v = Vec::with_capacity(n * n + 64);
    let mut h = 0x2545_f491u32;
    let mut next = move || {
        h ^= h << 13;
        h ^= h >> 17;
        h ^= h << 5;
        (h >> 8) as f32 / 16_777_216.0
    };
    for i in 0..n {
        for j in 0..n {
            v.push(Vec2::new(
                (i as f32 + next()) / n as f32,
                (j as f32 + next()) / n as f32,
            ));
        }
    }
    for k in 1..32 {
        let t = k as f32 / 32.0;
        v.push(Vec2::new(0.5, t));
        v.push(Vec2::new(t, 0.5));
    }
    v
}

#[test]
fn packets_equal_scalars_for_every_registered_sampler() {
    let us = interior_us(128);
    for s in registry::registry() {
        check_lanes(&us, |u: Vec2x8| s.sample(u), |u: Vec2| s.sample(u))
            .unwrap_or_else(|e| panic!("{} sample: {e}", s.name()));
        let xs: Vec<Vec3> = us.iter().map(|&u| s.sample(u).0).collect();
        check_lanes(&xs, |x: Vec3x8| s.pdf(x), |x: Vec3| s.pdf(x))
            .unwrap_or_else(|e| panic!("{} pdf: {e}", s.name()));
        check_lanes(&xs, |x: Vec3x8| s.inverse(x), |x: Vec3| s.inverse(x))
            .unwrap_or_else(|e| panic!("{} inverse: {e}", s.name()));
    }
}

#[test]
fn f32_samples_and_pdfs_match_the_f64_instance() {
    let us = interior_us(256);
    let mut failures = Vec::new();
    for s in registry::registry() {
        let (mut worst, mut worst_pdf) = (0.0f64, 0.0f64);
        for &u in &us {
            let (x, pdf) = s.sample(u);
            let (r, _) = s.sample(u.as_dvec2());
            // The pdf at the same point: near a steep lobe the two samples' pdfs differ by the
            // slope times the sample's own error, which is not the pdf's error.
            let pdf_r = s.pdf(x.as_dvec3());
            let scale = match s {
                Sampler::SphericalRectangle { .. } => r.length(),
                _ => 1.0,
            };
            let e = (x.as_dvec3() - r).length() / scale;
            worst = if e > worst || e.is_nan() { e } else { worst };
            if pdf_r > 0.0 {
                let ep = (pdf as f64 - pdf_r).abs() / pdf_r;
                worst_pdf = if ep > worst_pdf || ep.is_nan() {
                    ep
                } else {
                    worst_pdf
                };
            }
        }
        if !(worst <= 2e-6 && worst_pdf <= 1e-5) {
            failures.push(format!("{}: point {worst:e}, pdf {worst_pdf:e}", s.name()));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn inverse_returns_the_sample_u() {
    // Away from the edges, where several maps are ill-conditioned (the pole, the apex).
    let us: Vec<Vec2> = interior_us(128)
        .into_iter()
        .filter(|u| u.min_element() > 0.01 && u.max_element() < 0.99)
        .collect();
    let mut failures = Vec::new();
    for s in registry::registry() {
        let tol = s.roundtrip_tolerance();
        let worst = us
            .iter()
            .map(|&u| (s.inverse(s.sample(u).0) - u).abs().max_element())
            .fold(0.0f32, |a, e| if e > a || e.is_nan() { e } else { a });
        if worst.is_nan() || worst > tol {
            failures.push(format!(
                "{}: |inverse(sample(u)) − u| = {worst:e} > {tol:e}",
                s.name()
            ));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// A low-discrepancy-free u stream for χ²: a counter hash (any decent hash will do).
fn hashed_u(seed: u32) -> impl Fn(usize) -> Vec2 {
    move |i| {
        let h = |k: u32| {
            let mut x = (i as u32).wrapping_mul(0x9e37_79b9) ^ k ^ seed.wrapping_mul(0x85eb_ca6b);
            x ^= x >> 16;
            x = x.wrapping_mul(0x7feb_352d);
            x ^= x >> 15;
            x = x.wrapping_mul(0x846c_a68b);
            x ^= x >> 16;
            (x >> 8) as f32 / 16_777_216.0
        };
        Vec2::new(h(0x1234_5678), h(0x8765_4321))
    }
}

#[test]
fn every_registered_sampler_passes_chi_square() {
    let all = registry::registry();
    let alpha = sidak_alpha(0.01, all.len());
    let mut failures = Vec::new();
    for (k, s) in all.iter().enumerate() {
        let r = s.chi_square(200_000, hashed_u(k as u32 + 1));
        if !r.passes(alpha) {
            failures.push(format!("{}: {r}", s.name()));
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn chi_square_rejects_a_sampler_with_the_wrong_pdf() {
    // Negative controls through the same domains and binning as the test above: each sampler's
    // samples judged by a pdf that is slightly or grossly wrong.
    let controls = [
        (
            Sampler::UniformCone { h: 0.3 },
            Sampler::UniformCone { h: 0.25 },
        ),
        (Sampler::CosineHemisphere, Sampler::UniformHemisphere),
        (
            Sampler::PhongLobe { n: 20.0 },
            Sampler::PhongLobe { n: 22.0 },
        ),
        (Sampler::PolarDisk, Sampler::Tent),
    ];
    for (k, (s, judge)) in controls.into_iter().enumerate() {
        let r = s.chi_square_against(&judge, 200_000, hashed_u(99 + k as u32));
        assert!(
            r.p_value < 1e-6,
            "{} judged by {} accepted: {r}",
            s.name(),
            judge.name()
        );
    }
}
