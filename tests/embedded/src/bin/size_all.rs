//! The flash cost of everything a renderer would call: every sampler of the registry (the warps,
//! the lights, the BSDFs) with its pdf and inverse, the sequences, the packet RNG and the MIS
//! weights, and the direct estimator with every strategy (chosen at run time) over every light
//! type and both BSDFs. No printing, unlike `check`.

#![no_std]
#![no_main]

use core::hint::black_box as bb;
use cortex_m_rt::entry;
use glam::{Vec2, Vec3};
use mcsample::direct::{self, Config, Lights, ShadingPoint, Strategy};
use mcsample::registry::Sampler;
use mcsample::rng::Pcg32x8;
use mcsample::scene::{
    DiskLight, Lambert, Light, Phong, RectangleLight, SphereLight, TriangleLight,
};
use mcsample::x8::Vec2x8;
use mcsample::{mis, seq, warp};

#[entry]
fn main() -> ! {
    let u = bb(Vec2::new(0.3, 0.7));
    let (a, b, c) = (bb(Vec3::new(-0.5, -0.4, 1.0)), bb(Vec3::X), bb(Vec3::Y));
    let mut acc = 0.0f32;
    // Every sampler of the registry: its sample, pdf and inverse.
    for s in Sampler::all() {
        let (w, pdf) = s.sample(u);
        acc += w.x + pdf + s.pdf(w) + s.inverse(w).y;
    }
    acc += warp::tent(u.x) + warp::cosine_hemisphere(Vec2x8::splat(u)).x.to_array()[bb(3)];
    let i = bb(17u32);
    acc += seq::sobol(i, 3, 7) + seq::cmj_2d(i, 8, 8, 0, 7).x + seq::stratified(i, 16, 3, 7);
    acc += Pcg32x8::new([1; 8], [2; 8]).next_f32x8().to_array()[bb(2)];
    acc += mis::power(1.0, acc, 1.0, 0.5) + mis::balance(1.0, acc, 1.0, 0.5);

    let lights = [
        Light::from(SphereLight::new(
            bb(Vec3::new(1.0, 0.5, 3.0)),
            bb(0.7),
            Vec3::ONE,
        )),
        Light::from(DiskLight::new(
            bb(Vec3::Z * 2.0),
            Vec3::NEG_Z,
            bb(1.5),
            Vec3::ONE,
        )),
        Light::from(TriangleLight::new(
            a + Vec3::Z,
            b + Vec3::Z,
            c + Vec3::Z,
            Vec3::ONE,
        )),
        Light::from(RectangleLight::new(a + Vec3::Z, b, c, Vec3::ONE)),
    ];
    let at = ShadingPoint {
        p: bb(Vec3::ZERO),
        n: Vec3::Z,
        wo: bb(Vec3::new(0.3, 0.1, 0.9)),
    };
    let mut rng = rand_pcg::Pcg32::new(bb(1), 7);
    let mut visible = |_: Vec3, _: Vec3| true;
    let strategy = Strategy::ALL[bb(5usize) % Strategy::ALL.len()];
    let lights = Lights::uniform(&lights);
    let config = Config::new(bb(2), 2);
    let e1 = direct::estimate(
        strategy,
        &lights,
        &Lambert::new(Vec3::ONE),
        at,
        config,
        &mut rng,
        &mut visible,
    );
    let phong = Phong::new(Vec3::splat(0.3), Vec3::splat(0.5), bb(20.0));
    let e2 = direct::estimate(
        strategy, &lights, &phong, at, config, &mut rng, &mut visible,
    );
    acc += e1.radiance.x + e2.radiance.y;
    mcsample_firmware::exit(bb(acc).is_finite())
}
