//! The direct-lighting estimator on arbitrary scenes: up to three lights of every kind with
//! arbitrary geometry and radiance (or lined up behind one another, overlapping in direction), any shading point, normal and ωo, Lambert or Phong, every
//! strategy in either light-sampling mode, small sample counts, any roulette threshold and
//! sequence seed. Invariants: no
//! panic; the radiance is finite, and ≥ 0 except for optimal MIS, whose weights can be negative
//! (reflectances in [0, 1], radiance ≥ 0); it is 0 when
//! n·ωo < 0; the shadow rays are within the strategy's budget; and the packet forms (the same
//! inputs in all eight or sixteen lanes) equal the scalar form bit for bit, with eight or
//! sixteen times the rays.

#![no_main]

use glam::Vec3;
use libfuzzer_sys::fuzz_target;
use mcsample::direct::{self, Config, Lights, ShadingPoint, Strategy};
use mcsample::seq::{Generator, Sequence};
use mcsample::scene::{
    DiskLight, Lambert, Light, LightSampling, Phong, RectangleLight, SphereLight, TriangleLight,
};
use mcsample::verify::direct::Material;
use mcsample::x8::{F32x8, U32x8, Vec3x8};
use mcsample::x16::{F32x16, U32x16, Vec3x16};

fn floats(data: &[u8]) -> [f32; 32] {
    let mut out = [0.0f32; 32];
    for (o, c) in out.iter_mut().zip(data.chunks_exact(4)) {
        *o = f32::from_le_bytes([c[0], c[1], c[2], c[3]]);
    }
    out
}

fuzz_target!(|data: &[u8]| {
    let (head, rest) = data.split_at(data.len().min(6));
    let byte = |i: usize| head.get(i).copied().unwrap_or(0);
    let f = floats(rest);
    let v = |i: usize| Vec3::new(f[i], f[i + 1], f[i + 2]);
    let le = v(21).abs();
    let kinds = byte(0);
    // With bit 1 of byte 1 the lights overlap in direction: light k stands at (1 + k) times the
    // first light's offset from the shading point, behind it.
    let overlap = byte(1) & 2 != 0;
    let mut lights = Vec::new();
    for k in 0..(kinds % 4) {
        let (mut a, b, c, r) = (v(9 + 3 * k as usize % 9), v(12), v(15), f[18]);
        if overlap {
            a = v(0) + (v(9) - v(0)) * (1.0 + f32::from(k));
        }
        lights.push(match (kinds >> (2 + 2 * k)) & 3 {
            0 => Light::from(SphereLight::new(a, r, le)),
            1 => Light::from(DiskLight::new(a, b, r, le)),
            2 => Light::from(TriangleLight::new(a, b, c, le)),
            _ => Light::from(RectangleLight::new(a, b, c - b * (c.dot(b) / b.length_squared()), le)),
        });
    }
    let at = ShadingPoint { p: v(0), n: v(3), wo: v(6) };
    let kd = f[24].abs().min(1.0);
    let ks = (1.0 - kd) * f[25].abs().min(1.0);
    let material = if byte(1) & 1 == 0 {
        Material::Lambert(Lambert::new(Vec3::splat(kd)))
    } else {
        Material::Phong(Phong::new(Vec3::splat(kd), Vec3::splat(ks), f[26]))
    };
    let strategy = Strategy::ALL[byte(2) as usize % Strategy::ALL.len()];
    // Up to 11 of each, so that optimal MIS's cross-fitted path (8 and more) is reached.
    // Every light-sampling mode, from the top bits of the strategy's byte.
    let sampling = LightSampling::ALL[usize::from(byte(2) >> 6) % LightSampling::ALL.len()];
    let config = Config::new(u32::from(byte(3) % 12), u32::from(byte(4) % 12))
        .with_roulette(f[27])
        .with_light_sampling(sampling);
    let seed = u32::from(byte(5));
    let lights_sel = Lights::uniform(&lights);

    let mut s = Sequence { first: f[28].to_bits(), seed, generator: Generator::Sobol };
    let mut vis = |_: Vec3, to: Vec3| to.x.to_bits() & 1 == 0;
    let e = direct::estimate(strategy, &lights_sel, &material, at, config, &mut s, &mut vis);
    let name = strategy.name();
    assert!(e.radiance.is_finite(), "{name}: {e:?}");
    // Optimal MIS's weights may be negative (its control variate), and so may one estimate.
    if strategy != Strategy::OptimalMis {
        assert!(e.radiance.min_element() >= 0.0, "{name}: {e:?}");
    }
    let n = at.n.normalize_or_zero();
    // Clearly below (the estimator normalises by its own, scale-robust route: at grazing
    // angles the two roundings may disagree on the sign).
    if n.dot(at.wo.normalize_or_zero()) < -1e-5 {
        assert_eq!(e.radiance, Vec3::ZERO, "{name}: n·wo ≤ 0 must give 0");
    }
    let samples = config.samples();
    let budget = match strategy {
        Strategy::Ris => 1,
        Strategy::LightArea | Strategy::LightSolidAngle => samples,
        _ => samples * lights.len() as u32,
    };
    assert!(e.shadow_rays <= budget, "{name}: {} rays, budget {budget}", e.shadow_rays);

    let at8 = ShadingPoint { p: Vec3x8::splat(at.p), n: Vec3x8::splat(at.n), wo: Vec3x8::splat(at.wo) };
    let mut s8 = Sequence { first: U32x8::splat(f[28].to_bits()), seed, generator: Generator::Sobol };
    let mut vis8 = |m: F32x8, _: Vec3x8, to: Vec3x8| {
        let bits = to.x.to_array().map(|x| if x.to_bits() & 1 == 0 { f32::from_bits(!0) } else { 0.0 });
        m & F32x8::new(bits)
    };
    let e8 = direct::estimate(strategy, &lights_sel, &material.splat(), at8, config, &mut s8, &mut vis8);
    for lane in e8.radiance.to_array() {
        assert_eq!(lane.to_array().map(f32::to_bits), e.radiance.to_array().map(f32::to_bits), "{name}: packet");
    }
    assert_eq!(e8.shadow_rays, 8 * e.shadow_rays, "{name}: packet rays");

    let at16 = ShadingPoint { p: Vec3x16::splat(at.p), n: Vec3x16::splat(at.n), wo: Vec3x16::splat(at.wo) };
    let mut s16 = Sequence { first: U32x16::splat(f[28].to_bits()), seed, generator: Generator::Sobol };
    let mut vis16 = |m: F32x16, _: Vec3x16, to: Vec3x16| {
        let bits = to.x.to_array().map(|x| if x.to_bits() & 1 == 0 { f32::from_bits(!0) } else { 0.0 });
        m & F32x16::new(bits)
    };
    let e16 = direct::estimate(strategy, &lights_sel, &material.splat(), at16, config, &mut s16, &mut vis16);
    for lane in e16.radiance.to_array() {
        assert_eq!(lane.to_array().map(f32::to_bits), e.radiance.to_array().map(f32::to_bits), "{name}: x16 packet");
    }
    assert_eq!(e16.shadow_rays, 16 * e.shadow_rays, "{name}: x16 packet rays");
});
