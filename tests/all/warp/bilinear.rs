//! The bilinear warp (Hart et al., "Practical Product Sampling by Fitting and Composing Warps",
//! EGSR 2020) and the spherical polygons composed with it.
//!
//! Facts checked: the linear warp is the root of its quadratic CDF; equal weights are the
//! identity, so that a receiver without a normal gets the plain solid-angle sampler bit for bit;
//! the bilinear density is what the warp draws (χ²); composed with the polygons, the cosine
//! estimator of irradiance is unbiased against Lambert's formula and its variance falls well
//! below solid-angle sampling's; and the pdf a sample returns agrees with the pdf function.

use glam::{DVec2, Vec2, Vec3};
use mcsample::lane::Lane;
use mcsample::reference::polygon_irradiance;
use mcsample::registry::{TILTED, rectangle, triangle};
use mcsample::verify::ChiSquare;
use mcsample::warp::{
    self, BilinearRectangle, BilinearTriangle, SphericalRectangle, SphericalTriangle,
};

use crate::common::{TestRng, border, grid, lanes};

#[test]
fn linear_is_the_root_of_its_cdf_and_inverts_it() {
    let weights = [
        (1.0, 3.0),
        (3.0, 1.0),
        (0.01, 1.0),
        (1.0, 0.01),
        (0.02, 2.0),
        (1.0, 1.0 + 1e-6),
        (0.5, 0.5),
    ];
    let mut us: Vec<f32> = (0..=1000).map(|i| i as f32 / 1000.0).collect();
    us.extend(border().iter().map(|u| u[0]));
    // The backward error: how far u is from the exact CDF at the returned x. The forward error
    // is that times the slope dx/du, up to 50 where the density falls to 1/100 of its mean,
    // which no formula avoids.
    let cdf = |x: f64, a: f64, b: f64| x * (2.0 * a + x * (b - a)) / (a + b);
    let (mut worst_back, mut worst_u) = (0.0f64, 0.0f64);
    for (a, b) in weights {
        for &u in &us {
            let x = warp::linear(u, a, b);
            assert!((0.0..=1.0).contains(&x), "linear({u}, {a}, {b}) = {x}");
            let back = cdf(x as f64, a as f64, b as f64) - u as f64;
            worst_back = worst_back.max(back.abs());
            let inv = warp::linear_inverse(x, a, b) as f64;
            worst_u = worst_u.max((inv - cdf(x as f64, a as f64, b as f64)).abs());
        }
    }
    // x carries a few ε of relative rounding and the density is at most 2, so u is within 3ε;
    // the textbook root of (1, 1 + 1e-6) in f32 is off by 0.1.
    assert!(
        worst_back < 3.6e-7,
        "linear's backward error {worst_back:e}"
    );
    assert!(
        worst_u < 2.4e-7,
        "linear_inverse off the CDF by {worst_u:e}"
    );
    println!("backward error {worst_back:e}, inverse {worst_u:e}");
    let textbook = |u: f32, a: f32, b: f32| (-a + (a * a + u * (b * b - a * a)).sqrt()) / (b - a);
    let (a, b) = (1.0, 1.0 + 1e-6);
    let tb = (cdf(textbook(0.3, a, b) as f64, a as f64, b as f64) - 0.3).abs();
    assert!(
        tb > 1e-2,
        "the control: the textbook root is off by {tb:e} only"
    );
}

#[test]
fn weights_count_by_their_ratios_and_bad_ones_as_equal() {
    let w = [0.01, 1.0, 0.3, 3.0];
    let scaled = |k: f32| w.map(|x| x * k);
    let mut us: Vec<Vec2> = grid(16).into_iter().map(Vec2::from).collect();
    us.extend(border().into_iter().map(Vec2::from));
    for &u in &us {
        let (x, p) = (warp::bilinear(u, w), warp::bilinear_pdf(u, w));
        // Scaled by powers of two, as far as f32 reaches: bit for bit.
        for k in [2f32.powi(100), 2f32.powi(-100), 2f32.powi(-120)] {
            assert_eq!(warp::bilinear(u, scaled(k)), x, "u = {u}, scale {k:e}");
            assert_eq!(warp::bilinear_pdf(u, scaled(k)), p, "u = {u}, scale {k:e}");
        }
        for bad in [
            [0.0, 1.0, 1.0, 1.0],
            [-1.0, 1.0, 1.0, 1.0],
            [f32::NAN, 1.0, 1.0, 1.0],
            [1.0, f32::INFINITY, 1.0, 1.0],
        ] {
            assert_eq!(warp::bilinear(u, bad), u, "{bad:?}");
            assert_eq!(warp::bilinear_pdf(u, bad), 1.0, "{bad:?}");
            assert_eq!(warp::bilinear_inverse(u, bad), u, "{bad:?}");
        }
        // A weight 1e-30 of the others, whose square underflows: finite, in the square.
        let x = warp::bilinear(u, [1e-30, 1.0, 1.0, 1.0]);
        assert!(
            x.is_finite() && x.cmpge(Vec2::ZERO).all() && x.cmple(Vec2::ONE).all(),
            "{u}: {x}"
        );
    }
}

#[test]
fn equal_weights_are_the_identity_and_no_normal_the_plain_sampler() {
    let mut us: Vec<Vec2> = grid(64).into_iter().map(Vec2::from).collect();
    us.extend(border().into_iter().map(Vec2::from));
    for w in [0.01f32, 1.0, 3.7] {
        let w = [w; 4];
        for &u in &us {
            assert_eq!(warp::bilinear(u, w), u, "{w:?}");
            assert_eq!(warp::bilinear_pdf(u, w), 1.0, "{w:?}");
            assert_eq!(warp::bilinear_inverse(u, w), u, "{w:?}");
        }
    }
    let [a, b, c] = triangle(1.0);
    let [c0, ex, ey] = rectangle(1.0);
    let tri = SphericalTriangle::new(a, b, c);
    let rect = SphericalRectangle::new(c0, ex, ey);
    for n in [Vec3::ZERO, Vec3::NAN, Vec3::new(f32::INFINITY, 0.0, 1.0)] {
        let bt = BilinearTriangle::new(a, b, c, n);
        let br = BilinearRectangle::new(c0, ex, ey, n);
        let w = bt.weights();
        assert!(w.iter().all(|&x| x == w[0]), "n = {n}: weights {w:?}");
        for &u in &us {
            let (w, p) = tri.sample(u);
            assert_eq!(bt.sample(u), (w, p), "n = {n}, u = {u}");
            assert_eq!(bt.pdf(w), p, "n = {n}, u = {u}");
            assert_eq!(br.sample(u), rect.sample(u), "n = {n}, u = {u}");
        }
    }
    // A rectangle beyond the spherical inverse's reach (4e7 times its distance), whose pdf could
    // not find u′: equal weights, the plain sampler, so that its samples keep their pdf.
    let (c0, ex, ey) = (
        Vec3::new(-0.5, -0.5, 1.0),
        Vec3::new(2e7, 0.0, 0.0),
        Vec3::new(0.0, 2e7, 0.0),
    );
    let huge = BilinearRectangle::new(c0, ex, ey, TILTED);
    let w = huge.weights();
    assert!(w.iter().all(|&x| x == w[0]), "beyond reach: weights {w:?}");
    let (x, p) = huge.sample(Vec2::new(0.3, 0.6));
    assert!(
        p > 0.0 && huge.pdf(x) > 0.0,
        "beyond reach: {x} pdf {p}, pdf(x) {}",
        huge.pdf(x)
    );
    // The control: a normal makes them differ.
    let bt = BilinearTriangle::new(a, b, c, TILTED);
    assert_ne!(
        bt.sample(Vec2::new(0.3, 0.3)),
        tri.sample(Vec2::new(0.3, 0.3))
    );
}

/// The bilinear density in f64, the way the paper writes it.
fn bilinear_density(p: DVec2, w: [f32; 4]) -> f64 {
    let [w00, w10, w01, w11] = w.map(f64::from);
    let (x, y) = (p.x, p.y);
    let bilerp =
        (1.0 - x) * (1.0 - y) * w00 + x * (1.0 - y) * w10 + (1.0 - x) * y * w01 + x * y * w11;
    4.0 * bilerp / (w00 + w10 + w01 + w11)
}

#[test]
fn bilinear_draws_its_density() {
    let w = [0.01, 1.0, 0.3, 3.0];
    // The pdf function against the paper's density, and the χ² of the samples against it.
    for u in grid(50) {
        let u = Vec2::from(u);
        let got = warp::bilinear_pdf(u, w) as f64;
        let want = bilinear_density(u.as_dvec2(), w);
        assert!(
            (got / want - 1.0).abs() < 1e-6,
            "pdf at {u}: {got} vs {want}"
        );
    }
    let mut rng = TestRng::new(71);
    let r = ChiSquare::square().run(
        |_| warp::bilinear(rng.u2(), w),
        |p: DVec2| bilinear_density(p, w),
    );
    assert!(r.passes(0.01), "{r}");
    // The control: the corners (1, 0) and (0, 1) exchanged in the sampler only.
    let swapped = [0.01, 0.3, 1.0, 3.0];
    let mut rng = TestRng::new(71);
    let r = ChiSquare::square().run(
        |_| warp::bilinear(rng.u2(), swapped),
        |p: DVec2| bilinear_density(p, w),
    );
    assert!(r.p_value < 1e-9, "the swapped corners pass: {r}");
}

/// A light as the estimator sees it: a direction and its pdf per steradian from u.
type Draw<'a> = &'a dyn Fn(Vec2) -> (Vec3, f32);

/// Mean and standard error of the cosine estimator cos⁺/pdf over n Pcg32 samples.
fn cosine_estimate(draw: Draw, n: Vec3, count: usize, seed: u64) -> (f64, f64, f64) {
    let mut rng = TestRng::new(seed);
    let (mut sum, mut sum2) = (0.0f64, 0.0f64);
    for _ in 0..count {
        let (w, pdf) = draw(rng.u2());
        let f = if pdf > 0.0 {
            (n.dot(w.normalize()).max(0.0) / pdf) as f64
        } else {
            0.0
        };
        sum += f;
        sum2 += f * f;
    }
    let mean = sum / count as f64;
    let var = sum2 / count as f64 - mean * mean;
    (mean, (var / count as f64).sqrt(), var.sqrt())
}

/// A polygon light's two samplers, and the bound on the ratio of their estimators' σ.
struct Case<'a> {
    name: &'a str,
    verts: Vec<[f64; 3]>,
    plain: Draw<'a>,
    bilinear: Draw<'a>,
    ratio_bound: f64,
}

#[test]
fn the_cosine_estimator_is_unbiased_and_quieter_than_solid_angle() {
    let [a, b, c] = triangle(1.0);
    let [c0, ex, ey] = rectangle(1.0);
    let d = |v: Vec3| v.as_dvec3().to_array();
    let (tri, rect) = (
        SphericalTriangle::new(a, b, c),
        SphericalRectangle::new(c0, ex, ey),
    );
    let (btri, brect) = (
        BilinearTriangle::new(a, b, c, TILTED),
        BilinearRectangle::new(c0, ex, ey, TILTED),
    );
    let skew = ey + ex * 0.5;
    let para = SphericalRectangle::new(c0, ex, skew);
    let bpara = BilinearRectangle::new(c0, ex, skew, TILTED);
    assert!(para.by_area());
    let cases = [
        Case {
            name: "triangle",
            verts: vec![d(a), d(b), d(c)],
            plain: &|u| tri.sample(u),
            bilinear: &|u| btri.sample(u),
            ratio_bound: 0.35,
        },
        Case {
            name: "rectangle",
            verts: vec![d(c0), d(c0 + ex), d(c0 + ex + ey), d(c0 + ey)],
            plain: &|u| rect.sample(u),
            bilinear: &|u| brect.sample(u),
            ratio_bound: 0.2,
        },
        // Skewed, so sampled by area, with equal weights: the plain sampler, and still unbiased.
        Case {
            name: "parallelogram",
            verts: vec![d(c0), d(c0 + ex), d(c0 + ex + skew), d(c0 + skew)],
            plain: &|u| para.sample(u),
            bilinear: &|u| bpara.sample(u),
            ratio_bound: 1.0 + 1e-9,
        },
    ];
    let count = 1 << 16;
    for Case {
        name,
        verts,
        plain,
        bilinear,
        ratio_bound,
    } in cases
    {
        let e = polygon_irradiance(d(TILTED), &verts);
        let (m_plain, _, sd_plain) = cosine_estimate(plain, TILTED, count, 5);
        let (m, se, sd) = cosine_estimate(bilinear, TILTED, count, 5);
        assert!(
            (m - e).abs() < 4.0 * se,
            "{name}: {m} ± {se} against Lambert's {e}"
        );
        assert!(
            sd < ratio_bound * sd_plain,
            "{name}: σ {sd:e} against solid angle's {sd_plain:e} (mean {m_plain})"
        );
        println!(
            "{name}: E = {e:.6}, bilinear {m:.6} ± {se:.1e}, σ ratio {:.3}",
            sd / sd_plain
        );
    }
    // The controls. Weights on the wrong corners still draw a valid density, but not the cosine:
    // the σ bound rejects them. And the bilinear samples with the plain pdf are biased.
    let [w00, w10, w01, w11] = btri.weights();
    let wrong = [w11, w01, w10, w00];
    let misplaced = |u: Vec2| {
        let v = warp::bilinear(u, wrong);
        let (w, p) = tri.sample(v);
        (w, p * warp::bilinear_pdf(v, wrong))
    };
    let (_, _, sd_plain) = cosine_estimate(&|u| tri.sample(u), TILTED, count, 5);
    let (_, _, sd) = cosine_estimate(&misplaced, TILTED, count, 5);
    assert!(
        sd > 0.35 * sd_plain,
        "misplaced weights: σ ratio {}",
        sd / sd_plain
    );
    let e = polygon_irradiance(d(TILTED), &[d(a), d(b), d(c)]);
    let plain_pdf = |u: Vec2| (btri.sample(u).0, tri.sample(u).1);
    let (m, se, _) = cosine_estimate(&plain_pdf, TILTED, count, 5);
    assert!(
        (m - e).abs() > 10.0 * se,
        "the plain pdf: {m} ± {se} against {e}"
    );
}

#[test]
fn the_returned_pdf_agrees_with_the_pdf_function() {
    let mut rng = TestRng::new(23);
    let mut worst = [0.0f64; 2];
    let mut skipped = 0;
    for s in [1.0, 0.2, 0.01] {
        for n in [TILTED, Vec3::X, Vec3::NEG_X] {
            let [a, b, c] = triangle(s);
            let [c0, ex, ey] = rectangle(s);
            let t = BilinearTriangle::new(a, b, c, n);
            let r = BilinearRectangle::new(c0, ex, ey, n);
            for _ in 0..20_000 {
                let u = rng.u2();
                for (k, (x, p, q)) in [
                    {
                        let (x, p) = t.sample(u);
                        (x, p, t.pdf(x))
                    },
                    {
                        let (x, p) = r.sample(u);
                        (x, p, r.pdf(x))
                    },
                ]
                .into_iter()
                .enumerate()
                {
                    // At the boundary the inside test can round either way: rarely.
                    if q == 0.0 {
                        skipped += 1;
                        continue;
                    }
                    let rel = ((p - q) / q).abs() as f64;
                    worst[k] = worst[k].max(rel);
                    assert!(rel < 2e-5, "s = {s}, n = {n}, u = {u}, x = {x}: {p} vs {q}");
                }
            }
        }
    }
    println!(
        "worst relative difference: triangle {:e}, rectangle {:e}",
        worst[0], worst[1]
    );
    // 3.6·10⁵ samples; a handful on an edge.
    assert!(
        skipped <= 20,
        "{skipped} samples outside the pdf function's support"
    );
}

#[test]
fn both_widths_equal_the_scalar_form() {
    let mut rng = TestRng::new(9);
    let us: Vec<Vec2> = (0..512)
        .map(|_| rng.u2())
        .chain(border().into_iter().map(Vec2::from))
        .collect();
    let mut failures = Vec::new();
    let f = &mut failures;
    const W: [f64; 4] = [0.01, 1.0, 0.3, 3.0];
    lanes!(f, "bilinear", &us, |u: V2| warp::bilinear(u, W.map(L::c)));
    lanes!(f, "bilinear_pdf", &us, |u: V2| warp::bilinear_pdf(
        u,
        W.map(L::c)
    ));
    lanes!(f, "bilinear_inverse", &us, |u: V2| warp::bilinear_inverse(
        u,
        W.map(L::c)
    ));
    let [a, b, c] = triangle(1.0);
    let [c0, ex, ey] = rectangle(1.0);
    lanes!(f, "BilinearTriangle::sample", &us, |u: V2| {
        let k = |v: Vec3| V3::new(L::c(v.x.into()), L::c(v.y.into()), L::c(v.z.into()));
        BilinearTriangle::new(k(a), k(b), k(c), k(TILTED)).sample(u)
    });
    lanes!(f, "BilinearRectangle::sample", &us, |u: V2| {
        let k = |v: Vec3| V3::new(L::c(v.x.into()), L::c(v.y.into()), L::c(v.z.into()));
        BilinearRectangle::new(k(c0), k(ex), k(ey), k(Vec3::X)).sample(u)
    });
    // Lanes with and without a normal in one packet: some with equal weights (the plain map),
    // so that the packet takes the bilinear path for all of them.
    lanes!(f, "BilinearTriangle mixed lanes", &us, |u: V2| {
        let k = |v: Vec3| V3::new(L::c(v.x.into()), L::c(v.y.into()), L::c(v.z.into()));
        let on = L::select(u.x.lt(L::c(0.5)), L::ONE, L::ZERO);
        let n = V3::new(on * L::c(0.6), L::ZERO, on * L::c(0.8));
        let t = BilinearTriangle::new(k(a), k(b), k(c), n);
        let (w, p) = t.sample(u);
        ((w, p), t.pdf(w), t.inverse(w))
    });
    lanes!(f, "BilinearRectangle mixed lanes", &us, |u: V2| {
        let k = |v: Vec3| V3::new(L::c(v.x.into()), L::c(v.y.into()), L::c(v.z.into()));
        let on = L::select(u.y.lt(L::c(0.5)), L::ONE, L::ZERO);
        let n = V3::new(on * L::c(0.6), L::ZERO, on * L::c(0.8));
        let r = BilinearRectangle::new(k(c0), k(ex), k(ey), n);
        let (p, pdf) = r.sample(u);
        ((p, pdf), r.pdf(p), r.inverse(p))
    });
    assert!(failures.is_empty(), "{failures:#?}");
}
