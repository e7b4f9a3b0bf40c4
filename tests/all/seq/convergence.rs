//! Convergence and discrepancy of the generators: RMSE slopes on the Gaussian and the disk
//! indicator over N = 16…4096 and ≥ 64 seeds, and RMS L2-star discrepancy at N = 1024 over 32
//! seeds, against the targets each test states. Independent points are the negative control: the
//! same measurements must reject them.

use glam::Vec2;
use mcsample::seq::{
    self,
    quality::{
        self, DISK_INTEGRAL, GAUSSIAN_INTEGRAL, disk_indicator, gaussian, l2_star_discrepancy,
    },
};

/// A 2D point-set family: (index, N, seed) → point, the set of size N being indices 0..N.
type Family = fn(u32, u32, u32) -> Vec2;

/// The grid nx × ny = N = 2ᵏ used for the 2D stratified families: nx = 2^⌈k/2⌉.
fn grid(n: u32) -> (u32, u32) {
    let k = n.trailing_zeros();
    (1 << k.div_ceil(2), 1 << (k / 2))
}

fn independent(i: u32, _n: u32, s: u32) -> Vec2 {
    Vec2::new(seq::independent(i, 0, s), seq::independent(i, 1, s))
}
fn latin(i: u32, n: u32, s: u32) -> Vec2 {
    Vec2::new(
        seq::latin_hypercube(i, n, 0, s),
        seq::latin_hypercube(i, n, 1, s),
    )
}
fn jittered(i: u32, n: u32, s: u32) -> Vec2 {
    let (nx, ny) = grid(n);
    seq::jittered_2d(i, nx, ny, 0, s)
}
fn multi_jittered(i: u32, n: u32, s: u32) -> Vec2 {
    let (nx, ny) = grid(n);
    seq::multi_jittered_2d(i, nx, ny, 0, s)
}
fn cmj(i: u32, n: u32, s: u32) -> Vec2 {
    let (nx, ny) = grid(n);
    seq::cmj_2d(i, nx, ny, 0, s)
}
fn sobol(i: u32, _n: u32, s: u32) -> Vec2 {
    seq::sobol_2d(i, 0, s)
}

fn rmse_slope(family: Family, f: fn(Vec2) -> f64, exact: f64, seeds: u32) -> f64 {
    quality::rmse_slope(family, f, exact, 4..=12, seeds)
}

/// RMS over 32 seeds of the L2-star discrepancy of the first 1024 points, as a fraction of the
/// iid expectation √((2⁻² − 3⁻²)/N).
fn discrepancy_ratio(family: Family) -> f64 {
    let n = 1024;
    let ms = (0..32)
        .map(|s| {
            let pts: Vec<Vec2> = (0..n).map(|i| family(i, n, s)).collect();
            l2_star_discrepancy(&pts).powi(2)
        })
        .sum::<f64>()
        / 32.0;
    ms.sqrt() / ((0.25 - 1.0 / 9.0) / n as f64).sqrt()
}

/// Sobol with its two dimensions taken from different seeds: each axis is still stratified, but
/// the pair is no longer a net. A broken construction the slope and discrepancy tests must reject.
fn sobol_unpaired(i: u32, _n: u32, s: u32) -> Vec2 {
    Vec2::new(seq::sobol(i, 0, s), seq::sobol(i, 1, s ^ 0x55))
}

const SEEDS: u32 = 64;

#[test]
fn gaussian_slopes_meet_the_targets() {
    let slope = |f: Family| rmse_slope(f, gaussian, GAUSSIAN_INTEGRAL, SEEDS);
    let independent = slope(independent);
    assert!(
        (-0.6..=-0.4).contains(&independent),
        "independent {independent:.3}"
    );
    for (name, family, target) in [
        ("jittered", jittered as Family, -0.9),
        ("multi-jittered", multi_jittered, -0.9),
        ("sobol", sobol, -1.25),
    ] {
        let s = slope(family);
        assert!(s <= target, "{name}: slope {s:.3}, target ≤ {target}");
    }
}

/// Correlated multi-jittering (Kensler 2013) leaves the x–y interaction unstratified: a cell's x
/// offset depends only on its row, so on the Gaussian the RMSE falls only about as N^−0.76, worse
/// than plain jitter beyond N ≈ 256. Its measured slope must lie between plain random sampling
/// and multi-jitter: this records the blind spot, and would catch CMJ silently turning into
/// either.
#[test]
fn cmj_slope_shows_its_blind_spot() {
    let cmj = rmse_slope(cmj, gaussian, GAUSSIAN_INTEGRAL, SEEDS);
    let mj = rmse_slope(multi_jittered, gaussian, GAUSSIAN_INTEGRAL, SEEDS);
    assert!((-0.9..=-0.65).contains(&cmj), "cmj slope {cmj:.3}");
    assert!(
        mj < cmj - 0.15,
        "multi-jitter {mj:.3} should beat cmj {cmj:.3}"
    );
}

/// The disk indicator has a discontinuity, so stratification gains only N^−1/4 over random: at a
/// discontinuity the variance of jittered sampling in d dimensions falls as N^(−1−1/d) (Mitchell
/// 1996), so the RMSE as N^−3/4 in 2D; jittered and Owen-scrambled Sobol (Burley 2020) both
/// measure about −0.75.
#[test]
fn disk_slopes() {
    let slope = |f: Family| rmse_slope(f, disk_indicator, DISK_INTEGRAL, SEEDS);
    let independent = slope(independent);
    assert!(
        (-0.6..=-0.4).contains(&independent),
        "independent {independent:.3}"
    );
    for (name, family) in [
        ("jittered", jittered as Family),
        ("multi-jittered", multi_jittered),
        ("cmj", cmj),
        ("sobol", sobol),
    ] {
        let s = slope(family);
        assert!((-0.9..=-0.65).contains(&s), "{name}: disk slope {s:.3}");
    }
}

#[test]
fn slope_targets_reject_broken_sets() {
    let independent = rmse_slope(independent, gaussian, GAUSSIAN_INTEGRAL, SEEDS);
    assert!(
        independent > -0.9,
        "independent passes the jitter target: {independent:.3}"
    );
    let unpaired = rmse_slope(sobol_unpaired, gaussian, GAUSSIAN_INTEGRAL, SEEDS);
    assert!(
        unpaired > -1.25,
        "unpaired sobol passes the sobol target: {unpaired:.3}"
    );
}

#[test]
fn discrepancy_at_1024_meets_the_targets() {
    let sobol = discrepancy_ratio(sobol);
    assert!(sobol <= 0.12, "sobol: {sobol:.3} of iid");
    let jittered = discrepancy_ratio(jittered);
    assert!(jittered <= 0.35, "jittered: {jittered:.3} of iid");
    // The stronger stratifications sit between the two.
    for (name, family) in [("multi-jittered", multi_jittered as Family), ("cmj", cmj)] {
        let r = discrepancy_ratio(family);
        assert!(r <= 0.2, "{name}: {r:.3} of iid");
    }
}

#[test]
fn discrepancy_targets_reject_broken_sets() {
    let independent = discrepancy_ratio(independent);
    assert!(
        (0.8..1.2).contains(&independent),
        "independent: {independent:.3} of iid"
    );
    // A Latin hypercube alone is stratified per axis but not jointly.
    let latin = discrepancy_ratio(latin);
    assert!(
        latin > 0.35,
        "latin hypercube passes the jittered target: {latin:.3}"
    );
    let unpaired = discrepancy_ratio(sobol_unpaired);
    assert!(
        unpaired > 0.12,
        "unpaired sobol passes the sobol target: {unpaired:.3}"
    );
}
