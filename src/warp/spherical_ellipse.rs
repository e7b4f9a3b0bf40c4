//! Disk lights sampled by solid angle: directions uniform over the spherical ellipse that a disk
//! subtends, pdf 1/Ω per steradian (Guillén et al., "Area-Preserving Parameterizations for
//! Spherical Ellipses", EGSR 2017).
//!
//! Seen from the shading point, the disk's rim spans an elliptic cone. With w the unit normal
//! of the disk's plane towards it, d the distance to the plane and h the offset of the disk's
//! centre within the plane from the foot of the point, a direction ω = (X, Y, Z) (X along the
//! offset, Z along w) meets the disk when (dX − hZ)² + d²Y² ≤ r²Z². The quadratic form has the
//! eigenvalue d² along Y, and in the (X, Z) plane λ₊ ≥ d² and −L < 0; the eigenvector of −L is
//! the cone's axis, and projected orthographically onto the plane across the axis the cone's
//! directions fill the ellipse with semi-axes
//!
//! a² = L / (d² + L) along Y,  b² = L / (λ₊ + L) across it,
//!
//! the sines of the cone's half-angles. The map is polar on that ellipse: u₁ picks the angle φ
//! (from the major axis) so that the solid angle of the sector [0, φ] is u₁'s share, and u₀ the
//! angle θ from the axis within the sector's direction, uniformly in 1 − cos θ up to the rim,
//! 1 − cos θ_max(φ), with sin²θ_max(φ) = r(φ)² = a²b² / (b²cos²φ + a²sin²φ). The solid angle of
//! the sector of a quarter, φ ∈ [0, π/2], is
//!
//! F(φ) = ∫₀^φ (1 − cos θ_max) dφ' = φ − √(1 − a²)·(s R_F(x, y, z) + (m′/3) s³ R_J(x, y, z, 1)),
//!
//! with s = sin φ, x = cos²φ, y = 1 + m s², z = 1 + m′ s², m = a²/b² − 1 = (λ₊ − d²)/(d² + L) and
//! m′ = (a² − b²)/(b²(1 − a²)) = (λ₊ − d²)/d², Carlson's symmetric integrals of the first and
//! third kind (Carlson, "Numerical computation of real or complex elliptic integrals", Numer.
//! Algorithms 10, 1995), and Ω = 4F(π/2). Every coefficient is a quotient of the eigenvalues, so
//! none cancels, and λ₊ − d² is computed as a quotient too. F is a difference of two terms of
//! size φ, so its error is absolute: Ω is formed in f64, within 5e-15 sr of the disk's area
//! integral (measured on 20 000 random disks), 1e-7 of itself from [`ELLIPSE_MIN_SR`] = 1e-7 sr
//! up. Below that the disk is sampled by area instead, where the two densities agree to within
//! the disk's angular size, and Ω of an ellipse whose major sine is below √1e-5 comes from its
//! series πab(1 + (a² + b²)/8 + …), which does not cancel. Carlson's duplication stops at the
//! agreement of 1e-3 among its arguments (the series' error is then below 1e-17).
//!
//! The map does not evaluate F through Carlson's integrals at every sample. In the ellipse's
//! parametric angle τ (tan φ = (b/a) tan τ, the rim point (a cos τ, b sin τ)) the sector's
//! solid angle has the derivative
//!
//! dF/dτ = ab / (1 + √(1 − a²cos²τ − b²sin²τ)),
//!
//! between ab/2 and ab, smooth at any eccentricity and free of cancellation. Within each of eight
//! intervals of π/16 the map works in w = tan(τ − τ_k), where dF/dw = ab / ((1 + w²) +
//! √((1 + w²)N)) with N = (1 − a²)(cos τ_k − w sin τ_k)² + (1 − b²)(sin τ_k + w cos τ_k)², a sum
//! of non-negative terms: algebraic, so neither the quadrature nor the returned direction needs
//! a sine, cosine or arctangent. The set-up sums dF/dw over each interval by Gauss–Legendre's
//! six-node rule (a table of F at the knots); a sample's u₁ finds its interval by comparisons,
//! takes the cubic Hermite interpolant of w(F) through the table as the seed (within 3.4e-4 of
//! the disk's angular size, measured), and one Newton step on F (the same rule over [0, w],
//! dF/dw exact) brings it within 1e-9 of the angular size (measured over 3.2·10⁵ samples of
//! random disks against the solve run to 2⁻²⁰); a step above 2⁻¹⁴, which one valid sample in
//! 10⁴ takes, is followed by another. The map's density is 4F(π/2)/Ω as the table sums it, relative to 1/Ω:
//! within 4e-10 of 1 from 1e-3 sr (measured over 2·10⁵ random disks; below, Carlson's own
//! absolute error dominates the comparison), which [`SphericalEllipse::density_error`] reports.

use core::f64::consts::{FRAC_PI_2, PI};
use core::fmt;

use glam::Vec3;

use crate::frame::Frame;
use crate::lane::{Lane, Lanes, Mask, V2, V3, Widen};
use crate::math::Math;
use crate::point::{Point2, Point3, halved};
use crate::warp::common::{clamp_u, pick};
use crate::warp::disk::concentric_with_one_minus_r;
use crate::warp::family::{is_unit, lane, lanes3};
use crate::warp::polygon::{cross3_in, dot_wide, dot3_in, unit_wide, widen3};
use crate::warp::{Family, ONE_MINUS_EPS};

/// The smallest solid angle, in steradians, for which a disk is sampled by its spherical
/// ellipse; below, it is sampled by area. See the module's docs.
pub const ELLIPSE_MIN_SR: f32 = 1e-7;

/// The f64 lane of the same width as `L`.
type W<L> = <L as Widen>::Wide;

/// Duplication steps of Carlson's integrals at most (a lane stops once its arguments agree to
/// 1e-3, where the series' error is below 1e-17; arguments 10³⁰ apart need about 12).
const CARLSON_STEPS: usize = 40;

/// Intervals of the seed's table over the quarter's parametric angle.
const KNOTS: usize = 8;

/// tan(π/16): the range of the offset w = tan(τ − τ_k) within an interval.
const TAN_H: f64 = 0.198_912_367_379_658;

/// cos and sin of the knots kπ/16 (the last cosine exactly 0).
const KNOT_COS: [f64; KNOTS + 1] = [
    1.0,
    0.980_785_280_403_230_4,
    0.923_879_532_511_286_7,
    0.831_469_612_302_545_2,
    core::f64::consts::FRAC_1_SQRT_2,
    0.555_570_233_019_602_3,
    0.382_683_432_365_089_84,
    0.195_090_322_016_128_33,
    0.0,
];
const KNOT_SIN: [f64; KNOTS + 1] = [
    0.0,
    0.195_090_322_016_128_25,
    0.382_683_432_365_089_8,
    0.555_570_233_019_602_2,
    core::f64::consts::FRAC_1_SQRT_2,
    0.831_469_612_302_545_2,
    0.923_879_532_511_286_7,
    0.980_785_280_403_230_4,
    1.0,
];

/// Gauss–Legendre's six nodes on [−1, 1] and their weights.
const GL_X: [f64; 6] = [
    -0.932_469_514_203_152,
    -0.661_209_386_466_264_5,
    -0.238_619_186_083_196_9,
    0.238_619_186_083_196_9,
    0.661_209_386_466_264_5,
    0.932_469_514_203_152,
];
const GL_W: [f64; 6] = [
    0.171_324_492_379_170_3,
    0.360_761_573_048_138_6,
    0.467_913_934_572_691,
    0.467_913_934_572_691,
    0.360_761_573_048_138_6,
    0.171_324_492_379_170_3,
];

/// Newton's steps of the solve at most (a lane stops after a step below 2⁻¹⁴: one, as a rule).
const SOLVE_STEPS: usize = 24;

/// Each f64 lane through a scalar function (libm's, lane by lane).
#[inline(always)]
fn each<T: Lanes<Scalar = f64>>(x: T, f: impl Fn(f64) -> f64) -> T {
    T::from_fn(|i| f(x.lane(i)))
}

/// R_C(1, 1 + e) = atan(√e)/√e for e ≥ 0: its series below 1/16 (twelve terms, error below
/// e¹²/25 < 1e-16), libm's arctangent above, only where some lane needs it.
#[inline(always)]
fn rc1<T: Lanes<Scalar = f64>>(e: T) -> T {
    let mut series = T::c(1.0 / 23.0);
    for k in (0..11).rev() {
        let c = 1.0 / f64::from(2 * k + 1);
        series = series * (-e) + T::c(c);
    }
    let big = e.ge(T::c(0.0625));
    if big.any() {
        let atan = each(e, |e| {
            let r = libm::sqrt(e);
            libm::atan(r) / r
        });
        T::select(big, atan, series)
    } else {
        series
    }
}

/// Carlson's R_F(x, y, z) and R_J(x, y, z, 1), for x ∈ [0, 1] and y, z ≥ 1 (so that
/// (1 − x)(1 − y)(1 − z) ≤ 0 and R_J's R_C terms are arctangents), by their shared duplication,
/// until the arguments agree with their mean to 1e-3 (the series' relative error is then below
/// 1e-17).
#[inline(always)]
fn carlson<T: Lanes<Scalar = f64>>(x: T, y: T, z: T) -> (T, T) {
    let tol = T::c(1e-3);
    let mut v = [x, y, z, T::ONE];
    let mut sum = T::ZERO;
    let mut f = T::ONE;
    let spread = |v: &[T; 4]| {
        let a = (v[0] + v[1] + v[2] + T::TWO * v[3]) * T::c(0.2);
        let k = T::ONE / a;
        let d = v.map(|t| ((a - t) * k).abs());
        (d[0].max(d[1]).max(d[2]).max(d[3]), a)
    };
    let mut done = spread(&v).0.lt(tol);
    for _ in 0..CARLSON_STEPS {
        if done.all() {
            break;
        }
        let [sx, sy, sz, sp] = v.map(Lane::sqrt);
        let lam = sx * (sy + sz) + sy * sz;
        let d = (sp + sx) * (sp + sy) * (sp + sz);
        let e = ((v[3] - v[0]) * (v[3] - v[1]) * (v[3] - v[2]) / (d * d)).max(T::ZERO);
        let next_sum = sum + f * T::c(6.0) / d * rc1(e);
        sum = T::select(done, sum, next_sum);
        f = T::select(done, f, f * T::c(0.25));
        v = v.map(|t| T::select(done, t, (t + lam) * T::c(0.25)));
        done = done | spread(&v).0.lt(tol);
    }
    // The series about the mean, to fifth order in the deviations.
    let af = (v[0] + v[1] + v[2]) * T::c(1.0 / 3.0);
    let (dx, dy) = (T::ONE - v[0] / af, T::ONE - v[1] / af);
    let dz = -(dx + dy);
    let (e2, e3) = (dx * dy - dz * dz, dx * dy * dz);
    let rf = (T::ONE - e2 * T::c(0.1) + e3 * T::c(1.0 / 14.0) + e2 * e2 * T::c(1.0 / 24.0)
        - e2 * e3 * T::c(3.0 / 44.0))
        / af.sqrt();
    let (_, a) = spread(&v);
    let d = v.map(|t| (a - t) / a);
    let dp = -(d[0] + d[1] + d[2]) * T::HALF;
    let xyz = d[0] * d[1] * d[2];
    let e2 = d[0] * d[1] + d[0] * d[2] + d[1] * d[2] - T::c(3.0) * dp * dp;
    let e3 = xyz + T::TWO * e2 * dp + T::c(4.0) * dp * dp * dp;
    let e4 = (T::TWO * xyz + e2 * dp + T::c(3.0) * dp * dp * dp) * dp;
    let e5 = xyz * dp * dp;
    let t = T::ONE - e2 * T::c(3.0 / 14.0) + e3 * T::c(1.0 / 6.0) + e2 * e2 * T::c(9.0 / 88.0)
        - e4 * T::c(3.0 / 22.0)
        - e2 * e3 * T::c(9.0 / 52.0)
        + e5 * T::c(3.0 / 26.0);
    (rf, f * t / (a * a.sqrt()) + sum)
}

/// The shape of the spherical ellipse, in f64: the sines a ≥ b of its half-angles and the
/// coefficients of F.
#[derive(Clone, Copy)]
struct Shape<T> {
    /// a, b, ab, 1 − a² and 1 − b².
    a: T,
    b: T,
    ab: T,
    ca2: T,
    cb2: T,
    /// √(1 − a²), m and m′ of the module's docs.
    c0: T,
    m: T,
    mp: T,
    /// F at the knots τ_k = kπ/16 of the parametric angle (tan φ = (b/a) tan τ), k = 0..=8, and
    /// dτ/dF there: the table of the seed.
    knots: [T; KNOTS + 1],
    slopes: [T; KNOTS + 1],
}

impl<T: Lanes<Scalar = f64>> Shape<T> {
    /// F(φ) for φ ∈ [0, π/2] with s = sin φ, c = cos φ.
    #[inline(always)]
    fn area(&self, phi: T, s: T, c: T) -> T {
        let s2 = s * s;
        let (rf, rj) = carlson(c * c, T::ONE + self.m * s2, T::ONE + self.mp * s2);
        phi - self.c0 * s * (rf + self.mp * T::c(1.0 / 3.0) * s2 * rj)
    }

    /// 1 − cos θ_max at parametric angle τ (sine st, cosine ct): ρ²/(1 + √(1 − ρ²)), with
    /// ρ² = a²cos²τ + b²sin²τ the squared sine of the rim's angle from the axis, and
    /// 1 − ρ² = (1 − a²)cos²τ + (1 − b²)sin²τ, which does not cancel.
    #[inline(always)]
    fn rim(&self, st: T, ct: T) -> T {
        let (x, y) = (self.a * ct, self.b * st);
        let n = self.ca2 * ct * ct + self.cb2 * st * st;
        (x * x + y * y) / (T::ONE + n.sqrt())
    }

    /// The direction at w = tan(τ − τ_k) past the knot (cosine and sine kc, ks) and u₀, in the
    /// first quarter: the rim's azimuth (X, Y) ∝ (a cos τ, b sin τ), 1 − cos θ = k = u₀(1 −
    /// cos θ_max), sin θ = √(k(2 − k)). With s = 1 + w², X = a(kc − ks·w), Y = b(ks + kc·w)
    /// and N as in [`slope_w`](Self::slope_w), ρ² = (X² + Y²)/s and 1 + √(1 − ρ²) = D/s for
    /// D = s + √(sN), so k = u₀(X² + Y²)/D and the horizontal part is (X, Y)·√(u₀(2 − k)/D):
    /// no division by ρ (zero on the axis), one square root fewer.
    #[inline(always)]
    fn point(&self, kc: T, ks: T, w: T, u0: T) -> (T, T, T) {
        let (cx, cy) = (kc - ks * w, ks + kc * w);
        let (x, y) = (self.a * cx, self.b * cy);
        let n = self.ca2 * cx * cx + self.cb2 * cy * cy;
        let s = T::ONE + w * w;
        let r = T::ONE / (s + (s * n).sqrt());
        let k = u0 * (x * x + y * y) * r;
        let scale = (u0 * (T::TWO - k) * r).max(T::ZERO).sqrt();
        (x * scale, y * scale, T::ONE - k)
    }

    /// dF/dw at w = tan(τ − τ_k) in the interval of the knot with cosine and sine kc, ks:
    /// dF/dτ · dτ/dw = ab / ((1 + w²) + √((1 + w²)N)), where (1 + w²)(1 − ρ²) =
    /// N = (1 − a²)(kc − ks·w)² + (1 − b²)(ks + kc·w)² is a sum of non-negative terms. Algebraic
    /// in w: the quadrature needs no sine or cosine.
    #[inline(always)]
    fn slope_w(&self, kc: T, ks: T, w: T) -> T {
        let (x, y) = (kc - ks * w, ks + kc * w);
        let n = self.ca2 * x * x + self.cb2 * y * y;
        let s = T::ONE + w * w;
        self.ab / (s + (s * n).sqrt())
    }

    /// F at the knots and dτ/dF there (= dw/dF at w = 0): F from knot to knot by
    /// [`area_w`](Self::area_w), so that the table and the per-sample F are one function.
    #[inline(always)]
    fn tabulate(&mut self) {
        let mut f = T::ZERO;
        for k in 0..=KNOTS {
            let (kc, ks) = knot::<T>(k);
            let d = T::ONE / self.slope_w(kc, ks, T::ZERO);
            if let (Some(knot), Some(slope)) = (self.knots.get_mut(k), self.slopes.get_mut(k)) {
                *knot = f;
                *slope = d;
            }
            f = self.area_w(kc, ks, f, T::c(TAN_H));
        }
    }

    /// F(π/2) as the table sums it: what the map divides u₁ by (Carlson's F(π/2) gives Ω).
    #[inline(always)]
    fn total(&self) -> T {
        self.knots.last().copied().unwrap_or(T::ZERO)
    }

    /// F at w = tan(τ − τ_k) ∈ [0, tan(π/16)] past the knot (cosine and sine kc, ks, F_k = fk):
    /// F_k plus Gauss–Legendre's six-node rule for ∫ dF/dw over [0, w]. dF/dw is smooth in w,
    /// so the rule is exact to the f64 rounding of F (the table's F(π/2) meets Carlson's within
    /// 1e-11 from 1e-3 sr: [`SphericalEllipse::density_error`]) at every eccentricity.
    #[inline(always)]
    fn area_w(&self, kc: T, ks: T, fk: T, w: T) -> T {
        let g = GL_X.map(|x| self.slope_w(kc, ks, w * T::c((1.0 + x) * 0.5)));
        // Pairwise, for a shorter chain.
        let [g0, g1, g2, g3, g4, g5] = g;
        let [w0, w1, w2, ..] = GL_W.map(T::c);
        let acc = (w0 * (g0 + g5) + w1 * (g1 + g4)) + w2 * (g2 + g3);
        fk + acc * w * T::HALF
    }

    /// The parametric angle τ with F(τ) = t·F(π/2), t ∈ [0, 1], as its knot's cosine and sine
    /// and w = tan(τ − τ_k): the interval by comparisons, the table's cubic Hermite interpolant
    /// of w(F) as the seed, then Newton's steps on [`area_w`](Self::area_w) (dF/dw exact),
    /// stopping after a step below 2⁻¹⁴, whose successor would be below 1e-8 (the error
    /// shrinks as the square of the step, with a constant of order 1 since dF/dw varies by at
    /// most 2× over the interval): one, as a rule.
    #[inline(always)]
    fn solve(&self, t: T, active: T::Mask) -> (T, T, T) {
        let target = t * self.total();
        // The knot interval, counted by comparisons.
        let mut k = T::ZERO;
        for f in self.knots.iter().take(KNOTS).skip(1) {
            k = k + T::select(f.le(target), T::ONE, T::ZERO);
        }
        let (f0, f1) = (
            pick(&self.knots, k, |f| *f),
            pick(&self.knots, k + T::ONE, |f| *f),
        );
        // dw/dF at the interval's ends: dτ/dF there times dw/dτ = 1 + w².
        let d0 = pick(&self.slopes, k, |d| *d);
        let d1 = pick(&self.slopes, k + T::ONE, |d| *d) * T::c(1.0 + TAN_H * TAN_H);
        let (kc, ks) = (
            pick(&KNOT_COS, k, |&c| T::c(c)),
            pick(&KNOT_SIN, k, |&c| T::c(c)),
        );
        let top = T::c(TAN_H);
        let span = f1 - f0;
        let x = T::select(
            span.gt(T::ZERO),
            ((target - f0) / span).clamp(T::ZERO, T::ONE),
            T::ZERO,
        );
        let x2 = x * x;
        let x3 = x2 * x;
        let h10 = x3 - T::TWO * x2 + x;
        let h01 = T::c(3.0) * x2 - T::TWO * x3;
        let h11 = x3 - x2;
        let mut w = (h10 * span * d0 + h01 * top + h11 * span * d1).clamp(T::ZERO, top);
        let mut done = !active;
        for _ in 0..SOLVE_STEPS {
            if done.all() {
                break;
            }
            let err = self.area_w(kc, ks, f0, w) - target;
            let next = (w - err / self.slope_w(kc, ks, w)).clamp(T::ZERO, top);
            let small = (next - w).abs().lt(T::c(1.0 / 16384.0));
            w = T::select(done, w, next);
            done = done | small;
        }
        (kc, ks, w)
    }
}

/// The cosine and sine of knot k.
#[inline(always)]
fn knot<T: Lane>(k: usize) -> (T, T) {
    (
        T::c(KNOT_COS.get(k).copied().unwrap_or(0.0)),
        T::c(KNOT_SIN.get(k).copied().unwrap_or(1.0)),
    )
}

/// The set-up of a disk's spherical ellipse.
#[derive(Clone, Copy)]
struct Ellipse<L: Math> {
    /// The ellipse's frame: t the major axis, b the minor, n the cone's axis.
    frame: Frame<V3<L>>,
    /// The shape in f64 (valid lanes only).
    shape: Shape<W<L>>,
    /// a and b, and Ω (in f64, rounded).
    a: L,
    b: L,
    omega: L,
    omega_w: W<L>,
    /// The disk: its centre relative to the point, its frame (n its unit normal), its radius,
    /// the signed distance c·n and the area pdf 1/(πr²).
    center: V3<L>,
    disk: Frame<V3<L>>,
    r: L,
    h: L,
    area_pdf: L,
    /// Sampled by the ellipse (a disk of at least [`ELLIPSE_MIN_SR`] in front of the point), in
    /// both lanes.
    valid: L::Mask,
    valid_w: <W<L> as Lane>::Mask,
    /// Nothing to sample: a radius that is not positive and finite, a centre or normal that is
    /// not finite, a zero normal, or the point in the disk's plane.
    empty: L::Mask,
}

impl<L: Math> Ellipse<L> {
    /// The set-up; with `table` false, without the sampling table ([`Shape::tabulate`]), which
    /// only the sample and the inverse read: Ω, the frame and the hit test are the same.
    #[inline(always)]
    fn new(center: V3<L>, normal: V3<L>, radius: L, table: bool) -> Self {
        let zero = W::<L>::ZERO;
        let (c, nw) = (widen3::<L>(center), widen3::<L>(normal));
        let n = unit_wide(nw);
        // Lengths in units of |c|, so that no square overflows or underflows.
        let cl = dot3_in(c, c).sqrt();
        let r = radius.widen() / cl;
        let cu = c.scale(W::<L>::ONE / cl);
        let cn = dot3_in(cu, n);
        let d = cn.abs();
        // w: the plane's normal towards the disk; the offset within the plane and its length.
        let w = n.scale(W::<L>::ONE.copysign(cn));
        let off = cu - n.scale(cn);
        let hl = dot3_in(off, off).sqrt();
        let (d2, h2, r2) = (d * d, hl * hl, r * r);
        // The (X, Z) block [[d², −dh], [−dh, h² − r²]]: λ₊ − d² and λ₊ − (h² − r²) are
        // dh·dh over the sum of the other, so neither cancels.
        let delta = (d2 - (h2 - r2)) * W::<L>::HALF;
        let disc = (delta * delta + d2 * h2).sqrt();
        let big = disc + delta.abs();
        let q = d2 * h2 / big;
        let over_d2 = W::<L>::select(delta.ge(zero), q, big);
        let lp = d2 + over_d2;
        let l = d2 * r2 / lp;
        let (a2, b2) = (l / (d2 + l), l / (lp + l));
        let (sa, sb) = (a2.sqrt(), b2.sqrt());
        let mut shape = Shape {
            a: sa,
            b: sb,
            ab: sa * sb,
            ca2: d2 / (d2 + l),
            cb2: lp / (lp + l),
            c0: d / (d2 + l).sqrt(),
            m: over_d2 / (d2 + l),
            mp: over_d2 / d2,
            knots: [zero; KNOTS + 1],
            slopes: [zero; KNOTS + 1],
        };
        let one = W::<L>::ONE;
        let quarter = shape.area(W::<L>::c(FRAC_PI_2), one, zero);
        if table {
            shape.tabulate();
        }
        // A small ellipse by the series of ∫∫ dA/√(1 − ρ²) over its orthographic image:
        // πab(1 + (a² + b²)/8 + 3(3a⁴ + 2a²b² + 3b⁴)/64 + O(a⁶)), within 1e-15 relative for
        // a² < 1e-5, where F(π/2)'s absolute error (some 5e-15) would be 1e-10 of Ω or more.
        let series = W::<L>::c(PI)
            * (a2 * b2).sqrt()
            * (one
                + (a2 + b2) * W::<L>::c(0.125)
                + (W::<L>::c(3.0) * (a2 * a2 + b2 * b2) + W::<L>::TWO * a2 * b2)
                    * W::<L>::c(3.0 / 64.0));
        let omega_w = W::<L>::select(
            a2.lt(W::<L>::c(1e-5)),
            series,
            W::<L>::c(4.0) * quarter.max(zero),
        );
        // The frame: e_h along the offset (any direction across w on the axis), the major axis
        // Y = w × e_h, and in the (e_h, w) plane the axis ∝ (dh, d² + L) and the minor axis
        // across it.
        // Within 1e-9 of the axis (in units of |c|) the offset's direction is rounding noise and
        // the ellipse a circle to 1e-18: any direction across w will do.
        let on_axis = hl.le(W::<L>::c(1e-9));
        let any = Frame::from_normal(narrow_v::<L>(w));
        let eh_w = W::<L>::ONE / W::<L>::select(on_axis, one, hl);
        let eh = V3::select(
            L::narrow_mask(on_axis),
            any.t,
            narrow_v::<L>(off.scale(eh_w)),
        );
        // Across w to f64 rounding, so that the frame is orthonormal.
        let ehw = widen3::<L>(eh);
        let ehw = unit_wide(ehw - w.scale(dot3_in(ehw, w)));
        let y = cross3_in(w, ehw);
        let (ax, az) = (d * hl, d2 + l);
        let norm = one / (ax * ax + az * az).sqrt();
        let axis = ehw.scale(ax * norm) + w.scale(az * norm);
        let minor = ehw.scale(az * norm) - w.scale(ax * norm);
        let frame = Frame {
            t: narrow_v::<L>(unit_wide(y)),
            b: narrow_v::<L>(minor),
            n: narrow_v::<L>(axis),
        };
        let nf = narrow_v::<L>(n);
        let finite = |t: W<L>| t.lt(W::<L>::c(f64::INFINITY));
        let disk_ok = radius.gt(L::ZERO)
            & L::narrow_mask(finite(radius.widen()) & finite(cl) & cl.gt(zero) & d.gt(zero))
            & !nf.any_nan()
            & !center.any_nan();
        let area_pdf = L::c(1.0 / PI) / (radius * radius);
        let empty = !(disk_ok & area_pdf.is_finite());
        let omega = L::narrow(omega_w);
        let big_w = omega_w.ge(W::<L>::c(f64::from(ELLIPSE_MIN_SR)));
        let valid = !empty & L::narrow_mask(big_w);
        let empty_w = L::select(empty, L::ONE, L::ZERO).widen().gt(zero);
        let valid_w = big_w & !empty_w;
        Ellipse {
            frame,
            shape,
            a: L::narrow(sa),
            b: L::narrow(sb),
            omega,
            omega_w,
            center,
            disk: Frame::from_normal(nf),
            r: radius,
            h: L::narrow(cn * cl),
            area_pdf,
            valid,
            valid_w,
            empty,
        }
    }

    /// The local direction (in the ellipse's frame) of clamped u, on the valid lanes.
    #[inline(always)]
    fn sample_local(&self, u: V2<L>) -> V3<L> {
        let (one, two, three) = (W::<L>::ONE, W::<L>::TWO, W::<L>::c(3.0));
        // u₁ in quarters (0 along +major, 1 along +minor, …), the odd ones mirrored so that the
        // map is continuous across the axes.
        let t = u.y.widen() * W::<L>::c(4.0);
        // ⌊t⌋ clamped to 3 by comparisons (NaN gives 0; its sample is dropped).
        let step = |k: f64| W::<L>::select(t.ge(W::<L>::c(k)), one, W::<L>::ZERO);
        let q = step(1.0) + step(2.0) + step(3.0);
        let odd = q.eq(one) | q.eq(three);
        let f = t - q;
        let g = W::<L>::select(odd, one - f, f).clamp(W::<L>::ZERO, one);
        let (kc, ks, w) = self.shape.solve(g, self.valid_w);
        // 1 − cos θ uniform up to the rim: no cancellation for a small disk.
        let (x, y, z) = self.shape.point(kc, ks, w, u.x.widen());
        let sx = W::<L>::select(q.eq(one) | q.eq(two), -one, one);
        let sy = W::<L>::select(q.ge(two), -one, one);
        V3::new(L::narrow(x * sx), L::narrow(y * sy), L::narrow(z))
    }

    /// u of a unit local direction, on the valid lanes.
    #[inline(always)]
    fn inverse_local(&self, l: V3<L>) -> V2<L> {
        let (x, y, z) = (l.x.widen(), l.y.widen(), l.z.widen());
        let zero = W::<L>::ZERO;
        let rho2 = x * x + y * y;
        let (ax, ay) = (x.abs(), y.abs());
        // The parametric angle of the direction's azimuth: tan τ = (a/b) tan φ.
        let sh = &self.shape;
        let (ty, tx) = (sh.a * ay, sh.b * ax);
        let tn = (ty * ty + tx * tx).sqrt();
        let (st, ct) = (
            W::<L>::select(tn.gt(zero), ty / tn, zero),
            W::<L>::select(tn.gt(zero), tx / tn, W::<L>::ONE),
        );
        // The knot interval, τ ≥ τ_j by tan τ ≥ tan τ_j, and w = tan(τ − τ_k).
        let mut k = zero;
        for j in 1..KNOTS {
            let (cj, sj) = knot::<W<L>>(j);
            k = k + W::<L>::select((st * cj).ge(ct * sj), W::<L>::ONE, zero);
        }
        let (kc, ks) = (
            pick(&KNOT_COS, k, |&c| W::<L>::c(c)),
            pick(&KNOT_SIN, k, |&c| W::<L>::c(c)),
        );
        let fk = pick(&sh.knots, k, |f| *f);
        let w = ((st * kc - ct * ks) / (ct * kc + st * ks)).clamp(zero, W::<L>::c(TAN_H));
        let g = (sh.area_w(kc, ks, fk, w) / sh.total()).clamp(zero, W::<L>::ONE);
        // Quarters by sign: (+, +) 0, (−, +) 1, (−, −) 2, (+, −) 3; the odd ones mirrored.
        let (neg_x, neg_y) = (x.lt(zero), y.lt(zero));
        let odd = (neg_x & !neg_y) | (neg_y & !neg_x);
        let q = W::<L>::select(neg_y, W::<L>::TWO, zero) + W::<L>::select(odd, W::<L>::ONE, zero);
        let f = W::<L>::select(odd, W::<L>::ONE - g, g);
        let u1 = (q + f) * W::<L>::c(0.25);
        // 1 − cos θ = ρ²/(1 + z), over the rim's.
        let rim = self.shape.rim(st, ct);
        let k = W::<L>::select(z.gt(zero), rho2 / (W::<L>::ONE + z), W::<L>::ONE - z);
        let u0 = W::<L>::select(rim.gt(zero), k / rim, zero);
        let u = V2::new(L::narrow(u0), L::narrow(u1));
        V2::new(
            u.x.clamp(L::ZERO, L::ONE),
            u.y.clamp(L::ZERO, L::c(f64::from(ONE_MINUS_EPS))),
        )
    }

    /// True where unit ω (world) is within the ellipse, widened by 4ε in each semi-axis (in the
    /// sines of the orthographic projection), in front of the point.
    #[inline(always)]
    fn on_ellipse(&self, w: V3<L>) -> L::Mask {
        let l = self.frame.to_local(w);
        let slack = L::c(4.0) * L::EPSILON;
        let (x, y) = (l.x / (self.a + slack), l.y / (self.b + slack));
        l.z.gt(L::ZERO) & x.mul_add(x, y * y).le(L::ONE)
    }

    /// The area fallback's pdf per steradian of unit ω: h²/(|ω·n|³ πr²), with ω·n in f64 (it
    /// cancels at grazing angles).
    #[inline(always)]
    fn area_pdf_of(&self, w: V3<L>) -> L {
        let n = self.disk.n;
        let cos = dot_wide([w.x, w.y, w.z], [n.x, n.y, n.z]).abs();
        let pdf = self.area_pdf * (self.h * self.h) / (cos * cos * cos);
        L::select(pdf.is_finite(), pdf, L::ZERO)
    }
}

/// An f64 vector rounded to the lane.
#[inline(always)]
fn narrow_v<L: Math>(p: V3<W<L>>) -> V3<L> {
    V3::new(L::narrow(p.x), L::narrow(p.y), L::narrow(p.z))
}
/// A disk light sampled by solid angle from a shading point: see [`spherical_ellipse`]. The
/// set-up (the ellipse's frame and shape, Ω in f64) is paid once.
#[derive(Clone, Copy)]
pub struct SphericalEllipse<P: Point3>(Ellipse<P::Lane>);

impl<P: Point3<Lane = L>, L: Math> SphericalEllipse<P> {
    /// The disk of radius `radius` about `center` (relative to the shading point) with normal
    /// `normal` (any non-zero multiple; either side).
    #[inline]
    pub fn new(center: P, normal: P, radius: L) -> Self {
        Self(Ellipse::new(
            center.to_lanes(),
            normal.to_lanes(),
            radius,
            true,
        ))
    }

    /// [`new`](Self::new) for [`pdf`](Self::pdf), [`solid_angle`](Self::solid_angle) and
    /// [`by_area`](Self::by_area) alone, which give the same values: the sampling table (its
    /// nine knots, each an f64 evaluation of the area integral) is left out, so `sample`,
    /// `inverse` and `density_error` are not to be called on it.
    #[inline]
    pub(crate) fn for_pdf(center: P, normal: P, radius: L) -> Self {
        Self(Ellipse::new(
            center.to_lanes(),
            normal.to_lanes(),
            radius,
            false,
        ))
    }

    /// Ω, the solid angle the disk subtends, in f64 and rounded (0 where there is nothing to
    /// sample).
    #[inline]
    pub fn solid_angle(&self) -> L {
        L::select(self.0.empty, L::ZERO, self.0.omega)
    }

    /// The sines a ≥ b of the cone's half-angles along the ellipse's major and minor axes.
    #[inline]
    pub fn semi_axes(&self) -> (L, L) {
        (self.0.a, self.0.b)
    }

    /// The map's density relative to 1/Ω, minus 1, in f64: Ω (Carlson's, in f64) over 4F(π/2)
    /// as the map's table sums it, less 1 (see the module's docs). Meaningless where
    /// [`by_area`](Self::by_area).
    pub fn density_error(&self) -> <L as Widen>::Wide {
        self.0.omega_w / (self.0.shape.total() * W::<L>::c(4.0)) - W::<L>::ONE
    }

    /// True (lane by lane) where the disk is sampled by area instead: Ω below
    /// [`ELLIPSE_MIN_SR`], or nothing to sample.
    #[inline]
    pub fn by_area(&self) -> L::Mask {
        !self.0.valid
    }

    /// See [`spherical_ellipse`].
    #[inline]
    pub fn sample(&self, u: P::Vec2) -> (P, L) {
        let (w, nan_or_empty) = self.direction(u.to_lanes());
        let pdf = self.pdf_lanes(w);
        let dropped = nan_or_empty | !pdf.gt(L::ZERO);
        let w = V3::select(dropped, V3::new(L::ZERO, L::ZERO, L::ONE), w);
        (P::from_lanes(w), L::select(dropped, L::ZERO, pdf))
    }

    /// The direction of u (clamped) before the hit test of the pdf, and where u is NaN or the
    /// disk empty: for a caller with its own hit test (the disk light's).
    #[inline(always)]
    pub(crate) fn direction(&self, u: V2<L>) -> (V3<L>, L::Mask) {
        let e = &self.0;
        let uc = clamp_u(u);
        let mut w = V3::default();
        if e.valid.any() {
            w = e.frame.to_world(e.sample_local(uc));
        }
        let small = !e.valid & !e.empty;
        if small.any() {
            let (p, _) = concentric_with_one_minus_r(uc);
            let on = e.center + (e.disk.t.scale(p.x) + e.disk.b.scale(p.y)).scale(e.r);
            w = V3::select(e.valid, w, on.normalize_scaled());
        }
        (w, u.any_nan() | e.empty)
    }

    /// See [`spherical_ellipse_pdf`].
    #[inline]
    pub fn pdf(&self, w: P) -> L {
        self.pdf_lanes(w.to_lanes())
    }

    #[inline(always)]
    fn pdf_lanes(&self, w: V3<L>) -> L {
        let e = &self.0;
        let w = w.normalize_scaled();
        let on = e.on_ellipse(w);
        let pdf = L::select(e.valid, L::ONE / e.omega, e.area_pdf_of(w));
        L::select(on & !e.empty & !w.any_nan(), pdf, L::ZERO)
    }

    /// See [`spherical_ellipse_inverse`].
    #[inline]
    pub fn inverse(&self, w: P) -> P::Vec2 {
        let e = &self.0;
        let w = w.to_lanes();
        let unit = w.normalize_scaled();
        let mut u = V2::default();
        if e.valid.any() {
            u = e.inverse_local(e.frame.to_local(unit));
        }
        let small = !e.valid & !e.empty;
        if small.any() {
            // The ray's hit on the plane relative to the centre, n × (ω × c)/(ω·n), in radii,
            // in f64 (no product of f32 inputs overflows there); beyond the rim, or at a grazing
            // ω·n = 0, the rim point in its direction.
            let (wu, c, n) = (
                widen3::<L>(unit),
                widen3::<L>(e.center),
                widen3::<L>(e.disk.n),
            );
            let num = cross3_in(n, cross3_in(wu, c));
            let den = dot3_in(wu, n) * e.r.widen();
            let (tw, bw) = (widen3::<L>(e.disk.t), widen3::<L>(e.disk.b));
            let (px, py) = (dot3_in(num, tw), dot3_in(num, bw));
            let len = (px * px + py * py).sqrt();
            let zero = W::<L>::ZERO;
            let k = W::<L>::select(
                len.le(den.abs()),
                W::<L>::ONE / den,
                W::<L>::select(len.gt(zero), W::<L>::ONE.copysign(den) / len, zero),
            );
            let p = V2::new(L::narrow(px * k), L::narrow(py * k));
            let ua = crate::warp::concentric_disk_inverse(p);
            u = V2::select(e.valid, u, ua);
        }
        // Nothing to sample: every direction inverts to the corner (0, 0).
        let u = V2::select(e.empty, V2::default(), u);
        P::Vec2::from_lanes(u.nan_where(w.any_nan()))
    }
}

/// A direction towards the disk of radius `radius` about `center` (relative to the shading
/// point) with normal `normal`, uniform in the solid angle Ω it subtends, and its pdf per
/// steradian 1/Ω. [`spherical_ellipse_pdf`] gives the same number, bit for bit, at the
/// returned direction.
///
/// The map of the module's docs: polar on the disk's spherical ellipse, u₁ the angle (by a
/// Newton solve of the sector's solid angle, in f64) and u₀ the angle from the cone's axis,
/// uniform in 1 − cos θ. Both sides of the disk are sampled alike. Where
/// [`SphericalEllipse::by_area`] (Ω below [`ELLIPSE_MIN_SR`]) the disk is sampled uniformly by
/// area (the concentric map) instead, with pdf h²/(|ω·n|³ πr²).
///
/// u is clamped to [0, 1]². A radius that is not positive and finite (or so small that 1/(πr²)
/// overflows), a centre or normal that is not finite, a zero normal and a point in the disk's
/// plane give pdf 0 and direction +z, as NaN in u does.
#[inline]
pub fn spherical_ellipse<P: Point2<Lane = L>, L: Math>(
    u: P,
    center: P::Vec3,
    normal: P::Vec3,
    radius: L,
) -> (P::Vec3, L) {
    halved!(sample SphericalEllipse::new(center, normal, radius: lane) at u)
}

/// pdf per steradian that [`spherical_ellipse`] returns direction `w` (any positive multiple):
/// 1/Ω within the ellipse (its semi-axes widened by 4ε) and in front, else 0 (also for NaN,
/// and everywhere where there is nothing to sample); h²/(|ω·n|³ πr²) there where the disk is
/// sampled by area.
#[inline]
pub fn spherical_ellipse_pdf<P: Point3<Lane = L>, L: Math>(
    w: P,
    center: P,
    normal: P,
    radius: L,
) -> L {
    halved!(pdf SphericalEllipse::for_pdf(center, normal, radius: lane) at w)
}

/// Inverse of [`spherical_ellipse`]: the u that maps to direction `w` (any positive multiple),
/// clamped to the square; (0, 0) where there is nothing to sample. NaN gives NaN.
#[inline]
pub fn spherical_ellipse_inverse<P: Point3<Lane = L>, L: Math>(
    w: P,
    center: P,
    normal: P,
    radius: L,
) -> P::Vec2 {
    halved!(inverse SphericalEllipse::new(center, normal, radius: lane) at w)
}

/// The registry's [`spherical_ellipse`]: the disk about `c` with normal `n` and radius `r`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolidAngleDisk {
    /// The centre, relative to the shading point.
    pub c: Vec3,
    /// The disk's normal.
    pub n: Vec3,
    /// The radius.
    pub r: f32,
}

impl SolidAngleDisk {
    /// Which case it is: "circle" (seen along its axis), "ellipse", "thin" (b/a below ¼), or
    /// "area" where it falls back.
    pub fn case(&self) -> &'static str {
        let e = SphericalEllipse::new(self.c, self.n, self.r);
        let (a, b) = e.semi_axes();
        if e.by_area() {
            "area"
        } else if b == a {
            "circle"
        } else if b < 0.25 * a {
            "thin"
        } else {
            "ellipse"
        }
    }
}

impl Family for SolidAngleDisk {
    fn name(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "spherical_ellipse {}", self.case())
    }
    fn sampler<L: Math>(&self) -> impl Fn(V2<L>) -> (V3<L>, L) + Copy {
        let (c, n, r) = (lanes3::<L>(self.c), lanes3::<L>(self.n), lane::<L>(self.r));
        // Through `black_box`, as the polygons': the set-up is paid at every sample.
        #[inline(always)]
        move |u| {
            let (c, n, r) = core::hint::black_box((c, n, r));
            spherical_ellipse(u, c, n, r)
        }
    }
    fn pdf<L: Math>(&self, x: V3<L>) -> L {
        spherical_ellipse_pdf(x, lanes3(self.c), lanes3(self.n), lane(self.r))
    }
    fn inverse<L: Math>(&self, x: V3<L>) -> Option<V2<L>> {
        Some(spherical_ellipse_inverse(
            x,
            lanes3(self.c),
            lanes3(self.n),
            lane(self.r),
        ))
    }
    fn in_domain(&self, x: Vec3) -> bool {
        is_unit(x)
    }
}
