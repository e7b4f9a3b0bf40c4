//! Sphere lights sampled by projected solid angle (Peters & Dachsbacher, "Sampling Projected
//! Spherical Caps in Real Time", I3D 2019; the lune of Ureña & Georgiev, EGSR 2018).
//!
//! Facts checked: the projected area P equals the sphere's irradiance at radiance 1 (Snyder's
//! closed form across the horizon, π sin²σ cos θ above it) in all three cases; sampling with pdf
//! n·ω / P makes the cosine estimator exact for every sample; a cap centred at the zenith (no
//! direction towards the centre in the tangent plane) and one centred below the horizon; bad
//! input; lane i of the eight-wide form is the scalar call, with a different sphere per lane.

use glam::{DVec3, Vec2, Vec3};
use mcsample::reference::sphere_irradiance;
use mcsample::warp::{CAP_MAX_SPREAD, ProjectedCap, projected_cap, projected_cap_pdf};
use mcsample::x8::{F32x8, Vec2x8, Vec3x8};

use crate::common::TestRng;

/// A sphere seen from the origin with the normal +z: its centre's elevation β (radians), its
/// sin α, its distance.
fn sphere(beta: f64, phi: f64, sin_a: f64, d: f64) -> (Vec3, f32) {
    let c = DVec3::new(beta.cos() * phi.cos(), beta.cos() * phi.sin(), beta.sin()) * d;
    (c.as_vec3(), (sin_a * d) as f32)
}

/// The irradiance of the f32 sphere, in f64.
fn irradiance(c: Vec3, r: f32, n: Vec3) -> f64 {
    let (c, n) = (c.as_dvec3(), n.as_dvec3().normalize());
    let sigma = (r as f64 / c.length()).asin();
    sphere_irradiance(sigma, (c.dot(n) / c.length()).clamp(-1.0, 1.0).acos())
}

/// A random sphere, mostly across or near the horizon: elevation in [−0.6, 1.6] rad, sin α from
/// 1e-3 to 0.95, at distance 1 to 6, and a random unit normal it is expressed against.
fn random_case(rng: &mut TestRng) -> (Vec3, f32, f64) {
    let beta = (rng.u01() as f64 * 2.2 - 0.6).min(std::f64::consts::FRAC_PI_2);
    let phi = rng.u01() as f64 * std::f64::consts::TAU;
    let sin_a = 10f64.powf(-3.0 * rng.u01() as f64) * 0.95;
    let d = 1.0 + 5.0 * rng.u01() as f64;
    let (c, r) = sphere(beta, phi, sin_a, d);
    (c, r, sin_a)
}

/// P is the sphere's irradiance within 1e-6 relative wherever the map samples by projected solid
/// angle, in all three cases (counted: each must occur), and the falls back to the cone happen
/// only for lunes cancelling beyond CAP_MAX_SPREAD. (Measured: 6e-8, except 2.4e-6 where the
/// reference's own terms cancel, a thin lune of a tiny cap, spread above 256.)
#[test]
fn projected_area_is_the_sphere_irradiance() {
    let mut rng = TestRng::new(41);
    let (mut worst, mut cases) = (0.0f64, [0usize; 4]);
    for _ in 0..100_000 {
        let (c, r, _) = random_case(&mut rng);
        let cap = ProjectedCap::new(c, r, Vec3::Z);
        let reference = irradiance(c, r, Vec3::Z);
        let p = cap.projected_area() as f64;
        if reference == 0.0 {
            assert_eq!(p, 0.0, "{c} {r}");
            cases[3] += 1;
            continue;
        }
        if cap.by_solid_angle() {
            assert!(
                cap.spread() > CAP_MAX_SPREAD,
                "{c} {r}: fell back at {}",
                cap.spread()
            );
            cases[3] += 1;
            continue;
        }
        let (ellipse, lune) = cap.pieces();
        cases[usize::from(lune) + usize::from(lune && !ellipse)] += 1;
        let rel = (p - reference).abs() / reference;
        let bound = if cap.spread() < 256.0 { 1e-6 } else { 1e-5 };
        assert!(rel < bound, "{c} {r}: P {p} vs {reference} ({rel:e})");
        worst = worst.max(rel);
    }
    println!("cases above/across/below/other {cases:?}; worst P {worst:.2e}");
    assert!(cases.iter().all(|&k| k > 5_000), "{cases:?}");
}

/// Zero variance: on 10⁵ random spheres sampled by projected solid angle, every single-sample
/// cosine estimate cos θ / pdf of a receiver under radiance 1 is the irradiance within 1e-5.
/// The negative control: estimating with the ellipse alone (an unclipped cap, the lune left out)
/// fails the same bound on more than 95 % of the spheres across the horizon (the rest are caps
/// whose lune is below 1e-5 of P).
#[test]
fn cosine_estimates_have_no_variance() {
    let mut rng = TestRng::new(42);
    let (mut worst, mut checked, mut control_misses, mut across) = (0.0f64, 0, 0, 0);
    while checked < 100_000 {
        let (c, r, sin_a) = random_case(&mut rng);
        let cap = ProjectedCap::new(c, r, Vec3::Z);
        if cap.by_solid_angle() {
            continue;
        }
        let reference = irradiance(c, r, Vec3::Z);
        let (w, pdf) = cap.sample(rng.u2());
        if pdf == 0.0 {
            // A sample exactly on the horizon (u₀ = 0 in the lune), where the cosine is 0.
            assert!(w.z.abs() < 1e-6, "{c} {r}: dropped {w}");
            continue;
        }
        checked += 1;
        let estimate = w.z as f64 / pdf as f64;
        let rel = (estimate - reference).abs() / reference;
        assert!(
            rel < 1e-5,
            "{c} {r}: {w} {pdf} gives {estimate} vs {reference}"
        );
        worst = worst.max(rel);
        let (ellipse, lune) = cap.pieces();
        if ellipse && lune {
            across += 1;
            let cz = c.normalize().z as f64;
            let unclipped = std::f64::consts::PI * sin_a * sin_a * cz;
            if (unclipped - reference).abs() > 1e-5 * reference {
                control_misses += 1;
            }
        }
    }
    println!("worst estimate {worst:.2e}; control misses {control_misses}/{across}");
    assert!(
        across > 5_000 && control_misses * 20 > across * 19,
        "{control_misses}/{across}"
    );
}

/// A cap centred exactly on the normal has no azimuth towards its centre; it is the whole
/// ellipse (a disk of radius sin α about the zenith), P = π sin²α, and samples and inverses are
/// finite. Also at the normal −z: wholly below, P = 0, pdf 0 everywhere.
#[test]
fn cap_centred_at_the_zenith() {
    let cap = ProjectedCap::new(Vec3::new(0.0, 0.0, 2.0), 1.0, Vec3::Z);
    let p = std::f64::consts::PI * 0.25;
    assert!((cap.projected_area() as f64 - p).abs() < 1e-7 * p);
    let mut rng = TestRng::new(43);
    for _ in 0..1000 {
        let u = rng.u2();
        let (w, pdf) = cap.sample(u);
        assert!(w.is_finite() && pdf > 0.0, "{u}: {w} {pdf}");
        assert!((w.z as f64 / pdf as f64 - p).abs() < 1e-6 * p);
        assert!(
            1.0 - w.z <= 1.0 - 0.75f32.sqrt() + 1e-6,
            "{w} outside the cap"
        );
        let back = cap.inverse(w);
        assert!((back.x - u.x).abs() < 1e-5, "{u} → {back}");
    }
    let below = ProjectedCap::new(Vec3::new(0.0, 0.0, 2.0), 1.0, Vec3::NEG_Z);
    assert_eq!(below.projected_area(), 0.0);
    assert_eq!(below.sample(Vec2::new(0.3, 0.6)), (Vec3::Z, 0.0));
    assert_eq!(below.pdf(Vec3::Z), 0.0);
}

/// The three cases at a named geometry each: sin α = 0.5 with the centre at elevation 60°
/// (above), 20° (across: ellipse and lune) and −20° (below: the lune alone); P against the
/// closed forms, and the sampled directions on the cap, above the horizon.
#[test]
fn the_three_cases() {
    let names = ["above", "across", "below"];
    for (deg, name) in [60.0f64, 20.0, -20.0].into_iter().zip(names) {
        let (c, r) = sphere(deg.to_radians(), 0.7, 0.5, 3.0);
        let cap = ProjectedCap::new(c, r, Vec3::Z);
        let expected = match name {
            "above" => (true, false),
            "across" => (true, true),
            _ => (false, true),
        };
        assert_eq!(cap.pieces(), expected, "{name}");
        let reference = irradiance(c, r, Vec3::Z);
        let p = cap.projected_area() as f64;
        assert!(
            (p - reference).abs() < 1e-6 * reference,
            "{name}: {p} vs {reference}"
        );
        let mut rng = TestRng::new(44);
        let axis = c.normalize();
        for _ in 0..2000 {
            let (w, pdf) = cap.sample(rng.u2());
            assert!(w.z >= 0.0 && (pdf > 0.0 || w.z == 0.0), "{name}: {w} {pdf}");
            assert!(
                w.cross(axis).length() <= 0.5 + 1e-6 && w.dot(axis) > 0.0,
                "{name}: {w}"
            );
        }
    }
}

/// Bad input: NaN u, a point inside the sphere, a zero radius, non-finite centres and radii give
/// pdf 0 and +z; a zero or non-finite normal samples the cone; u = 1 and negative u are clamped;
/// nothing is NaN.
#[test]
fn bad_input() {
    let c = Vec3::new(1.0, 0.5, 2.0);
    let z = (Vec3::Z, 0.0);
    assert_eq!(projected_cap(Vec2::new(f32::NAN, 0.5), c, 0.5, Vec3::Z), z);
    assert_eq!(projected_cap(Vec2::new(0.3, 0.5), c, 5.0, Vec3::Z), z);
    assert_eq!(projected_cap(Vec2::new(0.3, 0.5), c, 0.0, Vec3::Z), z);
    for bad in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
        let v = Vec3::new(bad, 0.5, 2.0);
        assert_eq!(
            projected_cap(Vec2::new(0.3, 0.5), v, 0.5, Vec3::Z),
            z,
            "{bad}"
        );
        // Without a usable normal, the cone: pdf 1/(2π(1 − cos α)) on the cap.
        let (w, pdf) = projected_cap(Vec2::new(0.3, 0.5), c, 0.5, v);
        let cone = projected_cap(Vec2::new(0.3, 0.5), c, 0.5, Vec3::ZERO);
        assert_eq!((w, pdf), cone, "{bad}");
        let h = mcsample::warp::cone_h_from_sin2(0.25 / c.length_squared());
        assert!(
            (pdf * std::f32::consts::TAU * h - 1.0).abs() < 1e-5,
            "{bad}: {pdf}"
        );
        assert_eq!(
            projected_cap(Vec2::new(0.3, 0.5), c, bad, Vec3::Z),
            z,
            "{bad}"
        );
        assert_eq!(
            projected_cap_pdf(Vec3::new(bad, 0.0, 1.0), c, 0.5, Vec3::Z),
            0.0
        );
    }
    // Found by the fuzzer: a sphere 10²⁰ radii away has P ≈ 1e-40, whose cos θ / P overflowed
    // (now the cone, whose own pdf overflows too: dropped); a subnormal normal has no f32 unit
    // vector, and gave NaN directions (now the cone).
    let far = Vec3::new(5.880012e19, 3.689349e19, 2.3058078e18);
    let (w, pdf) = projected_cap(Vec2::new(0.0, 0.0), far, 0.5, Vec3::splat(0.5));
    assert_eq!((w, pdf), (Vec3::Z, 0.0));
    assert!(ProjectedCap::new(far, 0.5, Vec3::splat(0.5)).by_solid_angle());
    // At a lune's horn (u = (1, 0): depth W at y = −y_c) rounding put the direction just off
    // the cap, 3e-4 above the horizon: dropped to +z, not kept where it would not invert.
    let near = Vec3::new(0.0, -8.808098e-5, -4.0267474e-23);
    let (w, pdf) = projected_cap(Vec2::new(1.0, 0.0), near, 8.045271e-5, Vec3::splat(0.5));
    assert!(pdf > 0.0 || w == Vec3::Z, "{w} {pdf}");
    // At the other horn (u = (1, 1)) the lune's width is 0: the inverse divided 0 by it (NaN).
    let c2 = Vec3::new(48.56861, 204.88766, 195.26274);
    let n2 = Vec3::new(-1.5099264e-13, 1.5672303e-38, 1.7643896e-38);
    let cap = ProjectedCap::new(c2, 1.9526274e2, n2);
    let (w, _) = cap.sample(Vec2::ONE);
    let back = cap.inverse(w);
    assert!(
        back.cmpge(Vec2::ZERO).all() && back.cmple(Vec2::ONE).all(),
        "{back}"
    );
    // A centre 2e-22 rad from the normal: the azimuth's squares fell into f32's subnormals,
    // the turned frame was not orthonormal, and the sample 0.4 % off unit length.
    let c3 = Vec3::new(-24.219606, 2.423e-42, 0.0);
    let n3 = Vec3::new(-3.5834427e21, 0.5, 0.5);
    let (w, pdf) = projected_cap(Vec2::new(1.0, 1.5564642e-33), c3, 2.4219238e1, n3);
    assert!(pdf > 0.0 && (w.length() - 1.0).abs() < 1e-6, "{w} {pdf}");
    let subnormal = Vec3::new(9.1834e-41, 0.0, 0.0);
    let (w, pdf) = projected_cap(Vec2::new(0.3, 0.6), c, 0.5, subnormal);
    assert_eq!(
        (w, pdf),
        projected_cap(Vec2::new(0.3, 0.6), c, 0.5, Vec3::ZERO)
    );
    assert!(w.is_finite() && pdf > 0.0);
    for u in [
        Vec2::ONE,
        Vec2::new(-1.0, 2.0),
        Vec2::new(f32::INFINITY, 0.0),
    ] {
        let (w, pdf) = projected_cap(u, c, 0.5, Vec3::Z);
        assert!(
            w.is_finite() && pdf.is_finite() && pdf >= 0.0,
            "{u}: {w} {pdf}"
        );
    }
    // The pdf of a direction is the pdf of any positive multiple of it: its squared length is
    // kept in range by rescaling, not overflowed (1e20 and beyond) or flushed (1e-20 and below).
    let (w, pdf) = projected_cap(Vec2::new(0.3, 0.6), c, 0.5, Vec3::Z);
    assert!(pdf > 0.0);
    for k in [1e-37f32, 1e-30, 1e-20, 1e-12, 1e12, 1e20, 1e30, 1e37] {
        let scaled = projected_cap_pdf(w * k, c, 0.5, Vec3::Z);
        assert!(
            (scaled / pdf - 1.0).abs() < 1e-6,
            "{k}: {scaled} against {pdf}"
        );
    }
    // Zero, a subnormal largest component and an infinite one have no direction: pdf 0.
    for v in [Vec3::ZERO, w * 1e-40, Vec3::new(f32::INFINITY, 0.0, 1.0)] {
        assert_eq!(projected_cap_pdf(v, c, 0.5, Vec3::Z), 0.0, "{v}");
    }
    // A huge and a tiny scene give the same map as the unit one (f64 set-up, scaled frames).
    for k in [1e-20f32, 1e20] {
        let (w, pdf) = projected_cap(Vec2::new(0.3, 0.6), c * k, 0.5 * k, Vec3::Z);
        let (w1, pdf1) = projected_cap(Vec2::new(0.3, 0.6), c, 0.5, Vec3::Z);
        assert!(
            (w - w1).length() < 1e-6 && (pdf / pdf1 - 1.0).abs() < 1e-5,
            "{k}"
        );
    }
}

/// Lane i of the eight-wide map is the scalar map of lane i's sphere, bit for bit, with the
/// three cases and the fallback mixed in one packet (each lane solves its own lune).
#[test]
fn lanes_are_the_scalar_map() {
    let mut rng = TestRng::new(45);
    for _ in 0..2000 {
        let cases: [(Vec3, f32, f64); 8] = std::array::from_fn(|_| random_case(&mut rng));
        let n = Vec3::new(0.1, -0.2, 1.0);
        let us: [Vec2; 8] = std::array::from_fn(|_| rng.u2());
        let c8 = Vec3x8::from(cases.map(|c| c.0));
        let r8 = F32x8::from(cases.map(|c| c.1));
        let cap8 = ProjectedCap::new(c8, r8, Vec3x8::splat(n));
        let (w8, pdf8) = cap8.sample(Vec2x8::from(us));
        let back8 = cap8.inverse(w8);
        for i in 0..8 {
            let cap = ProjectedCap::new(cases[i].0, cases[i].1, n);
            let (w, pdf) = cap.sample(us[i]);
            assert_eq!(
                w8.lane(i).to_array().map(f32::to_bits),
                w.to_array().map(f32::to_bits)
            );
            assert_eq!(pdf8.to_array()[i].to_bits(), pdf.to_bits());
            let back = cap.inverse(w);
            assert_eq!(
                back8.lane(i).to_array().map(f32::to_bits),
                back.to_array().map(f32::to_bits)
            );
        }
    }
}
