//! Random numbers in packets: [`Pcg32x8`], eight PCG32 streams advanced together, and
//! [`Pcg32x16`], sixteen as two such packets.
//!
//! # Algorithm
//!
//! Each lane is the standard `pcg32` generator (PCG XSH RR 64/32, O'Neill 2014): a 64-bit linear
//! congruential state
//!
//! ```text
//! state' = state · 6364136223846793005 + increment   (mod 2⁶⁴), increment odd
//! ```
//!
//! and a 32-bit output taken from the state *before* the step by the "xorshift high, random
//! rotate" permutation:
//!
//! ```text
//! xsh = ((state ^ (state >> 18)) >> 27) as u32,  rot = (state >> 59) as u32,
//! out = xsh.rotate_right(rot)
//! ```
//!
//! The packet's layout is chosen at compile time, since the instructions that make it fast differ:
//! - with AVX2, or off x86-64 (NEON, wasm), each 64-bit state is two [`U32x8`] halves, stepped
//!   with 32-bit lane operations: one widening multiply of the low words, two wrapping multiplies
//!   for the cross terms, and an add with carry (`lanes32.rs`);
//! - on x86-64 without AVX2 (SSE2 only), which has neither a 32-bit lane multiply nor a per-lane
//!   shift, the states are four pairs of 64-bit lanes, stepped with `pmuludq`, the 32×32→64
//!   multiply of SSE2, and rotated by a 64-bit shift of the output doubled into both halves
//!   (`sse2.rs`).
//!
//! Both are exact modulo 2⁶⁴ and give the same values. See `benches/sequences.rs` and
//! BENCHMARKS.md for their speed against scalar `rand_pcg` generators.
//!
//! # Equivalence with `rand_pcg`
//!
//! Lane *i* of `Pcg32x8::new(states, streams)` produces exactly the sequence of
//! `rand_pcg::Pcg32::new(states[i], streams[i])`'s `next_u32`, in every build (the arithmetic is
//! integer and exact). [`Pcg32x8::lane`] returns lane *i* as a `rand_pcg::Pcg32` positioned at the
//! same point of its sequence, which implements `rand_core`'s `Rng` for code that wants a scalar
//! generator, and [`Pcg32x8::from_lanes`] goes the other way.
//!
//! # Floats
//!
//! [`Pcg32x8::next_f32x8`] maps a 32-bit output `x` to `(x >> 8) · 2⁻²⁴`: the 2²⁴ values
//! `0, 2⁻²⁴, …, 1 − 2⁻²⁴`, each with probability 2⁻²⁴, exactly representable in f32, so the
//! result is in [0, 1) and is never 1.0.

use crate::lane::{F32x8, F32x16, U32Lane, U32x8, U32x16, lane_of, zip_map};
use rand_pcg::Pcg32;
use wide::bytemuck;

#[cfg(not(all(target_arch = "x86_64", not(target_feature = "avx2"))))]
#[path = "lanes32.rs"]
mod layout;
#[cfg(all(target_arch = "x86_64", not(target_feature = "avx2")))]
#[path = "sse2.rs"]
mod layout;

/// The PCG multiplier for 64-bit state (the same constant as `rand_pcg`).
const MULTIPLIER: u64 = 6_364_136_223_846_793_005;

/// Eight independent PCG32 (XSH RR 64/32) generators, one per lane, stepped together.
///
/// Lane *i* is bit-for-bit `rand_pcg::Pcg32::new(states[i], streams[i])`; see the
/// [module documentation](self) for the algorithm and the float contract.
///
/// ```
/// use mcsample::rng::Pcg32x8;
/// use rand_core::Rng;
///
/// let mut packet = Pcg32x8::new([1, 2, 3, 4, 5, 6, 7, 8], [54; 8]);
/// let mut scalar = rand_pcg::Pcg32::new(3, 54);
/// let first = packet.next_u32x8().to_array();
/// assert_eq!(first[2], scalar.next_u32());
/// let u = packet.next_f32x8().to_array();
/// assert_eq!(u[2], (scalar.next_u32() >> 8) as f32 / (1u32 << 24) as f32);
/// assert!(u.iter().all(|&x| (0.0..1.0).contains(&x)));
/// ```
#[derive(Clone, Copy)]
pub struct Pcg32x8 {
    /// Each lane's state, in the target's layout.
    state: layout::Words,
    /// Each lane's (odd) increment, in the same layout.
    inc: layout::Words,
}

impl PartialEq for Pcg32x8 {
    fn eq(&self, other: &Self) -> bool {
        self.raw() == other.raw()
    }
}

impl core::fmt::Debug for Pcg32x8 {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let (states, incs) = self.raw();
        f.debug_struct("Pcg32x8")
            .field("states", &states)
            .field("increments", &incs)
            .finish()
    }
}

impl Pcg32x8 {
    /// Eight generators: lane *i* equals `rand_pcg::Pcg32::new(states[i], streams[i])`.
    ///
    /// As there, the increment is `(stream << 1) | 1` (the top bit of a stream is discarded), and
    /// the state is moved away from the seed by `state = (state + increment)`, then one step.
    /// Any values are allowed, including equal streams in different lanes.
    pub fn new(states: [u64; 8], streams: [u64; 8]) -> Self {
        let incs = streams.map(|s| (s << 1) | 1);
        let states = zip_map(states, incs, |s, inc| {
            s.wrapping_add(inc)
                .wrapping_mul(MULTIPLIER)
                .wrapping_add(inc)
        });
        Self::from_raw(states, incs)
    }

    /// The packet whose lane *i* continues `lanes[i]` from its current position (the inverse of
    /// [`lane`](Self::lane)).
    pub fn from_lanes(lanes: [Pcg32; 8]) -> Self {
        Self::from_raw(
            lanes.clone().map(|g| g.state()),
            lanes.map(|g| (g.stream() << 1) | 1),
        )
    }

    /// Lane `i` as a scalar `rand_pcg::Pcg32` at the same position: its `next_u32` (from
    /// `rand_core::Rng`) returns what lane `i` of the next [`next_u32x8`](Self::next_u32x8)
    /// would. A copy: stepping it does not step the packet. Larger `i` wrap (`i mod 8`).
    pub fn lane(&self, i: usize) -> Pcg32 {
        let (states, incs) = self.raw();
        Pcg32::from_state(lane_of(&states, i), lane_of(&incs, i) >> 1)
    }

    /// The next 32-bit output of every lane, then one step of every lane.
    #[inline]
    pub fn next_u32x8(&mut self) -> U32x8 {
        layout::next(&mut self.state, &self.inc)
    }

    /// The next output of every lane as a float in [0, 1): `(x >> 8) · 2⁻²⁴` for the 32-bit
    /// output `x` that [`next_u32x8`](Self::next_u32x8) would return. Exact, and never 1.0.
    #[inline]
    pub fn next_f32x8(&mut self) -> F32x8 {
        self.next_u32x8().to_unit_f32()
    }

    /// Jumps every lane ahead by `delta` steps, as if [`next_u32x8`](Self::next_u32x8) had been
    /// called `delta` times, in O(log delta) scalar work (Brown, "Random Number Generation with
    /// Arbitrary Stride", 1994, as in PCG's `pcg_advance_lcg_64`).
    ///
    /// `delta` steps of the LCG compose to `s ↦ A·s + C·inc` with `A = M^delta` and
    /// `C = 1 + M + … + M^(delta−1)`, both independent of the lane, found by square-and-multiply
    /// over the bits of `delta`. Since the period is 2⁶⁴, `advance(u64::MAX)` followed by one
    /// step returns every lane to where it was, i.e. `advance(u64::MAX)` steps back by one.
    pub fn advance(&mut self, delta: u64) {
        let (mult, plus) = lcg_jump(delta);
        let (states, incs) = self.raw();
        let states = zip_map(states, incs, |s, inc| {
            mult.wrapping_mul(s).wrapping_add(plus.wrapping_mul(inc))
        });
        *self = Self::from_raw(states, incs);
    }

    fn from_raw(states: [u64; 8], incs: [u64; 8]) -> Self {
        Self {
            state: layout::Words::new(states),
            inc: layout::Words::new(incs),
        }
    }

    fn raw(&self) -> ([u64; 8], [u64; 8]) {
        (self.state.get(), self.inc.get())
    }
}

/// Sixteen independent PCG32 generators, lane *i* bit-for-bit
/// `rand_pcg::Pcg32::new(states[i], streams[i])`: lanes 0–7 and 8–15 are two [`Pcg32x8`], whose
/// outputs fill the two halves of a sixteen-wide packet.
///
/// The state is 64 bits per lane, so sixteen lanes are two registers of eight 64-bit words
/// even with AVX-512; the eight-wide layouts already step them in the best form each target
/// has.
///
/// ```
/// use mcsample::rng::Pcg32x16;
/// use rand_core::Rng;
///
/// let mut packet = Pcg32x16::new(core::array::from_fn(|i| i as u64), [54; 16]);
/// let mut scalar = rand_pcg::Pcg32::new(13, 54);
/// assert_eq!(packet.next_u32x16().to_array()[13], scalar.next_u32());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pcg32x16 {
    /// Lanes 0–7 and 8–15.
    halves: [Pcg32x8; 2],
}

impl Pcg32x16 {
    /// Sixteen generators: lane *i* equals `rand_pcg::Pcg32::new(states[i], streams[i])`, with
    /// [`Pcg32x8::new`]'s seeding.
    pub fn new(states: [u64; 16], streams: [u64; 16]) -> Self {
        let half = |k: usize| {
            let pick = |a: [u64; 16]| core::array::from_fn(|i| lane_of(&a, i + 8 * k));
            Pcg32x8::new(pick(states), pick(streams))
        };
        Self {
            halves: [half(0), half(1)],
        }
    }

    /// The packet whose lane *i* continues `lanes[i]` from its current position.
    pub fn from_lanes(lanes: [Pcg32; 16]) -> Self {
        let states = lanes.clone().map(|g| g.state());
        let incs = lanes.map(|g| (g.stream() << 1) | 1);
        let half = |k: usize| {
            let pick = |a: [u64; 16]| core::array::from_fn(|i| lane_of(&a, i + 8 * k));
            Pcg32x8::from_raw(pick(states), pick(incs))
        };
        Self {
            halves: [half(0), half(1)],
        }
    }

    /// Lane `i` as a scalar `rand_pcg::Pcg32` at the same position (`i mod 16`), as
    /// [`Pcg32x8::lane`].
    pub fn lane(&self, i: usize) -> Pcg32 {
        let [lo, hi] = &self.halves;
        if i & 8 == 0 { lo.lane(i) } else { hi.lane(i) }
    }

    /// The next 32-bit output of every lane, then one step of every lane.
    #[inline]
    pub fn next_u32x16(&mut self) -> U32x16 {
        let [lo, hi] = &mut self.halves;
        bytemuck::cast([lo.next_u32x8(), hi.next_u32x8()])
    }

    /// The next output of every lane as a float in [0, 1), as [`Pcg32x8::next_f32x8`].
    #[inline]
    pub fn next_f32x16(&mut self) -> F32x16 {
        self.next_u32x16().to_unit_f32()
    }

    /// Jumps every lane ahead by `delta` steps, as [`Pcg32x8::advance`].
    pub fn advance(&mut self, delta: u64) {
        for h in &mut self.halves {
            h.advance(delta);
        }
    }
}

/// `(M^delta, 1 + M + … + M^(delta−1))` modulo 2⁶⁴: `delta` LCG steps are
/// `s ↦ mult·s + plus·inc`.
fn lcg_jump(mut delta: u64) -> (u64, u64) {
    let (mut acc_mult, mut acc_plus) = (1u64, 0u64);
    // (cur_mult, cur_plus): the map for 2^k steps, with unit increment.
    let (mut cur_mult, mut cur_plus) = (MULTIPLIER, 1u64);
    while delta > 0 {
        if delta & 1 != 0 {
            acc_mult = acc_mult.wrapping_mul(cur_mult);
            acc_plus = acc_plus.wrapping_mul(cur_mult).wrapping_add(cur_plus);
        }
        cur_plus = cur_mult.wrapping_add(1).wrapping_mul(cur_plus);
        cur_mult = cur_mult.wrapping_mul(cur_mult);
        delta >>= 1;
    }
    (acc_mult, acc_plus)
}
