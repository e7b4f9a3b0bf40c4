//! The error table of `mcsample::math`, measured against f64 std, plus special values and the
//! bit-for-bit agreement of the scalar and packet forms.
//!
//! [`TABLE`] is a copy of the table in the rustdoc of `src/math/mod.rs`: every test asserts that
//! the error it measures stays within the documented bound, so a wrong table fails here.
//!
//! ulp error = |f32 result − f64 reference| / ulp(reference rounded to f32), where ulp(v) =
//! 2^(e − 23) for v in [2^e, 2^(e+1)) and 2^-149 below 2^-126. It is relative everywhere, also at
//! the zeros of sin and cos: the f32 result must carry the tiny value, not an absolute error. A
//! result equal to the rounded reference counts 0 (this is how ±∞ and ±0 compare; the sign of
//! zero and the exact specials are checked separately).
//!
//! `cargo test --test all math::` measures 2^24 points per function. `cargo test --test all math:: --
//! --ignored` runs the exhaustive sweeps (every f32 of each domain; a few minutes) that the
//! documented maxima come from.

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4};

use crate::common::TestRng;
use mcsample::math::Math;
use mcsample::x8::F32x8;

// ---------------------------------------------------------------------------------------------
// The documented table (copied from src/math/mod.rs): (name, max ulp default build, max ulp
// with `-C target-feature=+avx2,+fma`).

const TABLE: &[(&str, f64, f64)] = &[
    ("sin", 1.47, 1.21),
    ("cos", 1.46, 1.21),
    ("sin_2pi", 1.68, 1.00),
    ("cos_2pi", 1.65, 0.88),
    ("sin_pi4", 1.68, 1.00),
    ("cos_pi4", 1.13, 0.88),
    ("atan2", 1.60, 1.60),
    ("asin", 1.94, 1.90),
    ("acos", 1.14, 1.12),
    ("ln", 1.02, 0.99),
    ("ln_1p", 1.07, 1.06),
    ("exp", 1.01, 1.04),
    ("exp_m1", 1.35, 1.33),
];

/// The domain of the sin_cos bound: |x| ≤ SIN_COS_DOMAIN (quadrant index j < 2¹²).
const SIN_COS_DOMAIN: f32 = 6433.0;
/// Beyond it, up to 2^22: absolute error ≤ SIN_COS_BEYOND · |x| · 2^-24.
const SIN_COS_BEYOND: f64 = 1.0;

/// Whether `mul_add` is fused in this build: x86 with the `fma` feature, and every aarch64 build
/// (NEON's `fmla` is part of the base architecture, and `wide` uses it). With every other
/// operation IEEE-exact, an aarch64 build computes what the x86 FMA build does, bit for bit, so
/// it shares that column.
const FMA: bool = cfg!(any(target_feature = "fma", target_arch = "aarch64"));

fn bound(name: &str) -> f64 {
    let row = TABLE
        .iter()
        .find(|r| r.0 == name)
        .unwrap_or_else(|| panic!("{name} missing from TABLE"));
    if FMA { row.2 } else { row.1 }
}

// ---------------------------------------------------------------------------------------------
// Measuring

fn ulp_of(v: f32) -> f64 {
    let b = v.to_bits() & 0x7fff_ffff;
    let e = ((b >> 23) as i32).max(1) - 127;
    2f64.powi(e - 23)
}

fn ulp_err(got: f32, want: f64) -> f64 {
    if got.is_nan() || want.is_nan() {
        return if got.is_nan() && want.is_nan() {
            0.0
        } else {
            f64::INFINITY
        };
    }
    let w32 = want as f32;
    if got == w32 {
        return 0.0;
    }
    if got.is_infinite() {
        return f64::INFINITY;
    }
    let m = if w32.is_infinite() { f32::MAX } else { w32 };
    (got as f64 - want).abs() / ulp_of(m)
}

/// Max error and where, for one output.
#[derive(Clone, Copy, Debug)]
struct Worst {
    err: f64,
    at: (f32, f32),
}

impl Worst {
    const NONE: Worst = Worst {
        err: 0.0,
        at: (0.0, 0.0),
    };
    fn add(&mut self, err: f64, at: (f32, f32)) {
        if err > self.err || err.is_nan() {
            *self = Worst { err, at };
        }
    }
    fn merge(self, o: Worst) -> Worst {
        if o.err > self.err { o } else { self }
    }
}

fn check(name: &str, w: Worst, points: u64) {
    let b = bound(name);
    println!(
        "{name:8} {points:>11} points: max {:.4} ulp at {:e}, {:e} ({:#010x}); documented {b} ({})",
        w.err,
        w.at.0,
        w.at.1,
        w.at.0.to_bits(),
        if FMA { "fma" } else { "default" }
    );
    assert!(
        w.err <= b,
        "{name}: measured {} ulp at ({:e}, {:e}) > documented {b}",
        w.err,
        w.at.0,
        w.at.1
    );
}

/// Uniform in value over [lo, hi].
fn uniform(rng: &mut TestRng, lo: f32, hi: f32) -> f32 {
    rng.range(lo as f64, hi as f64) as f32
}

/// Uniform over the f32 bit patterns in [lo, hi] (so uniform per binade, log-like), either sign
/// when `lo < 0 < hi`.
fn bits(rng: &mut TestRng, lo: f32, hi: f32) -> f32 {
    loop {
        let neg = rng.next_u32() & 1 == 1;
        let (a, b) = if neg { (pz(-hi), -lo) } else { (pz(lo), hi) };
        if b.is_nan() || b <= 0.0 {
            continue;
        }
        let (ba, bb) = (a.to_bits() as u64, b.to_bits() as u64);
        let v = f32::from_bits((ba + rng.next_u64() % (bb - ba + 1)) as u32);
        return if neg { -v } else { v };
    }
}

/// x if positive, else +0 (never −0, whose bits would be huge).
fn pz(x: f32) -> f32 {
    if x > 0.0 { x } else { 0.0 }
}

/// `n` points spread evenly over the bit patterns of [lo, hi] (both signs if lo < 0 < hi).
fn sweep(lo: f32, hi: f32, n: u64) -> impl Iterator<Item = f32> {
    let pos = (pz(lo), pz(hi));
    let neg = (pz(-hi), pz(-lo));
    let span = |(a, b): (f32, f32)| {
        if b > a || (b == a && b != 0.0) {
            (b.to_bits() - a.to_bits()) as u64 + 1
        } else {
            0
        }
    };
    let (sp, sn) = (span(pos), span(neg));
    let np = (n * sp).checked_div(sp + sn).unwrap_or(0);
    let nn = n - np;
    let make = move |(a, _): (f32, f32), s: u64, k: u64, sign: f32| {
        (0..k).map(move |i| {
            let off = if k > 1 { i * (s - 1) / (k - 1) } else { 0 };
            sign * f32::from_bits(a.to_bits() + off as u32)
        })
    };
    make(pos, sp, np.min(sp), 1.0).chain(make(neg, sn, nn.min(sn), -1.0))
}

/// Runs `body` over `n` points on both cores, each thread with its own seed.
fn par<F>(n: u64, body: F) -> Vec<Worst>
where
    F: Fn(u64, u64, &mut TestRng) -> Vec<Worst> + Sync,
{
    let threads = 2u64;
    std::thread::scope(|s| {
        let hs: Vec<_> = (0..threads)
            .map(|t| {
                let body = &body;
                s.spawn(move || {
                    let mut rng = TestRng::new(0x5eed_0000 + t);
                    body(t, n / threads, &mut rng)
                })
            })
            .collect();
        let res: Vec<Vec<Worst>> = hs.into_iter().map(|h| h.join().unwrap()).collect();
        (0..res[0].len())
            .map(|i| res.iter().fold(Worst::NONE, |m, r| m.merge(r[i])))
            .collect()
    })
}

// ---------------------------------------------------------------------------------------------
// References

fn ref_2pi(u: f32) -> (f64, f64) {
    // Exact reduction in u (as the f32 code does), then sin/cos of (π/2)·f, |f| ≤ ½.
    let u = u as f64;
    let r = u - u.round_ties_even();
    let q = (4.0 * r).round_ties_even();
    let (s, c) = (FRAC_PI_2 * (4.0 * r - q)).sin_cos();
    match q as i32 {
        0 => (s, c),
        1 => (c, -s),
        -1 => (-c, s),
        _ => (-s, -c),
    }
}

// ---------------------------------------------------------------------------------------------
// Point sets. Each function gets N points: half a sweep over the bit patterns of its domain,
// half random (uniform in value and uniform in bit pattern), plus the function's hard cases.

const N_FULL: u64 = 1 << 24;

/// f32 neighbours (±3 ulp) of j·π/2 for 1 ≤ j ≤ 4095: the hardest inputs for the reduction.
fn near_half_pi_multiples() -> Vec<f32> {
    let mut v = Vec::new();
    for j in 1..4096u32 {
        let c = (j as f64 * FRAC_PI_2) as f32;
        for d in -3i32..=3 {
            let x = f32::from_bits((c.to_bits() as i32 + d) as u32);
            v.push(x);
            v.push(-x);
        }
    }
    v
}

fn unary_points(
    t: u64,
    n: u64,
    rng: &mut TestRng,
    lo: f32,
    hi: f32,
    extra: &[(f32, f32)],
) -> Vec<f32> {
    // The sweep is split between the threads by parity.
    let mut v: Vec<f32> = sweep(lo, hi, n)
        .enumerate()
        .filter(|(i, _)| *i as u64 % 2 == t)
        .map(|(_, x)| x)
        .collect();
    let nr = n / 2;
    let groups = 2 + extra.len() as u64;
    for i in 0..nr {
        let x = match i % groups {
            0 => uniform(rng, lo, hi),
            1 => bits(rng, lo, hi),
            k => {
                let (a, b) = extra[(k - 2) as usize];
                uniform(rng, a, b)
            }
        };
        v.push(x);
    }
    v
}

// ---------------------------------------------------------------------------------------------
// The table, one test per function

#[test]
fn ulp_sin_cos() {
    let hard = near_half_pi_multiples();
    let d = SIN_COS_DOMAIN;
    let w = par(N_FULL, |t, n, rng| {
        let mut pts = unary_points(t, n, rng, -d, d, &[(-7.0, 7.0)]);
        if t == 0 {
            pts.extend_from_slice(&hard);
        }
        let (mut ws, mut wc) = (Worst::NONE, Worst::NONE);
        for x in pts {
            let (s, c) = <f32 as Math>::sin_cos(x);
            let (rs, rc) = (x as f64).sin_cos();
            ws.add(ulp_err(s, rs), (x, 0.0));
            wc.add(ulp_err(c, rc), (x, 0.0));
        }
        vec![ws, wc]
    });
    check("sin", w[0], N_FULL);
    check("cos", w[1], N_FULL);
}

#[test]
fn ulp_sincos_2pi() {
    let w = par(N_FULL, |t, n, rng| {
        let mut pts = unary_points(
            t,
            n,
            rng,
            -16_777_216.0,
            16_777_216.0,
            &[(0.0, 1.0), (-4.0, 4.0)],
        );
        // Every multiple of 2^-12 in [-2, 2] (quarter turns and their neighbours included).
        if t == 0 {
            pts.extend((-8192..=8192).map(|i| i as f32 / 4096.0));
        }
        let (mut ws, mut wc) = (Worst::NONE, Worst::NONE);
        for u in pts {
            let (s, c) = <f32 as Math>::sincos_2pi(u);
            let (rs, rc) = ref_2pi(u);
            ws.add(ulp_err(s, rs), (u, 0.0));
            wc.add(ulp_err(c, rc), (u, 0.0));
        }
        vec![ws, wc]
    });
    check("sin_2pi", w[0], N_FULL);
    check("cos_2pi", w[1], N_FULL);
}

/// The warps' `sincos_2pi_unit` skips the turn reduction and rotates by q ∈ {0, …, 4} quarter
/// turns instead of q ∈ {−2, …, 2}; on [0, 1] it must be `sincos_2pi` bit for bit, signed zeros
/// included (at u = ½ the sine is +0, which a rotation by d·(|d| − 2) would turn into −0). Every
/// 61st f32 of [0, 1], every f32 within 4096 ulp of each eighth of a turn, and −0, in both
/// widths.
#[test]
fn sincos_2pi_unit_is_sincos_2pi_on_the_unit_interval() {
    let one = 1.0f32.to_bits();
    let mut pts: Vec<f32> = (0..=one).step_by(61).map(f32::from_bits).collect();
    for k in 0..=8u32 {
        let b = (k as f32 / 8.0).to_bits();
        pts.extend((b.saturating_sub(4096)..=(b + 4096).min(one)).map(f32::from_bits));
    }
    pts.push(-0.0);
    let bits = |(s, c): (f32, f32)| (s.to_bits(), c.to_bits());
    let mut bad = 0usize;
    for chunk in pts.chunks(8) {
        let mut xs = [0.0f32; 8];
        xs[..chunk.len()].copy_from_slice(chunk);
        let (s8, c8) = <F32x8 as Math>::sincos_2pi_unit(F32x8::new(xs));
        let (s8, c8) = (s8.to_array(), c8.to_array());
        for (i, &u) in chunk.iter().enumerate() {
            let want = bits(<f32 as Math>::sincos_2pi(u));
            let got = bits(<f32 as Math>::sincos_2pi_unit(u));
            if got != want || (s8[i].to_bits(), c8[i].to_bits()) != want {
                if bad < 5 {
                    eprintln!(
                        "u = {u:e}: unit {got:x?}, x8 {:x?}, general {want:x?}",
                        (s8[i].to_bits(), c8[i].to_bits())
                    );
                }
                bad += 1;
            }
        }
    }
    assert_eq!(bad, 0, "{bad} of {} points differ", pts.len());
}

#[test]
fn ulp_sincos_pi4() {
    let w = par(N_FULL, |t, n, rng| {
        let pts = unary_points(t, n, rng, -1.0, 1.0, &[]);
        let (mut ws, mut wc) = (Worst::NONE, Worst::NONE);
        for x in pts {
            let (s, c) = <f32 as Math>::sincos_pi4(x);
            let (rs, rc) = (FRAC_PI_4 * x as f64).sin_cos();
            ws.add(ulp_err(s, rs), (x, 0.0));
            wc.add(ulp_err(c, rc), (x, 0.0));
        }
        vec![ws, wc]
    });
    check("sin_pi4", w[0], N_FULL);
    check("cos_pi4", w[1], N_FULL);
}

fn atan2_points(n_total: u64) -> Worst {
    let w = par(n_total, |t, n, rng| {
        let mut w = Worst::NONE;
        let mut one = |y: f32, x: f32| {
            let a = <f32 as Math>::atan2(y, x);
            w.add(ulp_err(a, (y as f64).atan2(x as f64)), (y, x));
        };
        // Sweeps along the lines y = ±1 and x = ±1 (every ratio scale), split by parity.
        for (i, v) in sweep(-f32::MAX, f32::MAX, n / 4).enumerate() {
            if i as u64 % 2 == t {
                one(1.0, v);
                one(v, 1.0);
                one(-0.75, v);
                one(v, -0.75);
            }
        }
        for i in 0..n / 2 {
            match i % 3 {
                // Uniform angle, log-uniform radius over 2^±120.
                0 => {
                    let th = std::f64::consts::PI * (2.0 * rng.range(0.0, 1.0) - 1.0);
                    let rad = 2f64.powf(240.0 * rng.range(0.0, 1.0) - 120.0);
                    one((rad * th.sin()) as f32, (rad * th.cos()) as f32);
                }
                // Independent random bit patterns (any finite magnitudes).
                1 => one(
                    bits(rng, -f32::MAX, f32::MAX),
                    bits(rng, -f32::MAX, f32::MAX),
                ),
                // Near the diagonal and near tan(π/8), where the reductions switch.
                _ => {
                    let x = bits(rng, -1e30, 1e30);
                    let k = [1.0f32, 0.414_213_57, 2.414_213_6][rng.below(3) as usize];
                    let y = x * k * (1.0 + (rng.range(0.0, 1.0) as f32 - 0.5) * 1e-5);
                    one(y, x);
                }
            }
        }
        vec![w]
    });
    w[0]
}

#[test]
fn ulp_atan2() {
    check("atan2", atan2_points(N_FULL), N_FULL);
}

#[test]
#[ignore = "2^30 pairs: a minute or two"]
fn exhaustive_atan2_sampled() {
    check("atan2", atan2_points(1 << 30), 1 << 30);
}

#[test]
fn ulp_asin_acos() {
    let w = par(N_FULL, |t, n, rng| {
        let pts = unary_points(t, n, rng, -1.0, 1.0, &[(0.45, 0.6), (0.9, 1.0)]);
        let (mut ws, mut wc) = (Worst::NONE, Worst::NONE);
        for x in pts {
            ws.add(ulp_err(<f32 as Math>::asin(x), (x as f64).asin()), (x, 0.0));
            wc.add(ulp_err(<f32 as Math>::acos(x), (x as f64).acos()), (x, 0.0));
        }
        vec![ws, wc]
    });
    check("asin", w[0], N_FULL);
    check("acos", w[1], N_FULL);
}

#[test]
fn ulp_ln() {
    let w = par(N_FULL, |t, n, rng| {
        let pts = unary_points(t, n, rng, 0.0, f32::MAX, &[(0.5, 2.0), (0.0, 1e-37)]);
        let mut w = Worst::NONE;
        for x in pts {
            w.add(ulp_err(<f32 as Math>::ln(x), (x as f64).ln()), (x, 0.0));
        }
        vec![w]
    });
    check("ln", w[0], N_FULL);
}

#[test]
fn ulp_ln_1p() {
    let w = par(N_FULL, |t, n, rng| {
        let mut pts = unary_points(t, n, rng, -1.0, 1.0, &[(-1.0, 4.0), (-0.3, 0.42)]);
        pts.extend(unary_points(t, n / 4, rng, 0.0, f32::MAX, &[(1.0, 1e4)]));
        let mut w = Worst::NONE;
        for x in pts {
            w.add(
                ulp_err(<f32 as Math>::ln_1p(x), (x as f64).ln_1p()),
                (x, 0.0),
            );
        }
        vec![w]
    });
    check("ln_1p", w[0], N_FULL);
}

#[test]
fn ulp_exp() {
    let w = par(N_FULL, |t, n, rng| {
        let pts = unary_points(
            t,
            n,
            rng,
            -110.0,
            90.0,
            &[(-1.0, 1.0), (-104.0, -87.0), (87.0, 89.0)],
        );
        let mut w = Worst::NONE;
        for x in pts {
            w.add(ulp_err(<f32 as Math>::exp(x), (x as f64).exp()), (x, 0.0));
        }
        vec![w]
    });
    check("exp", w[0], N_FULL);
}

#[test]
fn ulp_exp_m1() {
    let w = par(N_FULL, |t, n, rng| {
        let pts = unary_points(
            t,
            n,
            rng,
            -40.0,
            90.0,
            &[(-1.0, 1.0), (-0.36, 0.36), (87.0, 89.0)],
        );
        let mut w = Worst::NONE;
        for x in pts {
            w.add(
                ulp_err(<f32 as Math>::exp_m1(x), (x as f64).exp_m1()),
                (x, 0.0),
            );
        }
        vec![w]
    });
    check("exp_m1", w[0], N_FULL);
}

// ---------------------------------------------------------------------------------------------
// Exhaustive sweeps (every f32 of the domain): where the documented maxima come from.

fn exhaustive<F>(lo: f32, hi: f32, outs: usize, f: F) -> Vec<Worst>
where
    F: Fn(f32) -> Vec<f64> + Sync,
{
    // f returns the ulp errors of its outputs.
    let parts: Vec<(u32, u32, f32)> = {
        let mut p = Vec::new();
        if hi >= 0.0 {
            p.push((pz(lo).to_bits(), hi.to_bits(), 1.0));
        }
        if lo < 0.0 {
            p.push((pz(-hi).to_bits(), (-lo).to_bits(), -1.0));
        }
        p
    };
    std::thread::scope(|s| {
        let hs: Vec<_> = (0..2u32)
            .map(|t| {
                let (f, parts) = (&f, &parts);
                s.spawn(move || {
                    let mut w = vec![Worst::NONE; outs];
                    for &(a, b, sign) in parts {
                        let mut i = a + t;
                        while i <= b {
                            let x = sign * f32::from_bits(i);
                            for (k, e) in f(x).into_iter().enumerate() {
                                w[k].add(e, (x, 0.0));
                            }
                            i += 2;
                        }
                    }
                    w
                })
            })
            .collect();
        let r: Vec<Vec<Worst>> = hs.into_iter().map(|h| h.join().unwrap()).collect();
        (0..outs).map(|k| r[0][k].merge(r[1][k])).collect()
    })
}

#[test]
#[ignore = "every f32 of the domains: several minutes"]
fn exhaustive_unary() {
    type Errors = Box<dyn Fn(f32) -> Vec<f64> + Sync>;
    let cases: Vec<(&str, f32, f32, Errors)> = vec![
        (
            "sin_cos",
            -SIN_COS_DOMAIN,
            SIN_COS_DOMAIN,
            Box::new(|x| {
                let (s, c) = <f32 as Math>::sin_cos(x);
                let (rs, rc) = (x as f64).sin_cos();
                vec![ulp_err(s, rs), ulp_err(c, rc)]
            }),
        ),
        (
            "sincos_2pi",
            -16_777_216.0,
            16_777_216.0,
            Box::new(|u| {
                let (s, c) = <f32 as Math>::sincos_2pi(u);
                let (rs, rc) = ref_2pi(u);
                vec![ulp_err(s, rs), ulp_err(c, rc)]
            }),
        ),
        (
            "sincos_pi4",
            -1.0,
            1.0,
            Box::new(|x| {
                let (s, c) = <f32 as Math>::sincos_pi4(x);
                let (rs, rc) = (FRAC_PI_4 * x as f64).sin_cos();
                vec![ulp_err(s, rs), ulp_err(c, rc)]
            }),
        ),
        (
            "asin_acos",
            -1.0,
            1.0,
            Box::new(|x| {
                vec![
                    ulp_err(<f32 as Math>::asin(x), (x as f64).asin()),
                    ulp_err(<f32 as Math>::acos(x), (x as f64).acos()),
                ]
            }),
        ),
        (
            "ln",
            0.0,
            f32::MAX,
            Box::new(|x| vec![ulp_err(<f32 as Math>::ln(x), (x as f64).ln())]),
        ),
        (
            "ln_1p",
            -1.0,
            f32::MAX,
            Box::new(|x| vec![ulp_err(<f32 as Math>::ln_1p(x), (x as f64).ln_1p())]),
        ),
        (
            "exp",
            -f32::MAX,
            f32::MAX,
            Box::new(|x| vec![ulp_err(<f32 as Math>::exp(x), (x as f64).exp())]),
        ),
        (
            "exp_m1",
            -f32::MAX,
            f32::MAX,
            Box::new(|x| vec![ulp_err(<f32 as Math>::exp_m1(x), (x as f64).exp_m1())]),
        ),
    ];
    let names: &[(&str, &[&str])] = &[
        ("sin_cos", &["sin", "cos"]),
        ("sincos_2pi", &["sin_2pi", "cos_2pi"]),
        ("sincos_pi4", &["sin_pi4", "cos_pi4"]),
        ("asin_acos", &["asin", "acos"]),
        ("ln", &["ln"]),
        ("ln_1p", &["ln_1p"]),
        ("exp", &["exp"]),
        ("exp_m1", &["exp_m1"]),
    ];
    let mut failed = Vec::new();
    for (case, lo, hi, f) in cases {
        let outs = names.iter().find(|n| n.0 == case).unwrap().1;
        let n = (pz(hi).to_bits() as u64) + (pz(-lo).to_bits() as u64);
        let w = exhaustive(lo, hi, outs.len(), f);
        for (k, name) in outs.iter().enumerate() {
            let b = bound(name);
            println!(
                "{name:8} all {n} f32 in [{lo:e}, {hi:e}]: max {:.4} ulp at {:e} ({:#010x}); documented {b}",
                w[k].err,
                w[k].at.0,
                w[k].at.0.to_bits()
            );
            if w[k].err > b {
                failed.push(*name);
            }
        }
    }
    assert!(failed.is_empty(), "above the documented bound: {failed:?}");
}

// ---------------------------------------------------------------------------------------------
// sin_cos beyond its domain: finite, bounded, and with an absolute error that grows like |x|·ε.

#[test]
fn sin_cos_beyond_domain() {
    let mut rng = TestRng::new(7);
    let mut worst: f64 = 0.0;
    for i in 0..(1u32 << 20) {
        let x = if i % 2 == 0 {
            bits(&mut rng, SIN_COS_DOMAIN, f32::MAX)
        } else {
            uniform(&mut rng, SIN_COS_DOMAIN, 4.2e6)
        };
        let x = if i % 4 < 2 { x } else { -x };
        let (s, c) = <f32 as Math>::sin_cos(x);
        assert!(
            s.is_finite() && c.is_finite() && s.abs() <= 1.0 && c.abs() <= 1.0,
            "x = {x:e}: ({s}, {c})"
        );
        if x.abs() <= 4_194_304.0 {
            // Absolute error, in units of |x|·2^-24 (half an ulp of x, the uncertainty of x itself).
            let (rs, rc) = (x as f64).sin_cos();
            let e = (s as f64 - rs).abs().max((c as f64 - rc).abs())
                / (x.abs() as f64 * 2f64.powi(-24));
            worst = worst.max(e);
        } else {
            assert!(
                same(c, 1.0) && s == 0.0 && same(s.signum(), x.signum()),
                "x = {x:e}: ({s}, {c})"
            );
        }
    }
    println!(
        "sin_cos for {SIN_COS_DOMAIN} < |x| <= 2^22: max abs error = {worst:.3e} · |x| · 2^-24"
    );
    assert!(worst <= SIN_COS_BEYOND, "{worst}");
}

// ---------------------------------------------------------------------------------------------
// Special values

fn same(a: f32, b: f32) -> bool {
    (a.is_nan() && b.is_nan()) || a.to_bits() == b.to_bits()
}

#[track_caller]
fn expect(what: &str, got: f32, want: f32) {
    assert!(
        same(got, want),
        "{what}: got {got:e} ({:#010x}), want {want:e} ({:#010x})",
        got.to_bits(),
        want.to_bits()
    );
}

/// Within the documented bound of `name` (for values that need not be correctly rounded).
#[track_caller]
fn near(what: &str, name: &str, got: f32, want: f64) {
    let e = ulp_err(got, want);
    assert!(
        e <= bound(name),
        "{what}: got {got:e}, want {want:e}: {e} ulp"
    );
}

const NAN: f32 = f32::NAN;
const INF: f32 = f32::INFINITY;
const MIN_SUB: f32 = 1e-45;

#[test]
fn specials_trig() {
    let sc = <f32 as Math>::sin_cos;
    for (x, s, c) in [
        (0.0, 0.0, 1.0),
        (-0.0, -0.0, 1.0),
        (MIN_SUB, MIN_SUB, 1.0),
        (-MIN_SUB, -MIN_SUB, 1.0),
        (1e-20, 1e-20, 1.0),
    ] {
        expect(&format!("sin {x:e}"), sc(x).0, s);
        expect(&format!("cos {x:e}"), sc(x).1, c);
    }
    for x in [NAN, INF, -INF] {
        expect("sin", sc(x).0, NAN);
        expect("cos", sc(x).1, NAN);
    }
    // Huge finite arguments: finite and in [−1, 1].
    for x in [1e7f32, 1e10, 3e38, f32::MAX, -f32::MAX, 8_388_609.0] {
        let (s, c) = sc(x);
        assert!(s.abs() <= 1.0 && c.abs() <= 1.0, "{x:e}: {s} {c}");
    }

    let s2 = <f32 as Math>::sincos_2pi;
    // Whole turns give exactly (0, 1); quarter turns exactly ±1 and 0 (+0).
    for u in [0.0f32, 1.0, -1.0, 2.0, 17.0, -1e6, 16_777_216.0, 3e38] {
        expect(&format!("sin2pi {u}"), s2(u).0, 0.0);
        expect(&format!("cos2pi {u}"), s2(u).1, 1.0);
    }
    for (u, s, c) in [
        (0.25f32, 1.0f32, 0.0f32),
        (0.5, 0.0, -1.0),
        (0.75, -1.0, 0.0),
        (-0.25, -1.0, 0.0),
        (-0.5, 0.0, -1.0),
        (-0.75, 1.0, 0.0),
        (1.25, 1.0, 0.0),
        (2.5, 0.0, -1.0),
        (8_388_607.5, 0.0, -1.0),
    ] {
        expect(&format!("sin2pi {u}"), s2(u).0, s);
        expect(&format!("cos2pi {u}"), s2(u).1, c);
    }
    // ±0 in gives +0 for sin (the exact reduction loses the sign of zero).
    expect("sin2pi -0", s2(-0.0).0, 0.0);
    expect("cos2pi -0", s2(-0.0).1, 1.0);
    // Symmetry: sin is odd and cos even in u, bit for bit.
    let mut rng = TestRng::new(3);
    for _ in 0..10000 {
        let u = bits(&mut rng, -1e7, 1e7);
        let (a, b) = (s2(u), s2(-u));
        assert!(same(a.0, -b.0) || (a.0 == 0.0 && b.0 == 0.0), "{u}");
        assert!(same(a.1, b.1), "{u}");
    }
    for u in [NAN, INF, -INF] {
        expect("sin2pi", s2(u).0, NAN);
        expect("cos2pi", s2(u).1, NAN);
    }

    let p4 = <f32 as Math>::sincos_pi4;
    expect("sinpi4 0", p4(0.0).0, 0.0);
    expect("sinpi4 -0", p4(-0.0).0, -0.0);
    expect("cospi4 0", p4(0.0).1, 1.0);
    expect("sinpi4 1", p4(1.0).0, std::f32::consts::FRAC_1_SQRT_2);
    expect("cospi4 1", p4(1.0).1, std::f32::consts::FRAC_1_SQRT_2);
    expect("sinpi4 -1", p4(-1.0).0, -std::f32::consts::FRAC_1_SQRT_2);
    expect("sinpi4 NaN", p4(NAN).0, NAN);
    expect("cospi4 NaN", p4(NAN).1, NAN);
}

#[test]
fn specials_atan2() {
    use std::f32::consts::{FRAC_PI_2 as H, FRAC_PI_4 as Q, PI};
    let a = <f32 as Math>::atan2;
    let q3 = (3.0 * std::f64::consts::FRAC_PI_4) as f32;
    let tiny = 1f64.atan2(f32::MAX as f64) as f32;
    let cases: &[(f32, f32, f32)] = &[
        (0.0, 0.0, 0.0),
        (-0.0, 0.0, -0.0),
        (0.0, -0.0, PI),
        (-0.0, -0.0, -PI),
        (0.0, 1.0, 0.0),
        (-0.0, 1.0, -0.0),
        (0.0, -1.0, PI),
        (-0.0, -1.0, -PI),
        (1.0, 0.0, H),
        (1.0, -0.0, H),
        (-1.0, 0.0, -H),
        (1.0, 1.0, Q),
        (-1.0, -1.0, -q3),
        (1.0, -1.0, q3),
        (INF, INF, Q),
        (-INF, INF, -Q),
        (INF, -INF, q3),
        (-INF, -INF, -q3),
        (INF, 1.0, H),
        (-INF, -1e30, -H),
        (1.0, INF, 0.0),
        (-1.0, INF, -0.0),
        (1.0, -INF, PI),
        (-1.0, -INF, -PI),
        (f32::MAX, f32::MAX, Q),
        (f32::MAX, -f32::MAX, q3),
        (MIN_SUB, MIN_SUB, Q),
        (MIN_SUB, -MIN_SUB, q3),
        (MIN_SUB, 1.0, MIN_SUB),
        (1.0, f32::MAX, tiny),
        (NAN, 1.0, NAN),
        (1.0, NAN, NAN),
        (NAN, NAN, NAN),
        (INF, NAN, NAN),
        (NAN, INF, NAN),
        (0.0, NAN, NAN),
    ];
    for &(y, x, want) in cases {
        expect(&format!("atan2({y:e}, {x:e})"), a(y, x), want);
    }
}

#[test]
fn specials_asin_acos() {
    use std::f32::consts::{FRAC_PI_2 as H, PI};
    let (asin, acos) = (<f32 as Math>::asin, <f32 as Math>::acos);
    for (x, s, c) in [
        (0.0f32, 0.0f32, H),
        (-0.0, -0.0, H),
        (1.0, H, 0.0),
        (-1.0, -H, PI),
        (MIN_SUB, MIN_SUB, H),
        (1e-30, 1e-30, H),
    ] {
        expect(&format!("asin {x:e}"), asin(x), s);
        expect(&format!("acos {x:e}"), acos(x), c);
    }
    for x in [0.5f32, -0.5, 0.999_999_94, -0.999_999_94] {
        near(&format!("asin {x}"), "asin", asin(x), (x as f64).asin());
        near(&format!("acos {x}"), "acos", acos(x), (x as f64).acos());
    }
    for x in [NAN, INF, -INF, 1.000_000_1, -1.000_000_1, 2.0, -3e38] {
        expect(&format!("asin {x:e}"), asin(x), NAN);
        expect(&format!("acos {x:e}"), acos(x), NAN);
    }
}

#[test]
fn specials_log() {
    let (ln, l1p) = (<f32 as Math>::ln, <f32 as Math>::ln_1p);
    for (x, want) in [
        (1.0f32, 0.0f32),
        (0.0, -INF),
        (-0.0, -INF),
        (INF, INF),
        (-INF, NAN),
        (-1.0, NAN),
        (-MIN_SUB, NAN),
        (NAN, NAN),
        (2.0, std::f32::consts::LN_2),
    ] {
        expect(&format!("ln {x:e}"), ln(x), want);
    }
    for x in [
        MIN_SUB,
        3e-39,
        f32::MIN_POSITIVE,
        0.999_999_94,
        1.000_000_1,
        f32::MAX,
    ] {
        near(&format!("ln {x:e}"), "ln", ln(x), (x as f64).ln());
    }
    for (x, want) in [
        (0.0f32, 0.0f32),
        (-0.0, -0.0),
        (-1.0, -INF),
        (-1.000_000_1, NAN),
        (-INF, NAN),
        (INF, INF),
        (NAN, NAN),
        (MIN_SUB, MIN_SUB),
        (-MIN_SUB, -MIN_SUB),
        (1e-30, 1e-30),
        (1.0, std::f32::consts::LN_2),
    ] {
        expect(&format!("ln_1p {x:e}"), l1p(x), want);
    }
    for x in [-0.999_999_94, -0.5, 3e-8, f32::MAX, 1e30] {
        near(&format!("ln_1p {x:e}"), "ln_1p", l1p(x), (x as f64).ln_1p());
    }
}

#[test]
fn specials_exp() {
    let (exp, em1) = (<f32 as Math>::exp, <f32 as Math>::exp_m1);
    for (x, want) in [
        (0.0f32, 1.0f32),
        (-0.0, 1.0),
        (INF, INF),
        (-INF, 0.0),
        (NAN, NAN),
        // ln(f32::MAX) = 88.722839: the last finite result and the first infinite one.
        (88.722_84, INF),
        (89.0, INF),
        (1e30, INF),
        // 0 below ln(2^-150) = -103.97208.
        (-103.98, 0.0),
        (-104.0, 0.0),
        (-1e30, 0.0),
    ] {
        expect(&format!("exp {x:e}"), exp(x), want);
    }
    assert!(exp(88.722_83).is_finite());
    // Around 1, the overflow threshold and the subnormal range (one rounding, measured in
    // units of 2^-149 there).
    for x in [1.0f32, 88.722_83, -87.33655, -100.0, -103.27893, -103.9] {
        near(&format!("exp {x:e}"), "exp", exp(x), (x as f64).exp());
    }
    for (x, want) in [
        (0.0f32, 0.0f32),
        (-0.0, -0.0),
        (MIN_SUB, MIN_SUB),
        (-MIN_SUB, -MIN_SUB),
        (1e-30, 1e-30),
        (INF, INF),
        (-INF, -1.0),
        (NAN, NAN),
        (-17.4, -1.0),
        (-1e30, -1.0),
        (88.722_84, INF),
        (1e30, INF),
    ] {
        expect(&format!("exp_m1 {x:e}"), em1(x), want);
    }
    for x in [
        88.722_83f32, 1e-7, -1e-7, 0.346_573_6, -0.346_573_6, 1.0, -1.0, -17.0,
    ] {
        near(
            &format!("exp_m1 {x:e}"),
            "exp_m1",
            em1(x),
            (x as f64).exp_m1(),
        );
    }
}

// ---------------------------------------------------------------------------------------------
// Scalar and packet agree bit for bit

fn interesting(rng: &mut TestRng, i: u32, lo: f32, hi: f32) -> f32 {
    const SPECIAL: [f32; 14] = [
        0.0,
        -0.0,
        1.0,
        -1.0,
        0.5,
        -0.5,
        NAN,
        INF,
        -INF,
        MIN_SUB,
        -MIN_SUB,
        f32::MAX,
        -f32::MAX,
        f32::MIN_POSITIVE,
    ];
    match i % 8 {
        0 => SPECIAL[rng.below(SPECIAL.len() as u32) as usize],
        1 => f32::from_bits(rng.next_u32()),
        2 | 3 => bits(rng, lo, hi),
        _ => uniform(rng, lo, hi),
    }
}

fn lanes_unary(name: &str, lo: f32, hi: f32, f: fn(f32) -> f32, g: fn(F32x8) -> F32x8) {
    let mut rng = TestRng::new(0xb175 ^ name.len() as u64);
    for k in 0..(1u32 << 13) {
        let xs: [f32; 8] = std::array::from_fn(|i| interesting(&mut rng, k * 8 + i as u32, lo, hi));
        let v = g(F32x8::new(xs)).to_array();
        for i in 0..8 {
            let s = f(xs[i]);
            assert!(
                same(s, v[i]),
                "{name}({:e}): scalar {s:e} ({:#x}), lane {i} {:e} ({:#x})",
                xs[i],
                s.to_bits(),
                v[i],
                v[i].to_bits()
            );
        }
    }
}

#[test]
fn lanes_equal_scalar() {
    lanes_unary(
        "sin",
        -7000.0,
        7000.0,
        |x| <f32 as Math>::sin_cos(x).0,
        |x| Math::sin_cos(x).0,
    );
    lanes_unary(
        "cos",
        -7000.0,
        7000.0,
        |x| <f32 as Math>::sin_cos(x).1,
        |x| Math::sin_cos(x).1,
    );
    lanes_unary(
        "sin_2pi",
        -10.0,
        10.0,
        |x| <f32 as Math>::sincos_2pi(x).0,
        |x| Math::sincos_2pi(x).0,
    );
    lanes_unary(
        "cos_2pi",
        -10.0,
        10.0,
        |x| <f32 as Math>::sincos_2pi(x).1,
        |x| Math::sincos_2pi(x).1,
    );
    lanes_unary(
        "sin_pi4",
        -1.0,
        1.0,
        |x| <f32 as Math>::sincos_pi4(x).0,
        |x| Math::sincos_pi4(x).0,
    );
    lanes_unary(
        "cos_pi4",
        -1.0,
        1.0,
        |x| <f32 as Math>::sincos_pi4(x).1,
        |x| Math::sincos_pi4(x).1,
    );
    lanes_unary(
        "asin",
        -1.0,
        1.0,
        <f32 as Math>::asin,
        <F32x8 as Math>::asin,
    );
    lanes_unary(
        "acos",
        -1.0,
        1.0,
        <f32 as Math>::acos,
        <F32x8 as Math>::acos,
    );
    lanes_unary("ln", 0.0, f32::MAX, <f32 as Math>::ln, <F32x8 as Math>::ln);
    lanes_unary(
        "ln_1p",
        -1.0,
        1e6,
        <f32 as Math>::ln_1p,
        <F32x8 as Math>::ln_1p,
    );
    lanes_unary(
        "exp",
        -110.0,
        90.0,
        <f32 as Math>::exp,
        <F32x8 as Math>::exp,
    );
    lanes_unary(
        "exp_m1",
        -40.0,
        90.0,
        <f32 as Math>::exp_m1,
        <F32x8 as Math>::exp_m1,
    );

    let mut rng = TestRng::new(0xa7a2);
    for k in 0..(1u32 << 13) {
        let ys: [f32; 8] =
            std::array::from_fn(|i| interesting(&mut rng, k * 8 + i as u32, -1e3, 1e3));
        let xs: [f32; 8] =
            std::array::from_fn(|i| interesting(&mut rng, k * 8 + i as u32 + 3, -1e3, 1e3));
        let v = Math::atan2(F32x8::new(ys), F32x8::new(xs)).to_array();
        for i in 0..8 {
            let s = <f32 as Math>::atan2(ys[i], xs[i]);
            assert!(
                same(s, v[i]),
                "atan2({:e}, {:e}): scalar {s:e}, lane {i} {:e}",
                ys[i],
                xs[i],
                v[i]
            );
        }
    }
}
