//! One-dimensional test problems for MIS and resampling, with exact answers: two techniques on
//! [0, 1], p₁ = 1 (x = u) and p₂ = 0.2 + 1.6x, and integrands whose integrals are known. They
//! drive the estimator tests and the report's estimators table, and a user can run their own
//! weighting on them.

use crate::estimate::MeanVar;
use crate::mis::{self, FixedAlpha, OptimalMis, Reservoir};

use crate::lane::{F32x8, F32x16};

/// A two-technique heuristic: (n_f, pdf_f, n_g, pdf_g) → weight of f.
pub type Heuristic = fn(f32, f32, f32, f32) -> f32;
/// The same in the 8-wide packet.
pub type HeuristicX8 = fn(F32x8, F32x8, F32x8, F32x8) -> F32x8;
/// The same in the 16-wide packet.
pub type HeuristicX16 = fn(F32x16, F32x16, F32x16, F32x16) -> F32x16;

/// Every two-technique heuristic of [`mis`] in every width, the cutoff at α = 0.1: what the
/// report, the benches and the fuzz target iterate.
pub const HEURISTICS: [(&str, Heuristic, HeuristicX8, HeuristicX16); 4] = [
    ("balance", mis::balance, mis::balance, mis::balance),
    ("power", mis::power, mis::power, mis::power),
    ("maximum", mis::maximum, mis::maximum, mis::maximum),
    (
        "cutoff",
        |a, b, c, d| mis::cutoff(a, b, c, d, 0.1),
        |a, b, c, d| mis::cutoff(a, b, c, d, F32x8::splat(0.1)),
        |a, b, c, d| mis::cutoff(a, b, c, d, F32x16::splat(0.1)),
    ),
];

/// The first technique's density: uniform.
pub fn pdf1(_x: f64) -> f64 {
    1.0
}

/// The second technique's density: 0.2 + 1.6x, sampled by [`sample2`]. It is bounded away from
/// 0, so that every integrand here has finite variance under either technique alone (with 2x,
/// f/p₂ ~ 1/x at 0 and the single-technique variance, the table's yardstick, is infinite).
pub fn pdf2(x: f64) -> f64 {
    if (0.0..=1.0).contains(&x) {
        0.2 + 1.6 * x
    } else {
        0.0
    }
}

/// The inverse CDF of [`pdf2`]: the root of 0.8x² + 0.2x = u, as 2u/(0.2 + √(0.04 + 3.2u)),
/// which does not cancel.
pub fn sample2(u: f64) -> f64 {
    2.0 * u / (0.2 + (0.04 + 3.2 * u).sqrt())
}

/// An integrand on [0, 1] and its exact integral.
#[derive(Clone, Copy, Debug)]
pub struct Integrand {
    /// A short formula.
    pub name: &'static str,
    /// The function.
    pub f: fn(f64) -> f64,
    /// ∫₀¹ f.
    pub integral: f64,
}

/// A cubic that p₁ serves poorly, a decreasing quadratic that p₂ serves poorly, a mixture of the
/// two pdfs that is not proportional to their sum (optimal MIS has zero variance there, balance
/// does not), and a steep x⁵.
pub const INTEGRANDS: [Integrand; 4] = [
    Integrand {
        name: "x³ + 0.05",
        f: |x| x * x * x + 0.05,
        integral: 0.3,
    },
    Integrand {
        name: "(1 − x)² + 0.2",
        f: |x| (1.0 - x) * (1.0 - x) + 0.2,
        integral: 1.0 / 3.0 + 0.2,
    },
    Integrand {
        name: "0.8p₁ + 0.2p₂",
        f: |x| 0.84 + 0.32 * x,
        integral: 1.0,
    },
    Integrand {
        name: "6x⁵",
        f: |x| 6.0 * x * x * x * x * x,
        integral: 1.0,
    },
];

/// ∫ₐᵇ g by composite Simpson on `n` (even) intervals.
pub fn simpson(a: f64, b: f64, n: usize, g: impl Fn(f64) -> f64) -> f64 {
    let h = (b - a) / n as f64;
    let mut sum = g(a) + g(b);
    for i in 1..n {
        sum += g(a + i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
    }
    sum * h / 3.0
}

/// The optimal-MIS α of `f` for n₁ and n₂ samples, from the exact integrals
/// A_ik = ∫pᵢpₖ/S and bᵢ = ∫f·pᵢ/S (Simpson on 2·10⁵ intervals; the integrands are smooth).
pub fn exact_alpha(f: fn(f64) -> f64, n1: f64, n2: f64) -> [f64; 2] {
    let s = |x: f64| n1 * pdf1(x) + n2 * pdf2(x);
    let q = |g: &dyn Fn(f64) -> f64| simpson(0.0, 1.0, 200_000, |x| g(x) / s(x));
    let a11 = q(&|x| pdf1(x) * pdf1(x));
    let a12 = q(&|x| pdf1(x) * pdf2(x));
    let a22 = q(&|x| pdf2(x) * pdf2(x));
    let b1 = q(&|x| f(x) * pdf1(x));
    let b2 = q(&|x| f(x) * pdf2(x));
    let det = a11 * a22 - a12 * a12;
    [(a22 * b1 - a12 * b2) / det, (a11 * b2 - a12 * b1) / det]
}

/// The estimators compared, each over estimates that take `n` samples of each technique (2n
/// evaluations of f; RIS takes 2n candidates from p₁ and one evaluation of f).
pub const ESTIMATORS: [&str; 11] = [
    "technique 1",
    "technique 2",
    "balance",
    "power",
    "maximum",
    "cutoff 0.1",
    "one-sample (balance)",
    "optimal (direct)",
    "optimal (fixed α)",
    "ris (p̂ = p₂)",
    "ris (p̂ = p₂) ×2n",
];

/// Every estimator of [`ESTIMATORS`] on one integrand: `rounds` independent estimates each, from
/// a 64-bit stream seeded by `seed`. Technique i alone uses 2n samples of itself, so that every
/// estimator spends the same number of samples.
pub fn compare(integrand: &Integrand, n: usize, rounds: usize, seed: u64) -> [MeanVar; 11] {
    let f = integrand.f;
    let nf = n as f64;
    let alpha = exact_alpha(f, nf, nf);
    let mut state = seed ^ 0x9e37_79b9_7f4a_7c15;
    let mut uniform = move || {
        // SplitMix64: a stream independent of the crate's generators.
        state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    };
    let mut out = [MeanVar::new(); 11];
    let w32 = |h: Heuristic, own: f64, other: f64| {
        f64::from(h(n as f32, own as f32, n as f32, other as f32))
    };
    for _ in 0..rounds {
        let (mut single, mut h) = ([0.0; 2], [0.0; 4]);
        let mut direct = OptimalMis::new(nf, nf);
        let mut fixed = FixedAlpha::new(nf, nf, alpha);
        for j in 0..2 * n {
            let u = uniform();
            // Technique-alone estimates: 2n samples each.
            single[0] += f(u) / pdf1(u) / (2.0 * nf);
            let x2 = sample2(u);
            single[1] += f(x2) / pdf2(x2) / (2.0 * nf);
            // MIS: the first n samples from technique 1, the next n from technique 2.
            let (x, tech) = if j < n { (u, 0) } else { (x2, 1) };
            let (p1, p2) = (pdf1(x), pdf2(x));
            let (own, other) = if tech == 0 { (p1, p2) } else { (p2, p1) };
            for (acc, (_, weight, _, _)) in h.iter_mut().zip(HEURISTICS) {
                *acc += w32(weight, own, other) * f(x) / (nf * own);
            }
            direct.push(f(x), p1, p2);
            fixed.push(f(x), p1, p2);
        }
        // One-sample MIS, 2n times: choose by c = (½, ½), weight by balance.
        let mut one = 0.0;
        for _ in 0..2 * n {
            let pick = mis::one_sample([0.5f32, 0.5], uniform() as f32);
            let u = f64::from(pick.u);
            let x = if pick.index == 0 { u } else { sample2(u) };
            let (p1, p2) = (pdf1(x), pdf2(x));
            let p = if pick.index == 0 { p1 } else { p2 };
            let w = mis::balance_n([0.5f32, 0.5], [p1 as f32, p2 as f32])[pick.index as usize];
            // A weight of 0 (here: p₂ = 0 at x = 0, reachable by a 24-bit u) contributes 0.
            if w > 0.0 {
                one += f64::from(w) * f(x) / (f64::from(pick.probability) * p) / (2.0 * nf);
            }
        }
        let ris = |m: usize, uniform: &mut dyn FnMut() -> f64| {
            let mut r = Reservoir::new(f64::from(uniform() as f32));
            for _ in 0..m {
                let x = uniform();
                r.push(x, pdf2(x), pdf1(x));
            }
            let (y, w) = r.chosen();
            if w > 0.0 { f(y) * w } else { 0.0 }
        };
        let ris_one = ris(2 * n, &mut uniform);
        let ris_many = (0..2 * n).map(|_| ris(2 * n, &mut uniform)).sum::<f64>() / (2.0 * nf);
        let values = [
            single[0],
            single[1],
            h[0],
            h[1],
            h[2],
            h[3],
            one,
            direct.estimate(),
            fixed.estimate(),
            ris_one,
            ris_many,
        ];
        for (acc, v) in out.iter_mut().zip(values) {
            acc.push(v);
        }
    }
    out
}
