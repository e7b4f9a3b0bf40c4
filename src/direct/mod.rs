//! The direct-lighting estimator of "Monte Carlo II: Direct Illumination" (Pharr, CS348b): the
//! radiance a shading point reflects towards ωo from a slice of lights,
//!
//! L(x, ωo) = Σⱼ ∫ f(ωo, ωi) Leⱼ V(x, xⱼ(ωi)) cos θ dωi,
//!
//! by every strategy the lecture compares ([`Strategy`]), in every width: [`estimate`] on `Vec3`,
//! on [`Vec3x8`](crate::x8::Vec3x8) and on [`Vec3x16`](crate::x16::Vec3x16) (eight or sixteen
//! shading points, or estimates of one, in lock-step; lane *i* equals the scalar estimate of lane
//! *i*'s inputs bit for bit, given the same samples and visibility, and lanes may choose
//! different lights).
//!
//! # Inputs
//!
//! - a [`ShadingPoint`]: position, normal and ωo in world space (normal and ωo need not be unit;
//!   they are normalised);
//! - a BSDF ([`scene::Bsdf`](crate::scene::Bsdf): [`Lambert`](crate::scene::Lambert) or
//!   [`Phong`](crate::scene::Phong)), evaluated in the normal's [`Frame`](crate::frame::Frame);
//! - [`Lights`]: a borrowed slice of scalar lights, chosen uniformly or by a
//!   [`PowerTable`](crate::scene::PowerTable). Every lane of a packet sees the same lights;
//! - [`Samples`]: the u of sample s of the estimate, per pair of dimensions. [`Sequence`](crate::seq::Sequence) reads
//!   the stateless Owen-scrambled Sobol or independent generators of [`seq`](crate::seq) at index
//!   `first + s`; `rand_pcg::Pcg32`, [`Pcg32x8`](crate::rng::Pcg32x8) and
//!   [`Pcg32x16`](crate::rng::Pcg32x16) give their next values;
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
//! Each light is prepared at the shading point ([`Light::at`](crate::scene::Light::at)) once per estimate, so splitting
//! (N > 1) pays the set-up once; the first [`PREPARED_LIGHTS`] lights of the slice are kept
//! prepared, further ones are prepared at each use (the same numbers, more time). The
//! strategies that only trace directions (the hemispheres' and the BSDF's) prepare the lights by
//! area whatever [`Config::light_sampling`] says: they read only where their rays meet a light,
//! never its density, and the area mode has the least set-up.
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
//!
//! # Layout
//!
//! `inputs` holds what a caller passes (the strategy, the counts, the shading point, the lights
//! and the visibility test), `estimator` the state of one estimate and the steps every strategy
//! shares, `strategies` one method per strategy. The sample sources ([`Samples`],
//! [`Sequence`](crate::seq::Sequence)) live in [`seq`](crate::seq).

mod estimator;
mod inputs;
mod strategies;

pub use inputs::{Config, DirectLane, Estimate, Lights, ShadingPoint, Strategy, Visibility};

use crate::lane::{Lane, V3};
use crate::point::Point3;
use crate::scene::Bsdf;
use crate::seq::Samples;
use estimator::Estimator;

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
    let mut e = Estimator::new(strategy, lights, bsdf, at, config, samples, visibility);
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
