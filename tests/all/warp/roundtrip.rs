//! Inverse round trips: inverse(sample(u)) ≈ u for every sampler of the registry, at its
//! registered parameters and at the extremes of its parameter range, within the bound per
//! coordinate that the registry states (`Sampler::roundtrip_bound`).
//!
//! The azimuthal coordinate u₁ is periodic, so its error is taken modulo 1. Where the sample sits
//! at a pole of its parameterisation, one coordinate is not determined by the point and is not
//! compared (`Sampler::determined`): u₁ at the disk's centre or a lobe's axis, u₀ at the
//! spherical triangle's apex B (u₁ = 0).

use crate::common::{TestRng, random_inputs};
use glam::Vec2;
use mcsample::verify::registry::{self, Sampler};
use mcsample::warp;
use mcsample::warp::{PhongLobe, UniformCone};

const N: usize = 1 << 18;

fn us() -> Vec<Vec2> {
    let mut rng = TestRng::new(99);
    let mut v: Vec<Vec2> = (0..random_inputs(N)).map(|_| rng.u2()).collect();
    // The edges of the square, where the maps change branch.
    let edge = [0.0, 0.5, 1e-7, 0.25, 0.75, warp::ONE_MINUS_EPS];
    for &a in &edge {
        for k in 0..64 {
            let b = k as f32 / 64.0;
            v.push(Vec2::new(a, b));
            v.push(Vec2::new(b, a));
        }
    }
    v
}

fn periodic(d: f32) -> f32 {
    let d = d.abs();
    d.min(1.0 - d)
}

/// Runs the round trip of `s` over all u; the worst (u₀, u₁) errors against the registry's
/// bound, as a failure message.
fn measure(s: Sampler, us: &[Vec2]) -> Option<String> {
    let Some(bound) = s.roundtrip_bound() else {
        return Some(format!(
            "{}: an inverse without a round-trip bound",
            s.name()
        ));
    };
    let mut worst = (0.0f32, 0.0f32);
    let mut at = (Vec2::ZERO, Vec2::ZERO);
    for &u in us {
        let x = s.sample(u).0;
        let v = s.inverse(x);
        let [u0_defined, u1_defined] = s.determined(u, x);
        let e0 = if u0_defined { (v.x - u.x).abs() } else { 0.0 };
        let d1 = v.y - u.y;
        let e1 = if !u1_defined {
            0.0
        } else if s.u1_periodic() {
            periodic(d1)
        } else {
            d1.abs()
        };
        // NaN errors must fail: compare with negated ≤.
        if worse(e0, worst.0) {
            worst.0 = e0;
            at.0 = u;
        }
        if worse(e1, worst.1) {
            worst.1 = e1;
            at.1 = u;
        }
    }
    let name = s.name();
    println!(
        "{name:34} max |Δu₀| = {:.2e} at {:?}   max |Δu₁| = {:.2e} at {:?}",
        worst.0, at.0, worst.1, at.1
    );
    (worse(worst.0, bound[0]) || worse(worst.1, bound[1]))
        .then(|| format!("{name}: ({:e}, {:e}) exceeds {bound:?}", worst.0, worst.1))
}

#[test]
fn inverses_recover_u() {
    let us = us();
    let mut all = registry::registry();
    // The ends of the parameter ranges: the whole sphere and a pinpoint cone, the uniform
    // hemisphere and a needle lobe.
    all.extend([2.0, 1e-7].map(|h| Sampler::from(UniformCone { h })));
    all.extend([0.0, 1e6].map(|n| Sampler::from(PhongLobe { n })));
    // The lights and BSDFs have no inverse, and so no round-trip bound.
    let failures: Vec<String> = all
        .iter()
        .filter(|s| !s.has_inverse() && s.roundtrip_bound().is_some())
        .map(|s| format!("{}: a round-trip bound without an inverse", s.name()))
        .chain(
            all.iter()
                .filter(|s| s.has_inverse())
                .filter_map(|&s| measure(s, &us)),
        )
        .collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// True when `e` is a new worst error; NaN always is, so it cannot hide.
fn worse<T: PartialOrd>(e: T, current: T) -> bool {
    e.partial_cmp(&current) != Some(std::cmp::Ordering::Less)
        && e.partial_cmp(&current) != Some(std::cmp::Ordering::Equal)
}
