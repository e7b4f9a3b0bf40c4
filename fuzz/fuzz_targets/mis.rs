//! The MIS weights, one-sample MIS, optimal MIS and the RIS reservoir on arbitrary bit patterns
//! (NaN, ±∞, subnormals, negatives included): no panic; every heuristic weight in [0, 1] and never
//! NaN; the two weights of a pair summing to 1 within f32::EPSILON where either contribution is
//! positive and finite inputs; N-technique weights in [0, 1] summing to 1 or 0; the one-sample
//! choice a valid index with a rescaled u in [0, 1); the optimal-MIS estimate finite; and packet
//! lanes equal to the scalar form bit for bit.

#![no_main]

use libfuzzer_sys::fuzz_target;
use mcsample::lane::{F32x8, F32x16};
use mcsample::mis;
use mcsample::verify::mis1d::HEURISTICS;

fn floats(data: &[u8]) -> [f32; 16] {
    let mut out = [0f32; 16];
    for (o, c) in out.iter_mut().zip(data.chunks_exact(4)) {
        *o = f32::from_bits(u32::from_le_bytes([c[0], c[1], c[2], c[3]]));
    }
    out
}

fn weight(name: &str, w: f32) {
    assert!((0.0..=1.0).contains(&w), "{name}: weight {w}");
}


fuzz_target!(|data: &[u8]| {
    let x = floats(data);
    let (nf, pf, ng, pg, alpha) = (x[0], x[1], x[2], x[3], x[4]);
    let finite = x[..4].iter().all(|v| !v.is_nan());
    let positive = |n: f32, p: f32| n > 0.0 && p > 0.0;
    for (name, f, fx8, fx16) in HEURISTICS {
        let (wf, wg) = (f(nf, pf, ng, pg), f(ng, pg, nf, pf));
        weight(name, wf);
        weight(name, wg);
        if finite && (positive(nf, pf) || positive(ng, pg)) {
            assert!(((wf + wg) - 1.0).abs() <= f32::EPSILON, "{name}: {wf} + {wg}");
        }
        let s = F32x8::splat;
        let lanes = fx8(s(nf), s(pf), s(ng), s(pg)).to_array();
        assert!(lanes.iter().all(|l| l.to_bits() == wf.to_bits()), "{name}: lanes {lanes:?} against {wf}");
        let s = F32x16::splat;
        let lanes = fx16(s(nf), s(pf), s(ng), s(pg)).to_array();
        assert!(lanes.iter().all(|l| l.to_bits() == wf.to_bits()), "{name}: x16 lanes against {wf}");
    }
    weight("cutoff(α)", mis::cutoff(nf, pf, ng, pg, alpha));

    for w in [mis::balance_n([x[0], x[2], x[5]], [x[1], x[3], x[6]]), mis::power_n([x[0], x[2], x[5]], [x[1], x[3], x[6]])] {
        w.iter().for_each(|&v| weight("n-technique", v));
        let sum: f32 = w.iter().sum();
        assert!(sum == 0.0 || (sum - 1.0).abs() <= 4.0 * f32::EPSILON, "n-technique sum {sum}");
    }

    let c = [x[7], x[8], x[9]];
    let pick = mis::one_sample(c, x[10]);
    assert!(pick.index < 3);
    assert!((0.0..1.0).contains(&pick.u) || (pick.probability == 0.0 && pick.u == x[10]));
    weight("one-sample probability", pick.probability);
    let packet = mis::one_sample(c.map(F32x8::splat), F32x8::splat(x[10]));
    assert!(packet.index.to_array().iter().all(|&i| i == pick.index));
    assert!(packet.u.to_array().iter().all(|u| u.to_bits() == pick.u.to_bits()));
    let packet = mis::one_sample(c.map(F32x16::splat), F32x16::splat(x[10]));
    assert!(packet.index.to_array().iter().all(|&i| i == pick.index));
    assert!(packet.u.to_array().iter().all(|u| u.to_bits() == pick.u.to_bits()));

    let mut opt = mis::OptimalMis::new(f64::from(x[11]), f64::from(x[12]));
    let mut res = mis::Reservoir::new(f64::from(x[15]));
    for k in 0..4 {
        let (f, p1, p2) = (x[(13 + k) % 16], x[(14 + k) % 16], x[(k * 5) % 16]);
        opt.push(f64::from(f), f64::from(p1), f64::from(p2));
        res.push(k, f64::from(p1), f64::from(p2));
    }
    assert!(!opt.estimate().is_nan(), "optimal MIS: {}", opt.estimate());
    assert!(opt.alpha().is_none_or(|a| a.iter().all(|x| x.is_finite())));
    assert!(!opt.balance_estimate().is_nan());
    let (k, w) = res.chosen();
    assert!(k < 4 && w.is_finite() && w >= 0.0, "reservoir: {k} {w}");
});
