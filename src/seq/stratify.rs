//! Stratified families: stratified / Latin hypercube, jittered, multi-jittered and correlated
//! multi-jittered, written once over [`U32Lane`].
//!
//! Three pieces carry them all:
//!
//! - [`U32Lane::div_rem`] splits an index into (round, position) and a cell into (row, column)
//!   (packets divide by a multiply, as they have no integer divide);
//! - [`permute`] is a keyed bijection of [0, n) (a hash on ⌈log₂ n⌉ bits, cycle-walked into
//!   range), which orders strata and shuffles sub-strata;
//! - [`in_stratum`] puts a hashed jitter inside stratum `s` of `n` so that the f32 result lies in
//!   [s/n, (s+1)/n) exactly, not just up to rounding.

use super::hash::{hash_keyed, tagged_keys};
use crate::lane::{U32Lane, V2};

/// The most strata one axis resolves: above 2²³, strata are narrower than the spacing of f32 near
/// 1 (2⁻²⁴), so one point per stratum can no longer be represented. Larger counts are clamped.
pub const MAX_STRATA: u32 = 1 << 23;

// Tags of the internal streams of one (dim, seed); see `tagged_keys`.
const TAG_ORDER: u32 = 1;
const TAG_JITTER_X: u32 = 2;
const TAG_JITTER_Y: u32 = 3;
const TAG_COLUMNS: u32 = 4;
const TAG_ROWS: u32 = 5;

/// ⌈log₂ n⌉ for n ≥ 1.
#[inline(always)]
fn ceil_log2(n: u32) -> u32 {
    32 - (n - 1).leading_zeros()
}

/// A keyed bijection of [0, n) for 1 ≤ n ≤ 2³¹, applied to `i < n`; each lane has its own key.
///
/// The core is a bijection of the ⌈log₂ n⌉-bit integers: three rounds of xor with a key,
/// multiplication by an odd constant and an xorshift, each masked to the width (every step is
/// invertible there). Values that land outside [0, n) are mapped again until they land inside
/// ("cycle walking"): the orbit of `i` under a permutation of the 2ᵏ values returns to `i < n`, so
/// this ends, after fewer than 2 rounds on average as n > 2ᵏ⁻¹. The packet repeats the map only
/// on lanes still outside, so every lane follows its scalar path.
#[inline(always)]
pub(crate) fn permute<U: U32Lane>(i: U, n: u32, key: U) -> U {
    let bits = ceil_log2(n);
    let w = U::splat(((1u64 << bits) - 1) as u32);
    let half = (bits >> 1).max(1);
    // Round keys whose low bits depend on all of `key`: the low k bits of a product depend only on
    // the low k bits of its factors, so the high bits are folded down first.
    let k1 = key;
    let k2 = key
        .xor(key.shr_by::<11>())
        .wrapping_mul(U::splat(0x2c1b_3c6d));
    let k3 = k2
        .xor(k2.shr_by::<13>())
        .wrapping_mul(U::splat(0x297a_2d39));
    let map = |x: U| {
        let x = x.xor(k1).wrapping_mul(U::splat(0xa136_aaad)).and(w);
        let x = x
            .xor(x.shr(half))
            .xor(k2)
            .wrapping_mul(U::splat(0x9e37_79b1))
            .and(w);
        let x = x
            .xor(x.shr(half))
            .xor(k3)
            .wrapping_mul(U::splat(0x7feb_352d))
            .and(w);
        x.xor(x.shr(half))
    };
    let last = U::splat(n - 1);
    let mut x = map(i);
    let mut outside = x.gt_mask(last);
    while outside.any_nonzero() {
        x = U::select(outside, map(x), x);
        outside = x.gt_mask(last);
    }
    x
}

/// A point of stratum `s` of `n` equal strata of [0, 1), jittered by the hash `h`: an f32 in
/// [s/n, (s+1)/n), for 1 ≤ n ≤ [`MAX_STRATA`] and s < n.
///
/// The jitter keeps b = 23 − ⌈log₂ n⌉ bits of `h` and is placed at the midpoint of its sub-cell,
/// so the value is t/D with integers t = s·2ᵇ⁺¹ + 2·jitter + 1 and D = n·2ᵇ⁺¹ ≤ 2²⁴, both exact
/// in f32. The quotient is correctly rounded and lies at least 1/D ≥ 2⁻²⁴ inside the stratum's
/// ends, more than the half-ulp (≤ 2⁻²⁵) rounding can move it, so ⌊x·n⌋ = s exactly and
/// x ≤ 1 − 2⁻²⁴.
#[inline(always)]
pub(crate) fn in_stratum<U: U32Lane>(s: U, n: u32, h: U) -> U::F {
    let b = 23 - ceil_log2(n);
    let jitter = h.shr_by::<1>().shr(31 - b);
    let t = s.shl(b + 1).xor(jitter.shl_by::<1>()).xor(U::splat(1));
    t.ratio(n << (b + 1))
}

/// (index mod n, the key of the round ⌊index/n⌋): every block of n consecutive indices is one
/// stratified set, with its own order.
#[inline(always)]
fn round<U: U32Lane>(index: U, n: u32, dim: u32, seed: u32) -> (U, U) {
    let (r, j) = index.div_rem(n);
    (j, hash_keyed(r, tagged_keys(dim, seed, TAG_ORDER)))
}

/// One point of a stratified set of `count` strata of [0, 1): index i lands in stratum
/// π(i mod count), π a hashed permutation of the round ⌊i/count⌋ and of `(dim, seed)`, with a
/// hashed jitter inside it.
///
/// Each dimension has its own permutation, so reading several dimensions of the same indices gives
/// a Latin hypercube ([`latin_hypercube`] is this function under the name of that property).
/// `count` is clamped to [1, [`MAX_STRATA`]]; every index, including 2³² − 1, gives a value in
/// [0, 1).
#[inline(always)]
pub fn stratified<I: U32Lane>(index: I, count: u32, dim: u32, seed: u32) -> I::F {
    let n = count.clamp(1, MAX_STRATA);
    let (j, key) = round(index, n, dim, seed);
    let s = permute(j, n, key);
    in_stratum(s, n, jitter(index, dim, seed, TAG_JITTER_X))
}

/// The grid of a 2D generator: nx in [1, 2²³], ny in [1, 2²³/nx], so the nx·ny cells (and the
/// multi-jittered sub-strata) fit [`MAX_STRATA`].
#[inline(always)]
fn grid(nx: u32, ny: u32) -> (u32, u32) {
    let nx = nx.clamp(1, MAX_STRATA);
    // nx ≥ 1, clamped just above.
    #[allow(clippy::integer_division)]
    (nx, ny.clamp(1, MAX_STRATA / nx))
}

/// The cell (column, row) of `index` in a hashed order, the round key, and the clamped grid.
#[inline(always)]
fn cell<U: U32Lane>(index: U, nx: u32, ny: u32, dim: u32, seed: u32) -> (U, U, U, u32, u32) {
    let (nx, ny) = grid(nx, ny);
    let (j, key) = round(index, nx * ny, dim, seed);
    let (row, column) = permute(j, nx * ny, key).div_rem(nx);
    (column, row, key, nx, ny)
}

/// The jitter of `index` in the stream `tag` of (dim, seed).
#[inline(always)]
fn jitter<U: U32Lane>(index: U, dim: u32, seed: u32, tag: u32) -> U {
    hash_keyed(index, tagged_keys(dim, seed, tag))
}

/// A point with x in stratum `sx` of `nx` and y in stratum `sy` of `ny`, each jittered by its own
/// stream: the last step of every 2D generator.
#[inline(always)]
fn place<U: U32Lane>(
    index: U,
    (sx, nx): (U, u32),
    (sy, ny): (U, u32),
    dim: u32,
    seed: u32,
) -> U::Vec2 {
    let x = in_stratum(sx, nx, jitter(index, dim, seed, TAG_JITTER_X));
    let y = in_stratum(sy, ny, jitter(index, dim, seed, TAG_JITTER_Y));
    V2::new(x, y).into()
}

/// One point of a Latin hypercube of `count` points: dimension `dim` of point `index`. Every
/// dimension is stratified into `count` strata, each visited once per round of `count` indices,
/// with independent permutations per dimension. The same function as [`stratified`].
#[inline(always)]
pub fn latin_hypercube<I: U32Lane>(index: I, count: u32, dim: u32, seed: u32) -> I::F {
    stratified(index, count, dim, seed)
}

/// One point of a jittered nx × ny grid: index i visits cell π(i mod nx·ny), π a hashed
/// permutation of the round and of `(dim, seed)`, at a hashed position inside it.
///
/// `dim` numbers dimension pairs. nx is clamped to [1, 2²³] and ny to [1, 2²³/nx].
#[inline(always)]
pub fn jittered_2d<I: U32Lane>(index: I, nx: u32, ny: u32, dim: u32, seed: u32) -> I::Vec2 {
    let (column, row, _, nx, ny) = cell(index, nx, ny, dim, seed);
    place(index, (column, nx), (row, ny), dim, seed)
}

/// One point of a multi-jittered set of nx·ny points (Chiu, Shirley and Wang 1994): jittered on
/// the nx × ny grid, and x and y each one point per 1/(nx·ny) stratum. The fine strata are
/// shuffled by an independent permutation per column and per row, so x and y do not share a
/// pattern.
///
/// `dim` numbers dimension pairs; the grid is clamped as in [`jittered_2d`].
#[inline(always)]
pub fn multi_jittered_2d<I: U32Lane>(index: I, nx: u32, ny: u32, dim: u32, seed: u32) -> I::Vec2 {
    multi_jitter(index, nx, ny, dim, seed, false)
}

/// Kensler's correlated multi-jitter (Pixar Technical Memo 13-01, 2013): the structure of
/// [`multi_jittered_2d`], but every column shares one permutation and every row another.
///
/// That makes a cell's fine x-offset a function of its row alone, so the x–y interaction is not
/// stratified: on smooth 2D integrands it converges more slowly than [`multi_jittered_2d`] at
/// large N (the report measures both). Kept because it is the well-known, widely used form.
#[inline(always)]
pub fn cmj_2d<I: U32Lane>(index: I, nx: u32, ny: u32, dim: u32, seed: u32) -> I::Vec2 {
    multi_jitter(index, nx, ny, dim, seed, true)
}

/// The body of [`multi_jittered_2d`] (`correlated = false`) and [`cmj_2d`] (`correlated = true`).
///
/// Cell (c, r) of the nx × ny grid takes x-sub-stratum c·ny + π_c(r) and y-sub-stratum
/// r·nx + ρ_r(c) of the n = nx·ny fine strata, where π_c permutes [0, ny) and ρ_r permutes [0, nx):
/// each column holds each fine x-stratum of its range once, so the x values are one per fine
/// stratum and one per column, and likewise for y. Multi-jitter draws π_c for every column and ρ_r
/// for every row independently; correlated multi-jitter (Kensler) uses one π and one ρ per set.
#[inline(always)]
fn multi_jitter<U: U32Lane>(
    index: U,
    nx: u32,
    ny: u32,
    dim: u32,
    seed: u32,
    correlated: bool,
) -> U::Vec2 {
    let (column, row, key, nx, ny) = cell(index, nx, ny, dim, seed);
    let (column_key, row_key) = if correlated {
        (key, key)
    } else {
        (key.xor(column), key.xor(row))
    };
    let pi = permute(
        row,
        ny,
        hash_keyed(column_key, tagged_keys(dim, seed, TAG_COLUMNS)),
    );
    let rho = permute(
        column,
        nx,
        hash_keyed(row_key, tagged_keys(dim, seed, TAG_ROWS)),
    );
    let n = nx * ny;
    let x_stratum = column.wrapping_mul(U::splat(ny)).wrapping_add(pi);
    let y_stratum = row.wrapping_mul(U::splat(nx)).wrapping_add(rho);
    place(index, (x_stratum, n), (y_stratum, n), dim, seed)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn permute_is_a_bijection() {
        for n in [1u32, 2, 3, 5, 16, 17, 100, 1000, 4097] {
            for key in [0u32, 1, 0xdead_beef, 0x8000_0000] {
                let mut seen = [false; 4097];
                for i in 0..n {
                    let p = permute(i, n, key);
                    assert!(p < n && !seen[p as usize], "n {n} key {key} i {i} -> {p}");
                    seen[p as usize] = true;
                }
            }
        }
    }

    #[test]
    fn in_stratum_stays_inside() {
        for n in [1u32, 3, 7, 1000, 4099, 1 << 22, MAX_STRATA - 1, MAX_STRATA] {
            for s in [0, 1, n / 2, n - 1] {
                let s = s.min(n - 1);
                for h in [0u32, 1, 0x8000_0000, u32::MAX] {
                    let x: f32 = in_stratum(s, n, h);
                    let cell = (x as f64 * n as f64).floor() as u32;
                    assert_eq!(cell, s, "n {n} s {s} h {h:#x} -> {x}");
                    assert!(x < 1.0);
                }
            }
        }
    }
}
