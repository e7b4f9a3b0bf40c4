//! Owen-scrambled Sobol points by hashing (Burley, "Practical Hash-based Owen Scrambling",
//! JCGT 9(4), 2020), written once over [`U32Lane`].
//!
//! # Construction
//!
//! Dimension `dim` belongs to the set ⌊dim/4⌋ and uses Sobol dimension dim mod 4: the bit-reversed
//! index (van der Corput) for 0 and the first three Joe–Kuo dimensions for 1–3. Each set has its
//! own seed, so sets are independent scrambles: this is the padding that reaches any dimension.
//!
//! 1. The index is shuffled by a nested uniform scramble of its bits, seeded per set. It sends
//!    the first 2ᵐ indices onto an aligned block of 2ᵐ Sobol indices, which is itself a
//!    (0, m, 2)-net in dimensions 0 and 1, so every power-of-two prefix stays a net.
//! 2. The Sobol value is the GF(2) product of the generator matrix and the index bits.
//! 3. The value is Owen-scrambled, seeded per dimension.
//!
//! A nested uniform scramble flips each bit with a coin that depends on the seed and on the bits
//! above it. In bit-reversed order that is "each bit depends on the bits below", which additions
//! and multiplications have: Burley's hash `x += seed; x ^= x·c₁; …` (the Laine–Karras
//! construction with his constants, all `x ^= x·c` with c even so each step is invertible).
//! The whole pipeline is kept in reversed order so that only one reversal is needed per
//! scramble: the matrix columns are stored bit-reversed and indexed from the top bit. Dimensions
//! 0 and 1 (van der Corput and Pascal) need no matrix at all; 2 and 3 take four lookups in byte
//! tables of their columns' xors (8 KB in all).

use super::hash::lowbias32;
use crate::lane::{U32Lane, V2};

/// Joe–Kuo ("Constructing Sobol sequences with better two-dimensional projections", SIAM J. Sci.
/// Comput. 30, 2008; file new-joe-kuo-6.21201) parameters of their dimensions 2, 3 and 4: degree
/// s, coefficient bits a and initial direction integers m₁…m_s.
const JOE_KUO: [(u32, u32, [u32; 3]); 3] =
    [(1, 0, [1, 0, 0]), (2, 1, [1, 3, 0]), (3, 1, [1, 3, 1])];

/// The 32 direction numbers vₖ = mₖ·2³²⁻ᵏ of a Joe–Kuo dimension, from the recurrence
/// mₖ = 2ˢ·mₖ₋ₛ ⊕ mₖ₋ₛ ⊕ (⊕ᵢ₌₁..ₛ₋₁ 2ⁱ·aᵢ·mₖ₋ᵢ), aᵢ the i-th bit of a from the top of its s − 1 bits.
// Evaluated into constants only: an index out of range there is a compile error, not a
// run-time panic, and the loop bounds keep every index in range.
#[allow(clippy::indexing_slicing)]
const fn direction_numbers(s: u32, a: u32, init: [u32; 3]) -> [u32; 32] {
    let mut m = [0u32; 33]; // m[k] for k = 1..=32
    let mut k = 1;
    while k <= 32 {
        m[k] = if k <= s as usize {
            init[k - 1]
        } else {
            let mut x = (m[k - s as usize] << s) ^ m[k - s as usize];
            let mut i = 1;
            while i < s {
                let a_i = (a >> (s - 1 - i)) & 1;
                x ^= (a_i * m[k - i as usize]) << i;
                i += 1;
            }
            x
        };
        k += 1;
    }
    let mut v = [0u32; 32];
    let mut k = 1;
    while k <= 32 {
        // mₖ is odd and below 2ᵏ: shifted to the top, its lowest set bit is bit 32 − k.
        v[k - 1] = m[k] << (32 - k);
        k += 1;
    }
    v
}

/// The generator matrices of dimensions 2 and 3 (Joe–Kuo's 3 and 4) as byte tables. Column p of
/// a matrix is the bit-reversed direction number v_{p+1}, the contribution of index bit p, which
/// is bit 31 − p of the bit-reversed index. Entry b of table j is the xor of the columns of the
/// bits of byte j of that index (bits 31 − 8j down to 24 − 8j, bit 7 − i of b being column
/// 8j + i): four lookups instead of 32 column steps. Dimension 1 needs no table (see [`pascal`]).
// Evaluated into constants only: an index out of range there is a compile error, not a
// run-time panic, and the loop bounds keep every index in range.
#[allow(clippy::indexing_slicing)]
static TABLES: [[[u32; 256]; 4]; 2] = {
    let mut out = [[[0u32; 256]; 4]; 2];
    let mut d = 0;
    while d < 2 {
        let (s, a, init) = JOE_KUO[d + 1];
        let v = direction_numbers(s, a, init);
        let mut j = 0;
        while j < 4 {
            let mut b = 0;
            while b < 256 {
                let mut i = 0;
                while i < 8 {
                    if (b >> (7 - i)) & 1 == 1 {
                        out[d][j][b] ^= v[8 * j + i].reverse_bits();
                    }
                    i += 1;
                }
                b += 1;
            }
            j += 1;
        }
        d += 1;
    }
    out
};

/// The GF(2) product of a generator matrix (as its byte tables) and a bit-reversed index.
#[inline(always)]
fn matrix_product(tables: &[[u32; 256]; 4], reversed_index: u32) -> u32 {
    let [t0, t1, t2, t3] = tables;
    // The mask keeps every index below 256, so the lookups cannot miss.
    let at = |t: &[u32; 256], shift: u32| {
        t.get(((reversed_index >> shift) & 0xff) as usize)
            .copied()
            .unwrap_or(0)
    };
    at(t0, 24) ^ at(t1, 16) ^ at(t2, 8) ^ at(t3, 0)
}

/// Burley's hash in reversed-bit order: a nested uniform scramble of the bit-reversed value.
#[inline(always)]
fn scramble_reversed<U: U32Lane>(x: U, seed: u32) -> U {
    let x = x.wrapping_add(U::splat(seed));
    let x = x.xor(x.wrapping_mul(U::splat(0x6c50_b47c)));
    let x = x.xor(x.wrapping_mul(U::splat(0xb82f_1e52)));
    let x = x.xor(x.wrapping_mul(U::splat(0xc7af_e638)));
    x.xor(x.wrapping_mul(U::splat(0x8d22_f6e6)))
}

/// Sobol dimension 1 without its matrix loop. Its generator matrix is Pascal's triangle mod 2
/// (mₖ = 2mₖ₋₁ ⊕ mₖ₋₁): digit r of the value is the xor of the index bits c with binom(c, r) odd,
/// which by Lucas's theorem are the c whose bits include r's. In reversed order (digit r at bit
/// r) that xor over supersets is five shift-and-mask steps, one per bit of the position, instead
/// of 32 column steps.
#[inline(always)]
fn pascal<U: U32Lane>(index: U) -> U {
    let x = index;
    let x = x.xor(x.shr_by::<1>().and(U::splat(0x5555_5555)));
    let x = x.xor(x.shr_by::<2>().and(U::splat(0x3333_3333)));
    let x = x.xor(x.shr_by::<4>().and(U::splat(0x0f0f_0f0f)));
    let x = x.xor(x.shr_by::<8>().and(U::splat(0x00ff_00ff)));
    x.xor(x.shr_by::<16>().and(U::splat(0x0000_ffff)))
}

/// The seeds of a dimension: (index shuffle of its set, value scramble of the dimension).
#[inline(always)]
fn seeds(dim: u32, seed: u32) -> (u32, u32) {
    let set_seed = lowbias32(lowbias32(seed ^ 0x5851_f42d) ^ (dim >> 2));
    let index_seed = lowbias32(set_seed ^ 0x0bad_5eed);
    let value_seed = lowbias32(set_seed.wrapping_add(dim % 4 + 1));
    (index_seed, value_seed)
}

/// The 32-bit Owen-scrambled Sobol value of `index` in dimension `dim` for `seed`.
#[inline(always)]
pub(crate) fn sobol_bits<U: U32Lane>(index: U, dim: u32, seed: u32) -> U {
    let (index_seed, value_seed) = seeds(dim, seed);
    // The shuffled index, still bit-reversed: its top bit is the index's bit 0.
    let reversed_index = scramble_reversed(index.reverse_bits(), index_seed);
    let reversed_value = match dim % 4 {
        // Dimension 0 is the van der Corput sequence: the reversed value is the index itself.
        0 => reversed_index.reverse_bits(),
        1 => pascal(reversed_index.reverse_bits()),
        // Packets have no gather: they look the tables up lane by lane.
        d => {
            let [tables2, tables3] = &TABLES;
            let tables = if d == 2 { tables2 } else { tables3 };
            reversed_index.map(|x| matrix_product(tables, x))
        }
    };
    scramble_reversed(reversed_value, value_seed).reverse_bits()
}

/// Owen-scrambled Sobol (Burley 2020): dimension `dim` of point `index`, for `seed`.
///
/// Dimensions 0 and 1 of one seed form a (0, m, 2)-net for every prefix of N = 2ᵐ indices, and
/// every dimension alone is one point per 1/N stratum for such N. Dimensions go in sets of four
/// with independent seeds (padding), so any `dim` works. The module notes above give the
/// construction.
#[inline(always)]
pub fn sobol<I: U32Lane>(index: I, dim: u32, seed: u32) -> I::F {
    sobol_bits(index, dim, seed).to_unit_f32()
}

/// Dimensions 2·`dim` and 2·`dim` + 1 of [`sobol`]: `sobol_2d(i, 0, seed)` is the net.
#[inline(always)]
pub fn sobol_2d<I: U32Lane>(index: I, dim: u32, seed: u32) -> I::Vec2 {
    let d = dim.wrapping_mul(2);
    V2::new(sobol(index, d, seed), sobol(index, d.wrapping_add(1), seed)).into()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The five-step Pascal form of dimension 1 is the GF(2) product with Joe–Kuo dimension 2's
    /// direction numbers, on the reversed-value convention of the pipeline.
    #[test]
    fn pascal_is_the_matrix_product() {
        let (s, a, init) = JOE_KUO[0];
        let v = direction_numbers(s, a, init);
        let mut x = 0x2545_f491u32;
        for _ in 0..100_000 {
            x = x.wrapping_mul(747_796_405).wrapping_add(2_891_336_453);
            let product = (0..32)
                .filter(|b| (x >> b) & 1 == 1)
                .fold(0, |acc, b| acc ^ v[b]);
            assert_eq!(pascal(x), product.reverse_bits(), "index {x:#x}");
        }
    }

    /// The direction integers mₖ, k = 1..8, of Joe–Kuo dimensions 2–4, worked by hand from the
    /// published (s, a, m) and the paper's recurrence (the first two rows are also the classic
    /// Bratley–Fox values).
    #[test]
    fn direction_integers_match_the_published_ones() {
        let expected: [[u32; 8]; 3] = [
            [1, 3, 5, 15, 17, 51, 85, 255],
            [1, 3, 3, 9, 29, 23, 71, 197],
            [1, 3, 1, 5, 31, 29, 81, 147],
        ];
        for (d, want) in expected.iter().enumerate() {
            let (s, a, init) = JOE_KUO[d];
            let v = direction_numbers(s, a, init);
            for k in 1..=8usize {
                assert_eq!(v[k - 1] >> (32 - k), want[k - 1], "dim {} k {k}", d + 1);
            }
        }
    }
}
