//! The stratified families and Sobol: an independent reimplementation of the Sobol pipeline,
//! golden vectors, packets equal to scalars bit for bit, the structural properties each
//! generator promises (with negative controls that break a permutation), and the documented
//! behaviour on extreme inputs.

use super::golden::{GOLDEN_INDICES, GOLDEN_SEQ};
use crate::common::{TestRng, lanes};
use glam::Vec2;
use mcsample::seq::{
    self, MAX_STRATA,
    quality::{NetViolation, net_violation},
};

// ---------------------------------------------------------------------------------------------
// An independent Sobol reference, written the textbook way: natural bit order, direction numbers
// from the Bratley–Fox form of the recurrence on vₖ, and Burley's scramble as
// reverse ∘ hash ∘ reverse. The library keeps everything bit-reversed and its matrices in
// another form, so agreement checks both.

fn ref_lowbias32(mut x: u32) -> u32 {
    x ^= x >> 16;
    x = x.wrapping_mul(0x7feb_352d);
    x ^= x >> 15;
    x = x.wrapping_mul(0x846c_a68b);
    x ^ (x >> 16)
}

/// vₖ for Joe–Kuo's (s, a, m): vₖ = mₖ·2³²⁻ᵏ for k ≤ s, then
/// vₖ = vₖ₋ₛ ⊕ (vₖ₋ₛ >> s) ⊕ ⊕ᵢ aᵢ·vₖ₋ᵢ.
fn ref_directions(dim: u32) -> [u32; 32] {
    let mut v = [0u32; 32];
    if dim == 0 {
        for (k, vk) in v.iter_mut().enumerate() {
            *vk = 1 << (31 - k);
        }
        return v;
    }
    let (s, a, m): (usize, u32, &[u32]) = match dim {
        1 => (1, 0, &[1]),
        2 => (2, 1, &[1, 3]),
        3 => (3, 1, &[1, 3, 1]),
        _ => unreachable!(),
    };
    for k in 0..32 {
        v[k] = if k < s {
            m[k] << (31 - k)
        } else {
            let mut x = v[k - s] ^ (v[k - s] >> s);
            for i in 1..s {
                if (a >> (s - 1 - i)) & 1 == 1 {
                    x ^= v[k - i];
                }
            }
            x
        };
    }
    v
}

fn ref_burley_hash(mut x: u32, seed: u32) -> u32 {
    x = x.wrapping_add(seed);
    for c in [0x6c50_b47c_u32, 0xb82f_1e52, 0xc7af_e638, 0x8d22_f6e6] {
        x ^= x.wrapping_mul(c);
    }
    x
}

fn ref_owen(x: u32, seed: u32) -> u32 {
    ref_burley_hash(x.reverse_bits(), seed).reverse_bits()
}

/// The documented pipeline: set seed from (seed, dim/4), then shuffle, Sobol product, scramble.
fn ref_sobol(index: u32, dim: u32, seed: u32) -> u32 {
    let set_seed = ref_lowbias32(ref_lowbias32(seed ^ 0x5851_f42d) ^ (dim / 4));
    let index_seed = ref_lowbias32(set_seed ^ 0x0bad_5eed);
    let value_seed = ref_lowbias32(set_seed.wrapping_add(dim % 4 + 1));
    let shuffled = ref_owen(index, index_seed);
    let v = ref_directions(dim % 4);
    let x = (0..32)
        .filter(|b| (shuffled >> b) & 1 == 1)
        .fold(0, |x, b| x ^ v[b]);
    ref_owen(x, value_seed)
}

fn ref_unit(x: u32) -> f32 {
    (x >> 8) as f32 / 16_777_216.0
}

#[test]
fn sobol_matches_the_textbook_reference() {
    let mut rng = TestRng::new(1);
    for k in 0..200_000u32 {
        let (i, d, s) = if k < 4096 {
            (k, k % 9, 0)
        } else {
            (rng.next_u32(), rng.below(64), rng.next_u32())
        };
        let want = ref_unit(ref_sobol(i, d, s));
        let got = seq::sobol(i, d, s);
        assert_eq!(got.to_bits(), want.to_bits(), "sobol({i}, {d}, {s})");
    }
}

#[test]
fn unscrambled_reference_is_the_sobol_sequence() {
    // The reference itself, without scrambling, against the first eight Sobol points in
    // dimensions 1–3, worked by hand from the direction integers (natural order; the same points
    // as SciPy's unscrambled Sobol, which lists them in Gray-code order).
    let point = |i: u32, d: u32| {
        let v = ref_directions(d);
        (0..32)
            .filter(|b| (i >> b) & 1 == 1)
            .fold(0u32, |x, b| x ^ v[b]) as f64
            / 2f64.powi(32)
    };
    let want = [
        [0.0, 0.0, 0.0],
        [0.5, 0.5, 0.5],
        [0.25, 0.75, 0.75],
        [0.75, 0.25, 0.25],
        [0.125, 0.625, 0.375],
        [0.625, 0.125, 0.875],
        [0.375, 0.375, 0.625],
        [0.875, 0.875, 0.125],
    ];
    for (i, w) in want.iter().enumerate() {
        for d in 0..3 {
            assert_eq!(point(i as u32, d), w[d as usize], "point {i} dim {d}");
        }
    }
}

// ---------------------------------------------------------------------------------------------
// Golden vectors: the bits of fixed inputs, recorded when the generators were written. They pin
// the sequences that users and the external checks rely on; a change here is a breaking change.

fn bits(v: &[f32]) -> Vec<u32> {
    v.iter().map(|x| x.to_bits()).collect()
}

#[test]
fn golden_vectors() {
    let idx = GOLDEN_INDICES;
    let stratified: Vec<f32> = idx.iter().map(|&i| seq::stratified(i, 16, 3, 7)).collect();
    let latin: Vec<f32> = idx
        .iter()
        .map(|&i| seq::latin_hypercube(i, 100, 1, 7))
        .collect();
    let jittered: Vec<f32> = idx
        .iter()
        .flat_map(|&i| seq::jittered_2d(i, 4, 8, 2, 7).to_array())
        .collect();
    let mj: Vec<f32> = idx
        .iter()
        .flat_map(|&i| seq::multi_jittered_2d(i, 5, 3, 0, 7).to_array())
        .collect();
    let cmj: Vec<f32> = idx
        .iter()
        .flat_map(|&i| seq::cmj_2d(i, 8, 8, 0, 7).to_array())
        .collect();
    let sobol: Vec<f32> = idx.iter().map(|&i| seq::sobol(i, 5, 7)).collect();
    let got = [
        bits(&stratified),
        bits(&latin),
        bits(&jittered),
        bits(&mj),
        bits(&cmj),
        bits(&sobol),
    ];
    let want: [&[u32]; 6] = GOLDEN_SEQ;
    for (k, (g, w)) in got.iter().zip(want).enumerate() {
        assert_eq!(g.as_slice(), w, "generator {k}: {g:#x?}");
    }
}

// ---------------------------------------------------------------------------------------------
// Packets equal scalars, bit for bit.

#[test]
fn packets_equal_scalars_bit_for_bit() {
    let mut rng = TestRng::new(2);
    let mut indices: Vec<u32> = (0..2048).map(|_| rng.next_u32()).collect();
    indices.extend(0..2048);
    indices.extend([
        u32::MAX,
        u32::MAX - 1,
        0x8000_0000,
        MAX_STRATA,
        MAX_STRATA - 1,
    ]);
    let counts = [0u32, 1, 2, 3, 16, 100, 4096, 65_537, MAX_STRATA, u32::MAX];
    for round in 0..40 {
        let (d, s) = (rng.below(64), rng.next_u32());
        let n = counts[round % counts.len()];
        let (nx, ny) = (
            counts[round % counts.len()].min(1 << (round % 12)),
            counts[(round * 7 + 3) % counts.len()] % 300,
        );
        let ctx = format!("dim {d} seed {s} n {n} grid {nx}×{ny}");
        let mut f = Vec::new();
        lanes!(&mut f, &ctx, &indices, |i: U| seq::stratified(i, n, d, s));
        lanes!(&mut f, &ctx, &indices, |i: U| seq::latin_hypercube(
            i, n, d, s
        ));
        lanes!(&mut f, &ctx, &indices, |i: U| seq::jittered_2d(
            i, nx, ny, d, s
        ));
        lanes!(&mut f, &ctx, &indices, |i: U| seq::multi_jittered_2d(
            i, nx, ny, d, s
        ));
        lanes!(&mut f, &ctx, &indices, |i: U| seq::cmj_2d(i, nx, ny, d, s));
        lanes!(&mut f, &ctx, &indices, |i: U| seq::sobol(i, d, s));
        lanes!(&mut f, &ctx, &indices, |i: U| seq::sobol_2d(i, d, s));
        assert!(f.is_empty(), "{}", f.join("\n"));
    }
}

// ---------------------------------------------------------------------------------------------
// Structure. Each checker returns the first violation; the negative controls feed it a set made
// with a broken permutation (one index repeated in place of another, so two points share a
// stratum) and require that it is found.

/// The first stratum of n that holds no value or two, with values taken exactly (f64).
fn stratum_violation(values: &[f32], n: u32) -> Option<u32> {
    let mut count = vec![0u32; n as usize];
    for &v in values {
        assert!((0.0..1.0).contains(&v), "value {v} outside [0, 1)");
        count[(v as f64 * n as f64) as usize] += 1;
    }
    count.iter().position(|&c| c != 1).map(|s| s as u32)
}

/// One point per cell of the nx × ny grid?
fn cell_violation(points: &[Vec2], nx: u32, ny: u32) -> Option<(u32, u32)> {
    let mut count = vec![0u32; (nx * ny) as usize];
    for p in points {
        let cx = (p.x as f64 * nx as f64) as u32;
        let cy = (p.y as f64 * ny as f64) as u32;
        count[(cy * nx + cx) as usize] += 1;
    }
    count
        .iter()
        .position(|&c| c != 1)
        .map(|k| (k as u32 % nx, k as u32 / nx))
}

/// Indices of round r of a set of n, with index `r·n + 1` replaced by `r·n` when `broken`.
fn round(r: u32, n: u32, broken: bool) -> impl Iterator<Item = u32> {
    (0..n).map(move |j| if broken && j == 1 { r * n } else { r * n + j })
}

const COUNTS: [u32; 9] = [2, 3, 7, 16, 64, 100, 1000, 4096, 65_537];

#[test]
fn stratified_one_point_per_stratum() {
    for &n in &COUNTS {
        for seed in [0, 1, 0xdead_beef] {
            for r in [0, 1, 9] {
                let values: Vec<f32> = round(r, n, false)
                    .map(|i| seq::stratified(i, n, 2, seed))
                    .collect();
                assert_eq!(
                    stratum_violation(&values, n),
                    None,
                    "n {n} seed {seed} round {r}"
                );
                let broken: Vec<f32> = round(r, n, true)
                    .map(|i| seq::stratified(i, n, 2, seed))
                    .collect();
                assert!(stratum_violation(&broken, n).is_some(), "control, n {n}");
            }
        }
    }
}

#[test]
fn stratified_orders_differ_by_round_dimension_and_seed() {
    // The visiting order is a hashed permutation: rounds, dimensions and seeds each change it.
    let n = 64;
    let order = |r: u32, d: u32, s: u32| -> Vec<u32> {
        round(r, n, false)
            .map(|i| (seq::stratified(i, n, d, s) * n as f32) as u32)
            .collect()
    };
    let base = order(0, 0, 0);
    let identity: Vec<u32> = (0..n).collect();
    assert_ne!(base, identity);
    for other in [order(1, 0, 0), order(0, 1, 0), order(0, 0, 1)] {
        let same = base.iter().zip(&other).filter(|(a, b)| a == b).count();
        // A random permutation of 64 has about one fixed point in common with another.
        assert!(same < 8, "{same} of 64 strata in the same place");
    }
}

#[test]
fn latin_hypercube_in_every_dimension() {
    for &n in &COUNTS[..8] {
        for seed in [3, 4] {
            for dim in 0..6 {
                let values: Vec<f32> = round(2, n, false)
                    .map(|i| seq::latin_hypercube(i, n, dim, seed))
                    .collect();
                assert_eq!(stratum_violation(&values, n), None, "n {n} dim {dim}");
                let broken: Vec<f32> = round(2, n, true)
                    .map(|i| seq::latin_hypercube(i, n, dim, seed))
                    .collect();
                assert!(stratum_violation(&broken, n).is_some(), "control, n {n}");
            }
        }
    }
}

const GRIDS: [(u32, u32); 8] = [
    (1, 1),
    (1, 9),
    (9, 1),
    (2, 2),
    (3, 5),
    (8, 8),
    (16, 4),
    (64, 64),
];

#[test]
fn jittered_one_point_per_cell() {
    for &(nx, ny) in &GRIDS {
        for seed in [0, 11] {
            for r in [0, 3] {
                let n = nx * ny;
                let pts: Vec<Vec2> = round(r, n, false)
                    .map(|i| seq::jittered_2d(i, nx, ny, 1, seed))
                    .collect();
                assert_eq!(cell_violation(&pts, nx, ny), None, "{nx}×{ny} seed {seed}");
                if n > 1 {
                    let broken: Vec<Vec2> = round(r, n, true)
                        .map(|i| seq::jittered_2d(i, nx, ny, 1, seed))
                        .collect();
                    assert!(
                        cell_violation(&broken, nx, ny).is_some(),
                        "control {nx}×{ny}"
                    );
                }
            }
        }
    }
}

type Gen2 = fn(u32, u32, u32, u32, u32) -> Vec2;

/// Jittered, and one point per 1/(nx·ny) stratum of x and of y.
fn multi_jitter_violation(pts: &[Vec2], nx: u32, ny: u32) -> Option<&'static str> {
    let xs: Vec<f32> = pts.iter().map(|p| p.x).collect();
    let ys: Vec<f32> = pts.iter().map(|p| p.y).collect();
    if cell_violation(pts, nx, ny).is_some() {
        Some("cells")
    } else if stratum_violation(&xs, nx * ny).is_some() {
        Some("x strata")
    } else if stratum_violation(&ys, nx * ny).is_some() {
        Some("y strata")
    } else {
        None
    }
}

#[test]
fn multi_jittered_and_cmj_have_both_properties() {
    for (name, generator) in [
        ("multi_jittered_2d", seq::multi_jittered_2d as Gen2),
        ("cmj_2d", seq::cmj_2d),
    ] {
        for &(nx, ny) in &GRIDS {
            for seed in [0, 5] {
                for r in [0, 2] {
                    let n = nx * ny;
                    let pts: Vec<Vec2> = round(r, n, false)
                        .map(|i| generator(i, nx, ny, 3, seed))
                        .collect();
                    let v = multi_jitter_violation(&pts, nx, ny);
                    assert_eq!(v, None, "{name} {nx}×{ny} seed {seed} round {r}");
                    if n > 1 {
                        let broken: Vec<Vec2> = round(r, n, true)
                            .map(|i| generator(i, nx, ny, 3, seed))
                            .collect();
                        assert!(multi_jitter_violation(&broken, nx, ny).is_some());
                    }
                }
            }
        }
    }
}

#[test]
fn fine_strata_check_catches_a_broken_column_permutation() {
    // Within one column, give a point the x of its neighbour's fine stratum: every cell still
    // holds one point, so only the fine-strata check can see it.
    let (nx, ny) = (8, 8);
    let mut pts: Vec<Vec2> = (0..64)
        .map(|i| seq::multi_jittered_2d(i, nx, ny, 0, 1))
        .collect();
    assert_eq!(multi_jitter_violation(&pts, nx, ny), None);
    let column = |p: Vec2| (p.x * nx as f32) as u32;
    let row = |p: Vec2| (p.y * ny as f32) as u32;
    let (a, b) = (0..64)
        .flat_map(|a| (0..64).map(move |b| (a, b)))
        .find(|&(a, b)| a != b && column(pts[a]) == column(pts[b]))
        .unwrap();
    assert_ne!(row(pts[a]), row(pts[b]));
    pts[a].x = pts[b].x;
    assert_eq!(cell_violation(&pts, nx, ny), None);
    assert_eq!(multi_jitter_violation(&pts, nx, ny), Some("x strata"));
}

#[test]
fn cmj_shares_its_permutations_and_multi_jitter_does_not() {
    // In CMJ a cell's fine x-offset (x-stratum minus column·ny) depends on its row only; in
    // multi-jitter it varies between columns. This is the difference the slope test measures.
    let (nx, ny) = (16u32, 16u32);
    let offsets = |g: Gen2| -> Vec<Vec<u32>> {
        let mut by_row = vec![vec![]; ny as usize];
        for i in 0..nx * ny {
            let p = g(i, nx, ny, 0, 9);
            let fine = (p.x as f64 * (nx * ny) as f64) as u32;
            let (cx, cy) = ((p.x * nx as f32) as u32, (p.y * ny as f32) as u32);
            by_row[cy as usize].push(fine - cx * ny);
        }
        by_row
    };
    let all_equal = |v: &Vec<u32>| v.iter().all(|&o| o == v[0]);
    assert!(offsets(seq::cmj_2d).iter().all(all_equal));
    let mj = offsets(seq::multi_jittered_2d);
    assert!(mj.iter().filter(|row| all_equal(row)).count() == 0);
}

#[test]
fn sobol_prefixes_are_nets() {
    for seed in [0, 1, 2, 3, 0xffff_ffff, 0x1234_5678] {
        for m in 0..=12 {
            let pts: Vec<Vec2> = (0..1u32 << m).map(|i| seq::sobol_2d(i, 0, seed)).collect();
            assert_eq!(net_violation(&pts, m), None, "seed {seed:#x}, N = 2^{m}");
        }
        // Aligned blocks after the prefix are nets too (the index shuffle maps blocks to blocks).
        for (m, block) in [(6, 1), (8, 3), (10, 7)] {
            let pts: Vec<Vec2> = (block << m..(block + 1) << m)
                .map(|i| seq::sobol_2d(i, 0, seed))
                .collect();
            assert_eq!(
                net_violation(&pts, m),
                None,
                "seed {seed:#x}, block {block} of 2^{m}"
            );
        }
    }
}

#[test]
fn sobol_net_check_catches_a_broken_shuffle() {
    for m in 2..=12 {
        let pts: Vec<Vec2> = round(0, 1 << m, true)
            .map(|i| seq::sobol_2d(i, 0, 77))
            .collect();
        assert!(
            matches!(net_violation(&pts, m), Some(NetViolation::Collision { .. })),
            "m = {m}"
        );
    }
}

#[test]
fn every_sobol_dimension_is_stratified() {
    // Each dimension alone is a (0, 1)-sequence: 2^m points, one per 1/2^m stratum.
    for dim in [0, 1, 2, 3, 4, 7, 8, 13, 100] {
        for m in [1, 5, 10, 12] {
            let values: Vec<f32> = (0..1u32 << m).map(|i| seq::sobol(i, dim, 21)).collect();
            assert_eq!(stratum_violation(&values, 1 << m), None, "dim {dim}, 2^{m}");
        }
    }
}

#[test]
fn sobol_dimension_sets_are_decorrelated() {
    // Padding: dimension 4 is Sobol dimension 0 of another set, so it must not repeat dimension 0.
    let n = 1024;
    let same = (0..n)
        .filter(|&i| seq::sobol(i, 0, 5).to_bits() == seq::sobol(i, 4, 5).to_bits())
        .count();
    assert!(same < 4, "{same} of {n} equal");
    // And the pairs (0, 4) are spread like independent points: correlation near 0.
    let mean = |f: &dyn Fn(u32) -> f64| (0..n).map(f).sum::<f64>() / n as f64;
    let cov = mean(&|i| (seq::sobol(i, 0, 5) as f64 - 0.5) * (seq::sobol(i, 4, 5) as f64 - 0.5));
    assert!(
        cov.abs() < 4.0 / 12.0 / (n as f64).sqrt(),
        "covariance {cov}"
    );
    // Control: without padding, dimension 4 would repeat dimension 0, and the bound rejects that.
    let repeated = mean(&|i| (seq::sobol(i, 0, 5) as f64 - 0.5).powi(2));
    assert!(repeated.abs() >= 4.0 / 12.0 / (n as f64).sqrt());
}

// ---------------------------------------------------------------------------------------------
// Extreme inputs: documented, never 1.0, never a panic.

#[test]
fn extreme_indices_stay_below_one() {
    let mut rng = TestRng::new(5);
    let check = |v: f32, what: &str| assert!((0.0..1.0).contains(&v), "{what}: {v}");
    for k in 0..20_000u32 {
        let i = if k < 256 {
            u32::MAX - k
        } else {
            rng.next_u32()
        };
        let (d, s) = (rng.next_u32(), rng.next_u32());
        let n = rng.next_u32() >> rng.below(32);
        let (nx, ny) = (rng.below(5000), rng.below(5000));
        check(seq::stratified(i, n, d, s), "stratified");
        check(seq::latin_hypercube(i, n, d, s), "latin");
        for p in [
            seq::jittered_2d(i, nx, ny, d, s),
            seq::multi_jittered_2d(i, nx, ny, d, s),
            seq::cmj_2d(i, nx, ny, d, s),
            seq::sobol_2d(i, d, s),
        ] {
            check(p.x, "2d x");
            check(p.y, "2d y");
        }
        check(seq::sobol(i, d, s), "sobol");
    }
}

#[test]
fn counts_are_clamped_as_documented() {
    for i in [0u32, 1, 77, u32::MAX] {
        assert_eq!(seq::stratified(i, 0, 1, 2), seq::stratified(i, 1, 1, 2));
        assert_eq!(
            seq::stratified(i, u32::MAX, 1, 2),
            seq::stratified(i, MAX_STRATA, 1, 2)
        );
        assert_eq!(
            seq::jittered_2d(i, 0, 0, 1, 2),
            seq::jittered_2d(i, 1, 1, 1, 2)
        );
        // nx is clamped to 2²³, then ny to 2²³/nx.
        assert_eq!(
            seq::multi_jittered_2d(i, u32::MAX, 5, 1, 2),
            seq::multi_jittered_2d(i, MAX_STRATA, 1, 1, 2)
        );
        assert_eq!(
            seq::cmj_2d(i, 1 << 12, u32::MAX, 1, 2),
            seq::cmj_2d(i, 1 << 12, 1 << 11, 1, 2)
        );
    }
    // The largest count still gives one point per stratum (checked on a round's first strata by
    // their position: every value sits strictly inside its stratum).
    for i in 0..10_000u32 {
        let v = seq::stratified(i, MAX_STRATA, 0, 3);
        let s = (v as f64 * MAX_STRATA as f64).floor();
        assert!(
            v as f64 > s / MAX_STRATA as f64,
            "value {v} on a stratum edge"
        );
    }
}
