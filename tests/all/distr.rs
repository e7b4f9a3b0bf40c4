//! The `rand` feature: each distribution returns exactly the warp's value at the u it draws
//! (two `next_u32`, top 24 bits each), so the warp's pdf and inverse apply to its samples.

use glam::{Vec2, Vec3};
use mcsample::distr::{
    CosineHemisphere, PhongLobe, UniformCone, UniformHemisphere, UniformSphere, UnitDisk,
};
use mcsample::warp;
use rand::RngExt;
use rand_core::Rng;
use rand_pcg::Pcg32;

/// The u that the distributions draw, from a twin of the RNG.
fn u2(rng: &mut Pcg32) -> Vec2 {
    let unit = |x: u32| (x >> 8) as f32 / 16_777_216.0;
    let a = unit(rng.next_u32());
    Vec2::new(a, unit(rng.next_u32()))
}

#[test]
fn each_distribution_is_its_warp_at_the_drawn_u() {
    let (mut r, mut twin) = (Pcg32::new(3, 5), Pcg32::new(3, 5));
    for _ in 0..10_000 {
        let d: Vec2 = r.sample(UnitDisk);
        assert_eq!(d, warp::concentric_disk(u2(&mut twin)));
        let checks: [(Vec3, Vec3); 5] = [
            (
                r.sample(UniformHemisphere),
                warp::uniform_hemisphere(u2(&mut twin)),
            ),
            (
                r.sample(CosineHemisphere),
                warp::cosine_hemisphere(u2(&mut twin)),
            ),
            (r.sample(UniformSphere), warp::uniform_sphere(u2(&mut twin))),
            (
                r.sample(UniformCone { h: 0.2 }),
                warp::uniform_cone(u2(&mut twin), 0.2),
            ),
            (
                r.sample(PhongLobe { n: 30.0 }),
                warp::phong_lobe(u2(&mut twin), 30.0),
            ),
        ];
        for (got, want) in checks {
            assert_eq!(
                got.to_array().map(f32::to_bits),
                want.to_array().map(f32::to_bits)
            );
        }
    }
}
