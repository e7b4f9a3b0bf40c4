//! Hard inputs of the estimators: MIS weights in ratio form at extreme pdfs (13) and with sample
//! counts (25), and Russian roulette with a continuation probability below its floor (18). One
//! test per case, which collects every sub-failure; the numbers are the crate's hard-case names.

use crate::common::hard_case;
use crate::common::*;
use mcsample::estimate::{self, MeanVar};
use mcsample::mis;
use mcsample::verify::mis1d::HEURISTICS;
use mcsample::x8::F32x8;
use mcsample::x16::F32x16;

hard_case!(
    case_13_power_and_balance_in_ratio_form_at_extreme_pdfs,
    "power(1e20, 1e20) = power(1e-25, 1e-25) = 0.5, power(∞, 1) = 1, power(0, 0) = 0; balance likewise; both widths",
    || {
        let inf = f32::INFINITY;
        let cases: [([f32; 4], f32); 5] = [
            ([1.0, 1e20, 1.0, 1e20], 0.5),
            ([1.0, 1e-25, 1.0, 1e-25], 0.5),
            ([1.0, inf, 1.0, 1.0], 1.0),
            ([1.0, 0.0, 1.0, 0.0], 0.0),
            ([1.0, 1.0, 1.0, 0.0], 1.0),
        ];
        let mut r = vec![];
        for (x, want) in cases {
            // Every heuristic (balance and power, and maximum and cutoff too), every width.
            for (name, f, f8, f16) in HEURISTICS {
                let w = f(x[0], x[1], x[2], x[3]);
                let [a, b, c, d] = x.map(F32x8::splat);
                let w8 = f8(a, b, c, d);
                let [a, b, c, d] = x.map(F32x16::splat);
                r.push(check(
                    f16(a, b, c, d)
                        .to_array()
                        .iter()
                        .all(|l| l.to_bits() == w.to_bits()),
                    || format!("{name}{x:?}: x16 packet against scalar {w}"),
                ));
                r.push(check(w == want, || {
                    format!("{name}{x:?} = {w}, want {want}")
                }));
                r.push(check(
                    w8.to_array().iter().all(|l| l.to_bits() == w.to_bits()),
                    || format!("{name}{x:?}: packet {w8:?} against scalar {w}"),
                ));
            }
        }
        collect(r)
    }
);

hard_case!(
    case_18_roulette_q_1e_6_is_clamped_and_stays_unbiased,
    "roulette with q = 1e-6 clamps to ROULETTE_Q_MIN; the mean over 1e6 trials matches no roulette within 4σ",
    || {
        let mut r = vec![];
        let w = estimate::roulette(1e-6f32, 0.0);
        r.push(check(w == 1.0 / estimate::ROULETTE_Q_MIN, || {
            format!("roulette(1e-6, 0) = {w}")
        }));
        let mut rng = TestRng::new(18);
        let (mut acc, mut control) = (MeanVar::new(), MeanVar::new());
        for _ in 0..1_000_000 {
            let f = rng.u01() as f64; // E[f] = ½ without roulette
            let w = f64::from(estimate::roulette(1e-6f32, rng.u01()));
            acc.push(w * f);
            // Negative control: the survivors unweighted (1 instead of 1/q), biased by q.
            control.push(if w > 0.0 { f } else { 0.0 });
        }
        r.push(check(
            (acc.mean() - 0.5).abs() < 4.0 * acc.std_error(),
            || format!("mean {} ± {} against 0.5", acc.mean(), acc.std_error()),
        ));
        r.push(check(
            (control.mean() - 0.5).abs() > 4.0 * control.std_error(),
            || format!("the unweighted control passed: {}", control.mean()),
        ));
        collect(r)
    }
);

hard_case!(
    case_25_mis_weights_carry_the_counts_and_a_zero_count_gets_weight_0,
    "n_light = 2, n_bsdf = 1: w_l + w_b = 1 with the counts inside; a technique with count 0 gets weight 0",
    || {
        let mut r = vec![];
        let (pl, pb) = (0.7f32, 0.7f32);
        for (name, h) in [
            ("balance", mis::balance as fn(f32, f32, f32, f32) -> f32),
            ("power", mis::power),
        ] {
            let (wl, wb) = (h(2.0, pl, 1.0, pb), h(1.0, pb, 2.0, pl));
            r.push(check((wl + wb - 1.0).abs() <= f32::EPSILON, || {
                format!("{name}: {wl} + {wb}")
            }));
            let want = if name == "balance" { 2.0 / 3.0 } else { 0.8 };
            r.push(check((wl as f64 - want).abs() < 1e-6, || {
                format!("{name}: w_l = {wl}, want {want}")
            }));
            r.push(check(h(0.0, pl, 1.0, pb) == 0.0, || {
                format!("{name}: count 0 gives {}", h(0.0, pl, 1.0, pb))
            }));
            r.push(check(h(1.0, pb, 0.0, pl) == 1.0, || {
                format!("{name}: against count 0 gives {}", h(1.0, pb, 0.0, pl))
            }));
        }
        collect(r)
    }
);
