//! Tests of the verification layer itself: the χ² survival function against independent
//! references, the χ² harness on correct samplers (positive controls) and broken ones (negative
//! controls), and the lane-equality check.

use std::f32::consts::PI as PI32;
use std::f64::consts::PI;
use std::time::Instant;

use crate::common::TestRng;
use glam::{DVec2, DVec3, Vec2, Vec3};
use mcsample::verify::{
    ChiSquare, ChiSquareResult, check_lanes, chi2_sf, gamma_p, gamma_q, ln_gamma, sidak_alpha,
};
use mcsample::x8::{F32x8, U32x8, Vec2x8, Vec3x8};

// ---------------------------------------------------------------------------------------------
// Survival function

/// sf(x, 2m) = e^{−y} Σ_{k<m} y^k/k!, y = x/2 (Poisson CDF), each term built in log space by the
/// running sums ln y^k and ln k!, so that e^{−y} may underflow without harm.
fn sf_even_reference(x: f64, m: usize) -> f64 {
    let y = x / 2.0;
    let (ln_y, mut ln_term, mut sum) = (y.ln(), -y, 0.0);
    for k in 0..m {
        if k > 0 {
            ln_term += ln_y - (k as f64).ln();
        }
        sum += ln_term.exp();
    }
    sum
}

/// sf(x, 2m+1) = erfc(√y) + Σ_{j<m} e^{−y} y^{j+½}/Γ(j+3/2), with Γ(3/2) = √π/2 and
/// Γ(j+5/2) = (j+3/2) Γ(j+3/2) (the recurrence sf(x, k+2) = sf(x, k) + e^{−y}y^{k/2}/Γ(k/2+1)).
fn sf_odd_reference(x: f64, m: usize) -> f64 {
    let y = x / 2.0;
    let ln_y = y.ln();
    let mut ln_gamma_half = (PI.sqrt() / 2.0).ln(); // ln Γ(j + 3/2) at j = 0
    let mut sum = libm::erfc(y.sqrt());
    for j in 0..m {
        if j > 0 {
            ln_gamma_half += (j as f64 + 0.5).ln();
        }
        sum += (-y + (j as f64 + 0.5) * ln_y - ln_gamma_half).exp();
    }
    sum
}

/// x values around the mean of χ²_dof, out to ±6σ, and a few far in the tails.
fn xs_for(dof: f64) -> Vec<f64> {
    let sigma = (2.0 * dof).sqrt();
    let mut xs: Vec<f64> = (-24..=24)
        .map(|k| dof + 0.25 * k as f64 * sigma)
        .filter(|&x| x > 0.0)
        .collect();
    xs.extend([1e-3, 0.1, 0.5 * dof, 2.0 * dof, 3.0 * dof + 50.0]);
    xs
}

#[test]
fn sf_dof2_is_exp() {
    let mut worst: f64 = 0.0;
    for i in 0..=4000 {
        let x = i as f64 * 0.05;
        worst = worst.max((chi2_sf(x, 2.0) - (-x / 2.0).exp()).abs());
    }
    println!("dof 2: worst |sf − e^(−x/2)| = {worst:e}");
    assert!(worst <= 1e-12, "dof 2: worst abs error {worst:e}");
}

#[test]
fn sf_dof1_is_erfc() {
    let mut worst: f64 = 0.0;
    for i in 0..=4000 {
        let x = i as f64 * 0.01 + 1e-9;
        let reference = libm::erfc((x / 2.0).sqrt());
        worst = worst.max((chi2_sf(x, 1.0) - reference).abs());
    }
    println!("dof 1: worst |sf − erfc(√(x/2))| = {worst:e}");
    assert!(worst <= 1e-12, "dof 1: worst abs error {worst:e}");
}

#[test]
fn sf_even_dof_matches_poisson_sum() {
    let mut worst: (f64, f64, usize) = (0.0, 0.0, 0);
    for m in [1, 2, 3, 4, 5, 8, 13, 50, 100, 317, 1000, 2500, 5000] {
        let dof = 2 * m;
        for x in xs_for(dof as f64) {
            let err = (chi2_sf(x, dof as f64) - sf_even_reference(x, m)).abs();
            if err > worst.0 {
                worst = (err, x, dof);
            }
        }
    }
    println!(
        "even dof 2..10000: worst abs error {:e} at x = {}, dof = {}",
        worst.0, worst.1, worst.2
    );
    assert!(
        worst.0 <= 1e-9,
        "worst abs error {:e} at x = {}, dof = {}",
        worst.0,
        worst.1,
        worst.2
    );
}

#[test]
fn sf_odd_dof_matches_erfc_recurrence() {
    let mut worst: (f64, f64, usize) = (0.0, 0.0, 0);
    for m in [0, 1, 2, 3, 6, 21, 99, 400, 1234, 2500] {
        let dof = 2 * m + 1;
        for x in xs_for(dof as f64) {
            let err = (chi2_sf(x, dof as f64) - sf_odd_reference(x, m)).abs();
            if err > worst.0 {
                worst = (err, x, dof);
            }
        }
    }
    println!(
        "odd dof 1..5001: worst abs error {:e} at x = {}, dof = {}",
        worst.0, worst.1, worst.2
    );
    assert!(
        worst.0 <= 1e-9,
        "worst abs error {:e} at x = {}, dof = {}",
        worst.0,
        worst.1,
        worst.2
    );
}

/// Published critical values and values computed with mpmath at 40 digits
/// (`gammainc(k/2, x/2, inf, regularized=True)`), including non-integer dof and dof ~10⁴.
#[test]
fn sf_known_values() {
    let table: &[(f64, f64, f64)] = &[
        (3.841458820694124, 1.0, 0.05),
        (18.307038053275146, 10.0, 0.05),
        (124.34211340400407, 100.0, 0.05),
        (0.5, 3.0, 0.918_891_411_654_675_9),
        (7.0, 3.0, 0.071_897_772_496_465_13),
        (30.0, 7.0, 9.495_972_508_134_184e-5),
        (0.01, 0.5, 0.706_919_105_278_980_4),
        (2.5, 4.5, 0.715_695_754_862_238),
        (4900.0, 5000.0, 0.841_361_110_332_228_8),
        (5000.0, 5000.0, 0.497_340_378_892_345_1),
        (5100.0, 5000.0, 0.158_639_348_619_403_95),
        (5250.0, 5000.0, 0.006_828_758_143_813_642),
        (4800.0, 5001.0, 0.978_856_559_152_623_9),
        (10200.0, 10200.0, 0.498_137_894_872_710_26),
        (9900.0, 10201.0, 0.983_153_649_480_530_8),
        (10650.0, 10200.0, 9.351_039_777_154_379e-4),
        (60.0, 20.0, 7.121_750_862_815_577e-6),
        (1e-3, 1.0, 0.974_772_879_369_960_4),
    ];
    for &(x, dof, want) in table {
        let got = chi2_sf(x, dof);
        assert!(
            (got - want).abs() <= 1e-10,
            "chi2_sf({x}, {dof}) = {got}, want {want}"
        );
    }
    // Deep tail: relative accuracy.
    let got = chi2_sf(200.0, 50.0);
    let want = 7.857_610_724_654_744e-20;
    assert!(
        ((got - want) / want).abs() < 1e-9,
        "chi2_sf(200, 50) = {got:e}"
    );
    // Edges.
    assert_eq!(chi2_sf(0.0, 7.0), 1.0);
    assert_eq!(chi2_sf(f64::INFINITY, 7.0), 0.0);
    assert!(chi2_sf(f64::NAN, 7.0).is_nan());
    assert!((gamma_p(3.3, 2.2) + gamma_q(3.3, 2.2) - 1.0).abs() < 1e-15);
}

#[test]
fn ln_gamma_matches_factorials() {
    let mut ln_fact = 0.0; // ln (n−1)!
    for n in 1..=300 {
        if n > 1 {
            ln_fact += ((n - 1) as f64).ln();
        }
        let got = ln_gamma(n as f64);
        assert!(
            (got - ln_fact).abs() <= 1e-12 * ln_fact.abs().max(1.0),
            "ln Γ({n}) = {got}, want {ln_fact}"
        );
    }
    assert!((ln_gamma(0.5) - PI.sqrt().ln()).abs() < 1e-14);
}

#[test]
fn sidak_correction() {
    assert!((sidak_alpha(0.01, 1) - 0.01).abs() < 1e-17);
    for k in [2, 7, 100, 10_000] {
        let a = sidak_alpha(0.01, k);
        assert!(((1.0 - a).powi(k as i32) - 0.99).abs() < 1e-12, "k = {k}");
        assert!(a < 0.01 / k as f64 * 1.01 && a > 0.01 / k as f64);
    }
}

// ---------------------------------------------------------------------------------------------
// Chi-square harness: samplers

fn polar_disk(u: Vec2) -> Vec2 {
    let (s, c) = (2.0 * PI32 * u.y).sin_cos();
    u.x.sqrt() * Vec2::new(c, s)
}

fn polar_disk_broken(u: Vec2) -> Vec2 {
    let (s, c) = (2.0 * PI32 * u.y).sin_cos();
    u.x * Vec2::new(c, s)
}

fn uniform_sphere(u: Vec2) -> Vec3 {
    let z = 1.0 - 2.0 * u.x;
    let r = (1.0 - z * z).max(0.0).sqrt();
    let (s, c) = (2.0 * PI32 * u.y).sin_cos();
    Vec3::new(r * c, r * s, z)
}

fn cosine_hemisphere(u: Vec2) -> Vec3 {
    let p = polar_disk(u);
    Vec3::new(p.x, p.y, (1.0 - p.length_squared()).max(0.0).sqrt())
}

const UNIFORM_DISK: fn(DVec2) -> f64 = |_| 1.0 / PI;
const UNIFORM_SPHERE: fn(DVec3) -> f64 = |_| 1.0 / (4.0 * PI);

/// Number of positive χ² tests below, for the Šidák correction.
const POSITIVE_TESTS: usize = 4;

fn report(name: &str, r: &ChiSquareResult, secs: f64) {
    println!("{name}: {r} [{secs:.3} s]");
}

fn accept(name: &str, r: &ChiSquareResult, secs: f64) {
    report(name, r, secs);
    let level = sidak_alpha(0.01, POSITIVE_TESTS);
    assert!(r.passes(level), "{name} rejected at {level:e}: {r}");
    assert!((r.pdf_integral - 1.0).abs() < 1e-3, "{name}: {r}");
}

fn reject(name: &str, r: &ChiSquareResult, secs: f64) {
    report(name, r, secs);
    assert!(r.p_value < 1e-6, "{name} not rejected: {r}");
    assert!(!r.passes(sidak_alpha(0.01, POSITIVE_TESTS)), "{name}: {r}");
}

fn timed<T>(f: impl FnOnce() -> T) -> (T, f64) {
    let t = Instant::now();
    let r = f();
    (r, t.elapsed().as_secs_f64())
}

// Positive controls ---------------------------------------------------------------------------

#[test]
fn accepts_uniform_square() {
    let mut rng = TestRng::new(0);
    let (r, t) = timed(|| ChiSquare::square().run(|_| rng.u2(), |_: DVec2| 1.0));
    assert_eq!(r.res, (101, 101));
    assert_eq!(r.samples, 1_000_000);
    accept("uniform square", &r, t);
}

#[test]
fn accepts_uniform_disk() {
    let mut rng = TestRng::new(1);
    let (r, t) = timed(|| ChiSquare::disk().run(|_| polar_disk(rng.u2()), UNIFORM_DISK));
    accept("uniform disk (r = sqrt u)", &r, t);
}

#[test]
fn accepts_uniform_sphere() {
    let mut rng = TestRng::new(3);
    let (r, t) = timed(|| ChiSquare::sphere().run(|_| uniform_sphere(rng.u2()), UNIFORM_SPHERE));
    assert_eq!(r.res, (50, 101));
    accept("uniform sphere (z = 1 - 2u)", &r, t);
}

/// A non-uniform pdf with a support edge at the equator: the lower half's cells expect exactly 0
/// and receive nothing, and the equator's row (cut in its middle) is integrated exactly.
#[test]
fn accepts_cosine_hemisphere() {
    let mut rng = TestRng::new(5);
    let (r, t) = timed(|| {
        ChiSquare::sphere().run(
            |_| cosine_hemisphere(rng.u2()),
            |w: DVec3| w.z.max(0.0) / PI,
        )
    });
    assert!(r.expected.iter().filter(|&&e| e == 0.0).count() >= 50 * 50);
    let integral = ChiSquare::sphere()
        .expected(|w: DVec3| w.z.max(0.0) / PI)
        .integral;
    assert!((integral - 1.0).abs() < 1e-4, "integral {integral}");
    accept("cosine hemisphere", &r, t);
}

// Negative controls ---------------------------------------------------------------------------

#[test]
fn rejects_disk_with_r_equal_u() {
    let mut rng = TestRng::new(7);
    let (r, t) = timed(|| ChiSquare::disk().run(|_| polar_disk_broken(rng.u2()), UNIFORM_DISK));
    assert_eq!(r.invalid_samples, 0);
    reject("disk with r = u", &r, t);
}

#[test]
fn rejects_pdf_scaled_by_1_05() {
    let mut rng = TestRng::new(9);
    let (r, t) =
        timed(|| ChiSquare::disk().run(|_| polar_disk(rng.u2()), |p| 1.05 * UNIFORM_DISK(p)));
    assert!((r.pdf_integral - 1.05).abs() < 1e-9, "{r}");
    reject("uniform disk against 1.05/pi", &r, t);
}

#[test]
fn rejects_cosine_sampler_against_uniform_sphere_pdf() {
    let mut rng = TestRng::new(11);
    let (r, t) = timed(|| ChiSquare::sphere().run(|_| cosine_hemisphere(rng.u2()), UNIFORM_SPHERE));
    reject("cosine hemisphere against uniform sphere pdf", &r, t);
}

#[test]
fn rejects_a_single_nan_sample() {
    let mut rng = TestRng::new(13);
    let (r, t) = timed(|| {
        ChiSquare::square().run(
            |i| {
                if i == 123_456 {
                    Vec2::new(f32::NAN, 0.5)
                } else {
                    rng.u2()
                }
            },
            |_: DVec2| 1.0,
        )
    });
    assert_eq!(r.invalid_samples, 1);
    assert_eq!(r.first_invalid.as_ref().map(|f| f.0), Some(123_456));
    assert_eq!(r.p_value, 0.0);
    reject("square with one NaN sample", &r, t);
}

#[test]
fn rejects_samples_outside_the_domain() {
    let mut rng = TestRng::new(15);
    let r = ChiSquare::disk()
        .samples(100_000)
        .run(|_| 1.01 * polar_disk(rng.u2()), UNIFORM_DISK);
    assert!(r.invalid_samples > 1000, "{r}");
    reject("disk of radius 1.01", &r, 0.0);

    // Directions that are not unit vectors are outside the sphere.
    let mut rng = TestRng::new(17);
    let r = ChiSquare::sphere()
        .samples(100_000)
        .run(|_| 1.001 * uniform_sphere(rng.u2()), UNIFORM_SPHERE);
    assert_eq!(r.invalid_samples, 100_000, "{r}");
    reject("sphere of radius 1.001", &r, 0.0);
}

#[test]
fn rejects_samples_where_the_pdf_is_zero() {
    // A uniform sphere sampler against the uniform *hemisphere* pdf: half the samples land in
    // cells that expect nothing (and the statistic alone would be infinite there).
    let mut rng = TestRng::new(19);
    let r = ChiSquare::sphere().samples(100_000).run(
        |_| uniform_sphere(rng.u2()),
        |w: DVec3| if w.z >= 0.0 { 1.0 / (2.0 * PI) } else { 0.0 },
    );
    assert!(r.samples_in_zero_cells > 40_000, "{r}");
    reject("uniform sphere against hemisphere pdf", &r, 0.0);
}

#[test]
fn rejects_a_pdf_that_is_nan_somewhere() {
    let mut rng = TestRng::new(21);
    let r = ChiSquare::disk().samples(100_000).run(
        |_| polar_disk(rng.u2()),
        |p: DVec2| if p.x > 0.9 { f64::NAN } else { 1.0 / PI },
    );
    assert!(r.invalid_pdf_nodes > 0, "{r}");
    reject("pdf NaN near the rim", &r, 0.0);
}

/// Coarser settings behave: few samples make most cells small, and pooling keeps the test valid.
#[test]
fn pools_small_cells() {
    let mut rng = TestRng::new(23);
    let r = ChiSquare::disk()
        .samples(20_000)
        .res(101, 101)
        .ires(4)
        .run(|_| polar_disk(rng.u2()), UNIFORM_DISK);
    println!("pooled: {r}");
    assert_eq!(r.pooled_cells, 101 * 101); // every cell expects ~1.96
    assert!(r.dof > 3000 && r.dof < 4100, "{r}");
    assert!(r.passes(sidak_alpha(0.01, POSITIVE_TESTS)), "{r}");
}

// ---------------------------------------------------------------------------------------------
// Lane equality

fn scalar_fn((p, s): (Vec2, f32)) -> (Vec3, f32) {
    let q = Vec3::new(p.x * s + 1.0, p.y - s, p.x * p.y / (s + 2.0));
    (q, (q.x * q.x + q.y * q.y).sqrt())
}

fn packet_fn((p, s): (Vec2x8, F32x8)) -> (Vec3x8, F32x8) {
    let one = F32x8::splat(1.0);
    let two = F32x8::splat(2.0);
    let q = Vec3x8 {
        x: p.x * s + one,
        y: p.y - s,
        z: p.x * p.y / (s + two),
    };
    (q, (q.x * q.x + q.y * q.y).sqrt())
}

fn lane_inputs(n: usize) -> Vec<(Vec2, f32)> {
    let mut rng = TestRng::new(25);
    (0..n)
        .map(|_| (rng.u2() * 4.0 - 2.0, rng.u01() * 3.0 - 1.0))
        .collect()
}

#[test]
fn check_lanes_accepts_identical_functions() {
    let inputs = lane_inputs(1000);
    assert_eq!(check_lanes(&inputs, packet_fn, scalar_fn), Ok(1000));
    // Not a multiple of 8: padded by repeating the inputs.
    assert_eq!(check_lanes(&inputs[..13], packet_fn, scalar_fn), Ok(16));
    assert_eq!(check_lanes(&inputs[..0], packet_fn, scalar_fn), Ok(0));
    // u32 packets too.
    let mut rng = TestRng::new(27);
    let ints: Vec<u32> = (0..77).map(|_| rng.next_u32()).collect();
    let r = check_lanes(&ints, |x: U32x8| x ^ (x >> 7), |x: u32| x ^ (x >> 7));
    assert_eq!(r, Ok(80));
}

#[test]
fn check_lanes_detects_one_ulp_in_lane_5() {
    let inputs = lane_inputs(1000);
    let perturbed = |i: (Vec2x8, F32x8)| {
        let (q, d) = packet_fn(i);
        let mut a = q.to_array();
        a[5].y = f32::from_bits(a[5].y.to_bits() + 1);
        (Vec3x8::from(a), d)
    };
    let err = check_lanes(&inputs, perturbed, scalar_fn).unwrap_err();
    println!("{err}");
    assert_eq!((err.index, err.lane), (5, 5));
    assert_eq!(err.mismatches, 125); // lane 5 of each of the 125 packets
    assert_eq!(err.checked, 1000);
    assert_eq!(err.packet_bits.len(), 4);
    let diff: Vec<u32> = err
        .packet_bits
        .iter()
        .zip(&err.scalar_bits)
        .map(|(a, b)| a.wrapping_sub(*b))
        .collect();
    assert_eq!(diff, [0, 1, 0, 0]);
}

#[test]
fn check_lanes_compares_zero_sign_and_nan_bits() {
    let inputs: Vec<f32> = (0..16).map(|i| i as f32).collect();
    // −0.0 in lane 3 against +0.0.
    let neg_zero = |x: F32x8| {
        let mut a = (x * F32x8::splat(0.0)).to_array();
        a[3] = -0.0;
        F32x8::new(a)
    };
    let err = check_lanes(&inputs, neg_zero, |x: f32| x * 0.0).unwrap_err();
    assert_eq!((err.lane, err.mismatches), (3, 2));
    // A NaN with another payload is a mismatch, the same NaN is not.
    let nan_a = f32::from_bits(0x7fc0_0000);
    let nan_b = f32::from_bits(0x7fc0_0001);
    let err = check_lanes(&inputs, |_: F32x8| F32x8::splat(nan_b), |_: f32| nan_a).unwrap_err();
    assert_eq!(err.mismatches, 16);
    assert_eq!(
        check_lanes(&inputs, |_: F32x8| F32x8::splat(nan_a), |_: f32| nan_a),
        Ok(16)
    );
}
