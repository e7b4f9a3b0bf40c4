//! The estimators table: on `verify::mis1d`'s problems, the variance of every MIS heuristic, of
//! optimal MIS, one-sample MIS and RIS relative to the best single technique at equal sample
//! counts; and the time per MIS weight, scalar, x8 and x16.

use glam::Vec4;
use mcsample::lane::{F32x8, F32x16};
use mcsample::verify::mis1d::{self, ESTIMATORS, HEURISTICS, HeuristicX8, INTEGRANDS};

use crate::{Config, time_pair};

pub struct EstRow {
    pub integrand: &'static str,
    pub estimator: &'static str,
    pub variance: f64,
    pub vs_best_single: f64,
}

pub struct WeightRow {
    pub name: &'static str,
    pub scalar_ns: f64,
    pub x8_ns: f64,
    /// ns per weight of the 16-wide form, and its throughput over the 8-wide form's, from their
    /// own interleaved pair.
    pub x16_ns: f64,
    pub x16_vs_x8: f64,
}

/// Samples per technique in one estimate.
pub const N: usize = 4;

pub fn variances(cfg: &Config) -> Vec<EstRow> {
    let rounds = if cfg.quick { 20_000 } else { 200_000 };
    let mut rows = Vec::new();
    for (k, integrand) in INTEGRANDS.iter().enumerate() {
        let acc = mis1d::compare(integrand, N, rounds, 100 + k as u64);
        let best = acc[0].variance().min(acc[1].variance());
        for (estimator, a) in ESTIMATORS.iter().zip(&acc) {
            rows.push(EstRow {
                integrand: integrand.name,
                estimator,
                variance: a.variance(),
                vs_best_single: a.variance() / best,
            });
        }
    }
    rows
}

pub fn weight_times(cfg: &Config) -> Vec<WeightRow> {
    // (n_f, pdf_f, n_g, pdf_g) with pdfs spread over twelve decades.
    let mut state = 0x2545_f491_u32;
    let mut next = move || {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        state
    };
    let quads: Vec<Vec4> = (0..crate::POINTS)
        .map(|_| {
            let pdf = |x: u32| 10f32.powf((x >> 8) as f32 / 16_777_216.0 * 12.0 - 6.0);
            Vec4::new(1.0 + (next() % 4) as f32, pdf(next()), 1.0, pdf(next()))
        })
        .collect();
    let packets: Vec<[F32x8; 4]> = quads
        .chunks_exact(8)
        .map(|c| core::array::from_fn(|k| F32x8::new(core::array::from_fn(|i| c[i][k]))))
        .collect();
    let packets16: Vec<[F32x16; 4]> = quads
        .chunks_exact(16)
        .map(|c| core::array::from_fn(|k| F32x16::new(core::array::from_fn(|i| c[i][k]))))
        .collect();
    let x8_loop = |fx8: HeuristicX8| {
        move |p: &[[F32x8; 4]], out: &mut [F32x8]| {
            for (o, p) in out.iter_mut().zip(p) {
                *o = fx8(p[0], p[1], p[2], p[3]);
            }
        }
    };
    HEURISTICS
        .iter()
        .map(|&(name, f, fx8, fx16)| {
            let (scalar_ns, x8_ns) = time_pair(
                cfg,
                &quads,
                &packets,
                &|q: &[Vec4], out: &mut [f32]| {
                    for (o, q) in out.iter_mut().zip(q) {
                        *o = f(q.x, q.y, q.z, q.w);
                    }
                },
                &x8_loop(fx8),
            );
            // Per packet of eight in both loops, which cover the same weights.
            let (x8_again, x16) = time_pair(
                cfg,
                &packets,
                &packets16,
                &x8_loop(fx8),
                &|p: &[[F32x16; 4]], out: &mut [F32x16]| {
                    for (o, p) in out.iter_mut().zip(p) {
                        *o = fx16(p[0], p[1], p[2], p[3]);
                    }
                },
            );
            WeightRow {
                name,
                scalar_ns,
                x8_ns,
                x16_ns: x16 / 8.0,
                x16_vs_x8: x8_again / x16,
            }
        })
        .collect()
}
