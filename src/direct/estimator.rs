//! The state of one estimate (the shading frame, the lights prepared at the point, the
//! counters) and the steps every strategy shares: choosing a light, sampling it, the BSDF's f·cos
//! and pdf, and the shadow ray with roulette.

use glam::Vec3;

use super::{Config, DirectLane, Lights, PREPARED_LIGHTS, ShadingPoint, Strategy, Visibility};
use crate::estimate::roulette;
use crate::frame::Frame;
use crate::lane::{Lane, Mask, V2, V3, lane_of};
use crate::point::{Point2, Point3};
use crate::scene::{self, Bsdf, Light, PreparedLight, luminance};
use crate::seq::Samples;

/// The lights prepared at the shading point, each on first use.
type Cache<V> = [Option<PreparedLight<V>>; PREPARED_LIGHTS];

/// The state of one estimate: the frame, the prepared lights, and the counters.
pub(super) struct Estimator<'a, 's, V: Point3, B, S, F> {
    pub(super) lights: &'s Lights<'a>,
    pub(super) bsdf: &'s B,
    pub(super) p: V3<V::Lane>,
    pub(super) frame: Frame<V3<V::Lane>>,
    /// ωo in the local frame.
    pub(super) wo: V3<V::Lane>,
    /// n·ωo > 0 and finite input.
    pub(super) valid: <V::Lane as Lane>::Mask,
    pub(super) n_light: u32,
    pub(super) n_bsdf: u32,
    pub(super) tau: V::Lane,
    /// How the lights are prepared to sample (for the frame's normal).
    pub(super) sampling: scene::LightSampling,
    pub(super) samples: &'s mut S,
    pub(super) visibility: &'s mut F,
    pub(super) cache: Cache<V>,
    /// Where a light beyond the cache is prepared for one use.
    pub(super) spare: Option<PreparedLight<V>>,
    pub(super) rays: u32,
}

/// How `strategy` prepares the lights when the caller asks for `sampling`. The strategies that
/// only trace directions (the hemispheres' and the BSDF's) never sample a light nor read its
/// density, only whether and where their rays meet it, so they prepare by area, the mode with the
/// least set-up (no spherical ellipse for the disk, no bilinear or projected table for the
/// polygons); the directions, and so the estimate, do not depend on the mode.
fn preparation(strategy: Strategy, sampling: scene::LightSampling) -> scene::LightSampling {
    match strategy {
        Strategy::UniformThetaPhi
        | Strategy::UniformHemisphere
        | Strategy::CosineHemisphere
        | Strategy::Bsdf => scene::LightSampling::Area,
        _ => sampling,
    }
}

/// A light sample as the estimator uses it: the direction, the unoccluded f·Le·cos θ, the pdf
/// including the light's selection probability, and the point the shadow ray goes to.
pub(super) struct Sampled<L: Lane> {
    pub(super) wi: V3<L>,
    pub(super) fcos_le: V3<L>,
    pub(super) pdf: L,
    pub(super) to: V3<L>,
}

impl<'a, 's, V, L, B, S, F> Estimator<'a, 's, V, B, S, F>
where
    V: Point3<Lane = L>,
    L: DirectLane,
    B: Bsdf<V>,
    S: Samples<V::Vec2>,
    F: Visibility<V>,
{
    pub(super) fn new(
        strategy: Strategy,
        lights: &'s Lights<'a>,
        bsdf: &'s B,
        at: ShadingPoint<V>,
        config: Config,
        samples: &'s mut S,
        visibility: &'s mut F,
    ) -> Self {
        let (n, wo) = (at.n.to_lanes(), at.wo.to_lanes());
        let frame = Frame::from_normal(n.normalize_scaled());
        let wo = frame.to_local(wo.normalize_scaled());
        let p = at.p.to_lanes();
        let finite = p.x.is_finite() & p.y.is_finite() & p.z.is_finite();
        let (n_light, n_bsdf) = config.counts();
        let tau = L::c(f64::from(config.roulette));
        Self {
            lights,
            bsdf,
            p,
            frame,
            wo,
            valid: wo.z.gt(L::ZERO) & finite,
            n_light,
            n_bsdf,
            // τ ≤ 0 or NaN: no roulette.
            tau: L::select(tau.gt(L::ZERO), tau, L::ZERO),
            sampling: preparation(strategy, config.light_sampling),
            samples,
            visibility,
            cache: [None; PREPARED_LIGHTS],
            spare: None,
            rays: 0,
        }
    }

    pub(super) fn u(&mut self, s: u32, pair: u32) -> V2<L> {
        self.samples.get(s, pair).to_lanes()
    }

    /// Light `j` prepared at the shading point, by reference: a prepared packet light is large
    /// (a triangle's is over a kilobyte), and it is read for every sample.
    pub(super) fn prepared(&mut self, j: usize) -> &PreparedLight<V> {
        let p = V::from_lanes(self.p);
        // Out of range (never asked): a light that is on no direction.
        let dark = Light::from(scene::SphereLight::new(Vec3::ZERO, 0.0, Vec3::ZERO));
        let light = self.lights.lights().get(j).copied().unwrap_or(dark);
        let n = V::from_lanes(self.frame.n);
        let slot = match self.cache.get_mut(j) {
            Some(slot) => slot,
            None => {
                self.spare = None;
                &mut self.spare
            }
        };
        match slot {
            Some(prepared) => prepared,
            None => light.splat::<V>().prepare_into(slot, p, n, self.sampling),
        }
    }

    /// For each light that some lane chose (`index`, a float), `f(self, j, lanes that chose j)`:
    /// one pass per distinct light, so that lanes may choose different lights.
    pub(super) fn for_chosen(&mut self, index: L, mut f: impl FnMut(&mut Self, usize, L::Mask)) {
        for j in 0..self.lights.lights().len() {
            let m = index.eq(L::c(j as f64));
            if m.any() {
                f(self, j, m);
            }
        }
    }

    /// f·cos θ at world direction `wi` (0 below the horizon).
    pub(super) fn fcos(&self, wi: V3<L>) -> V3<L> {
        self.fcos_local(self.frame.to_local(wi))
    }

    /// f·cos θ at local direction `wl`.
    pub(super) fn fcos_local(&self, wl: V3<L>) -> V3<L> {
        let f = self.bsdf.eval(V::from_lanes(self.wo), V::from_lanes(wl));
        f.to_lanes().scale(wl.z.max(L::ZERO))
    }

    /// The BSDF's pdf at world direction `wi`.
    pub(super) fn bsdf_pdf(&self, wi: V3<L>) -> L {
        let wl = self.frame.to_local(wi);
        self.bsdf.pdf(V::from_lanes(self.wo), V::from_lanes(wl))
    }

    /// Each lane's light choice from u: the index (as a float, exact below 2²⁴) and its
    /// probability.
    pub(super) fn choose(&self, u: L) -> (L, L) {
        // Room for the widest packet's lanes.
        let mut pmf = [0.0f32; 16];
        let index = L::from_fn(|i| {
            let c = self.lights.choose(u.lane(i));
            if let Some(p) = pmf.get_mut(i) {
                *p = c.pmf;
            }
            c.index as f32
        });
        (index, L::from_fn(|i| lane_of(&pmf, i)))
    }

    /// The shadow ray to `to` for contribution `c`, with roulette driven by `ru`: `c` (divided
    /// by the continuation probability) where visible, else 0.
    pub(super) fn shadow(&mut self, c: V3<L>, to: V3<L>, ru: L) -> V3<L> {
        let y = luminance(c);
        let active = y.gt(L::ZERO) & y.is_finite() & !to.any_nan();
        let low = y.lt(self.tau);
        let k = L::select(low, roulette(y / self.tau, ru), L::ONE);
        let go = active & k.gt(L::ZERO);
        if !go.any() {
            return V3::all(L::ZERO);
        }
        let vis = self
            .visibility
            .visible(go, V::from_lanes(self.p), V::from_lanes(to));
        self.rays += L::count(go);
        V3::select(vis & go, c.scale(k), V3::all(L::ZERO))
    }

    /// A light sample from sample `s`: the choice from pair 1's x, the direction from pair 0.
    pub(super) fn light_sample(&mut self, s: u32) -> Sampled<L> {
        let (u, v) = (self.u(s, 0), self.u(s, 1));
        self.light_sample_with(u, v.x)
    }

    /// The light technique's density along world direction `wi`: Σⱼ pmfⱼ·pdfⱼ over the lights.
    pub(super) fn mixture_pdf(&mut self, wi: V3<L>) -> L {
        let mut pl = L::ZERO;
        for l in 0..self.lights.lights().len() {
            let pdf = self.prepared(l).pdf(V::from_lanes(wi));
            pl = pdf.mul_add(L::c(f64::from(self.lights.pmf(l))), pl);
        }
        pl
    }

    /// Σⱼ over the lights along world direction `wi`: weight(pmfⱼ·pdfⱼ)·fcos·Leⱼ behind a shadow
    /// ray each, with roulette from `ru`. Where `weight` does not read the light's density
    /// (`reads_pdf` false), each light gives only its distance, which a light sampled through
    /// the bilinear warp finds without the spherical inverse its pdf needs.
    pub(super) fn along(
        &mut self,
        wi: V3<L>,
        fcos: V3<L>,
        ru: L,
        reads_pdf: bool,
        weight: impl Fn(L) -> L,
    ) -> V3<L> {
        let mut sum = V3::all(L::ZERO);
        if !(luminance(fcos).gt(L::ZERO)).any() {
            return sum;
        }
        let wv = V::from_lanes(wi);
        for j in 0..self.lights.lights().len() {
            let pmf = L::c(f64::from(self.lights.pmf(j)));
            let l = self.prepared(j);
            let (pdf, t) = if reads_pdf {
                l.pdf_hit(wv)
            } else {
                (L::ZERO, l.hit(wv))
            };
            let on = t.is_finite();
            if !on.any() {
                continue;
            }
            let c = mul(fcos, l.le().to_lanes()).scale(weight(pdf * pmf));
            let c = V3::select(on, c, V3::all(L::ZERO));
            let to = self.p + wi.scale(L::select(on, t, L::ZERO));
            sum = sum + self.shadow(c, to, ru);
        }
        sum
    }
}

/// The component-wise product.
#[inline(always)]
pub(super) fn mul<L: Lane>(a: V3<L>, b: V3<L>) -> V3<L> {
    V3::new(a.x * b.x, a.y * b.y, a.z * b.z)
}

/// v/w (w > 0 where used).
#[inline(always)]
pub(super) fn scale_div<L: Lane>(v: V3<L>, w: L) -> V3<L> {
    v.scale(L::ONE / w)
}

/// A sum over `n` samples divided by n; 0 for none.
#[inline(always)]
pub(super) fn per_count<L: Lane>(sum: V3<L>, n: u32) -> V3<L> {
    if n == 0 {
        V3::all(L::ZERO)
    } else {
        sum.scale(L::ONE / L::c(f64::from(n)))
    }
}
