//! The direct-lighting estimator of "Monte Carlo II: Direct Illumination" (Pharr, CS348b): the
//! radiance a shading point reflects towards ωo from a slice of lights,
//!
//! L(x, ωo) = Σⱼ ∫ f(ωo, ωi) Leⱼ V(x, xⱼ(ωi)) cos θ dωi,
//!
//! by every strategy the lecture compares ([`Strategy`]), in both widths: [`estimate`] on
//! `Vec3` and on [`Vec3x8`] (eight shading points, or eight estimates of one, in lock-step; lane
//! *i* equals the scalar estimate of lane *i*'s inputs bit for bit, given the same samples and
//! visibility, and lanes may choose different lights).
//!
//! # Inputs
//!
//! - a [`ShadingPoint`]: position, normal and ωo in world space (normal and ωo need not be unit;
//!   they are normalised);
//! - a BSDF ([`scene::Bsdf`]: [`Lambert`](crate::scene::Lambert) or
//!   [`Phong`](crate::scene::Phong)), evaluated in the normal's [`Frame`];
//! - [`Lights`]: a borrowed slice of scalar lights, chosen uniformly or by a
//!   [`PowerTable`]. Every lane of a packet sees the same lights;
//! - [`Samples`]: the u of sample s of the estimate, per pair of dimensions. [`Sequence`] reads
//!   the stateless Owen-scrambled Sobol or independent generators of [`seq`] at index
//!   `first + s`; `rand_pcg::Pcg32` and [`Pcg32x8`] give their next values;
//! - [`Visibility`]: a callback from the shading point to a point on a light, `FnMut(from, to)
//!   -> bool` for the scalar form and `FnMut(mask, from, to) -> mask` for packets (only lanes
//!   of the mask ask; the estimator ignores the answer elsewhere). It is called only for
//!   samples that would contribute, and every call is counted ([`Estimate::shadow_rays`],
//!   active lanes only).
//!
//! # The integrand, and what is a sample
//!
//! Lights are treated as independent emitters: a direction that passes through two lights
//! collects both, each behind its own shadow ray (the caller's visibility decides whether one
//! light hides the other). Every strategy spends N = `n_light + n_bsdf` samples per estimate
//! ([`Config`]), so that strategies compare at equal sample counts; MIS splits them into
//! `n_light` light samples and `n_bsdf` BSDF samples.
//!
//! Light samples choose their light with one u (uniformly or by power) and divide by its
//! probability. MIS is applied per light (Veach's multi-sample estimator for each Leⱼ term), so
//! the light technique's density for light j is pmfⱼ·pdfⱼ.
//!
//! # Splitting and roulette
//!
//! Each light is prepared at the shading point ([`Light::at`]) once per estimate, so splitting
//! (N > 1) pays the set-up once; the first [`PREPARED_LIGHTS`] lights of the slice are kept
//! prepared, further ones are prepared at each use (the same numbers, more time).
//!
//! With `Config::roulette` = τ > 0, a shadow ray whose weighted unoccluded contribution has
//! luminance y < τ is traced with probability q = max(y/τ, [`ROULETTE_Q_MIN`](crate::estimate::ROULETTE_Q_MIN)) and its
//! contribution divided by q (Russian roulette, unbiased): the expected number of rays traced
//! falls by Σ(1 − q) over the samples below τ.
//!
//! # Sample dimensions
//!
//! Sample s of an estimate reads pair 0 for its direction (or point), pair 1 for its discrete
//! choice (x: the light, or the technique of one-sample MIS) and roulette (y), and RIS reads
//! pair 2 of sample 0 for the reservoir. MIS's light samples are s = 0 … n_light − 1 and its
//! BSDF samples s = n_light … N − 1.
//!
//! # Bad input
//!
//! The estimate is finite and never NaN: a shading point with n·ωo ≤ 0 (or NaN), no lights,
//! lights of zero radiance, degenerate lights and a shading point on or inside a light give 0
//! (or the finite part of the sum); a sample whose contribution is not finite is dropped, and
//! an estimate whose sum overflows f32 (radiance near f32::MAX) is 0.
//! Sample counts are capped at [`MAX_SAMPLES`] each.

use glam::{Vec2, Vec3};

use crate::estimate::roulette;
use crate::frame::Frame;
use crate::lane::{F32x8, Lane, Lane32, Mask, U32Lane, V2, V3, lane_of, zip_map};
use crate::math::Math;
use crate::mis::{self, OptimalMis, Reservoir};
use crate::point::{Point2, Point3};
use crate::rng::Pcg32x8;
use crate::scene::{self, Bsdf, Light, LightChoice, PowerTable, PreparedLight, luminance};
use crate::seq;
use crate::warp::{
    cosine_hemisphere, cosine_hemisphere_pdf, uniform_hemisphere, uniform_hemisphere_pdf,
};
use crate::x8::{Vec2x8, Vec3x8};

/// How many lights of the slice stay prepared for a whole estimate.
pub const PREPARED_LIGHTS: usize = 8;

/// The fewest samples of each technique with which [`Strategy::OptimalMis`] fits its weights;
/// below, it is the balance heuristic. α fitted from a half of n samples per technique is noisy
/// for small n: on the 22 scenes of `verify::direct`, the worst relative RMSE of the cross-fitted
/// estimate over the balance heuristic's was 78× at 2 + 2 samples, 2.2× at 4 + 4, 1.45× at
/// 8 + 8, 1.19× at 16 + 16 and 1.09× at 32 + 32, while its best over the power heuristic's was
/// 0.03× from 4 + 4 on (2048 estimates each, independent samples).
pub const OPTIMAL_MIN_SAMPLES: u32 = 8;

/// The most samples of each technique one estimate takes: larger counts are clamped.
pub const MAX_SAMPLES: u32 = 1 << 16;

/// A strategy of the lecture. Each spends N = `n_light + n_bsdf` samples ([`Config`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Strategy {
    /// θ and φ uniform: the lecture's "inefficient but correct" estimator π²·f·Le·cos θ·sin θ.
    UniformThetaPhi,
    /// Directions uniform over the hemisphere, pdf 1/(2π).
    UniformHemisphere,
    /// Directions by the cosine, pdf cos θ/π.
    CosineHemisphere,
    /// A light, then a point uniform on its area; the pdf converted by cos θₗ/r².
    LightArea,
    /// A light, then a direction by the light's own solid-angle sampler.
    LightSolidAngle,
    /// Directions by the BSDF's sampler.
    Bsdf,
    /// `n_light` light and `n_bsdf` BSDF samples, balance heuristic.
    MisBalance,
    /// `n_light` light and `n_bsdf` BSDF samples, power heuristic (β = 2).
    MisPower,
    /// N samples, each from light sampling with probability `n_light`/N, else the BSDF, weighted
    /// by the balance heuristic (the mixture density).
    OneSampleMis,
    /// The samples of [`MisBalance`](Self::MisBalance), combined by optimal MIS (Kondapaneni
    /// et al. 2019), cross-fitted: α from one half of the samples weights the other half, per
    /// channel; the balance heuristic below [`OPTIMAL_MIN_SAMPLES`] of either technique.
    /// Unbiased when the samples of
    /// an estimate are independent (see `Estimator::optimal`). Its weights can be negative (the
    /// control variate), so one estimate can be negative; the mean is not.
    OptimalMis,
    /// Resampled importance sampling (Talbot et al. 2005): N light-sampled candidates weighted
    /// by their unshadowed contribution's luminance, one of them kept, one shadow ray.
    Ris,
}

impl Strategy {
    /// Every strategy, in the lecture's order.
    pub const ALL: [Strategy; 11] = [
        Self::UniformThetaPhi,
        Self::UniformHemisphere,
        Self::CosineHemisphere,
        Self::LightArea,
        Self::LightSolidAngle,
        Self::Bsdf,
        Self::MisBalance,
        Self::MisPower,
        Self::OneSampleMis,
        Self::OptimalMis,
        Self::Ris,
    ];

    /// The name the report and its JSON use.
    pub const fn name(self) -> &'static str {
        match self {
            Self::UniformThetaPhi => "uniform_theta_phi",
            Self::UniformHemisphere => "uniform_hemisphere",
            Self::CosineHemisphere => "cosine_hemisphere",
            Self::LightArea => "light_area",
            Self::LightSolidAngle => "light_solid_angle",
            Self::Bsdf => "bsdf",
            Self::MisBalance => "mis_balance",
            Self::MisPower => "mis_power",
            Self::OneSampleMis => "one_sample_mis",
            Self::OptimalMis => "optimal_mis",
            Self::Ris => "ris",
        }
    }
}

/// Sample counts and roulette.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Config {
    /// Light samples per estimate (MIS), clamped to [`MAX_SAMPLES`].
    pub n_light: u32,
    /// BSDF samples per estimate (MIS), clamped to [`MAX_SAMPLES`].
    pub n_bsdf: u32,
    /// The roulette threshold τ on a shadow ray's contribution (luminance); 0 (or NaN, or
    /// negative) traces every ray.
    pub roulette: f32,
}

impl Config {
    /// `n_light` light and `n_bsdf` BSDF samples, no roulette.
    pub const fn new(n_light: u32, n_bsdf: u32) -> Self {
        Self {
            n_light,
            n_bsdf,
            roulette: 0.0,
        }
    }

    /// The same counts with roulette threshold τ.
    pub const fn with_roulette(self, tau: f32) -> Self {
        Self {
            roulette: tau,
            ..self
        }
    }

    /// The counts as used: each clamped to [`MAX_SAMPLES`].
    fn counts(&self) -> (u32, u32) {
        (self.n_light.min(MAX_SAMPLES), self.n_bsdf.min(MAX_SAMPLES))
    }

    /// N: the samples every strategy takes per estimate. A [`Sequence`] should advance `first`
    /// by this much per estimate.
    pub fn samples(&self) -> u32 {
        let (l, b) = self.counts();
        l + b
    }
}

/// Where the estimate is taken: the point, its surface normal and the direction towards the
/// viewer, in world space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadingPoint<V: Point3 = Vec3> {
    /// The position.
    pub p: V,
    /// The surface normal (normalised by the estimator).
    pub n: V,
    /// The direction towards the viewer (normalised by the estimator).
    pub wo: V,
}

/// One estimate of the reflected radiance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Estimate<V: Point3 = Vec3> {
    /// L(x, ωo), RGB.
    pub radiance: V,
    /// The visibility calls it made (for a packet, the active lanes summed over calls).
    pub shadow_rays: u32,
}

/// The lights of a scene and how a light sample chooses among them.
#[derive(Clone, Copy, Debug)]
pub struct Lights<'a> {
    lights: &'a [Light],
    table: Option<PowerTable<'a>>,
}

impl<'a> Lights<'a> {
    /// Every light with equal probability.
    pub fn uniform(lights: &'a [Light]) -> Self {
        Self {
            lights,
            table: None,
        }
    }

    /// Lights chosen in proportion to power by `table`, which must have been built from the
    /// same slice ([`PowerTable::new`]).
    pub fn by_power(lights: &'a [Light], table: PowerTable<'a>) -> Self {
        Self {
            lights,
            table: Some(table),
        }
    }

    /// The lights.
    pub fn lights(&self) -> &'a [Light] {
        self.lights
    }

    fn choose(&self, u: f32) -> LightChoice {
        match &self.table {
            Some(t) => t.select(u),
            None => LightChoice::uniform(self.lights.len(), u),
        }
    }

    fn pmf(&self, index: usize) -> f32 {
        match &self.table {
            Some(t) => t.pmf(index),
            None => LightChoice::uniform(self.lights.len(), 0.0).pmf,
        }
    }
}

/// The source of an estimate's sample values: `get(s, pair)` is pair `pair` of dimensions of
/// sample `s` of the estimate, in [0, 1)².
pub trait Samples<P: Point2> {
    /// Pair `pair` of sample `s`.
    fn get(&mut self, s: u32, pair: u32) -> P;
}

/// Which stateless generator a [`Sequence`] reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Generator {
    /// [`seq::sobol_2d`], Owen-scrambled Sobol: pair k is dimensions 2k and 2k + 1.
    Sobol,
    /// [`seq::independent`], a hash of (index, dimension, seed).
    Independent,
}

/// Samples from a stateless generator: sample s of the estimate is index `first + s` (mod 2³²;
/// per lane for a packet), so consecutive estimates should advance `first` by
/// [`Config::samples`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sequence<I: U32Lane = u32> {
    /// The index of sample 0.
    pub first: I,
    /// The scramble seed.
    pub seed: u32,
    /// The generator.
    pub generator: Generator,
}

impl<I: U32Lane> Samples<I::Vec2> for Sequence<I>
where
    I::Vec2: Point2,
{
    #[inline]
    fn get(&mut self, s: u32, pair: u32) -> I::Vec2 {
        let i = self.first.wrapping_add(I::splat(s));
        match self.generator {
            Generator::Sobol => seq::sobol_2d(i, pair, self.seed),
            Generator::Independent => {
                let d = pair.wrapping_mul(2);
                V2::new(
                    seq::independent(i, d, self.seed),
                    seq::independent(i, d.wrapping_add(1), self.seed),
                )
                .into()
            }
        }
    }
}

/// The generator's next two values, whatever s and the pair.
impl Samples<Vec2> for rand_pcg::Pcg32 {
    #[inline]
    fn get(&mut self, _s: u32, _pair: u32) -> Vec2 {
        use rand_core::Rng;
        let x = self.next_u32().to_unit_f32();
        Vec2::new(x, self.next_u32().to_unit_f32())
    }
}

/// The generator's next two packets, whatever s and the pair: lane i draws what
/// `rand_pcg::Pcg32` lane i draws for the scalar form.
impl Samples<Vec2x8> for Pcg32x8 {
    #[inline]
    fn get(&mut self, _s: u32, _pair: u32) -> Vec2x8 {
        let x = self.next_f32x8();
        Vec2x8::new(x, self.next_f32x8())
    }
}

/// The caller's visibility test between the shading point and a point on a light.
pub trait Visibility<V: Point3> {
    /// True (per lane) where `to` is visible from `from`, for the lanes of `active`; the answer
    /// is ignored elsewhere.
    fn visible(
        &mut self,
        active: <V::Lane as Lane>::Mask,
        from: V,
        to: V,
    ) -> <V::Lane as Lane>::Mask;
}

impl<F: FnMut(Vec3, Vec3) -> bool> Visibility<Vec3> for F {
    #[inline]
    fn visible(&mut self, active: bool, from: Vec3, to: Vec3) -> bool {
        active && self(from, to)
    }
}

impl<F: FnMut(F32x8, Vec3x8, Vec3x8) -> F32x8> Visibility<Vec3x8> for F {
    #[inline]
    fn visible(&mut self, active: F32x8, from: Vec3x8, to: Vec3x8) -> F32x8 {
        active & self(active, from, to)
    }
}

mod sealed {
    pub trait Sealed {}
    impl Sealed for f32 {}
    impl Sealed for crate::lane::F32x8 {}
}

/// The widths the estimator runs in: `f32` and [`F32x8`]. Per-lane work (the light choice, the
/// f64 accumulators of optimal MIS and RIS) goes through these lanes one at a time, with the
/// scalar code.
pub trait DirectLane: Math + Lane32 + sealed::Sealed {
    /// The number of lanes.
    const WIDTH: usize;
    /// Lane i.
    fn lane(self, i: usize) -> f32;
    /// The lanes f(0), f(1), ….
    fn from_fn(f: impl FnMut(usize) -> f32) -> Self;
    /// The number of lanes set in `m`.
    fn count(m: Self::Mask) -> u32;

    /// Optimal MIS's accumulator of one colour channel at this width: [`OptimalMis`] or
    /// [`mis::OptimalMisX8`], the same sums lane by lane.
    type Optimal: Copy;
    /// An empty accumulator for counts n₁, n₂.
    fn optimal(n1: f64, n2: f64) -> Self::Optimal;
    /// One sample per lane.
    fn optimal_push(acc: &mut Self::Optimal, f: Self, pdf1: Self, pdf2: Self);
    /// Cross-fitted: the mean of a's estimate with α from b and b's with α from a.
    fn optimal_cross(a: &Self::Optimal, b: &Self::Optimal) -> Self;
    /// The balance heuristic's estimate.
    fn optimal_balance(a: &Self::Optimal) -> Self;
}

impl DirectLane for f32 {
    const WIDTH: usize = 1;
    #[inline(always)]
    fn lane(self, _i: usize) -> f32 {
        self
    }
    #[inline(always)]
    fn from_fn(mut f: impl FnMut(usize) -> f32) -> Self {
        f(0)
    }
    #[inline(always)]
    fn count(m: bool) -> u32 {
        u32::from(m)
    }

    type Optimal = OptimalMis;
    fn optimal(n1: f64, n2: f64) -> OptimalMis {
        OptimalMis::new(n1, n2)
    }
    #[inline(always)]
    fn optimal_push(acc: &mut OptimalMis, f: f32, pdf1: f32, pdf2: f32) {
        acc.push(f64::from(f), f64::from(pdf1), f64::from(pdf2));
    }
    fn optimal_cross(a: &OptimalMis, b: &OptimalMis) -> f32 {
        (0.5 * (a.estimate_with_alpha_of(b) + b.estimate_with_alpha_of(a))) as f32
    }
    fn optimal_balance(a: &OptimalMis) -> f32 {
        a.balance_estimate() as f32
    }
}

impl DirectLane for F32x8 {
    const WIDTH: usize = 8;
    #[inline(always)]
    fn lane(self, i: usize) -> f32 {
        lane_of(&self.to_array(), i)
    }
    #[inline(always)]
    fn from_fn(f: impl FnMut(usize) -> f32) -> Self {
        F32x8::new(core::array::from_fn(f))
    }
    #[inline(always)]
    fn count(m: F32x8) -> u32 {
        m.to_bitmask().count_ones()
    }

    type Optimal = mis::OptimalMisX8;
    fn optimal(n1: f64, n2: f64) -> mis::OptimalMisX8 {
        mis::OptimalMisX8::new(n1, n2)
    }
    #[inline(always)]
    fn optimal_push(acc: &mut mis::OptimalMisX8, f: F32x8, pdf1: F32x8, pdf2: F32x8) {
        acc.push(f, pdf1, pdf2);
    }
    fn optimal_cross(a: &mis::OptimalMisX8, b: &mis::OptimalMisX8) -> F32x8 {
        let (ab, ba) = (a.estimate_with_alpha_of(b), b.estimate_with_alpha_of(a));
        F32x8::new(zip_map(ab, ba, |x, y| (0.5 * (x + y)) as f32))
    }
    fn optimal_balance(a: &mis::OptimalMisX8) -> F32x8 {
        F32x8::new(a.balance_estimate().map(|x| x as f32))
    }
}

/// One estimate of L(x, ωo) at `at` by `strategy`: see the [module documentation](self).
pub fn estimate<V, B, S, F>(
    strategy: Strategy,
    lights: &Lights<'_>,
    bsdf: &B,
    at: ShadingPoint<V>,
    config: Config,
    samples: &mut S,
    visibility: &mut F,
) -> Estimate<V>
where
    V: Point3,
    V::Lane: DirectLane,
    B: Bsdf<V>,
    S: Samples<V::Vec2>,
    F: Visibility<V>,
{
    let mut e = Estimator::new(lights, bsdf, at, config, samples, visibility);
    let sum = match strategy {
        Strategy::UniformThetaPhi
        | Strategy::UniformHemisphere
        | Strategy::CosineHemisphere
        | Strategy::Bsdf => e.directions(strategy),
        Strategy::LightArea => e.light_area(),
        Strategy::LightSolidAngle => e.light_solid_angle(),
        Strategy::MisBalance | Strategy::MisPower => e.mis(strategy == Strategy::MisPower),
        Strategy::OneSampleMis => e.one_sample(),
        Strategy::OptimalMis => e.optimal(),
        Strategy::Ris => e.ris(),
    };
    let finite = sum.x.is_finite() & sum.y.is_finite() & sum.z.is_finite();
    let l = V3::select(e.valid & finite, sum, V3::all(V::Lane::ZERO));
    Estimate {
        radiance: V::from_lanes(l.canon()),
        shadow_rays: e.rays,
    }
}

/// The lights prepared at the shading point, each on first use.
type Cache<V> = [Option<PreparedLight<V>>; PREPARED_LIGHTS];

/// The state of one estimate: the frame, the prepared lights, and the counters.
struct Estimator<'a, 's, V: Point3, B, S, F> {
    lights: &'s Lights<'a>,
    bsdf: &'s B,
    p: V3<V::Lane>,
    frame: Frame<V3<V::Lane>>,
    /// ωo in the local frame.
    wo: V3<V::Lane>,
    /// n·ωo > 0 and finite input.
    valid: <V::Lane as Lane>::Mask,
    n_light: u32,
    n_bsdf: u32,
    tau: V::Lane,
    samples: &'s mut S,
    visibility: &'s mut F,
    cache: Cache<V>,
    /// Where a light beyond the cache is prepared for one use.
    spare: Option<PreparedLight<V>>,
    rays: u32,
}

/// A light sample as the estimator uses it: the direction, the unoccluded f·Le·cos θ, the pdf
/// including the light's selection probability, and the point the shadow ray goes to.
struct Sampled<L: Lane> {
    wi: V3<L>,
    fcos_le: V3<L>,
    pdf: L,
    to: V3<L>,
}

impl<'a, 's, V, L, B, S, F> Estimator<'a, 's, V, B, S, F>
where
    V: Point3<Lane = L>,
    L: DirectLane,
    B: Bsdf<V>,
    S: Samples<V::Vec2>,
    F: Visibility<V>,
{
    fn new(
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
            samples,
            visibility,
            cache: [None; PREPARED_LIGHTS],
            spare: None,
            rays: 0,
        }
    }

    fn u(&mut self, s: u32, pair: u32) -> V2<L> {
        self.samples.get(s, pair).to_lanes()
    }

    /// Light `j` prepared at the shading point, by reference: a prepared packet light is large
    /// (a triangle's is over a kilobyte), and it is read for every sample.
    fn prepared(&mut self, j: usize) -> &PreparedLight<V> {
        let p = V::from_lanes(self.p);
        // Out of range (never asked): a light that is on no direction.
        let dark = Light::Sphere(scene::SphereLight::new(Vec3::ZERO, 0.0, Vec3::ZERO));
        let light = self.lights.lights.get(j).copied().unwrap_or(dark);
        let prepare = || light.splat::<V>().at(p);
        match self.cache.get_mut(j) {
            Some(slot) => slot.get_or_insert_with(prepare),
            None => self.spare.insert(prepare()),
        }
    }

    /// For each light that some lane chose (`index`, a float), `f(self, j, lanes that chose j)`:
    /// one pass per distinct light, so that lanes may choose different lights.
    fn for_chosen(&mut self, index: L, mut f: impl FnMut(&mut Self, usize, L::Mask)) {
        for j in 0..self.lights.lights.len() {
            let m = index.eq(L::c(j as f64));
            if m.any() {
                f(self, j, m);
            }
        }
    }

    /// f·cos θ at world direction `wi` (0 below the horizon).
    fn fcos(&self, wi: V3<L>) -> V3<L> {
        self.fcos_local(self.frame.to_local(wi))
    }

    /// f·cos θ at local direction `wl`.
    fn fcos_local(&self, wl: V3<L>) -> V3<L> {
        let f = self.bsdf.eval(V::from_lanes(self.wo), V::from_lanes(wl));
        f.to_lanes().scale(wl.z.max(L::ZERO))
    }

    /// The BSDF's pdf at world direction `wi`.
    fn bsdf_pdf(&self, wi: V3<L>) -> L {
        let wl = self.frame.to_local(wi);
        self.bsdf.pdf(V::from_lanes(self.wo), V::from_lanes(wl))
    }

    /// Each lane's light choice from u: the index (as a float, exact below 2²⁴) and its
    /// probability.
    fn choose(&self, u: L) -> (L, L) {
        let mut pmf = [0.0f32; 8];
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
    fn shadow(&mut self, c: V3<L>, to: V3<L>, ru: L) -> V3<L> {
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
    fn light_sample(&mut self, s: u32) -> Sampled<L> {
        let (u, v) = (self.u(s, 0), self.u(s, 1));
        self.light_sample_with(u, v.x)
    }

    /// Σⱼ over the lights along world direction `wi`: weight(pmfⱼ·pdfⱼ)·fcos·Leⱼ behind a shadow
    /// ray each, with roulette from `ru`.
    fn along(&mut self, wi: V3<L>, fcos: V3<L>, ru: L, weight: impl Fn(L) -> L) -> V3<L> {
        let mut sum = V3::all(L::ZERO);
        if !(luminance(fcos).gt(L::ZERO)).any() {
            return sum;
        }
        let wv = V::from_lanes(wi);
        for j in 0..self.lights.lights.len() {
            let pmf = L::c(f64::from(self.lights.pmf(j)));
            let l = self.prepared(j);
            let (pdf, t) = l.pdf_hit(wv);
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

    /// The direction strategies: each sample a direction from the hemisphere or the BSDF, and
    /// every light along it.
    fn directions(&mut self, strategy: Strategy) -> V3<L> {
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
            sum = sum + self.along(wi, fcos, ru, |_| L::ONE);
        }
        sum.scale(L::ONE / L::c(f64::from(n.max(1))))
    }

    /// Light sampling in solid angle: f·Le·cos θ/(pmf·pdf) per sample.
    fn light_solid_angle(&mut self) -> V3<L> {
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
    fn light_area(&mut self) -> V3<L> {
        let n = self.n_light + self.n_bsdf;
        let mut sum = V3::all(L::ZERO);
        let p = V::from_lanes(self.p);
        for s in 0..n {
            let (u, v) = (self.u(s, 0), self.u(s, 1));
            let (index, pmf) = self.choose(v.x);
            let zero = V3::all(L::ZERO);
            let (mut x, mut nl, mut le, mut pdf) = (zero, zero, zero, L::ZERO);
            let (lights, u) = (self.lights.lights, V::Vec2::from_lanes(u));
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
    fn mis(&mut self, power: bool) -> V3<L> {
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
            bsdf = bsdf + self.along(wi, fcos, ru, |pl| w(nb, nl, pb, pl) / pb);
        }
        per_count(light, self.n_light) + per_count(bsdf, self.n_bsdf)
    }

    /// A BSDF sample from sample `s`: the world direction, f·cos θ and the pdf.
    fn bsdf_sample(&mut self, s: u32) -> (V3<L>, V3<L>, L) {
        let u = self.u(s, 0);
        self.bsdf_sample_with(u)
    }

    /// One-sample MIS: technique chosen by pair 1's x with probabilities ∝ (n_light, n_bsdf),
    /// weighted by the balance heuristic, so each sample is f/(c_l·p_l + c_b·p_b).
    fn one_sample(&mut self) -> V3<L> {
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
                c = c + self.along(wi, fcos, v.y, |pl| L::ONE / cl.mul_add(pl, cb * pb));
            }
            sum = sum + c;
        }
        sum.scale(L::ONE / L::c(total))
    }

    /// [`light_sample`](Self::light_sample) from given u: the direction pair and the choice u.
    fn light_sample_with(&mut self, u: V2<L>, choice: L) -> Sampled<L> {
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
    fn bsdf_sample_with(&mut self, u: V2<L>) -> (V3<L>, V3<L>, L) {
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
    fn optimal(&mut self) -> V3<L> {
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
        // Per half, one accumulator per colour channel.
        let [mut acc0, mut acc1] = [0, 1].map(|k| {
            let (a, b) = fold_counts(k);
            [L::optimal(a, b); 3]
        });
        let push = |acc: &mut [L::Optimal; 3], f: V3<L>, pl: L, pb: L| {
            for (a, f) in acc.iter_mut().zip([f.x, f.y, f.z]) {
                L::optimal_push(a, f, pl, pb);
            }
        };
        let second = |j: u32| cross && j % 2 == 1;
        let (cl, cb) = (L::c(f64::from(nl)), L::c(f64::from(nb)));
        for s in 0..nl {
            let x = self.light_sample(s);
            let ru = self.u(s, 1).y;
            let pb = self.bsdf_pdf(x.wi);
            // Roulette by the balance-weighted contribution; the accumulator takes f itself.
            let w = mis::balance(cl, x.pdf, cb, pb);
            let kept = self.shadow(x.fcos_le.scale(w), x.to, ru);
            let f = V3::select(w.gt(L::ZERO), scale_div(kept, w), V3::all(L::ZERO));
            push(if second(s) { &mut acc1 } else { &mut acc0 }, f, x.pdf, pb);
        }
        for j in 0..nb {
            let s = nl + j;
            let (wi, fcos, pb) = self.bsdf_sample(s);
            let ru = self.u(s, 1).y;
            // The light technique's density along wi: Σⱼ pmfⱼ·pdfⱼ over the lights it meets.
            let mut pl = L::ZERO;
            for l in 0..self.lights.lights.len() {
                let pdf = self.prepared(l).pdf(V::from_lanes(wi));
                pl = pdf.mul_add(L::c(f64::from(self.lights.pmf(l))), pl);
            }
            let w = mis::balance(cb, pb, cl, pl);
            let kept = self.along(wi, fcos, ru, |_| w / pb);
            let f = V3::select(w.gt(L::ZERO), scale_div(kept, w / pb), V3::all(L::ZERO));
            push(if second(j) { &mut acc1 } else { &mut acc0 }, f, pl, pb);
        }
        let est = |a: &L::Optimal, b: &L::Optimal| {
            if cross {
                L::optimal_cross(a, b)
            } else {
                L::optimal_balance(a)
            }
        };
        let ([x0, x1, x2], [y0, y1, y2]) = (&acc0, &acc1);
        V3::new(est(x0, y0), est(x1, y1), est(x2, y2))
    }

    /// RIS: N light-sampled candidates with target p̂ = luminance(f·Le·cos θ), one kept, one
    /// shadow ray.
    fn ris(&mut self) -> V3<L> {
        let n = self.n_light + self.n_bsdf;
        let u = self.u(0, 2).x;
        let mut res: [Reservoir<u32>; 8] = core::array::from_fn(|i| Reservoir::new(u.lane(i)));
        let zero = V3::all(L::ZERO);
        let (mut c, mut to) = (zero, zero);
        for s in 0..n {
            let x = self.light_sample(s);
            let target = luminance(x.fcos_le);
            let mut kept = [0.0f32; 8];
            for (i, (r, k)) in res.iter_mut().zip(&mut kept).enumerate().take(L::WIDTH) {
                r.push(s, f64::from(target.lane(i)), f64::from(x.pdf.lane(i)));
                // The reservoir holds candidate s only if it has just taken it.
                *k = if r.chosen().is_some_and(|(y, _)| y == s) {
                    1.0
                } else {
                    0.0
                };
            }
            let m = L::from_fn(|i| lane_of(&kept, i)).gt(L::ZERO);
            c = V3::select(m, x.fcos_le, c);
            to = V3::select(m, x.to, to);
        }
        // The RIS weight Σw/(M·p̂(y)): 0 where no candidate had weight.
        let w = L::from_fn(|i| lane_of(&res, i).chosen().map_or(0.0, |(_, w)| w as f32));
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

/// The component-wise product.
#[inline(always)]
fn mul<L: Lane>(a: V3<L>, b: V3<L>) -> V3<L> {
    V3::new(a.x * b.x, a.y * b.y, a.z * b.z)
}

/// v/w (w > 0 where used).
#[inline(always)]
fn scale_div<L: Lane>(v: V3<L>, w: L) -> V3<L> {
    v.scale(L::ONE / w)
}

/// A sum over `n` samples divided by n; 0 for none.
#[inline(always)]
fn per_count<L: Lane>(sum: V3<L>, n: u32) -> V3<L> {
    if n == 0 {
        V3::all(L::ZERO)
    } else {
        sum.scale(L::ONE / L::c(f64::from(n)))
    }
}
