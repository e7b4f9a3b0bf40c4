//! One method per [`Strategy`]: each returns the sum of its samples' contributions divided by
//! its sample count, per lane, before the estimate's finiteness rule.

use super::estimator::{Estimator, Sampled, mul, per_count, scale_div};
use super::{DirectLane, OPTIMAL_MIN_SAMPLES, Strategy, Visibility};
use crate::lane::{Lane, Mask, U32Lane, V2, V3};
use crate::math::Math;
use crate::mis::{self, OptimalMis, Reservoir};
use crate::point::{Point2, Point3};
use crate::scene::{Bsdf, luminance};
use crate::seq::Samples;
use crate::warp::{
    cosine_hemisphere, cosine_hemisphere_pdf, uniform_hemisphere, uniform_hemisphere_pdf,
};

impl<V, L, B, S, F> Estimator<'_, '_, V, B, S, F>
where
    V: Point3<Lane = L>,
    L: DirectLane,
    B: Bsdf<V>,
    S: Samples<V::Vec2>,
    F: Visibility<V>,
{
    /// The direction strategies: each sample a direction from the hemisphere or the BSDF, and
    /// every light along it.
    pub(super) fn directions(&mut self, strategy: Strategy) -> V3<L> {
        let n = self.n_light + self.n_bsdf;
        let mut sum = V3::all(L::ZERO);
        for s in 0..n {
            let (u, ru) = (self.u(s, 0), self.u(s, 1).y);
            // The world direction, f·cos θ there, and 1/pdf.
            let (wi, fcos, inv_pdf) = match strategy {
                // The BSDF's sample carries f at its direction (for Phong, most of the cost).
                Strategy::Bsdf => {
                    let (wi, fcos, pdf) = self.bsdf_sample_with(u);
                    (wi, fcos, L::ONE / pdf)
                }
                _ => {
                    let (wl, inv_pdf) = hemisphere(strategy, u);
                    (self.frame.to_world(wl), self.fcos_local(wl), inv_pdf)
                }
            };
            let ok = inv_pdf.is_finite() & inv_pdf.gt(L::ZERO);
            let fcos = V3::select(ok, fcos.scale(inv_pdf), V3::all(L::ZERO));
            sum = sum + self.along(wi, fcos, ru, false, |_| L::ONE);
        }
        sum.scale(L::ONE / L::c(f64::from(n.max(1))))
    }

    /// Light sampling in solid angle: f·Le·cos θ/(pmf·pdf) per sample.
    pub(super) fn light_solid_angle(&mut self) -> V3<L> {
        let n = self.n_light + self.n_bsdf;
        let mut sum = V3::all(L::ZERO);
        for s in 0..n {
            let x = self.light_sample(s);
            let ru = self.u(s, 1).y;
            let c = x.fcos_le.scale(L::ONE / x.pdf);
            sum = sum + self.shadow(c, x.to, ru);
        }
        sum.scale(L::ONE / L::c(f64::from(n.max(1))))
    }

    /// Light sampling by area: f·Le·cos θ·cos θₗ/(r²·pmf·pdf_A) per sample.
    pub(super) fn light_area(&mut self) -> V3<L> {
        let n = self.n_light + self.n_bsdf;
        let mut sum = V3::all(L::ZERO);
        let p = V::from_lanes(self.p);
        for s in 0..n {
            let (u, v) = (self.u(s, 0), self.u(s, 1));
            let (index, pmf) = self.choose(v.x);
            let zero = V3::all(L::ZERO);
            let (mut x, mut nl, mut le, mut pdf) = (zero, zero, zero, L::ZERO);
            let (lights, u) = (self.lights.lights(), V::Vec2::from_lanes(u));
            self.for_chosen(index, |_, j, m| {
                if let Some(light) = lights.get(j) {
                    let a = light.splat::<V>().sample_area(p, u);
                    x = V3::select(m, a.p.to_lanes(), x);
                    nl = V3::select(m, a.n.to_lanes(), nl);
                    le = V3::select(m, a.le.to_lanes(), le);
                    pdf = L::select(m, a.pdf, pdf);
                }
            });
            let d = x - self.p;
            let r2 = d.length_squared();
            let wi = d.normalize_scaled();
            let cos_l = wi.dot(nl).abs();
            let g = cos_l / (r2 * pdf * pmf);
            let ok = g.is_finite() & g.gt(L::ZERO);
            let c = mul(self.fcos(wi), le).scale(L::select(ok, g, L::ZERO));
            sum = sum + self.shadow(c, x, v.y);
        }
        sum.scale(L::ONE / L::c(f64::from(n.max(1))))
    }

    /// MIS of `n_light` light and `n_bsdf` BSDF samples, balance or power heuristic.
    pub(super) fn mis(&mut self, power: bool) -> V3<L> {
        let (nl, nb) = (L::c(f64::from(self.n_light)), L::c(f64::from(self.n_bsdf)));
        let w = |a: L, b: L, pa: L, pb: L| {
            if power {
                mis::power(a, pa, b, pb)
            } else {
                mis::balance(a, pa, b, pb)
            }
        };
        let mut light = V3::all(L::ZERO);
        for s in 0..self.n_light {
            let x = self.light_sample(s);
            let ru = self.u(s, 1).y;
            let pb = self.bsdf_pdf(x.wi);
            let c = x.fcos_le.scale(w(nl, nb, x.pdf, pb) / x.pdf);
            light = light + self.shadow(c, x.to, ru);
        }
        let mut bsdf = V3::all(L::ZERO);
        for s in self.n_light..self.n_light + self.n_bsdf {
            let (wi, fcos, pb) = self.bsdf_sample(s);
            let ru = self.u(s, 1).y;
            bsdf = bsdf + self.along(wi, fcos, ru, true, |pl| w(nb, nl, pb, pl) / pb);
        }
        per_count(light, self.n_light) + per_count(bsdf, self.n_bsdf)
    }

    /// A BSDF sample from sample `s`: the world direction, f·cos θ and the pdf.
    pub(super) fn bsdf_sample(&mut self, s: u32) -> (V3<L>, V3<L>, L) {
        let u = self.u(s, 0);
        self.bsdf_sample_with(u)
    }

    /// One-sample MIS: technique chosen by pair 1's x with probabilities ∝ (n_light, n_bsdf),
    /// weighted by the balance heuristic, so each sample is f/(c_l·p_l + c_b·p_b).
    pub(super) fn one_sample(&mut self) -> V3<L> {
        let n = self.n_light + self.n_bsdf;
        let total = f64::from(n.max(1));
        let cl = L::c(f64::from(self.n_light) / total);
        let cb = L::c(f64::from(self.n_bsdf) / total);
        let mut sum = V3::all(L::ZERO);
        for s in 0..n {
            let (u, v) = (self.u(s, 0), self.u(s, 1));
            let pick = mis::one_sample([cl, cb], v.x);
            // Index 0 is the light technique: its bits or'ed into 1.0's are 1.0 exactly.
            let one = L::from_bits(pick.index | <L::U as U32Lane>::splat(0x3f80_0000));
            let use_light = one.eq(L::ONE);
            let mut c = V3::all(L::ZERO);
            if use_light.any() {
                // The light sampler reads its choice from the rescaled u: replay sample s with it.
                let x = self.light_sample_with(u, pick.u);
                let pb = self.bsdf_pdf(x.wi);
                let denom = cl.mul_add(x.pdf, cb * pb);
                let lc = x.fcos_le.scale(L::ONE / denom);
                let lc = V3::select(use_light & x.pdf.gt(L::ZERO), lc, V3::all(L::ZERO));
                c = c + self.shadow(lc, x.to, v.y);
            }
            if (!use_light).any() {
                let (wi, fcos, pb) = self.bsdf_sample_with(u);
                let fcos = V3::select(!use_light, fcos, V3::all(L::ZERO));
                c = c + self.along(wi, fcos, v.y, true, |pl| L::ONE / cl.mul_add(pl, cb * pb));
            }
            sum = sum + c;
        }
        sum.scale(L::ONE / L::c(total))
    }

    /// [`light_sample`](Self::light_sample) from given u: the direction pair and the choice u.
    pub(super) fn light_sample_with(&mut self, u: V2<L>, choice: L) -> Sampled<L> {
        let (index, pmf) = self.choose(choice);
        let zero = V3::all(L::ZERO);
        let (mut wi, mut le, mut pdf, mut dist) = (zero, zero, L::ZERO, L::ZERO);
        let u = V::Vec2::from_lanes(u);
        self.for_chosen(index, |e, j, m| {
            let ls = e.prepared(j).sample(u);
            wi = V3::select(m, ls.wi.to_lanes(), wi);
            le = V3::select(m, ls.le.to_lanes(), le);
            pdf = L::select(m, ls.pdf, pdf);
            dist = L::select(m, ls.dist, dist);
        });
        let pdf = pdf * pmf;
        let ok = pdf.gt(L::ZERO) & pdf.is_finite();
        Sampled {
            wi,
            fcos_le: V3::select(ok, mul(self.fcos(wi), le), zero),
            pdf: L::select(ok, pdf, L::ZERO),
            to: self.p + wi.scale(dist),
        }
    }

    /// A BSDF sample from given u.
    pub(super) fn bsdf_sample_with(&mut self, u: V2<L>) -> (V3<L>, V3<L>, L) {
        let b = self
            .bsdf
            .sample(V::from_lanes(self.wo), V::Vec2::from_lanes(u));
        let wl = b.wi.to_lanes();
        let wi = self.frame.to_world(wl);
        let ok = b.pdf.gt(L::ZERO);
        let fcos = b.f.to_lanes().scale(wl.z.max(L::ZERO));
        (wi, V3::select(ok, fcos, V3::all(L::ZERO)), b.pdf)
    }

    /// Optimal MIS over the samples of [`mis`](Self::mis), cross-fitted so that it is
    /// unbiased: the samples fall into two halves by the parity of their index within their
    /// technique, each half is a complete MIS estimator with half the counts, α is fitted on one
    /// half and applied to the other (and vice versa), and the two estimates are averaged. Below
    /// `OPTIMAL_MIN_SAMPLES` of either technique the halves are too small to fit α, and it is the
    /// balance heuristic. Per lane and channel, in f64.
    pub(super) fn optimal(&mut self) -> V3<L> {
        let (nl, nb) = (self.n_light, self.n_bsdf);
        let half = |n: u32, k: u32| f64::from((n >> 1) + (n & 1) * (1 - k));
        let cross = nl >= OPTIMAL_MIN_SAMPLES && nb >= OPTIMAL_MIN_SAMPLES;
        let fold_counts = |k: u32| {
            if cross {
                (half(nl, k), half(nb, k))
            } else {
                (f64::from(nl), f64::from(nb))
            }
        };
        // Per half, one accumulator per colour channel, in the f64 lane of this width.
        let [mut acc0, mut acc1] = [0, 1].map(|k| {
            let (a, b) = fold_counts(k);
            [OptimalMis::<L::Wide>::new(a, b); 3]
        });
        let push = |acc: &mut [OptimalMis<L::Wide>; 3], f: V3<L>, pl: L, pb: L| {
            for (a, f) in acc.iter_mut().zip([f.x, f.y, f.z]) {
                a.push(f.widen(), pl.widen(), pb.widen());
            }
        };
        let second = |j: u32| cross && j % 2 == 1;
        let (cl, cb) = (L::c(f64::from(nl)), L::c(f64::from(nb)));
        // Both techniques estimate one integrand over directions, F(ω) = Σⱼ f·cos θ·Leⱼ·Vⱼ,
        // with one density each: the BSDF's, and the light technique's mixture
        // p_L(ω) = Σⱼ pmfⱼ·pdfⱼ(ω) (choose a light, then a direction from it). So a light sample
        // collects every light along its direction, as a BSDF sample does, whichever light it
        // came from: with the chosen light's term alone, the two techniques would estimate
        // different integrands where lights overlap, and the fitted α would bias the estimate.
        for s in 0..nl {
            let x = self.light_sample(s);
            let ru = self.u(s, 1).y;
            let kept_sample = x.pdf.gt(L::ZERO);
            let pl = self.mixture_pdf(x.wi);
            // A dropped light sample (pdf 0) is counted and adds nothing.
            let pb = L::select(kept_sample, self.bsdf_pdf(x.wi), L::ZERO);
            let pl = L::select(kept_sample, pl, L::ZERO);
            let fcos = V3::select(kept_sample, self.fcos(x.wi), V3::all(L::ZERO));
            // Roulette by the balance-weighted contribution; the accumulator takes F itself.
            let w = mis::balance(cl, pl, cb, pb);
            let kept = self.along(x.wi, fcos, ru, false, |_| w / pl);
            let f = V3::select(w.gt(L::ZERO), scale_div(kept, w / pl), V3::all(L::ZERO));
            push(if second(s) { &mut acc1 } else { &mut acc0 }, f, pl, pb);
        }
        for j in 0..nb {
            let s = nl + j;
            let (wi, fcos, pb) = self.bsdf_sample(s);
            let ru = self.u(s, 1).y;
            let pl = self.mixture_pdf(wi);
            let w = mis::balance(cb, pb, cl, pl);
            let kept = self.along(wi, fcos, ru, false, |_| w / pb);
            let f = V3::select(w.gt(L::ZERO), scale_div(kept, w / pb), V3::all(L::ZERO));
            push(if second(j) { &mut acc1 } else { &mut acc0 }, f, pl, pb);
        }
        let est = |a: &OptimalMis<L::Wide>, b: &OptimalMis<L::Wide>| {
            L::narrow(if cross {
                // Each half's estimate with α from the other, averaged.
                (a.estimate_with_alpha_of(b) + b.estimate_with_alpha_of(a)) * L::Wide::HALF
            } else {
                a.balance_estimate()
            })
        };
        let ([x0, x1, x2], [y0, y1, y2]) = (&acc0, &acc1);
        V3::new(est(x0, y0), est(x1, y1), est(x2, y2))
    }

    /// RIS: N light-sampled candidates with target p̂ = luminance(f·Le·cos θ), one kept, one
    /// shadow ray.
    pub(super) fn ris(&mut self) -> V3<L> {
        let n = self.n_light + self.n_bsdf;
        let u = self.u(0, 2).x;
        let mut res = Reservoir::<L::Index, L::Wide>::new(u.widen());
        let zero = V3::all(L::ZERO);
        let (mut c, mut to) = (zero, zero);
        for s in 0..n {
            let x = self.light_sample(s);
            let target = luminance(x.fcos_le);
            let taken = res.push(L::index(s), target.widen(), x.pdf.widen());
            let m = L::narrow_mask(taken);
            c = V3::select(m, x.fcos_le, c);
            to = V3::select(m, x.to, to);
        }
        // The RIS weight Σw/(M·p̂(y)): 0 where no candidate had weight.
        let w = L::narrow(res.chosen().1);
        let ru = self.u(0, 1).y;
        self.shadow(c.scale(w), to, ru)
    }
}

/// A local direction of the uniform θφ, uniform or cosine hemisphere strategy, and 1/pdf.
#[inline(always)]
fn hemisphere<L: Math>(strategy: Strategy, u: V2<L>) -> (V3<L>, L) {
    match strategy {
        Strategy::UniformThetaPhi => {
            // θ = (π/2)u₀, φ = 2πu₁: the pdf per sr is 1/(π² sin θ).
            let u = V2::new(u.x.clamp(L::ZERO, L::ONE), u.y.clamp(L::ZERO, L::ONE));
            let (sin_t, cos_t) = (u.x * L::c(0.25)).sincos_2pi_unit();
            let (sin_p, cos_p) = u.y.sincos_2pi_unit();
            let pi2 = L::c(core::f64::consts::PI * core::f64::consts::PI);
            (V3::new(sin_t * cos_p, sin_t * sin_p, cos_t), pi2 * sin_t)
        }
        Strategy::UniformHemisphere => {
            let w: V3<L> = uniform_hemisphere(u);
            (w, L::ONE / uniform_hemisphere_pdf(w))
        }
        _ => {
            let w: V3<L> = cosine_hemisphere(u);
            (w, L::ONE / cosine_hemisphere_pdf(w))
        }
    }
}
