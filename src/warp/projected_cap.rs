//! Sphere lights sampled by projected solid angle: directions towards a sphere distributed as the
//! receiver's cosine n·ω over the part of its cap above the horizon, exactly, with pdf n·ω / P
//! per steradian (P the cap's projected solid angle: its irradiance at radiance 1).
//!
//! In the shading frame (+z along n, +x towards the sphere's centre c, which lies at elevation
//! β), the cap of half-angle α (sin α = r/d) projects orthographically onto the unit disk as
//! follows (Peters & Dachsbacher, "Sampling Projected Spherical Caps in Real Time", I3D 2019):
//!
//! - its boundary circle becomes the ellipse E centred at (cos α·cos β, 0) with half-extents
//!   (sin α·|sin β|, sin α), inside the unit disk;
//! - where the cap crosses the horizon (|β| < α), E touches the unit circle at x = x_cut =
//!   cos α / cos β, and the cap's part on the far side of that chord projects to the whole
//!   segment {x ≥ x_cut} of the disk.
//!
//! So the projected cap is E alone when the cap is wholly above the horizon; E plus the lune
//! (the segment minus E) when its centre is above the horizon and the cap straddles it; the
//! lune alone when the centre is below. One map serves the three cases, each of them exact:
//!
//! - **E**, the linear image of a disk, is sampled in closed form: u₀ is the squared radius, u₁
//!   the angle (polar, as the cone's).
//! - **The lune** is sliced along y: at height y its width is the gap between the unit circle
//!   and E's far side, W(y) = √(1 − y²) − x_E(y), and its area below y has a closed form G(y)
//!   (arcsines). u₁ picks y by a Newton solve of G(y) = u₁·G(y_c), and u₀ the depth from the
//!   horizon uniformly. The set-up tabulates G and W at eight heights; the seed is the cubic
//!   Hermite interpolant of y(G) between them (its slopes are 1/W), and next to a horn, where
//!   W vanishes, a cube-root model of G's approach to its end. The seed is within 3e-4·y_c of
//!   the root for nine samples in ten, and one Newton step ends the solve there.
//! - u₁ first chooses between E and the lune by area.
//!
//! This is the decomposition of Ureña and Georgiev (EGSR 2018: ellipse plus lune); the paper of
//! Peters & Dachsbacher samples the lune's case approximately (its density varies by up to √2),
//! which this map does not. The lift ω = (x, y, z) takes z from the geometry rather than from
//! √(1 − x² − y²), which cancels near the horizon: over E, z² = sin²α(1 − ρ²) + q_z² (q the point
//! of the cap's circle's disk below ω), in the lune z² = δ(2√(1 − y²) − δ) (δ the depth).
//!
//! P, where the lune appears, is a difference of sectors that cancels when the lune is thin
//! (the cap just touching the horizon from below, or just clearing it from above): beyond a
//! cancellation of [`CAP_MAX_SPREAD`] the sphere is sampled by its cone of directions instead
//! ([`uniform_cone`](crate::warp::uniform_cone)), with that pdf. A cap wholly above the horizon
//! never falls back, at any size: E's area is π sin²α sin β, with no cancellation.

use core::f64::consts::PI;
use core::fmt;

use glam::Vec3;

use crate::frame::Frame;
use crate::lane::{Lane, Lanes, Mask, V2, V3, Widen};
use crate::math::Math;
use crate::point::{Point2, Point3, halved, split_fields};
use crate::warp::common::{azimuth_fraction, clamp_u, pick};
use crate::warp::family::{is_unit, lane, lanes3};
use crate::warp::polygon::{cross3_in, dot3_in, widen3};
use crate::warp::{Family, cone_h_from_sin2, uniform_cone, uniform_cone_inverse};

/// The largest ratio of the lune's area terms to their sum (its area) for which a cap across
/// the horizon is sampled by projected solid angle; beyond, by its cone. See the module's docs.
pub const CAP_MAX_SPREAD: f32 = 1024.0;

/// Newton steps of the lune's solve at most (a lane stops once a step no longer moves y).
const SOLVE_STEPS: usize = 8;

/// Heights of the lune's seed table: y_c·k/K for k = 0 … K − 1.
const LUNE_KNOTS: usize = 8;

/// The lune at one height of its seed table: G, the area below it as the f32 solve sums it, and
/// 1/W, the slope of y(G) there.
#[derive(Clone, Copy)]
struct LuneKnot<L> {
    g: L,
    inv_w: L,
}

split_fields!(LuneKnot<L: Math> by L { g, inv_w });

/// θ − sin θ for θ ∈ [0, π/2] by its Taylor series θ³/3! − θ⁵/5! + … − θ²¹/21!, whose
/// truncation is below 3e-18 relative there: no cancellation near 0, and no choice between a
/// series and θ − sin θ. Such a select, once LLVM pairs the two arcsine terms in one register,
/// becomes a jump on θ < 1 that varies from sample to sample and resolves only after the
/// arcsines. Plain products, so that the f64 lanes agree with the scalar f64.
#[inline(always)]
fn theta_minus_sin<T: Lane>(theta: T) -> T {
    let t2 = theta * theta;
    // By Horner in θ², from the θ²¹ term.
    let mut acc = T::c(-1.0 / 51_090_942_171_709_440_000.0);
    for c in [
        1.0 / 121_645_100_408_832_000.0,
        -1.0 / 355_687_428_096_000.0,
        1.0 / 1_307_674_368_000.0,
        -1.0 / 6_227_020_800.0,
        1.0 / 39_916_800.0,
        -1.0 / 362_880.0,
        1.0 / 5040.0,
        -1.0 / 120.0,
        1.0 / 6.0,
    ] {
        acc = acc * t2 + T::c(c);
    }
    theta * t2 * acc
}

/// B(y) = ∫₀^y (1 − √(1 − τ²)) dτ = y − ½(y√(1 − y²) + asin y) for y ∈ [0, 1], as
/// ½y³/(1 + √(1 − y²)) − ½(asin y − y): both terms keep their precision near 0, where B ≈ y³/6.
#[inline(always)]
fn chord_deficit<T: Lane>(y: T, asin: T) -> T {
    let c = (T::ONE - y * y).max(T::ZERO).sqrt();
    T::HALF * (y * y * y / (T::ONE + c) - theta_minus_sin(asin))
}

/// The three terms of the lune's area between heights 0 and y: W(0)·y, B(y) and
/// a·sin α·B(y/sin α) (the area is the first minus the second plus the third), in any lane,
/// with its arcsine.
#[inline(always)]
fn lune_terms<T: Lane>(w0: T, a: T, s: T, y: T, asin: impl Fn(T) -> T) -> [T; 3] {
    let v = (y / s).min(T::ONE);
    [
        w0 * y,
        chord_deficit(y, asin(y)),
        a * s * chord_deficit(v, asin(v)),
    ]
}

/// arcsine of each f64 lane (libm's).
#[inline(always)]
fn asin_wide<T: Lanes<Scalar = f64>>(y: T) -> T {
    T::from_fn(|i| libm::asin(y.lane(i)))
}

/// 1 − √(1 − y²), as y²/(1 + √(1 − y²)).
#[inline(always)]
fn sag<L: Math>(y: L) -> L {
    let y2 = y * y;
    y2 / (L::ONE + (L::ONE - y2).max(L::ZERO).sqrt())
}

/// The f64 lane of the same width as `L`.
type W<L> = <L as Widen>::Wide;

/// The set-up of a cap's projected-solid-angle map, in its frame (+z the normal, +x towards the
/// centre).
#[derive(Clone, Copy)]
struct Cap<L: Math> {
    /// The shading frame, +x towards the centre's azimuth.
    frame: Frame<V3<L>>,
    /// cos β, sin β of the centre's elevation; sin α, cos α of the cap's half-angle.
    cx: L,
    cz: L,
    s: L,
    cos_a: L,
    /// E: its centre's x, its half-extent along x (sin α·|sin β|), its area (0 where the centre
    /// is below the horizon).
    xe: L,
    a: L,
    ellipse: L,
    /// The lune: W(0) = 1 − cos(α − |β|), its half-height y_c (0 when there is none), the area of
    /// its upper half (summed in f64), and G(y_c), the same area as the f32 solve sums it.
    w0: L,
    yc: L,
    half: L,
    g_end: L,
    /// The seed table, and the shape of the last interval's model (see [`Cap::solve`]).
    knots: [LuneKnot<L>; LUNE_KNOTS],
    horn: L,
    /// P.
    p: L,
    /// The lune's area terms over its area (1 without a lune): how far its f32 sums cancel.
    spread: L,
    /// The cone of the fallback: its frame about the centre and h = 1 − cos α.
    cone: Frame<V3<L>>,
    h: L,
    /// The unit normal and centre direction (world).
    n: V3<L>,
    c: V3<L>,
    /// Sampled by projected solid angle (finite input, outside the sphere, some of the cap above
    /// the horizon, the lune within [`CAP_MAX_SPREAD`]).
    valid: L::Mask,
    /// Nothing above the horizon, or degenerate input: no direction to sample.
    empty: L::Mask,
}

// A sphere light prepared at sixteen lanes without AVX-512 builds the set-up as two calls of
// eight (`point::Split`): its f64 terms spill at width 16.
split_fields!(Cap<L: Math> by L {
    frame, cx, cz, s, cos_a, xe, a, ellipse, w0, yc, half, g_end, knots, horn, p, spread, cone,
    h, n, c, valid: mask, empty: mask,
});

impl<L: Math> Cap<L> {
    #[inline(always)]
    fn new(center: V3<L>, radius: L, n: V3<L>) -> Self {
        // The scalars of the geometry in f64, where f32 inputs neither overflow nor cancel: sin β
        // of a centre near the horizon, and s² − sin²β, which decides the lune, keep their
        // relative precision.
        let (d, nw) = (widen3::<L>(center), widen3::<L>(n));
        let (dd, nn) = (dot3_in(d, d).sqrt(), dot3_in(nw, nw).sqrt());
        let one = W::<L>::ONE;
        let s_w = radius.abs().widen() / dd;
        let cz_w = dot3_in(d, nw) / (dd * nn);
        let x = cross3_in(d, nw);
        let cx_w = dot3_in(x, x).sqrt() / (dd * nn);
        let cos_w = (one - s_w * s_w).max(W::<L>::ZERO).sqrt();
        let sigma_w = (s_w - cz_w.abs()) * (s_w + cz_w.abs());
        let q = sigma_w / (cx_w * (cx_w + cos_w));
        let sin_g = sigma_w / (s_w * cx_w + cos_w * cz_w.abs());
        let cos_g = cos_w * cx_w + s_w * cz_w.abs();
        let [s, cos_a, cx, cz] = [s_w, cos_w, cx_w, cz_w].map(L::narrow);
        let lune = L::narrow_mask(sigma_w.gt(W::<L>::ZERO));
        let yc = L::select(lune, L::narrow((q * (W::<L>::TWO - q)).sqrt()), L::ZERO);
        let w0 = L::select(lune, L::narrow(sin_g * sin_g / (one + cos_g)), L::ZERO);
        let s2 = s * s;
        let xe = L::narrow(cos_w * cx_w);
        let a = L::narrow(s_w * cz_w.abs());
        let ellipse = L::select(
            cz.gt(L::ZERO),
            L::narrow(W::<L>::c(PI) * s_w * s_w * cz_w),
            L::ZERO,
        );
        let n = n.normalize_scaled();
        let c = center.normalize_scaled();
        let duff = Frame::from_normal(n);
        let local = duff.to_local(c);
        // The frame turned about n to the centre's azimuth (at the zenith any will do), once
        // here rather than at every sample.
        // Within 2⁻⁶⁰ of the axis the squares below would fall into f32's subnormals and the
        // azimuth would not be a unit vector; there the cap is centred to f32 precision anyway.
        let rho = local.x.mul_add(local.x, local.y * local.y).sqrt();
        let near = local.x.abs().max(local.y.abs());
        let on_axis = !near.gt(L::c(8.673_617_379_884_035e-19));
        let (ca, sa) = (
            L::select(on_axis, L::ONE, local.x / rho),
            L::select(on_axis, L::ZERO, local.y / rho),
        );
        let turn = |t: V3<L>, b: V3<L>, c: L, s: L| {
            V3::new(
                c.mul_add(t.x, s * b.x),
                c.mul_add(t.y, s * b.y),
                c.mul_add(t.z, s * b.z),
            )
        };
        let frame = Frame {
            t: turn(duff.t, duff.b, ca, sa),
            b: turn(duff.b, duff.t, ca, -sa),
            n: duff.n,
        };
        let mut cap = Cap {
            frame,
            cx,
            cz,
            s,
            cos_a,
            xe,
            a,
            ellipse,
            w0,
            yc,
            half: L::ZERO,
            g_end: L::ZERO,
            knots: [LuneKnot {
                g: L::ZERO,
                inv_w: L::ZERO,
            }; LUNE_KNOTS],
            horn: L::ZERO,
            p: ellipse,
            spread: L::ONE,
            cone: Frame::from_normal(c),
            h: cone_h_from_sin2(s2),
            n,
            c,
            valid: lune,
            empty: lune,
        };
        // The lune's upper half: W(0)·y_c − B(y_c) + a·sin α·B(y_c/sin α), whose terms cancel for
        // a thin lune. Summed in f64 for P (with libm's arcsine, lane by lane: only where some
        // lane has a lune), and in f32 as the solve sums it, where the cancellation bounds the
        // map's accuracy.
        let (g_end, spread, half) = if lune.any() {
            let [t0, t1, t2] = lune_terms(w0, a, s, yc, L::asin);
            let g_end = L::select(lune, t0 - t1 + t2, L::ZERO);
            let lune_w = sigma_w.gt(W::<L>::ZERO);
            let yc = W::<L>::select(lune_w, (q * (W::<L>::TWO - q)).sqrt(), W::<L>::ZERO);
            let w0 = sin_g * sin_g / (one + cos_g);
            let [h0, h1, h2] = lune_terms(w0, s_w * cz_w.abs(), s_w, yc, asin_wide);
            let half = W::<L>::select(lune_w, h0 - h1 + h2, W::<L>::ZERO);
            (g_end, (t0 + t1 + t2) / g_end, half)
        } else {
            (L::ZERO, L::ONE, W::<L>::ZERO)
        };
        cap.half = L::narrow(half);
        cap.g_end = g_end;
        if lune.any() {
            cap.tabulate();
        }
        cap.spread = L::select(lune, spread, L::ONE);
        let ellipse_w = W::<L>::c(PI) * s_w * s_w * cz_w.max(W::<L>::ZERO);
        cap.p = L::narrow(ellipse_w + half * W::<L>::TWO);
        // A sphere to sample: a positive radius, seen from outside, at a finite centre. Then
        // with a normal (non-zero, finite) nothing may be above the horizon (nothing to sample),
        // and without one the cone samples it.
        let zero = W::<L>::ZERO;
        // (The f32 unit vectors are NaN for a subnormal largest component: such a centre has no
        // sphere to sample, such a normal none to follow.)
        let sphere = L::narrow_mask(
            s_w.gt(zero) & s_w.lt(one) & dd.lt(W::<L>::c(f64::INFINITY)) & dd.gt(zero),
        ) & !c.any_nan();
        let normal = L::narrow_mask(nn.gt(zero) & nn.lt(W::<L>::c(f64::INFINITY))) & !n.any_nan();
        cap.empty = !sphere | (normal & !cap.p.gt(L::ZERO));
        // P below 1e-30 (a sphere 10¹⁵ radii away) leaves cos θ / P too near f32's overflow.
        let tiny = cap.p.lt(L::c(1e-30));
        cap.valid = !cap.empty & normal & !tiny & cap.spread.le(L::c(CAP_MAX_SPREAD as f64));
        cap
    }

    /// The seed table: G and 1/W at y_c·k/K, and the last interval's model, whose slope at its
    /// knot matches W there: see [`solve`](Self::solve).
    #[inline(always)]
    fn tabulate(&mut self) {
        let step = self.yc * L::c(1.0 / LUNE_KNOTS as f64);
        let mut knots = self.knots;
        for (k, knot) in knots.iter_mut().enumerate() {
            let y = step * L::c(k as f64);
            knot.g = if k == 0 { L::ZERO } else { self.area_below(y) };
            knot.inv_w = L::ONE / self.width(y);
        }
        self.knots = knots;
        let last = knots[LUNE_KNOTS - 1];
        // The last interval's model d = r + c·r(1 − r) (see `solve`) has dd/dr = 1 − c at its
        // start, where the true slope is 3/m, m = W·(y_c/K)/(G(y_c) − G) the slope there of the
        // area left against d. c stays in [−1, 1], where d is monotone in r.
        let m = step / (last.inv_w * (self.g_end - last.g));
        self.horn = (L::ONE - L::c(3.0) / m).clamp(-L::ONE, L::ONE);
    }

    /// The width of the lune at height y ∈ [0, y_c]: W(0) − sag(y) + a·sag(y/sin α).
    #[inline(always)]
    fn width(&self, y: L) -> L {
        let v = (y / self.s).min(L::ONE);
        (self.w0 - sag(y) + self.a * sag(v)).max(L::ZERO)
    }

    /// The lune's area between heights 0 and y ∈ [0, y_c].
    #[inline(always)]
    fn area_below(&self, y: L) -> L {
        let [t0, t1, t2] = lune_terms(self.w0, self.a, self.s, y, L::asin);
        t0 - t1 + t2
    }

    /// Local direction → world.
    #[inline(always)]
    fn world(&self, l: V3<L>) -> V3<L> {
        self.frame.to_world(l)
    }

    /// World (unit) → local.
    #[inline(always)]
    fn local(&self, w: V3<L>) -> V3<L> {
        self.frame.to_local(w)
    }

    /// The map on the valid lanes: local direction for clamped u.
    #[inline(always)]
    fn sample_local(&self, u: V2<L>) -> V3<L> {
        // u₁ chooses E or the lune by area; where there is no lune, u₁ is E's own.
        let lune = self.half.gt(L::ZERO);
        let t = u.y * self.p;
        let in_ellipse = t.lt(self.ellipse) | !lune;
        let mut out = V3::default();
        if (in_ellipse & self.valid).any() {
            let u1 = L::select(lune, t / self.ellipse, u.y).min(L::ONE);
            let (sin, cos) = u1.sincos_2pi_unit();
            let rho = u.x.sqrt();
            let (ex, ey) = (rho * cos, rho * sin);
            // The point of the circle's disk below ω, and ω's height above it.
            let qz = self.cos_a.mul_add(self.cz, -(self.s * self.cx * ex));
            let z2 = (self.s * self.s).mul_add(L::ONE - u.x, qz * qz);
            out = V3::new(self.a.mul_add(ex, self.xe), self.s * ey, z2.sqrt());
        }
        let into_lune = !in_ellipse & self.valid;
        if into_lune.any() {
            // Fraction of the lune below y, in [0, 1], as a signed share of its upper half.
            let f = ((t - self.ellipse) / (L::TWO * self.half)).clamp(L::ZERO, L::ONE);
            let target = (L::TWO * f - L::ONE) * self.g_end;
            let y = self.solve(target.abs(), into_lune).copysign(target);
            let circle = (L::ONE - y * y).max(L::ZERO).sqrt();
            let delta = u.x * self.width(y.abs());
            let z = (delta * (L::TWO * circle - delta)).max(L::ZERO).sqrt();
            out = V3::select(into_lune, V3::new(circle - delta, y, z), out);
        }
        out
    }

    /// y ∈ [0, y_c] with area_below(y) = target ∈ [0, G(y_c)], on the lanes of `active`: the
    /// seed from the table, then Newton's steps.
    ///
    /// The seed: the table's interval by comparisons; inside it the cubic Hermite interpolant of
    /// y(G) from the knots' G and slopes 1/W. The last interval ends at the horn, where W = 0 and
    /// G approaches its end as the cube of the distance d (the ellipse touches the circle) or,
    /// for a centre on the horizon, as its square. There d (in units of the interval) is
    /// r + c·r(1 − r) with r the cube root of the share of the interval's area left: exact at
    /// both ends, with c matching the slope at the interval's start. Measured over caps of
    /// sin²α from 1e-4 to 0.9, their centres from 0.99α below to 0.9α above the horizon (5·10⁵
    /// samples in the lune): the seed is within 3e-4·y_c of the root for 92 % of them, where
    /// Newton's first step is already below the stopping size, and within 1e-2·y_c for all but
    /// one; the solve takes 1.07 steps per sample.
    #[inline(always)]
    fn solve(&self, target: L, active: L::Mask) -> L {
        let mut k = L::ZERO;
        for knot in self.knots.iter().skip(1) {
            k = k + L::select(knot.g.le(target), L::ONE, L::ZERO);
        }
        let step = self.yc * L::c(1.0 / LUNE_KNOTS as f64);
        let (k0, k1) = (k.widen(), (k + L::ONE).widen());
        let (g0, i0) = (
            pick(&self.knots, k0, |t| t.g),
            pick(&self.knots, k0, |t| t.inv_w),
        );
        let (g1, i1) = (
            pick(&self.knots, k1, |t| t.g),
            pick(&self.knots, k1, |t| t.inv_w),
        );
        let y0 = k * step;
        let span = g1 - g0;
        let x = ((target - g0) / span).clamp(L::ZERO, L::ONE);
        let x2 = x * x;
        let (h01, h10, h11) = (
            x2 * (L::c(3.0) - L::TWO * x),
            x * (x - L::ONE) * (x - L::ONE),
            x2 * (x - L::ONE),
        );
        let mut y = y0 + step * h01 + span * (i0 * h10 + i1 * h11);
        let horn = k.ge(L::c((LUNE_KNOTS - 1) as f64));
        if (horn & active).any() {
            let left = ((self.g_end - target) / (self.g_end - g0)).clamp(L::ZERO, L::ONE);
            let r = L::select(
                left.gt(L::ZERO),
                (left.ln() * L::c(1.0 / 3.0)).exp(),
                L::ZERO,
            );
            let d = r + self.horn * r * (L::ONE - r);
            y = L::select(horn, self.yc - d * step, y);
        }
        let mut y = L::select(y.is_finite(), y, y0).clamp(L::ZERO, self.yc);
        let mut done = !active;
        for _ in 0..SOLVE_STEPS {
            let w = self.width(y);
            let step = (target - self.area_below(y)) / w;
            let step = L::select(w.gt(L::ZERO) & step.is_finite(), step, L::ZERO);
            let next = (y + step).clamp(L::ZERO, self.yc);
            // Converged once a step moves y by under √ε of y_c: Newton's next would move it by
            // about the square of that, ε. A stopped lane keeps its value, so that every lane
            // follows its scalar path.
            let small = (next - y).abs().le(self.yc * L::EPSILON.sqrt());
            y = L::select(done, y, next);
            done = done | small;
            if done.all() {
                break;
            }
        }
        y
    }

    /// u of a local direction on the valid lanes.
    #[inline(always)]
    fn inverse_local(&self, l: V3<L>) -> V2<L> {
        let lune = self.half.gt(L::ZERO);
        let ex = (l.x - self.xe) / self.a;
        let ey = l.y / self.s;
        let r2 = ex.mul_add(ex, ey * ey);
        let in_ellipse = (r2.le(L::ONE) & self.cz.gt(L::ZERO)) | !lune;
        let mut u = V2::default();
        if in_ellipse.any() {
            let u1 = azimuth_fraction(ex, ey);
            let u1 = L::select(lune, u1 * self.ellipse / self.p, u1);
            u = V2::new(r2.min(L::ONE), u1);
        }
        if (!in_ellipse).any() {
            let y = l.y.abs().min(self.yc);
            let circle = (L::ONE - y * y).max(L::ZERO).sqrt();
            // Any direction inverts to a point of the square: at the horns (W = 0) every depth
            // is the same point, u₀ = 0; a direction far off the lune clamps.
            let tiny = L::c(f32::MIN_POSITIVE as f64);
            let delta = l.z * l.z / (circle + l.x).max(tiny);
            let width = self.width(y);
            let u0 = L::select(width.gt(L::ZERO), delta / width, L::ZERO);
            let below = (self.area_below(y) / self.g_end).copysign(l.y);
            let u1 = self.half.mul_add(L::ONE + below, self.ellipse) / self.p;
            u = V2::select(in_ellipse, u, V2::new(u0, u1));
        }
        clamp_u(u)
    }

    /// True where ω, of squared length `len2`, is within the cap, widened by 2ε in sin θ (θ from
    /// the centre), as the sphere light's own test.
    #[inline(always)]
    fn on_cap(&self, w: V3<L>, len2: L) -> L::Mask {
        let bound = self.s + L::TWO * L::EPSILON;
        let x = w.cross(self.c);
        w.dot(self.c).gt(L::ZERO) & x.dot(x).le(bound * bound * len2)
    }
}

/// A sphere light sampled by projected solid angle for a receiver with unit normal `n`: see
/// [`projected_cap`]. The set-up (the frame, the ellipse and the lune, P) is paid once.
#[derive(Clone, Copy)]
pub struct ProjectedCap<P: Point3>(Cap<P::Lane>);

split_fields!(ProjectedCap<P: Point3> by P::Lane { 0 });

impl<P: Point3<Lane = L>, L: Math> ProjectedCap<P> {
    /// The sphere of radius `radius` about `center` (relative to the shading point), seen by a
    /// receiver with normal `n` (any positive multiple).
    #[inline]
    pub fn new(center: P, radius: L, n: P) -> Self {
        Self(Cap::new(center.to_lanes(), radius, n.to_lanes()))
    }

    /// P, the projected solid angle of the cap's part above the horizon: the sphere's
    /// irradiance at radiance 1 (0 for a sphere wholly below the horizon, or for a point inside
    /// it).
    #[inline]
    pub fn projected_area(&self) -> L {
        L::select(self.0.empty, L::ZERO, self.0.p)
    }

    /// True (lane by lane) where the sphere is sampled by its cone of directions instead: a lune
    /// cancelling by more than [`CAP_MAX_SPREAD`], a normal that is 0 or not finite, P below
    /// 1e-30, or nothing to sample (see [`projected_cap`]).
    #[inline]
    pub fn by_solid_angle(&self) -> L::Mask {
        !self.0.valid
    }

    /// The lune's area terms over its area, 1 without a lune: the cancellation that
    /// [`CAP_MAX_SPREAD`] bounds.
    #[inline]
    pub fn spread(&self) -> L {
        self.0.spread
    }

    /// Which case each lane is (bit 0: the ellipse is sampled, bit 1: the lune is), for the
    /// registry's names and the tests.
    #[inline]
    pub fn pieces(&self) -> (L::Mask, L::Mask) {
        let c = &self.0;
        (
            c.ellipse.gt(L::ZERO) & c.valid,
            c.half.gt(L::ZERO) & c.valid,
        )
    }

    /// See [`projected_cap`].
    #[inline]
    pub fn sample(&self, u: P::Vec2) -> (P, L) {
        let c = &self.0;
        let u = u.to_lanes();
        let (mut w, mut horizon) = (V3::default(), !c.valid);
        if c.valid.any() {
            let local = c.sample_local(clamp_u(u));
            horizon = local.z.eq(L::ZERO);
            // Unit to rounding already: the lift keeps |p|² + z² = 1 in its algebra.
            w = c.world(local);
        }
        if (!c.valid).any() {
            let wc = c.cone.to_world(uniform_cone(u, c.h));
            w = V3::select(c.valid, w, wc);
        }
        // The pdf function's own path, so that the two agree bit for bit.
        let pdf = self.pdf_lanes(w);
        // A direction on the horizon (u₀ = 0 in the lune) keeps its place with pdf 0, so that it
        // inverts; other dropped samples give +z: NaN u, nothing to sample, the cone's
        // overflow, and a direction that rounding put just off the cap (at a lune's horn).
        let dropped = u.any_nan() | c.empty;
        let pdf = L::select(dropped, L::ZERO, pdf);
        let keep = pdf.gt(L::ZERO) | (c.valid & horizon & !dropped);
        let w = V3::select(keep, w, V3::new(L::ZERO, L::ZERO, L::ONE));
        (P::from_lanes(w), pdf)
    }

    /// See [`projected_cap_pdf`].
    #[inline]
    pub fn pdf(&self, w: P) -> L {
        self.pdf_lanes(w.to_lanes())
    }

    #[inline(always)]
    fn pdf_lanes(&self, w: V3<L>) -> L {
        let c = &self.0;
        // ω is not normalised: cos θ is n·ω / |ω| and the cap's test scales by |ω|², one root
        // and one division on the sample's critical path where `normalize` has a root and four
        // divisions.
        let w = w.in_square_range();
        let len2 = w.dot(w);
        let on_cap = c.on_cap(w, len2);
        let cos = w.dot(c.n);
        let own = L::select(on_cap & cos.gt(L::ZERO), cos / (len2.sqrt() * c.p), L::ZERO);
        // The cone's pdf, 0 where it overflows (h below about 4.6e-40), as `uniform_cone_pdf`.
        let cone = if (!c.valid).any() {
            let cone = L::c(0.5 / PI) / c.h;
            L::select(on_cap & cone.is_finite(), cone, L::ZERO)
        } else {
            L::ZERO
        };
        let pdf = L::select(c.valid, own, cone);
        L::select(c.empty | w.any_nan(), L::ZERO, pdf)
    }

    /// See [`projected_cap_inverse`].
    #[inline]
    pub fn inverse(&self, w: P) -> P::Vec2 {
        let c = &self.0;
        let w = w.to_lanes();
        let unit = w.normalize_scaled();
        let mut u = V2::default();
        if c.valid.any() {
            u = c.inverse_local(c.local(unit));
        }
        if (!c.valid).any() {
            let uc = uniform_cone_inverse(c.cone.to_local(unit), c.h);
            u = V2::select(c.valid, u, uc);
        }
        P::Vec2::from_lanes(u.nan_where(w.any_nan()))
    }
}

/// A direction towards the sphere of radius `radius` about `center` (relative to the shading
/// point), distributed as the cosine n·ω of a receiver with normal `n` over the part of the
/// sphere's cap above its horizon, and its pdf per steradian n·ω / P (P the projected solid
/// angle, [`ProjectedCap::projected_area`]). [`projected_cap_pdf`] gives the same number, bit
/// for bit, at the returned direction.
///
/// The map of the module's docs: exact in all three cases (the cap wholly above the horizon,
/// its centre above and the cap across, its centre below), a closed form for the first and a
/// Newton solve for the lune. Where [`ProjectedCap::by_solid_angle`] (a lune thinner than
/// [`CAP_MAX_SPREAD`] allows) it is [`uniform_cone`] about the centre instead, with pdf
/// 1/(2π(1 − cos α)).
///
/// u is clamped to [0, 1]². A sphere wholly below the horizon, a point inside or on the sphere
/// (r ≥ |center|), a radius of 0 and a centre or radius that is not finite give pdf 0 and
/// direction +z, as NaN in u does; a normal that is 0 or not finite, and P below 1e-30 (a
/// sphere some 10¹⁵ radii away), sample the cone, whose pdf is 0 where it overflows f32.
#[inline]
pub fn projected_cap<P: Point2<Lane = L>, L: Math>(
    u: P,
    center: P::Vec3,
    radius: L,
    n: P::Vec3,
) -> (P::Vec3, L) {
    halved!(sample ProjectedCap::new(center, radius: lane, n) at u)
}

/// pdf per steradian that [`projected_cap`] returns direction `w` (any positive multiple):
/// n·ω / P on the cap (widened by 2ε in the sine of the angle from its centre, as the sphere
/// light's test) and above the horizon, else 0 (also for NaN, and everywhere where there is
/// nothing to sample); the cone's 1/(2π(1 − cos α)) on the cap where it falls back.
#[inline]
pub fn projected_cap_pdf<P: Point3<Lane = L>, L: Math>(w: P, center: P, radius: L, n: P) -> L {
    halved!(pdf ProjectedCap::new(center, radius: lane, n) at w)
}

/// Inverse of [`projected_cap`]: the u that maps to direction `w` (any positive multiple),
/// clamped to the square. NaN gives NaN.
#[inline]
pub fn projected_cap_inverse<P: Point3<Lane = L>, L: Math>(
    w: P,
    center: P,
    radius: L,
    n: P,
) -> P::Vec2 {
    halved!(inverse ProjectedCap::new(center, radius: lane, n) at w)
}

/// The registry's [`projected_cap`]: the sphere about `c` of radius `r`, for the receiver's
/// normal `n`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProjectedSolidAngleCap {
    /// The centre.
    pub c: Vec3,
    /// The radius.
    pub r: f32,
    /// The receiver's unit normal.
    pub n: Vec3,
}

impl ProjectedSolidAngleCap {
    /// Which case it is: "above" (the cap wholly above the horizon), "across" (centre above,
    /// ellipse and lune), "below" (centre below, the lune alone), or "cone" where it falls back.
    pub fn case(&self) -> &'static str {
        let cap = ProjectedCap::new(self.c, self.r, self.n);
        match (cap.by_solid_angle(), cap.pieces()) {
            (true, _) => "cone",
            (false, (true, false)) => "above",
            (false, (true, true)) => "across",
            (false, _) => "below",
        }
    }
}

impl Family for ProjectedSolidAngleCap {
    fn name(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "projected_cap {}", self.case())
    }
    fn sampler<L: Math>(&self) -> impl Fn(V2<L>) -> (V3<L>, L) + Copy {
        let (c, r, n) = (lanes3::<L>(self.c), lane::<L>(self.r), lanes3::<L>(self.n));
        // Through `black_box`, as the polygons': the set-up is paid at every sample.
        #[inline(always)]
        move |u| {
            let (c, r, n) = core::hint::black_box((c, r, n));
            projected_cap(u, c, r, n)
        }
    }
    fn pdf<L: Math>(&self, x: V3<L>) -> L {
        projected_cap_pdf(x, lanes3(self.c), lane(self.r), lanes3(self.n))
    }
    fn inverse<L: Math>(&self, x: V3<L>) -> Option<V2<L>> {
        Some(projected_cap_inverse(
            x,
            lanes3(self.c),
            lane(self.r),
            lanes3(self.n),
        ))
    }
    fn in_domain(&self, x: Vec3) -> bool {
        is_unit(x)
    }
    /// Near the lune's horns (u₁ within 1e-2 of either end of its share) the lune narrows as the
    /// square of the distance from the horn, so y inherits the cube root of the rounding of
    /// its area: measured up to 7e-5 within 1e-5 of a horn of the registry's caps, 5e-6 beyond
    /// 1e-3. Error measurements skip those u.
    fn parameter_sensitive(&self, u: glam::Vec2) -> bool {
        let cap = ProjectedCap::new(self.c, self.r, self.n);
        if cap.by_solid_angle() || !cap.pieces().1 {
            return false;
        }
        let c = &cap.0;
        let start = c.ellipse / c.p;
        (u.y - start).abs() < 1e-2 || u.y > 1.0 - 1e-2
    }
}
