//! The flash cost of one light with the direct estimator: a sphere light over a Lambert point,
//! one power-MIS estimate with PCG32 samples.

#![no_std]
#![no_main]

use core::hint::black_box as bb;
use cortex_m_rt::entry;
use glam::Vec3;
use mcsample::direct::{self, Config, Lights, ShadingPoint, Strategy};
use mcsample::scene::{Lambert, Light, SphereLight};

#[entry]
fn main() -> ! {
    let lights = [Light::from(SphereLight::new(
        bb(Vec3::new(1.0, 0.5, 3.0)),
        bb(0.7),
        Vec3::ONE,
    ))];
    let at = ShadingPoint {
        p: bb(Vec3::ZERO),
        n: Vec3::Z,
        wo: bb(Vec3::new(0.3, 0.1, 0.9)),
    };
    let mut rng = rand_pcg::Pcg32::new(bb(1), 7);
    let mut visible = |_: Vec3, _: Vec3| true;
    let e = direct::estimate(
        Strategy::MisPower,
        &Lights::uniform(&lights),
        &Lambert::new(Vec3::ONE),
        at,
        Config::new(1, 1),
        &mut rng,
        &mut visible,
    );
    mcsample_firmware::exit(bb(e.radiance.x) > 0.0)
}
