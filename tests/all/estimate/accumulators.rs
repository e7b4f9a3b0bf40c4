//! The estimators' bookkeeping: Welford's running variance against a two-pass f64 computation on
//! adversarial streams, merging, the packet accumulators, Russian roulette (mean and variance,
//! Veach's V + (1/q − 1)E[F²]) and splitting (mean unchanged, the optimal count).

use crate::common::TestRng;
use mcsample::estimate::{self, MeanVar, ROULETTE_Q_MIN};
use mcsample::lane::{F32x8, F32x16, F64x8, F64x16, Widen};

/// The reference: the mean by Neumaier's compensated sum (a plain f64 sum of 10⁷ values near
/// 1e9 loses the fractions: its ulp at 1e16 is 2), then Σ(x − mean)².
fn two_pass(xs: &[f64]) -> (f64, f64) {
    let n = xs.len() as f64;
    let (mut sum, mut comp) = (0.0f64, 0.0f64);
    for &x in xs {
        let t = sum + x;
        comp += if sum.abs() >= x.abs() {
            (sum - t) + x
        } else {
            (x - t) + sum
        };
        sum = t;
    }
    let mean = (sum + comp) / n;
    let var = xs.iter().map(|x| (x - mean) * (x - mean)).sum::<f64>() / (n - 1.0);
    (mean, var)
}

fn naive(xs: &[f64]) -> f64 {
    let n = xs.len() as f64;
    let (s, s2) = xs.iter().fold((0.0, 0.0), |(s, s2), x| (s + x, s2 + x * x));
    (s2 - s * s / n) / (n - 1.0)
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// Three adversarial streams of 10⁷ values: 1e8 ± 1, a large offset plus uniform noise, and
/// magnitudes mixed over twenty decades. The variance stays within 1e-10
/// relative of the two-pass result; the naive Σx² form (the negative control) misses by more than 1e-6 on the
/// first.
#[test]
fn welford_matches_two_pass_where_naive_fails() {
    let mut rng = TestRng::new(20);
    let streams: [Vec<f64>; 3] = [
        (0..10_000_000)
            .map(|_| 1e8 + if rng.below(2) == 0 { 1.0 } else { -1.0 })
            .collect(),
        (0..10_000_000).map(|_| 1e9 + rng.range(0.0, 1.0)).collect(),
        (0..10_000_000)
            .map(|_| 10f64.powf(rng.range(-10.0, 10.0)))
            .collect(),
    ];
    let mut worst = 0f64;
    for (i, xs) in streams.iter().enumerate() {
        let mut acc = MeanVar::new();
        for &x in xs {
            acc.push(x);
        }
        let (mean, var) = two_pass(xs);
        assert_eq!(acc.count(), xs.len() as u64);
        assert!(
            rel(acc.mean(), mean) < 1e-12,
            "stream {i}: mean {} against {mean}",
            acc.mean()
        );
        let e = rel(acc.variance(), var);
        worst = worst.max(e);
        println!("stream {i}: relative variance error {e:e}");
        assert!(
            e < 1e-10,
            "stream {i}: variance {} against {var} ({e})",
            acc.variance()
        );
        let se = (var / xs.len() as f64).sqrt();
        assert!(rel(acc.std_error(), se) < 1e-8);
    }
    println!("worst relative variance error: {worst:e}");
    let e = rel(naive(&streams[0]), two_pass(&streams[0]).1);
    assert!(
        e > 1e-6,
        "the naive form should fail here, but erred by only {e}"
    );
}

/// Merging uneven parts gives the long stream's mean and variance, and counts add as u64 past
/// 2³² (33 doublings of a two-value accumulator).
#[test]
fn merge_equals_one_stream_and_counts_do_not_wrap() {
    let mut rng = TestRng::new(21);
    let xs: Vec<f64> = (0..100_000).map(|_| 1e6 + rng.range(-3.0, 5.0)).collect();
    let mut whole = MeanVar::new();
    xs.iter().for_each(|&x| whole.push(x));
    let cuts = [0, 1, 2, 10, 999, 50_000, 77_777, 100_000];
    let mut merged = MeanVar::new();
    merged.merge(&MeanVar::new());
    for w in cuts.windows(2) {
        let mut part = MeanVar::new();
        xs[w[0]..w[1]].iter().for_each(|&x| part.push(x));
        merged.merge(&part);
    }
    assert_eq!(merged.count(), whole.count());
    assert!(rel(merged.mean(), whole.mean()) < 1e-14);
    assert!(rel(merged.variance(), whole.variance()) < 1e-9);

    let mut big = MeanVar::new();
    big.push(1.0);
    big.push(3.0);
    for _ in 0..32 {
        let copy = big;
        big.merge(&copy);
    }
    assert_eq!(big.count(), 1u64 << 33);
    assert_eq!(big.mean(), 2.0);
    let n = (1u64 << 33) as f64;
    assert!(rel(big.variance(), n / (n - 1.0)) < 1e-12);
    // Empty and single-value accumulators.
    assert_eq!(
        (MeanVar::new().variance(), MeanVar::new().std_error()),
        (0.0, 0.0)
    );
}

/// The packet accumulators of both widths: lane i equals a scalar accumulator of lane i's
/// values bit for bit, and the reduction matches one scalar accumulator of every value.
macro_rules! packet_accumulators {
    ($test:ident, $n:literal, $f:ty, $w:ty) => {
        #[test]
        fn $test() {
            let mut rng = TestRng::new(22);
            let mut packet = MeanVar::<$w>::new();
            let mut lanes = [MeanVar::new(); $n];
            let mut all = MeanVar::new();
            for _ in 0..10_000 {
                let x: [f32; $n] = core::array::from_fn(|_| rng.u01() * 100.0 + 1e4);
                packet.push(<$f>::new(x).widen());
                for i in 0..$n {
                    lanes[i].push(x[i] as f64);
                    all.push(x[i] as f64);
                }
            }
            for (i, lane) in lanes.iter().enumerate() {
                assert_eq!(packet.lane(i), *lane);
            }
            let r = packet.reduce();
            assert_eq!(r.count(), all.count());
            assert!(rel(r.mean(), all.mean()) < 1e-14);
            assert!(rel(r.variance(), all.variance()) < 1e-10);
        }
    };
}
packet_accumulators!(packet_accumulators, 8, F32x8, F64x8);
packet_accumulators!(sixteen_lane_accumulators, 16, F32x16, F64x16);

/// Roulette's values, clamps and bad inputs, in both widths.
#[test]
fn roulette_values_and_bad_inputs() {
    let cases: [(f32, f32, f32); 8] = [
        (0.5, 0.25, 2.0),
        (0.5, 0.5, 0.0),
        (2.0, 0.99, 1.0),
        (1e-6, 0.04, 1.0 / ROULETTE_Q_MIN),
        (1e-6, 0.06, 0.0),
        (f32::NAN, 0.7, 1.0),
        (0.5, f32::NAN, 0.0),
        (-1.0, 0.01, 1.0 / ROULETTE_Q_MIN),
    ];
    for (q, u, want) in cases {
        let got = estimate::roulette(q, u);
        assert_eq!(got, want, "roulette({q}, {u})");
        let lanes = estimate::roulette(F32x8::splat(q), F32x8::splat(u)).to_array();
        assert!(lanes.iter().all(|l| l.to_bits() == got.to_bits()));
        let lanes = estimate::roulette(F32x16::splat(q), F32x16::splat(u)).to_array();
        assert!(lanes.iter().all(|l| l.to_bits() == got.to_bits()));
        assert_eq!(estimate::roulette(q as f64, u as f64) as f32, want);
    }
}

/// Roulette with q = 0.3 on F = X², X uniform: the mean stays 1/3 (4σ) and the variance is
/// Var F + (1/q − 1)E[F²] = 4/45 + (7/3)/5 (4 standard errors of the variance). A roulette that
/// forgets the 1/q weight (the negative control) fails the mean. And q = 1e-6, clamped to
/// ROULETTE_Q_MIN, stays unbiased over 10⁶ trials.
#[test]
fn roulette_keeps_the_mean_and_adds_the_predicted_variance() {
    let run = |q: f32, forget: bool, seed: u64| {
        let mut rng = TestRng::new(seed);
        let mut acc = MeanVar::new();
        let mut m4 = 0.0;
        let n = 1_000_000;
        for _ in 0..n {
            let x = rng.u01() as f64;
            let r = estimate::roulette(q, rng.u01()) as f64;
            let r = if forget && r > 0.0 { 1.0 } else { r };
            let v = r * x * x;
            acc.push(v);
            m4 += v.powi(4);
        }
        (acc, m4 / n as f64)
    };
    let (acc, m4) = run(0.3, false, 23);
    let mean = 1.0 / 3.0;
    assert!(
        (acc.mean() - mean).abs() < 4.0 * acc.std_error(),
        "{}",
        acc.mean()
    );
    let q = 0.3f64;
    let predicted = 4.0 / 45.0 + (1.0 / q - 1.0) * 0.2;
    // Standard error of a variance estimate: √((μ₄ − σ⁴)/n), with the raw fourth moment as a
    // (larger) stand-in for the central one.
    let se_var = ((m4 - predicted * predicted) / 1e6).sqrt();
    assert!(
        (acc.variance() - predicted).abs() < 4.0 * se_var,
        "variance {} against {predicted} (se {se_var})",
        acc.variance()
    );
    let (bad, _) = run(0.3, true, 23);
    assert!(
        (bad.mean() - mean).abs() > 4.0 * bad.std_error(),
        "control passed: {}",
        bad.mean()
    );
    let (tiny, _) = run(1e-6, false, 24);
    assert!((tiny.mean() - mean).abs() < 4.0 * tiny.std_error());
}

/// Splitting k sub-samples of y under one x leaves the mean of ∫∫ x(x + y) = 7/12 unchanged for
/// k = 1…8 (4σ), with the variance falling as k grows; dividing by k + 1 instead of k (the
/// negative control) is caught.
#[test]
fn splitting_keeps_the_mean() {
    let run = |k: u32, off: u32| {
        let mut rng = TestRng::new(25 + k as u64);
        let mut acc = MeanVar::new();
        for _ in 0..200_000 {
            let x = rng.u01() as f64;
            let inner: f64 = (0..k).map(|_| x + rng.u01() as f64).sum();
            acc.push(x * inner / (k + off) as f64);
        }
        acc
    };
    let want = 7.0 / 12.0;
    let mut last = f64::INFINITY;
    for k in [1, 2, 4, 8] {
        let acc = run(k, 0);
        assert!(
            (acc.mean() - want).abs() < 4.0 * acc.std_error(),
            "k = {k}: {}",
            acc.mean()
        );
        assert!(acc.variance() < last);
        last = acc.variance();
    }
    let bad = run(4, 1);
    assert!((bad.mean() - want).abs() > 4.0 * bad.std_error());
}

/// split_count returns the integer minimiser of (V₁ + V₂/k)(C₁ + kC₂) over its range (checked by
/// brute force on random problems), and the documented values on degenerate ones.
#[test]
fn split_count_is_the_integer_optimum() {
    assert_eq!(estimate::split_count(1.0, 4.0, 4.0, 1.0, 1, 64), 4);
    let mut rng = TestRng::new(26);
    for _ in 0..20_000 {
        let p: [f64; 4] = core::array::from_fn(|_| 10f64.powf(rng.range(-3.0, 3.0)));
        let (min, max) = (1 + rng.below(4), 5 + rng.below(60));
        let cost = |k: u32| (p[0] + p[1] / k as f64) * (p[2] + k as f64 * p[3]);
        let best = (min..=max).map(cost).fold(f64::INFINITY, f64::min);
        let k = estimate::split_count(p[0], p[1], p[2], p[3], min, max);
        assert!((min..=max).contains(&k));
        assert!(
            cost(k) <= best * (1.0 + 1e-12),
            "{p:?}: {k} costs {} > {best}",
            cost(k)
        );
    }
    assert_eq!(estimate::split_count(0.0, 1.0, 1.0, 1.0, 2, 9), 9);
    assert_eq!(estimate::split_count(1.0, 1.0, 1.0, 0.0, 2, 9), 9);
    assert_eq!(estimate::split_count(1.0, 0.0, 1.0, 1.0, 2, 9), 2);
    assert_eq!(estimate::split_count(0.0, 0.0, 1.0, 1.0, 2, 9), 2);
    assert_eq!(estimate::split_count(f64::NAN, 1.0, 1.0, 1.0, 2, 9), 2);
    assert_eq!(estimate::split_count(1.0, -1.0, 1.0, 1.0, 2, 9), 2);
    assert_eq!(estimate::split_count(1.0, 1e300, 1e300, 1e-300, 0, 0), 1);
}
