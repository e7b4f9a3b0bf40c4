//! Multiple importance sampling: the weights that combine techniques (Veach 1997, ch. 9), and the
//! choice of one technique per sample.
//!
//! # Two techniques
//!
//! [`balance`], [`power`] (β = 2), [`maximum`] and [`cutoff`] each take `(n_f, pdf_f, n_g, pdf_g)`
//! and return the weight of technique f, whose contribution is a = n_f·pdf_f against
//! b = n_g·pdf_g for g. Counts are floats, so one-sample MIS's selection probabilities fit too.
//! Every function is generic over the lane: `f32`, [`F32x8`](crate::x8::F32x8) and `f64`, with
//! the same operations in each, so packets equal scalars bit for bit.
//!
//! **Ratio form.** The weights are written in r = min(a, b)/max(a, b) ∈ [0, 1]: with t = h(r)
//! (h(r) = r for balance, r² for power), the larger contribution gets 1/(1 + t) and the smaller
//! t/(1 + t). The naive a²/(a² + b²) overflows to ∞/∞ at pdfs of 1e20 and underflows to 0/0 at
//! 1e-25; r does neither. The pdfs are first divided by the larger one, so a and b are finite for
//! every finite input, and the products n·pdf never overflow.
//!
//! **Error** (f32, measured on 10⁶ pairs with pdfs log-uniform over 1e-30…1e30 plus zeros,
//! subnormals and ∞, `tests/all/estimate/mis.rs`): against the f64 weight of the same inputs, balance and
//! cutoff are within 3 ulp of the weight (2.8 seen), power within 5 (4.8 seen: squaring doubles
//! the ratio's error), maximum exact, wherever the weight is above 1e-30 (below, the pdf ratio is
//! subnormal and loses bits). The two weights of one pair, `w(f, g)` and `w(g, f)`, come from the
//! same r, so w(f, g) + w(g, f) = 1 within f32::EPSILON wherever either contribution is positive.
//!
//! **Special values**, the same in every width:
//! - a weight is 0 when its own pdf or count is 0 or negative, so (0, 0) gives 0 and 0;
//! - it is 1 when the other's pdf or count is 0 (and its own is not);
//! - an infinite pdf (or count) beats every finite one, giving 1 and 0; two infinite pdfs give
//!   ½ each (a delta is better routed by a flag, but this one is defined);
//! - NaN in either pdf or count gives 0.
//!
//! # N techniques
//!
//! [`balance_n`] and [`power_n`] return the weights of all N techniques of a fixed-size array at
//! once, with the same ratio form (every contribution divided by the largest) and the same rules.
//!
//! # One-sample MIS
//!
//! [`one_sample`] picks technique i with probability cᵢ from one u and rescales u to [0, 1) for
//! the chosen sampler, so stratification in u carries over. The estimate is then
//! wᵢ·f/(cᵢ·pᵢ), with wᵢ from [`balance_n`] with counts c (balance is optimal in this model).
//!
//! # Beyond the heuristics
//!
//! [`OptimalMis`] fits the optimal weights of Kondapaneni et al. (2019) for two techniques from
//! the samples themselves, with a closed-form 2×2 solve and no allocation; [`FixedAlpha`] is its
//! unbiased form. [`Reservoir`] is resampled importance sampling's weighted reservoir (Talbot et
//! al. 2005), driven by one u. Both sum in f64 and are generic over the f64 lane: `f64`, or
//! [`F64x8`] for one accumulator or reservoir per packet lane.

use crate::lane::{F64x8, F64x16, Lane, Lane32, Lanes, U32Lane, U32x8, U32x16, zip_map};
use crate::warp::ONE_MINUS_EPS;

/// Where f's weight is decided without a ratio: NaN, zero or negative inputs, and ∞.
#[inline(always)]
fn special<L: Lane>(n_f: L, p_f: L, n_g: L, p_g: L, general: L) -> L {
    let inf = L::c(f64::INFINITY);
    let valid_f = n_f.gt(L::ZERO) & p_f.gt(L::ZERO);
    let valid_g = n_g.gt(L::ZERO) & p_g.gt(L::ZERO);
    let inf_f = valid_f & (p_f.eq(inf) | n_f.eq(inf));
    let inf_g = valid_g & (p_g.eq(inf) | n_g.eq(inf));
    let w = L::select(inf_f, L::select(inf_g, L::HALF, L::ONE), general);
    let w = L::select(inf_g & !inf_f, L::ZERO, w);
    let w = L::select(valid_g, w, L::ONE);
    let nan = p_g.is_nan() | n_g.is_nan();
    L::select(valid_f & !nan, w, L::ZERO)
}

/// f's weight from t = h(r): 1/(1 + t) if f's contribution is the larger, t/(1 + t) if not. Both
/// calls of a pair see the same r, since it is built from min and max.
#[inline(always)]
fn two<L: Lane>(n_f: L, p_f: L, n_g: L, p_g: L, h: impl Fn(L) -> L) -> L {
    // Divide both pdfs by the larger: one becomes 1 exactly, the other q ∈ [0, 1].
    let f_pdf_larger = p_f.ge(p_g);
    let q = p_f.min(p_g) / p_f.max(p_g);
    let a = L::select(f_pdf_larger, n_f, n_f * q);
    let b = L::select(f_pdf_larger, n_g * q, n_g);
    let t = h(a.min(b) / a.max(b));
    let w = L::select(a.gt(b), L::ONE, t) / (L::ONE + t);
    special(n_f, p_f, n_g, p_g, w)
}

/// The balance heuristic: a/(a + b) with a = n_f·pdf_f, b = n_g·pdf_g, in ratio form.
///
/// The weight of technique f against g; see the [module documentation](self) for the error and
/// the special values (0 for NaN, zero or negative own inputs; 1 against a zero; ½ for two ∞).
#[inline(always)]
pub fn balance<L: Lane>(n_f: L, pdf_f: L, n_g: L, pdf_g: L) -> L {
    two(n_f, pdf_f, n_g, pdf_g, |r| r)
}

/// The power heuristic with β = 2: a²/(a² + b²), in ratio form. Special values as [`balance`].
#[inline(always)]
pub fn power<L: Lane>(n_f: L, pdf_f: L, n_g: L, pdf_g: L) -> L {
    two(n_f, pdf_f, n_g, pdf_g, |r| r * r)
}

/// The maximum heuristic: 1 if f's contribution is the larger, 0 if it is the smaller, ½ on a
/// tie (so that the two weights still sum to 1). Special values as [`balance`].
#[inline(always)]
pub fn maximum<L: Lane>(n_f: L, pdf_f: L, n_g: L, pdf_g: L) -> L {
    two(n_f, pdf_f, n_g, pdf_g, |r| {
        L::select(r.lt(L::ONE), L::ZERO, L::ONE)
    })
}

/// The cutoff heuristic: a contribution below `alpha` times the larger one gets 0, and the rest
/// share by balance. `alpha` is clamped to [0, 1] (NaN acts as 0, which is balance; 1 is
/// maximum). Special values as [`balance`].
#[inline(always)]
pub fn cutoff<L: Lane>(n_f: L, pdf_f: L, n_g: L, pdf_g: L, alpha: L) -> L {
    let alpha = L::select(alpha.gt(L::ZERO), alpha.min(L::ONE), L::ZERO);
    two(n_f, pdf_f, n_g, pdf_g, |r| {
        L::select(r.lt(alpha), L::ZERO, r)
    })
}

/// The weights of N techniques for h(a) = a^β: h(aᵢ)/Σ h(aₖ) with aₖ = nₖ·pdfₖ, every
/// contribution divided by the largest first, so nothing overflows.
///
/// Special values as for two: a technique with a zero, negative or NaN count or pdf gets 0;
/// techniques with an infinite pdf share 1 equally and the rest get 0; if any input is NaN,
/// every weight is 0; if no technique has a positive contribution, every weight is 0.
#[inline(always)]
fn weights_n<L: Lane, const N: usize>(n: [L; N], pdf: [L; N], h: impl Fn(L) -> L) -> [L; N] {
    let inf = L::c(f64::INFINITY);
    let valid: [L::Mask; N] = zip_map(n, pdf, |n, p| n.gt(L::ZERO) & p.gt(L::ZERO));
    let is_inf: [L::Mask; N] = zip_map(
        valid,
        zip_map(n, pdf, |n, p| p.eq(inf) | n.eq(inf)),
        |v, i| v & i,
    );
    let keep = |m: L::Mask, x: L| L::select(m, x, L::ZERO);

    let mut max_pdf = L::ZERO;
    let mut nan = L::ZERO.gt(L::ZERO);
    let mut infinite = L::ZERO;
    for (((&v, &i), &nk), &pk) in valid.iter().zip(&is_inf).zip(&n).zip(&pdf) {
        max_pdf = keep(v & !i, pk).max(max_pdf);
        nan = nan | nk.is_nan() | pk.is_nan();
        infinite = infinite + keep(i, L::ONE);
    }
    let a: [L; N] = zip_map(valid, zip_map(n, pdf, |n, p| n * (p / max_pdf)), keep);
    let mut max_a = L::ZERO;
    for &x in &a {
        max_a = x.max(max_a);
    }
    let t: [L; N] = zip_map(valid, a, |v, x| keep(v, h(x / max_a)));
    let mut sum = L::ZERO;
    for &x in &t {
        sum = sum + x;
    }
    zip_map(zip_map(valid, is_inf, |v, i| (v, i)), t, |(v, i), tk| {
        let w = L::select(infinite.gt(L::ZERO), keep(i, L::ONE) / infinite, tk / sum);
        L::select(nan | !v, L::ZERO, w)
    })
}

/// The balance heuristic over N techniques: `[w₀, …, w_{N−1}]` with wᵢ = aᵢ/Σaₖ, aₖ = nₖ·pdfₖ.
/// As in the [module documentation](self): zero, negative or NaN inputs give 0, infinite pdfs
/// share 1, NaN anywhere gives 0 everywhere, and so does no positive contribution at all.
#[inline(always)]
pub fn balance_n<L: Lane, const N: usize>(counts: [L; N], pdfs: [L; N]) -> [L; N] {
    weights_n(counts, pdfs, |r| r)
}

/// The power heuristic (β = 2) over N techniques: wᵢ = aᵢ²/Σaₖ². Special values as
/// [`balance_n`].
#[inline(always)]
pub fn power_n<L: Lane, const N: usize>(counts: [L; N], pdfs: [L; N]) -> [L; N] {
    weights_n(counts, pdfs, |r| r * r)
}

/// The technique [`one_sample`] chose, per lane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Choice<L: Lane32> {
    /// Its index in `0..N` (the bits of a `u32` in each lane).
    pub index: L::U,
    /// The probability with which it was chosen, cᵢ/Σcₖ; 0 if no technique could be.
    pub probability: L,
    /// u rescaled to [0, 1) within the chosen technique's share, to drive its sampler.
    pub u: L,
}

/// One-sample MIS: choose technique i with probability cᵢ/Σcₖ by one u ∈ [0, 1).
///
/// The shares lie end to end on [0, 1) in index order; the chosen one contains u·Σc, and the
/// returned u is the position within it, (u·Σc − Σ_{k<i} cₖ)/cᵢ, clamped to [0, 1 − 2⁻²⁴]. So a
/// stratified u stays stratified within each technique.
///
/// Zero, negative, infinite and NaN probabilities are never chosen (the others need not sum to
/// 1: they are normalised); u is clamped to [0, 1), and NaN u acts as 0. If no cᵢ is positive, the result is index 0 with probability 0 (the estimate must then be
/// 0). Rounding at a boundary can only move u to a neighbouring technique with cᵢ > 0.
#[inline(always)]
pub fn one_sample<L: Lane32, const N: usize>(c: [L; N], u: L) -> Choice<L> {
    // Only positive finite probabilities count; dividing by the largest keeps their sum finite.
    let inf = L::c(f64::INFINITY);
    let c: [L; N] = c.map(|x| L::select(x.gt(L::ZERO) & x.lt(inf), x, L::ZERO));
    let mut largest = L::ZERO;
    for &x in &c {
        largest = x.max(largest);
    }
    let c: [L; N] = c.map(|x| x / L::select(largest.gt(L::ZERO), largest, L::ONE));
    let mut total = L::ZERO;
    for &x in &c {
        total = total + x;
    }
    let one_minus_eps = L::c(ONE_MINUS_EPS as f64);
    let u = L::select(u.gt(L::ZERO), u.min(one_minus_eps), L::ZERO);
    let target = u * total;
    // Walk the shares: the first positive one whose end lies beyond target is the choice. If
    // rounding leaves target at or past the last end, the last positive share takes it.
    let none = L::ZERO.gt(L::ZERO);
    let (mut found, mut any) = (none, none);
    let mut end = L::ZERO;
    // (index as float bits, share, start) of the choice and of the last positive share.
    let (mut chosen, mut last) = ((L::ZERO, L::ZERO, L::ZERO), (L::ZERO, L::ZERO, L::ZERO));
    for (k, &ck) in c.iter().enumerate() {
        let start = end;
        end = start + ck;
        let positive = ck.gt(L::ZERO);
        let this = (L::from_bits(L::U::splat(k as u32)), ck, start);
        let take = positive & !found & target.lt(end);
        chosen = pick(take, this, chosen);
        last = pick(positive, this, last);
        found = found | take;
        any = any | positive;
    }
    let (index, share, share_start) = pick(found, chosen, last);
    let within = ((target - share_start) / share)
        .max(L::ZERO)
        .min(one_minus_eps);
    Choice {
        index: index.to_bits(),
        probability: L::select(any, share / total, L::ZERO),
        u: L::select(any, within, u),
    }
}

#[inline(always)]
fn pick<L: Lane>(m: L::Mask, a: (L, L, L), b: (L, L, L)) -> (L, L, L) {
    (
        L::select(m, a.0, b.0),
        L::select(m, a.1, b.1),
        L::select(m, a.2, b.2),
    )
}

// ---------------------------------------------------------------------------------------------
// Optimal MIS for two techniques

/// Optimal MIS weights for two techniques (Kondapaneni, Vévoda, Grittmann, Škrivan, Slusallek
/// and Křivánek, "Optimal Multiple Importance Sampling", SIGGRAPH 2019), accumulated without
/// allocation.
///
/// The estimator is balance MIS plus a control variate built from the two pdfs:
/// F = α₁ + α₂ + Σ (f − α₁p₁ − α₂p₂)/S over the samples of both techniques, with
/// S = n₁p₁ + n₂p₂ and nᵢ the samples technique i takes per estimate. Its variance is smallest
/// for the α that solves A·α = b, A_ik = ∫pᵢpₖ/S and bᵢ = ∫f·pᵢ/S. [`push`](Self::push) gathers
/// their sample estimates Â_ik = Σpᵢpₖ/S² and b̂ᵢ = Σf·pᵢ/S², and [`alpha`](Self::alpha) solves
/// the 2×2 system in closed form (Cramer's rule).
///
/// **Two modes.**
/// - [`estimate`](Self::estimate), the direct estimate: α from the same samples. The residual sum
///   then vanishes exactly (Σₖnₖpₖ/S = 1), so F = α₁ + α₂. It is consistent, with a bias of
///   order 1/N that is not small for few samples: on the 1D integrands of
///   `tests/all/estimate/mis_estimators.rs` it measured −2.7 % to −14 % of the integral at 4
///   samples per technique, −0.48 % to −2.3 % at 16 and −0.10 % to −0.44 % at 64 (0 where f lies
///   in the span of the pdfs). Accumulate over many estimates, or use the unbiased form, where
///   that matters.
/// - [`FixedAlpha`], the unbiased form: α fixed beforehand (from a pilot pass with this
///   accumulator, or from an analytic value), and the residual sum kept;
///   [`estimate_with_alpha_of`](Self::estimate_with_alpha_of) does the same with α from another
///   accumulator.
///
/// **Fallback.** When the system is singular (one technique never produced a positive pdf, or the
/// two pdfs are proportional over the samples: det ≤ 1e-9·A₁₁A₂₂), there is no control variate to
/// fit and [`estimate`](Self::estimate) returns the balance-heuristic estimate Σf/S instead, as
/// does [`balance_estimate`](Self::balance_estimate) always. Samples with a NaN or infinite f or
/// pdf, a negative pdf, S = 0, or terms beyond f64's range (pdf/S above 1e154, from counts tiny
/// against the pdfs) are counted but contribute nothing. The estimate is therefore finite unless
/// the sums of finite terms themselves overflow; it is never NaN.
///
/// **Widths.** Sums are in f64, over the f64 lane `W`: `OptimalMis` (`W = f64`) is one
/// accumulator, `OptimalMis<F64x8>` eight, one per packet lane, pushed by the same generic code,
/// so lane i equals a scalar accumulator given lane i's samples, bit for bit
/// ([`lane`](Self::lane)), and the sums vectorise.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OptimalMis<W = f64> {
    counts: [f64; 2],
    samples: u64,
    sums: Sums<W>,
}

/// The sums of optimal MIS, lane by lane.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
struct Sums<W> {
    /// Â₁₁, Â₁₂, Â₂₂.
    a: [W; 3],
    b: [W; 2],
    /// Σ f/S: the balance heuristic's sum.
    balance: W,
    /// Σ p₁/S, Σ p₂/S: with `balance`, the residual sum for any α (it is linear in α).
    q: [W; 2],
}

impl<W: Lane> Sums<W> {
    /// One sample per lane: f and both pdfs. Unusable samples (see [`mixture`]) and terms beyond
    /// the lane's range add 0.
    #[inline(always)]
    fn push(&mut self, counts: [f64; 2], f: W, pdf1: W, pdf2: W) {
        let (usable, s) = mixture(counts, f, pdf1, pdf2);
        let (q1, q2, g) = (pdf1 / s, pdf2 / s, f / s);
        let terms = [q1 * q1, q1 * q2, q2 * q2, g * q1, g * q2, g, q1, q2];
        // pdf/S beyond 1e154 (tiny counts against large pdfs) would overflow a square.
        let keep = terms.iter().fold(usable, |m, t| m & t.is_finite());
        let add = |acc: &mut W, t: W| *acc = *acc + W::select(keep, t, W::ZERO);
        let [a11, a12, a22, b1, b2, g, q1, q2] = terms;
        add(&mut self.a[0], a11);
        add(&mut self.a[1], a12);
        add(&mut self.a[2], a22);
        add(&mut self.b[0], b1);
        add(&mut self.b[1], b2);
        add(&mut self.balance, g);
        add(&mut self.q[0], q1);
        add(&mut self.q[1], q2);
    }

    /// Lane `i` of every sum.
    fn lane(&self, i: usize) -> Sums<f64>
    where
        W: Lanes<Scalar = f64>,
    {
        let at = |w: W| w.lane(i);
        Sums {
            a: self.a.map(at),
            b: self.b.map(at),
            balance: at(self.balance),
            q: self.q.map(at),
        }
    }
}

impl<W: Lanes<Scalar = f64>> OptimalMis<W> {
    /// An empty accumulator (per lane) for techniques taking `n1` and `n2` samples per estimate
    /// (fractions such as one-sample MIS's selection probabilities are allowed). Negative or NaN
    /// counts act as 0.
    pub fn new(n1: f64, n2: f64) -> Self {
        Self {
            counts: counts(n1, n2),
            samples: 0,
            sums: Sums {
                a: [W::ZERO; 3],
                b: [W::ZERO; 2],
                balance: W::ZERO,
                q: [W::ZERO; 2],
            },
        }
    }

    /// One sample per lane, from either technique: its integrand value f and both techniques'
    /// pdfs at it.
    #[inline]
    pub fn push(&mut self, f: W, pdf1: W, pdf2: W) {
        self.samples += 1;
        self.sums.push(self.counts, f, pdf1, pdf2);
    }

    /// The samples pushed so far (per lane).
    pub fn samples(&self) -> u64 {
        self.samples
    }

    /// Lane `i`'s accumulator (`i` modulo the width).
    pub fn lane(&self, i: usize) -> OptimalMis {
        OptimalMis {
            counts: self.counts,
            samples: self.samples,
            sums: self.sums.lane(i),
        }
    }

    /// The balance-heuristic estimate from the same samples: Σf/S over the rounds of n₁ + n₂
    /// samples seen. 0 before any sample.
    pub fn balance_estimate(&self) -> W {
        W::from_fn(|i| {
            let l = self.lane(i);
            per_round(l.sums.balance, l.samples, l.counts)
        })
    }

    /// The direct optimal-MIS estimate α₁ + α₂ (consistent, bias of order 1/N), or the balance
    /// estimate where the system is singular.
    pub fn estimate(&self) -> W {
        W::from_fn(|i| {
            let l = self.lane(i);
            match l.alpha() {
                Some([a1, a2]) => a1 + a2,
                None => per_round(l.sums.balance, l.samples, l.counts),
            }
        })
    }

    /// The unbiased estimate from this accumulator's samples with α fitted on `pilot`'s, which
    /// must be independent of them: α₁ + α₂ + Σ(f − α₁p₁ − α₂p₂)/S per round, as
    /// [`FixedAlpha`] computes it (the residual is linear in α, so the sums kept here suffice).
    /// Where `pilot`'s system is singular, α = 0: the balance estimate. Lane by lane.
    ///
    /// Cross-fitting, two halves each the pilot of the other, gives an unbiased optimal-MIS
    /// estimate from one set of samples with no pilot pass.
    pub fn estimate_with_alpha_of(&self, pilot: &Self) -> W {
        W::from_fn(|i| {
            let (l, p) = (self.lane(i), pilot.lane(i));
            let [a1, a2] = p.alpha().unwrap_or([0.0, 0.0]);
            let residual = l.sums.balance - a1 * l.sums.q[0] - a2 * l.sums.q[1];
            a1 + a2 + per_round(residual, l.samples, l.counts)
        })
    }
}

impl OptimalMis {
    /// The solved α, or `None` where the system is singular (see the type's documentation).
    pub fn alpha(&self) -> Option<[f64; 2]> {
        // Cramer's rule on A/ka and b/kb, whose entries are at most 1, so that no product
        // overflows; α = (kb/ka)·(A/ka)⁻¹(b/kb).
        let Sums { a, b, .. } = self.sums;
        let ka = a[0].max(a[2]);
        let kb = b[0].abs().max(b[1].abs());
        if !(ka > 0.0 && ka.is_finite() && kb.is_finite()) {
            return None;
        }
        if kb == 0.0 {
            return Some([0.0, 0.0]);
        }
        let [a11, a12, a22] = a.map(|x| x / ka);
        let [b1, b2] = b.map(|x| x / kb);
        let det = a11 * a22 - a12 * a12;
        // Cauchy–Schwarz makes det ≥ 0; near 0 the system carries no information.
        let regular = det > 1e-9 * a11 * a22;
        let scale = kb / ka;
        let alpha = [
            (a22 * b1 - a12 * b2) / det * scale,
            (a11 * b2 - a12 * b1) / det * scale,
        ];
        (regular && alpha.iter().all(|x| x.is_finite())).then_some(alpha)
    }
}

/// The unbiased form of optimal MIS: F = α₁ + α₂ + Σ(f − α₁p₁ − α₂p₂)/S with α fixed before the
/// samples are drawn. See [`OptimalMis`]; bad samples are treated the same way.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FixedAlpha {
    counts: [f64; 2],
    alpha: [f64; 2],
    samples: u64,
    residual: f64,
}

impl FixedAlpha {
    /// An accumulator with sample counts n₁, n₂ per estimate and the fixed α.
    pub fn new(n1: f64, n2: f64, alpha: [f64; 2]) -> Self {
        Self {
            counts: counts(n1, n2),
            alpha,
            ..Self::default()
        }
    }

    /// One sample, from either technique, with both pdfs at it.
    #[inline]
    pub fn push(&mut self, f: f64, pdf1: f64, pdf2: f64) {
        self.samples += 1;
        let (usable, s) = mixture(self.counts, f, pdf1, pdf2);
        if usable {
            let r = (f - self.alpha[0] * pdf1 - self.alpha[1] * pdf2) / s;
            if r.is_finite() {
                self.residual += r;
            }
        }
    }

    /// The unbiased estimate α₁ + α₂ + (residual sum per round of n₁ + n₂ samples).
    pub fn estimate(&self) -> f64 {
        self.alpha[0] + self.alpha[1] + per_round(self.residual, self.samples, self.counts)
    }
}

/// Sample counts per estimate: negative or NaN act as 0.
fn counts(n1: f64, n2: f64) -> [f64; 2] {
    [n1, n2].map(|n| if n > 0.0 { n } else { 0.0 })
}

/// S = n₁p₁ + n₂p₂, and where the sample is usable: finite f, finite non-negative pdfs,
/// 0 < S < ∞.
#[inline(always)]
fn mixture<W: Lane>(counts: [f64; 2], f: W, pdf1: W, pdf2: W) -> (W::Mask, W) {
    let ok = |x: W| x.is_finite() & x.ge(W::ZERO);
    let s = W::c(counts[0]) * pdf1 + W::c(counts[1]) * pdf2;
    let usable = ok(pdf1) & ok(pdf2) & f.is_finite() & s.gt(W::ZERO) & s.is_finite();
    (usable, s)
}

/// A sum over every sample, per round of n₁ + n₂ samples; 0 before any sample.
fn per_round(sum: f64, samples: u64, counts: [f64; 2]) -> f64 {
    let rounds = samples as f64 / (counts[0] + counts[1]);
    if rounds > 0.0 { sum / rounds } else { 0.0 }
}

// ---------------------------------------------------------------------------------------------
// Resampled importance sampling

/// A weighted reservoir for resampled importance sampling (Talbot, Cline and Egbert 2005):
/// candidates xⱼ drawn from p stream through it with weights wⱼ = p̂(xⱼ)/p(xⱼ), and it keeps one,
/// y = xⱼ with probability wⱼ/Σw, in one pass and without storing the others.
///
/// The choice comes from the single u given to [`new`](Self::new), not from a hidden generator:
/// at each candidate, with W the running sum including it, the candidate replaces the kept one
/// when u·W < wⱼ, and u is rescaled to [0, 1) within whichever side it fell. So a stratified u
/// stratifies the choice (u is held in f64, which leaves ample bits for millions of candidates).
///
/// [`chosen`](Self::chosen) returns y and the RIS weight (1/p̂(y))·(1/M)·Σw: the estimate is
/// f(y) times it, unbiased when p̂ > 0 wherever f ≠ 0. A candidate with a zero, negative or NaN
/// target or pdf has weight 0: it is never kept but still counts in M.
///
/// **Widths.** Generic over the f64 lane `W` like [`OptimalMis`]: `Reservoir<T>` keeps any
/// `Copy` candidate; `Reservoir<U32x8, F64x8>` is eight reservoirs offered the same candidate
/// indices with per-lane targets and pdfs, each lane equal to a scalar reservoir of its values,
/// bit for bit ([`lane`](Self::lane)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reservoir<T, W = f64> {
    u: W,
    total: W,
    count: u32,
    kept: T,
    /// p̂ of the kept candidate; 0 while none is kept.
    target: W,
}

/// A candidate a [`Reservoir`] can keep lane by lane: chosen between two by the mask `M` of the
/// reservoir's lane. Every `Copy` type is one for the scalar reservoir; [`U32x8`] and [`U32x16`]
/// (candidate indices) for the packet ones.
pub trait Candidate<M>: Copy {
    /// One lane's candidate.
    type Scalar: Copy;
    /// `a` where `m` is set, else `b`, per lane.
    fn pick(m: M, a: Self, b: Self) -> Self;
    /// Lane `i`'s candidate (`i` modulo the width). Named apart from [`Lanes::lane`] because
    /// every `Copy` type is a candidate.
    fn in_lane(self, i: usize) -> Self::Scalar;
}

impl<T: Copy> Candidate<bool> for T {
    type Scalar = T;
    #[inline(always)]
    fn pick(m: bool, a: T, b: T) -> T {
        if m { a } else { b }
    }
    #[inline(always)]
    fn in_lane(self, _i: usize) -> T {
        self
    }
}

/// The packet widths' candidate indices, chosen by the f64 mask of the same width (its lanes as
/// bits: `$bits`).
macro_rules! packet_candidate {
    ($($m:ty, $u:ty, |$x:ident| $bits:expr);*) => {$(
        impl Candidate<$m> for $u {
            type Scalar = u32;
            #[inline(always)]
            fn pick(m: $m, a: $u, b: $u) -> $u {
                let bits = { let $x = m; $bits };
                let m = <$u>::new(core::array::from_fn(|i| 0u32.wrapping_sub((bits >> i) & 1)));
                (a & m) | (b & !m)
            }
            #[inline(always)]
            fn in_lane(self, i: usize) -> u32 {
                crate::lane::lane_of(&self.to_array(), i)
            }
        }
    )*};
}
packet_candidate!(
    F64x8, U32x8, |m| m.to_bitmask();
    F64x16, U32x16, |m| m.lo.to_bitmask() | (m.hi.to_bitmask() << 8)
);

impl<T, W> Reservoir<T, W>
where
    W: Lanes<Scalar = f64>,
    T: Candidate<W::Mask> + Default,
{
    /// An empty reservoir (per lane) driven by `u` ∈ [0, 1) (clamped to [0, 1 − 2⁻²⁴]; NaN acts
    /// as 0).
    pub fn new(u: W) -> Self {
        let one_minus_eps = W::c(f64::from(ONE_MINUS_EPS));
        Self {
            u: W::select(u.gt(W::ZERO), u.min(one_minus_eps), W::ZERO),
            total: W::ZERO,
            count: 0,
            kept: T::default(),
            target: W::ZERO,
        }
    }

    /// Offers a candidate drawn with density `pdf`, whose target is `target` (p̂, unnormalised),
    /// and returns the lanes that keep it.
    #[inline]
    pub fn push(&mut self, candidate: T, target: W, pdf: W) -> W::Mask {
        self.count += 1;
        let w = target / pdf;
        let ok = target.gt(W::ZERO) & pdf.gt(W::ZERO) & w.is_finite();
        let before = self.total;
        self.total = W::select(ok, self.total + w, self.total);
        let x = self.u * self.total;
        let take = ok & x.lt(w);
        let rest = ((x - w) / before).min(W::c(f64::from(ONE_MINUS_EPS)));
        self.u = W::select(take, x / w, W::select(ok, rest, self.u));
        self.kept = T::pick(take, candidate, self.kept);
        self.target = W::select(take, target, self.target);
        take
    }

    /// The candidates offered so far, M.
    pub fn count(&self) -> u32 {
        self.count
    }

    /// The kept candidate and its RIS weight Σw/(M·p̂(y)); where no candidate had a positive
    /// weight, `T::default()` and weight 0.
    pub fn chosen(&self) -> (T, W) {
        let kept = self.target.gt(W::ZERO);
        let weight = self.total / (W::c(f64::from(self.count)) * self.target);
        (self.kept, W::select(kept, weight, W::ZERO))
    }

    /// Lane `i`'s reservoir (`i` modulo the width).
    pub fn lane(&self, i: usize) -> Reservoir<T::Scalar> {
        Reservoir {
            u: self.u.lane(i),
            total: self.total.lane(i),
            count: self.count,
            kept: self.kept.in_lane(i),
            target: self.target.lane(i),
        }
    }
}
