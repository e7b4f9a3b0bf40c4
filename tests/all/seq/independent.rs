//! `seq::independent`: golden values, an independent re-implementation of the hash, packet vs
//! scalar bit equality, the [0, 1) range, moments and χ² uniformity, with negative controls.

use crate::common::{TestRng, lanes};
use glam::DVec2;
use mcsample::lane::U32Lane;
use mcsample::seq;
use mcsample::verify::{ChiSquare, check_lanes};
use mcsample::x8::U32x8;

/// Wellons's lowbias32, written out from its published definition (not from the crate).
fn ref_lowbias32(mut x: u32) -> u32 {
    x ^= x >> 16;
    x = x.wrapping_mul(0x7feb_352d);
    x ^= x >> 15;
    x = x.wrapping_mul(0x846c_a68b);
    x ^= x >> 16;
    x
}

/// The documented hash: k1 = lb(lb(dim ^ φ) ^ seed), k2 = lb(k1 + φ), h = lb(lb(index ^ k1) + k2).
fn ref_hash3(index: u32, dim: u32, seed: u32) -> u32 {
    const PHI: u32 = 0x9e37_79b9;
    let k1 = ref_lowbias32(ref_lowbias32(dim ^ PHI) ^ seed);
    let k2 = ref_lowbias32(k1.wrapping_add(PHI));
    ref_lowbias32(ref_lowbias32(index ^ k1).wrapping_add(k2))
}

/// (h >> 8) · 2⁻²⁴ by an ordinary (exact) integer-to-float conversion and division.
fn ref_unit(h: u32) -> f32 {
    ((h >> 8) as f64 / 16_777_216.0) as f32
}

#[test]
fn lowbias32_reference_is_a_bijection_on_a_sample() {
    // Sanity of the reference itself: no collisions among 2^16 consecutive inputs, and 0 ↦ 0.
    assert_eq!(ref_lowbias32(0), 0);
    let mut v: Vec<u32> = (0..1u32 << 16).map(ref_lowbias32).collect();
    v.sort_unstable();
    v.dedup();
    assert_eq!(v.len(), 1 << 16);
}

#[test]
fn hash_matches_independent_reimplementation() {
    let mut rng = TestRng::new(1);
    let mut specials = vec![
        (0, 0, 0),
        (u32::MAX, 0, 0),
        (u32::MAX, u32::MAX, u32::MAX),
        (1, 2, 3),
    ];
    specials.extend((0..100_000).map(|_| (rng.next_u32(), rng.below(64), rng.next_u32())));
    for (i, d, s) in specials {
        let h = ref_hash3(i, d, s);
        assert_eq!(seq::hash3(i, d, s), h, "hash3({i}, {d}, {s})");
        assert_eq!(
            seq::independent(i, d, s).to_bits(),
            ref_unit(h).to_bits(),
            "independent({i}, {d}, {s})"
        );
    }
}

#[test]
fn golden_values() {
    // (index, dim, seed, hash3, independent bits). Fixed forever: changing the hash changes every
    // rendered image, so it must be a deliberate act that edits this table.
    const GOLDEN: [(u32, u32, u32, u32, u32); 6] = GOLDEN_TABLE;
    for (i, d, s, h, f) in GOLDEN {
        assert_eq!(seq::hash3(i, d, s), h, "hash3({i}, {d}, {s})");
        assert_eq!(ref_hash3(i, d, s), h, "reference hash3({i}, {d}, {s})");
        assert_eq!(
            seq::independent(i, d, s).to_bits(),
            f,
            "independent({i}, {d}, {s})"
        );
    }
}

const GOLDEN_TABLE: [(u32, u32, u32, u32, u32); 6] = [
    (0, 0, 0, 0x084e_1a40, 0x3d04_e1a0),
    (1, 0, 0, 0xf038_8ab7, 0x3f70_388a),
    (0, 1, 0, 0x1a65_f787, 0x3dd3_2fb8),
    (0, 0, 1, 0x8310_2892, 0x3f03_1028),
    (u32::MAX, 7, 0xdead_beef, 0x9bd9_5a67, 0x3f1b_d95a),
    (12345, 3, 42, 0xa0d8_e7c5, 0x3f20_d8e7),
];

#[test]
fn unit_conversion_is_exact_and_below_one() {
    assert_eq!(u32::MAX.to_unit_f32(), 1.0 - 1.0 / 16_777_216.0);
    assert_eq!(0u32.to_unit_f32().to_bits(), 0);
    assert_eq!(0x100u32.to_unit_f32(), 1.0 / 16_777_216.0);
    let mut rng = TestRng::new(2);
    for x in (0..1_000_000)
        .map(|_| rng.next_u32())
        .chain([0xff, 0x1ff, 0x8000_0000, 0xffff_ff00, 0xffff_feff])
    {
        assert_eq!(x.to_unit_f32().to_bits(), ref_unit(x).to_bits(), "{x:#x}");
    }
    let p = U32x8::new([
        0,
        0xff,
        0x100,
        0x1ff,
        0x200,
        0x8000_0000,
        0xffff_feff,
        u32::MAX,
    ]);
    let got = p.to_unit_f32().to_array();
    for (k, x) in p.to_array().into_iter().enumerate() {
        assert_eq!(got[k].to_bits(), ref_unit(x).to_bits(), "lane {k}");
    }
}

#[test]
fn packet_equals_scalar_bit_for_bit() {
    let mut rng = TestRng::new(3);
    let mut indices: Vec<u32> = (0..4096).map(|_| rng.next_u32()).collect();
    indices.extend([0, 1, u32::MAX, u32::MAX - 1, 0x8000_0000, 0xff, 0x100, 7]);
    let mut f = Vec::new();
    for _ in 0..64 {
        let (d, s) = (rng.below(256), rng.next_u32());
        let ctx = format!("dim {d} seed {s}");
        lanes!(&mut f, &format!("independent, {ctx}"), &indices, |i: U| {
            seq::independent(i, d, s)
        });
        lanes!(&mut f, &format!("hash3, {ctx}"), &indices, |i: U| {
            seq::hash3(i, d, s)
        });
    }
    assert!(f.is_empty(), "{}", f.join("\n"));
}

#[test]
fn packet_check_catches_a_wrong_lane() {
    // Negative control for the harness: a packet that mixes up dimensions is caught.
    let indices: Vec<u32> = (0..64).collect();
    assert!(
        check_lanes::<u32, f32>(
            &indices,
            |i| seq::independent(i, 1, 0),
            |i| seq::independent(i, 0, 0),
        )
        .is_err()
    );
}

#[test]
fn last_index_is_below_one() {
    let mut rng = TestRng::new(4);
    for k in 0..100_000u32 {
        let (d, s) = if k < 1000 {
            (k, k)
        } else {
            (rng.next_u32(), rng.next_u32())
        };
        let v = seq::independent(u32::MAX, d, s);
        assert!((0.0..1.0).contains(&v), "independent(MAX, {d}, {s}) = {v}");
    }
    let v = seq::independent(U32x8::splat(u32::MAX), 5, 9).to_array();
    assert!(v.iter().all(|x| (0.0..1.0).contains(x)));
}

fn moments(f: impl Fn(u32) -> f32, n: u32) -> (f64, f64) {
    let (mut s1, mut s2) = (0.0f64, 0.0f64);
    for i in 0..n {
        let v = f(i) as f64;
        assert!((0.0..1.0).contains(&v));
        s1 += v;
        s2 += v * v;
    }
    let nf = n as f64;
    let mean = s1 / nf;
    (mean, s2 / nf - mean * mean)
}

#[test]
fn mean_and_variance() {
    let n = 1u32 << 20;
    let nf = n as f64;
    let sd_mean = (1.0 / 12.0 / nf).sqrt();
    // Var of (u − ½)²: 1/80 − 1/144.
    let sd_var = ((1.0 / 80.0 - 1.0 / 144.0) / nf).sqrt();
    for (d, s) in [(0, 0), (1, 0), (0, 1), (17, 0xdead_beef)] {
        let (mean, var) = moments(|i| seq::independent(i, d, s), n);
        assert!(
            (mean - 0.5).abs() < 4.0 * sd_mean,
            "dim {d} seed {s}: mean {mean}"
        );
        assert!(
            (var - 1.0 / 12.0).abs() < 4.0 * sd_var,
            "dim {d} seed {s}: var {var}"
        );
    }
    // Negative control: values squeezed towards ½ (u ↦ ¼ + u/2) keep the mean but not the
    // variance.
    let (mean, var) = moments(|i| 0.25 + 0.5 * seq::independent(i, 0, 0), n);
    assert!((mean - 0.5).abs() < 4.0 * sd_mean);
    assert!((var - 1.0 / 12.0).abs() > 4.0 * sd_var);
}

const ALPHA: f64 = 1e-3;

fn chi2_pairs(f: impl Fn(u32) -> (f32, f32)) -> mcsample::verify::ChiSquareResult {
    ChiSquare::square().run(
        |i| {
            let (x, y) = f(i as u32);
            DVec2::new(x as f64, y as f64)
        },
        |_| 1.0,
    )
}

#[test]
fn pairs_are_uniform_chi_square() {
    for s in [0, 1, 0x1234_5678] {
        let r = chi2_pairs(|i| (seq::independent(i, 0, s), seq::independent(i, 1, s)));
        assert!(r.passes(ALPHA), "dims 0, 1, seed {s}: {r}");
        let r = chi2_pairs(|i| (seq::independent(i, 3, s), seq::independent(i, 3, s + 1)));
        assert!(r.passes(ALPHA), "dim 3, seeds {s}, {}: {r}", s + 1);
    }
}

#[test]
fn chi_square_rejects_correlated_dimensions() {
    // The same dimension twice: every pair lies on the diagonal.
    let r = chi2_pairs(|i| (seq::independent(i, 0, 0), seq::independent(i, 0, 0)));
    assert!(!r.passes(ALPHA), "diagonal accepted: {r}");
    // A weak hash without mixing: h(i, d) = (i + d)·φ. Dimension 1 is dimension 0 shifted by φ
    // mod 1, so the pairs lie on two lines.
    let weak = |i: u32, d: u32| (i.wrapping_add(d).wrapping_mul(0x9e37_79b9)).to_unit_f32();
    let r = chi2_pairs(|i| (weak(i, 0), weak(i, 1)));
    assert!(!r.passes(ALPHA), "weak hash accepted: {r}");
}

/// The largest deviation from ½, over input bits of (index, dim, seed) and output bits, of the
/// probability that flipping the input bit flips the output bit, over `n` random inputs.
fn worst_avalanche(h: impl Fn(u32, u32, u32) -> u32, n: u32) -> f64 {
    let mut rng = TestRng::new(5);
    let mut flips = [[0u32; 32]; 96];
    for _ in 0..n {
        let x = [rng.next_u32(), rng.next_u32(), rng.next_u32()];
        let base = h(x[0], x[1], x[2]);
        for (j, row) in flips.iter_mut().enumerate() {
            let mut y = x;
            y[j / 32] ^= 1 << (j % 32);
            let d = base ^ h(y[0], y[1], y[2]);
            for (k, c) in row.iter_mut().enumerate() {
                *c += (d >> k) & 1;
            }
        }
    }
    flips
        .iter()
        .flatten()
        .map(|&c| (c as f64 / n as f64 - 0.5).abs())
        .fold(0.0, f64::max)
}

#[test]
fn hash_avalanche() {
    // 4096 trials per (input bit, output bit): sd of a fraction 0.0078, so 0.045 is ≈ 6σ over
    // 3072 pairs.
    let n = 4096;
    let worst = worst_avalanche(seq::hash3, n);
    assert!(worst < 0.045, "worst avalanche deviation {worst}");
    // Negative control: a multiplicative hash without xorshifts; high input bits never reach
    // low output bits.
    let weak =
        |i: u32, d: u32, s: u32| (i ^ d.wrapping_mul(0x85eb_ca6b) ^ s).wrapping_mul(0x9e37_79b9);
    assert!(worst_avalanche(weak, n) > 0.45);
}
