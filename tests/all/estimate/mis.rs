//! MIS weights (Veach 1997, ch. 9): the special values, the partition of unity of every pair,
//! the error against the f64 weight of the same inputs, packets against scalars bit for bit, the
//! N-technique forms, and one-sample MIS's choice and rescaled u.

use crate::common::{TestRng, lanes};
use mcsample::lane::F32x8;
use mcsample::mis;

type Two = fn(f32, f32, f32, f32) -> f32;
type TwoX8 = fn(F32x8, F32x8, F32x8, F32x8) -> F32x8;

fn cutoff_quarter(a: f32, b: f32, c: f32, d: f32) -> f32 {
    mis::cutoff(a, b, c, d, 0.25)
}
fn cutoff_quarter_x8(a: F32x8, b: F32x8, c: F32x8, d: F32x8) -> F32x8 {
    mis::cutoff(a, b, c, d, F32x8::splat(0.25))
}

/// Every two-technique heuristic, scalar and packet, with its exact weight in f64 from the
/// contributions a = n_f·p_f and b = n_g·p_g (finite, not both 0), and its documented bound in
/// ulp of the weight.
type Heuristic = (&'static str, Two, TwoX8, fn(f64, f64) -> f64, f64);
const HEURISTICS: [Heuristic; 4] = [
    (
        "balance",
        mis::balance,
        mis::balance,
        |a, b| a / (a + b),
        3.0,
    ),
    (
        "power",
        mis::power,
        mis::power,
        |a, b| a * a / (a * a + b * b),
        5.0,
    ),
    (
        "maximum",
        mis::maximum,
        mis::maximum,
        |a, b| {
            if a > b {
                1.0
            } else if a < b {
                0.0
            } else {
                0.5
            }
        },
        0.0,
    ),
    (
        "cutoff 0.25",
        cutoff_quarter,
        cutoff_quarter_x8,
        |a, b| {
            let m = a.max(b);
            let (a2, b2) = (
                if a < 0.25 * m { 0.0 } else { a },
                if b < 0.25 * m { 0.0 } else { b },
            );
            a2 / (a2 + b2)
        },
        3.0,
    ),
];

/// The weight in both widths; panics unless every packet lane equals the scalar bit for bit.
fn both(name: &str, f: Two, fx8: TwoX8, x: [f32; 4]) -> f32 {
    let w = f(x[0], x[1], x[2], x[3]);
    let s = F32x8::splat;
    let lanes = fx8(s(x[0]), s(x[1]), s(x[2]), s(x[3])).to_array();
    for l in lanes {
        assert_eq!(
            l.to_bits(),
            w.to_bits(),
            "{name}{x:?}: packet {l} against scalar {w}"
        );
    }
    w
}

#[test]
fn special_values_in_both_widths() {
    let inf = f32::INFINITY;
    let nan = f32::NAN;
    // (n_f, p_f, n_g, p_g) → weight of f, for every heuristic.
    let cases: [([f32; 4], f32); 17] = [
        ([1.0, 1e20, 1.0, 1e20], 0.5),
        ([1.0, 1e-25, 1.0, 1e-25], 0.5),
        ([1.0, f32::MAX, 1.0, f32::MAX], 0.5),
        ([1.0, 1e-45, 1.0, 1e-45], 0.5), // the smallest subnormal
        ([3.0, f32::MAX, 3.0, f32::MAX], 0.5), // n·p overflows; the ratio does not
        ([1.0, inf, 1.0, 1.0], 1.0),
        ([1.0, 1.0, 1.0, inf], 0.0),
        ([1.0, inf, 1.0, inf], 0.5),
        ([1.0, 0.0, 1.0, 1.0], 0.0),
        ([0.0, 1.0, 1.0, 1.0], 0.0),
        ([0.0, inf, 1.0, 1.0], 0.0), // count 0 beats an infinite pdf: 0·∞ is not NaN here
        ([1.0, 0.0, 1.0, 0.0], 0.0),
        ([1.0, 1.0, 1.0, 0.0], 1.0),
        ([1.0, 1.0, 0.0, 1.0], 1.0),
        ([1.0, nan, 1.0, 1.0], 0.0),
        ([1.0, 1.0, 1.0, nan], 0.0),
        ([1.0, -1.0, 1.0, 1.0], 0.0),
    ];
    for (name, f, fx8, _, _) in HEURISTICS {
        for (x, want) in cases {
            let w = both(name, f, fx8, x);
            assert_eq!(w, want, "{name}{x:?}");
        }
    }
    // Counts enter the weights (n_light = 2, n_bsdf = 1 at equal pdfs): 2/3 and 1/3 by balance,
    // 4/5 and 1/5 by power.
    let close = |w: f32, want: f64| ((w as f64) - want).abs() <= 1e-7;
    assert!(close(mis::balance(2.0, 0.7, 1.0, 0.7), 2.0 / 3.0));
    assert!(close(mis::balance(1.0, 0.7, 2.0, 0.7), 1.0 / 3.0));
    assert!(close(mis::power(2.0, 0.7, 1.0, 0.7), 0.8));
    assert!(close(mis::power(1.0, 0.7, 2.0, 0.7), 0.2));
}

/// A positive pdf, log-uniform over [1e-30, 1e30], or one of the special values.
fn pdf(rng: &mut TestRng) -> f32 {
    match rng.below(40) {
        0 => 0.0,
        1 => f32::INFINITY,
        2 => f32::from_bits(1 + rng.below(0x007f_ffff)), // subnormal
        3 => f32::MAX,
        _ => 10f64.powf(rng.range(-30.0, 30.0)) as f32,
    }
}

fn count(rng: &mut TestRng) -> f32 {
    match rng.below(8) {
        0 => 0.0,
        1 => rng.u01() + 1e-3, // a one-sample probability
        2 => 1.0 + rng.below(64) as f32,
        _ => 1.0,
    }
}

/// Over 10⁶ pairs, w(f, g) + w(g, f) = 1 within f32::EPSILON wherever either contribution is
/// positive, and each weight is within a few ulp of the f64 weight of the same inputs.
#[test]
fn pairs_sum_to_one_and_match_f64() {
    let mut rng = TestRng::new(10);
    let mut worst_sum = [0f64; 4];
    let mut worst_ulp = [0f64; 4];
    for _ in 0..1_000_000 {
        let x = [
            count(&mut rng),
            pdf(&mut rng),
            count(&mut rng),
            pdf(&mut rng),
        ];
        let (a, b) = (x[0] as f64 * x[1] as f64, x[2] as f64 * x[3] as f64);
        for (h, (name, f, _, exact, bound)) in HEURISTICS.iter().enumerate() {
            let wf = f(x[0], x[1], x[2], x[3]);
            let wg = f(x[2], x[3], x[0], x[1]);
            assert!((0.0..=1.0).contains(&wf), "{name}{x:?} = {wf}");
            if a > 0.0 || b > 0.0 {
                let e = ((wf + wg) as f64 - 1.0).abs();
                worst_sum[h] = worst_sum[h].max(e);
                assert!(e <= f32::EPSILON as f64, "{name}{x:?}: {wf} + {wg}");
            }
            if a > 0.0 && b > 0.0 && a.is_finite() && b.is_finite() {
                let want = exact(a, b);
                // Error in ulps of the weight where no intermediate ratio is subnormal (below
                // that, q = min pdf/max pdf loses bits, as any f32 computation of it would).
                if want > 1e-30 {
                    let ulp = f32::EPSILON as f64 * 2f64.powi((want.log2().floor()) as i32);
                    let e = (wf as f64 - want).abs() / ulp;
                    worst_ulp[h] = worst_ulp[h].max(e);
                    assert!(e <= *bound, "{name}{x:?}: {wf} against {want} ({e} ulp)");
                }
            }
        }
    }
    println!("worst |sum − 1|: {worst_sum:?}; worst ulp against f64: {worst_ulp:?}");
}

/// The check above can fail: the naive power heuristic a²/(a² + b²) breaks it.
#[test]
fn negative_control_naive_power_breaks_the_sum() {
    let naive = |a: f32, b: f32| (a * a) / (a * a + b * b);
    let (wf, wg) = (naive(1e20, 1e20), naive(1e20, 1e20));
    assert!(wf.is_nan() && wg.is_nan());
    let (wf, wg) = (naive(3e-25, 1e-25), naive(1e-25, 3e-25));
    let e = ((wf + wg) - 1.0).abs();
    assert!(e.is_nan() || e > f32::EPSILON, "{wf} + {wg}");
}

/// Packets equal scalars bit for bit on random inputs, lane by lane, NaN included.
#[test]
fn packets_equal_scalars() {
    let mut rng = TestRng::new(11);
    let draw = |rng: &mut TestRng| -> [f32; 8] {
        core::array::from_fn(|_| match rng.below(16) {
            0 => f32::NAN,
            1 => -1.0,
            _ => pdf(rng),
        })
    };
    for _ in 0..20_000 {
        let x: [[f32; 8]; 5] = core::array::from_fn(|_| draw(&mut rng));
        let v = x.map(F32x8::new);
        for (name, f, fx8, _, _) in HEURISTICS {
            let got = fx8(v[0], v[1], v[2], v[3]).to_array();
            for i in 0..8 {
                let want = f(x[0][i], x[1][i], x[2][i], x[3][i]);
                assert_eq!(got[i].to_bits(), want.to_bits(), "{name} lane {i}");
            }
        }
        let got = mis::cutoff(v[0], v[1], v[2], v[3], v[4]).to_array();
        let n3 = mis::power_n([v[0], v[2], v[4]], [v[1], v[3], v[4]]);
        let b3 = mis::balance_n([v[0], v[2], v[4]], [v[1], v[3], v[4]]);
        let pick = mis::one_sample([v[0], v[1], v[2]], v[3]);
        for i in 0..8 {
            let want = mis::cutoff(x[0][i], x[1][i], x[2][i], x[3][i], x[4][i]);
            assert_eq!(got[i].to_bits(), want.to_bits());
            let s3 = mis::power_n([x[0][i], x[2][i], x[4][i]], [x[1][i], x[3][i], x[4][i]]);
            let t3 = mis::balance_n([x[0][i], x[2][i], x[4][i]], [x[1][i], x[3][i], x[4][i]]);
            for k in 0..3 {
                assert_eq!(n3[k].to_array()[i].to_bits(), s3[k].to_bits());
                assert_eq!(b3[k].to_array()[i].to_bits(), t3[k].to_bits());
            }
            let p = mis::one_sample([x[0][i], x[1][i], x[2][i]], x[3][i]);
            assert_eq!(pick.index.to_array()[i], p.index);
            assert_eq!(
                pick.probability.to_array()[i].to_bits(),
                p.probability.to_bits()
            );
            assert_eq!(pick.u.to_array()[i].to_bits(), p.u.to_bits());
        }
    }
}

/// The weights and the one-sample choice in both packet widths, against the scalar form, on
/// the same draws (NaN, negative, zero, ∞, subnormal and twelve decades of pdfs).
#[test]
fn weights_equal_scalars_in_both_widths() {
    let mut rng = TestRng::new(12);
    let mut draw = || match rng.below(16) {
        0 => f32::NAN,
        1 => -1.0,
        _ => pdf(&mut rng),
    };
    type Five = ((f32, f32), (f32, f32, f32));
    let xs: Vec<Five> = (0..1 << 14)
        .map(|_| ((draw(), draw()), (draw(), draw(), draw())))
        .collect();
    let f = &mut Vec::new();
    lanes!(f, "balance", &xs, |((a, b), (c, d, _)): (
        (L, L),
        (L, L, L)
    )| mis::balance(a, b, c, d));
    lanes!(f, "power", &xs, |((a, b), (c, d, _)): (
        (L, L),
        (L, L, L)
    )| mis::power(a, b, c, d));
    lanes!(f, "maximum", &xs, |((a, b), (c, d, _)): (
        (L, L),
        (L, L, L)
    )| mis::maximum(a, b, c, d));
    lanes!(f, "cutoff", &xs, |((a, b), (c, d, e)): (
        (L, L),
        (L, L, L)
    )| mis::cutoff(a, b, c, d, e));
    lanes!(f, "power_n", &xs, |((a, b), (c, d, e)): (
        (L, L),
        (L, L, L)
    )| {
        let [x, y, z] = mis::power_n([a, c, e], [b, d, e]);
        (x, y, z)
    });
    lanes!(f, "balance_n", &xs, |((a, b), (c, d, e)): (
        (L, L),
        (L, L, L)
    )| {
        let [x, y, z] = mis::balance_n([a, c, e], [b, d, e]);
        (x, y, z)
    });
    lanes!(f, "one_sample", &xs, |((a, b), (c, d, _)): (
        (L, L),
        (L, L, L)
    )| {
        let pick = mis::one_sample([a, b, c], d);
        (pick.index, pick.probability, pick.u)
    });
    assert!(f.is_empty(), "{}", f.join("\n"));
}
