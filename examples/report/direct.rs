//! The direct-lighting table: every strategy of `mcsample::direct` on every scene of
//! `verify::direct` (analytic, quadrature, the lecture's 4 × 4 MIS grid), in each light-sampling
//! mode that changes the scene's lights, at N = 64 + 64
//! samples per estimate with independent samples and unit visibility. Per row: the mean, its
//! standard error and bias in σ, the relative RMSE of one estimate, the time per estimate (the
//! x8 path per lane, and the scalar path), the x16 path's throughput over the x8 path's, the
//! shadow rays, and the efficiency 1/(rel MSE × time) relative to the best single strategy of the
//! scene in any mode.

use std::hint::black_box;
use std::time::Instant;

use glam::Vec3;
use mcsample::direct::{self, Config as DirectConfig, ShadingPoint, Strategy};
use mcsample::scene::{LightSampling, Shape};
use mcsample::seq::{Generator, Sequence};
use mcsample::verify::direct::{
    DirectRun, DirectScene, analytic_scenes, grid_scenes, quadrature_scenes, run,
};
use mcsample::x8::{F32x8, U32x8, Vec3x8};
use mcsample::x16::{F32x16, U32x16, Vec3x16};

use crate::Config;

/// Samples per technique in one estimate.
pub const N: u32 = 64;

pub struct DirectRow {
    pub scene: String,
    pub strategy: &'static str,
    /// How the strategy's light samples were drawn ([`LightSampling::name`]).
    pub light_sampling: &'static str,
    pub reference: f64,
    pub run: DirectRun,
    /// x8 path, ns per estimate (per lane).
    pub ns: f64,
    /// Scalar path, ns per estimate.
    pub scalar_ns: f64,
    /// The x16 path's estimates per second over the x8 path's, timed as their own pair.
    pub x16_vs_x8: f64,
    /// 1/(rel MSE × ns).
    pub efficiency: f64,
    /// Efficiency over the best single strategy's of the same scene.
    pub vs_best_single: f64,
    /// Efficiency over the same strategy's on the same scene with lights sampled by solid
    /// angle.
    pub vs_solid_angle: f64,
}

impl DirectRow {
    /// (mean − reference)/stderr; `None` where every estimate was equal (no sample reached the
    /// light, so the standard error is 0 and says nothing), or where the mean is the reference
    /// to the f32 estimates' rounding (1e-5: the estimator sums its N = 64 samples in f32, and
    /// equal terms round alike, by up to 64·2⁻²⁴ = 3.8e-6): a zero-variance estimator's (projected light
    /// sampling of a Lambertian receiver) standard error is that rounding, not a spread.
    pub fn bias_sigma(&self) -> Option<f64> {
        let exact = (self.run.mean - self.reference).abs() <= 1e-5 * self.reference.abs();
        (self.run.stderr > 0.0 && !exact).then(|| self.run.bias_sigma(self.reference))
    }
}

const SINGLE: [Strategy; 6] = [
    Strategy::UniformThetaPhi,
    Strategy::UniformHemisphere,
    Strategy::CosineHemisphere,
    Strategy::LightArea,
    Strategy::LightSolidAngle,
    Strategy::Bsdf,
];

/// The scalar path's ns per estimate over `count` estimates.
fn scalar_ns(scene: &DirectScene, strategy: Strategy, config: DirectConfig, count: u32) -> f64 {
    let mut table = Vec::new();
    let lights = scene.lights(&mut table);
    let mut visible = |from: Vec3, to: Vec3| scene.visible(from, to);
    let t = Instant::now();
    for e in 0..count {
        let mut s = Sequence {
            first: e * config.samples(),
            seed: 3,
            generator: Generator::Independent,
        };
        black_box(direct::estimate(
            strategy,
            &lights,
            &scene.material,
            black_box(scene.at),
            config,
            &mut s,
            &mut visible,
        ));
    }
    t.elapsed().as_secs_f64() * 1e9 / f64::from(count)
}

/// ns per estimate of the packet path of one width (`$f`, `$u`, `$v`: its lane, index lane and
/// vector), `count` estimates with unit visibility: the same loop for both widths.
macro_rules! packet_ns {
    ($name:ident, $n:literal, $f:ty, $u:ty, $v:ty) => {
        fn $name(scene: &DirectScene, strategy: Strategy, config: DirectConfig, count: u32) -> f64 {
            let mut table = Vec::new();
            let lights = scene.lights(&mut table);
            let material = scene.material.splat();
            let at = ShadingPoint {
                p: <$v>::splat(scene.at.p),
                n: <$v>::splat(scene.at.n),
                wo: <$v>::splat(scene.at.wo),
            };
            let mut visible = |m: $f, _: $v, _: $v| m;
            let t = Instant::now();
            for packet in 0..count.div_ceil($n) {
                let first = <$u>::new(core::array::from_fn(|i| {
                    (packet * $n + i as u32).wrapping_mul(config.samples())
                }));
                let mut s = Sequence {
                    first,
                    seed: 3,
                    generator: Generator::Independent,
                };
                black_box(direct::estimate(
                    strategy,
                    &lights,
                    &material,
                    black_box(at),
                    config,
                    &mut s,
                    &mut visible,
                ));
            }
            t.elapsed().as_secs_f64() * 1e9 / f64::from(count.div_ceil($n) * $n)
        }
    };
}
packet_ns!(x8_ns, 8, F32x8, U32x8, Vec3x8);
packet_ns!(x16_ns, 16, F32x16, U32x16, Vec3x16);

/// The x16 path's throughput over the x8 path's on the scenes without occluders (the packet
/// visibility here is unit), the two alternated over `rounds` and compared by their medians.
fn x16_vs_x8(scene: &DirectScene, strategy: Strategy, config: DirectConfig, count: u32) -> f64 {
    if !scene.occluders.is_empty() {
        return f64::NAN;
    }
    let (mut a, mut b) = (Vec::new(), Vec::new());
    for _ in 0..5 {
        a.push(x8_ns(scene, strategy, config, count));
        b.push(x16_ns(scene, strategy, config, count));
    }
    let med = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2]
    };
    med(&mut a) / med(&mut b)
}

/// The light-sampling modes that change `scene`: those of any of its lights, in the order of
/// [`LightSampling::ALL`].
fn modes(scene: &DirectScene) -> Vec<LightSampling> {
    LightSampling::ALL
        .into_iter()
        .filter(|m| scene.lights.iter().any(|l| l.shape.modes().contains(m)))
        .collect()
}

pub fn direct(cfg: &Config) -> Vec<DirectRow> {
    let estimates: u64 = if cfg.quick { 1024 } else { 4096 };
    let mut scenes = analytic_scenes();
    scenes.extend(quadrature_scenes());
    scenes.extend(grid_scenes());
    let mut rows = Vec::new();
    for (k, scene) in scenes.iter().enumerate() {
        let first = rows.len();
        let runs = modes(scene)
            .into_iter()
            .flat_map(|m| Strategy::ALL.map(|s| (m, s)));
        for (mode, strategy) in runs {
            let config = DirectConfig::new(N, N).with_light_sampling(mode);
            let t = Instant::now();
            let r = run(
                scene,
                strategy,
                config,
                estimates,
                (Generator::Independent, 1000 + k as u32),
            );
            let ns = t.elapsed().as_secs_f64() * 1e9 / r.estimates as f64;
            let scalar = scalar_ns(scene, strategy, config, (estimates / 8) as u32);
            let x16 = x16_vs_x8(scene, strategy, config, (estimates / 4) as u32);
            rows.push(DirectRow {
                scene: scene.name.clone(),
                strategy: strategy.name(),
                light_sampling: mode.name(),
                reference: scene.reference,
                efficiency: 1.0 / (r.rel_rmse * r.rel_rmse * ns),
                run: r,
                ns,
                scalar_ns: scalar,
                x16_vs_x8: x16,
                vs_best_single: 0.0,
                vs_solid_angle: 0.0,
            });
        }
        let best = rows[first..]
            .iter()
            .filter(|r| SINGLE.iter().any(|s| s.name() == r.strategy))
            .map(|r| r.efficiency)
            .filter(|e| e.is_finite())
            .fold(0.0, f64::max);
        let plain: Vec<(&'static str, f64)> = rows[first..]
            .iter()
            .filter(|r| r.light_sampling == LightSampling::SolidAngle.name())
            .map(|r| (r.strategy, r.efficiency))
            .collect();
        for r in &mut rows[first..] {
            r.vs_best_single = r.efficiency / best;
            let same = plain.iter().find(|(s, _)| *s == r.strategy);
            r.vs_solid_angle = same.map_or(f64::NAN, |(_, e)| r.efficiency / e);
        }
    }
    rows
}
