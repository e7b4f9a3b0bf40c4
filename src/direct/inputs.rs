//! What a caller passes to [`estimate`](super::estimate): the strategy, the sample counts, the
//! shading point, the lights and the visibility test; and the widths the estimator runs in.

use glam::Vec3;

use super::MAX_SAMPLES;
use crate::lane::{F32x8, F32x16, Lane, Lane32, Lanes, U32x8, U32x16};
use crate::math::Math;
use crate::mis::Candidate;
use crate::point::Point3;
use crate::scene::{Light, LightChoice, LightSampling, PowerTable};
use crate::x8::Vec3x8;
use crate::x16::Vec3x16;

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
    /// channel; the balance heuristic below [`OPTIMAL_MIN_SAMPLES`](super::OPTIMAL_MIN_SAMPLES) of either technique.
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
    /// How every strategy that samples a light by direction samples it (all but `light_area`,
    /// which samples points by area): by solid angle (the default), or through the bilinear
    /// cosine warp for the shading normal ([`LightSampling`]).
    pub light_sampling: LightSampling,
}

impl Config {
    /// `n_light` light and `n_bsdf` BSDF samples, no roulette.
    pub const fn new(n_light: u32, n_bsdf: u32) -> Self {
        Self {
            n_light,
            n_bsdf,
            roulette: 0.0,
            light_sampling: LightSampling::SolidAngle,
        }
    }

    /// The same counts, the lights sampled by `sampling`.
    pub const fn with_light_sampling(self, sampling: LightSampling) -> Self {
        Self {
            light_sampling: sampling,
            ..self
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
    pub(super) fn counts(&self) -> (u32, u32) {
        (self.n_light.min(MAX_SAMPLES), self.n_bsdf.min(MAX_SAMPLES))
    }

    /// N: the samples every strategy takes per estimate. A [`Sequence`](crate::seq::Sequence) should advance `first`
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

    pub(super) fn choose(&self, u: f32) -> LightChoice {
        match &self.table {
            Some(t) => t.select(u),
            None => LightChoice::uniform(self.lights.len(), u),
        }
    }

    pub(super) fn pmf(&self, index: usize) -> f32 {
        match &self.table {
            Some(t) => t.pmf(index),
            None => LightChoice::uniform(self.lights.len(), 0.0).pmf,
        }
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

/// The packet widths' visibility: the callback's mask, and-ed with the lanes that asked.
macro_rules! packet_visibility {
    ($($f:ty, $v:ty);*) => {$(
        impl<F: FnMut($f, $v, $v) -> $f> Visibility<$v> for F {
            #[inline]
            fn visible(&mut self, active: $f, from: $v, to: $v) -> $f {
                active & self(active, from, to)
            }
        }
    )*};
}
packet_visibility!(F32x8, Vec3x8; F32x16, Vec3x16);

mod sealed {
    pub trait Sealed {}
    impl Sealed for f32 {}
    impl Sealed for crate::lane::F32x8 {}
    impl Sealed for crate::lane::F32x16 {}
}

/// The widths the estimator runs in: `f32`, [`F32x8`] and [`F32x16`]. Per-lane work (the light choice) goes
/// through the lanes one at a time ([`Lanes`](crate::lane::Lanes)); the accumulators of optimal MIS and RIS sum in
/// the f64 lane of the same width ([`Widen`](crate::lane::Widen)).
pub trait DirectLane: Math + Lane32 + Lanes<Scalar = f32> + sealed::Sealed {
    /// The candidate index a RIS reservoir keeps per lane: `u32`, [`U32x8`] or [`U32x16`].
    type Index: Candidate<<Self::Wide as Lane>::Mask> + Default;
    /// Index `s` in every lane.
    fn index(s: u32) -> Self::Index;
    /// The number of lanes set in `m`.
    fn count(m: Self::Mask) -> u32;
}

impl DirectLane for f32 {
    type Index = u32;
    #[inline(always)]
    fn index(s: u32) -> u32 {
        s
    }
    #[inline(always)]
    fn count(m: bool) -> u32 {
        u32::from(m)
    }
}

/// The packet widths: a candidate index of the same width, and a mask's lane count.
macro_rules! packet_direct_lane {
    ($($f:ty, $u:ty);*) => {$(
        impl DirectLane for $f {
            type Index = $u;
            #[inline(always)]
            fn index(s: u32) -> $u {
                <$u>::splat(s)
            }
            #[inline(always)]
            fn count(m: $f) -> u32 {
                m.to_bitmask().count_ones()
            }
        }
    )*};
}
packet_direct_lane!(F32x8, U32x8; F32x16, U32x16);
