//! The counter-based hash of `(index, dim, seed)`, and the independent stream it gives.

use crate::lane::U32Lane;

/// The lowbias32 integer finaliser: `x ^= x >> 16; x *= 0x7feb352d; x ^= x >> 15;
/// x *= 0x846ca68b; x ^= x >> 16`.
///
/// Source of the constants and shifts (a fact, not code): Chris Wellons, "Prospecting for Hash
/// Functions" (nullprogram.com, 2018) and his hash-prospector project, where this two-round
/// xorshift-multiply function is listed as `lowbias32`, found by a search that minimises avalanche
/// bias (≈ 0.17 in that project's measure).
/// It is a bijection of u32: xorshifts and odd multiplications are invertible.
#[inline(always)]
pub(crate) fn lowbias32<U: U32Lane>(x: U) -> U {
    let x = x.xor(x.shr_by::<16>()).wrapping_mul(U::splat(0x7feb_352d));
    let x = x.xor(x.shr_by::<15>()).wrapping_mul(U::splat(0x846c_a68b));
    x.xor(x.shr_by::<16>())
}

/// The golden-ratio constant ⌊2³²/φ⌋, used to keep (dim, seed) = (0, 0) away from the fixed point
/// 0 of lowbias32.
const GOLDEN: u32 = 0x9e37_79b9;

/// The keys of stream `(dim, seed)`: computed once per call, in scalar, for both widths.
#[inline(always)]
fn keys(dim: u32, seed: u32) -> (u32, u32) {
    let k1 = lowbias32(lowbias32(dim ^ GOLDEN) ^ seed);
    let k2 = lowbias32(k1.wrapping_add(GOLDEN));
    (k1, k2)
}

/// A 32-bit hash of `(index, dim, seed)` with full avalanche, and a bijection of `index` for a
/// fixed `(dim, seed)`.
///
/// The stream keys are `k1 = lowbias32(lowbias32(dim ^ 0x9e3779b9) ^ seed)` and
/// `k2 = lowbias32(k1 + 0x9e3779b9)`; the hash is `lowbias32(lowbias32(index ^ k1) + k2)`
/// (wrapping `+`). `lowbias32` is Wellons's two-round finaliser; two rounds on the index make
/// every input bit affect every output bit with probability close to ½.
#[inline(always)]
pub fn hash3<I: U32Lane>(index: I, dim: u32, seed: u32) -> I {
    hash_keyed(index, keys(dim, seed))
}

/// The `index`-th value of the independent uniform stream `(dim, seed)`: [`hash3`]`(index, dim,
/// seed)` as a 24-bit float in [0, 1).
///
/// Distinct indices give distinct values of the 32-bit hash (it is a bijection of `index` for a
/// fixed `(dim, seed)`), so the 24-bit outputs repeat only where 256 hashes share their top bits.
#[inline(always)]
pub fn independent<I: U32Lane>(index: I, dim: u32, seed: u32) -> I::F {
    hash3(index, dim, seed).to_unit_f32()
}

/// The keys of an internal stream: the keys of `(dim, seed)` mixed with a `tag`, so that the
/// generators' permutation and jitter streams are unrelated to each other and to
/// [`independent`]'s stream of the same `(dim, seed)`.
#[inline(always)]
pub(crate) fn tagged_keys(dim: u32, seed: u32, tag: u32) -> (u32, u32) {
    let (k1, _) = keys(dim, seed);
    let k1 = lowbias32(k1 ^ tag.wrapping_mul(GOLDEN));
    (k1, lowbias32(k1.wrapping_add(GOLDEN)))
}

/// The two-round hash of `index` under precomputed keys: [`hash3`]'s body.
#[inline(always)]
pub(crate) fn hash_keyed<U: U32Lane>(index: U, (k1, k2): (u32, u32)) -> U {
    lowbias32(lowbias32(index.xor(U::splat(k1))).wrapping_add(U::splat(k2)))
}
