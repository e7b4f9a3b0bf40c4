//! `Pcg32x8` and `Pcg32x16` against `rand_pcg::Pcg32`, lane by lane: outputs, floats,
//! jump-ahead, a golden vector and a negative control for the comparison itself.

use super::golden::GOLDEN_PCG32;
use mcsample::rng::{Pcg32x8, Pcg32x16};
use rand_core::Rng;
use rand_pcg::Pcg32;

const STEPS: usize = 10_000;
const PCG_MULTIPLIER: u64 = 6_364_136_223_846_793_005;

/// SplitMix64, to draw seeds without depending on the generator under test. This file does not
/// use the other tests' `common::TestRng`: that is PCG32 itself (`rand_pcg::Pcg32`, the reference
/// here), so seeding from it would make the seed sets depend on the algorithm being checked.
fn splitmix(x: &mut u64) -> u64 {
    *x = x.wrapping_add(0x9e37_79b9_7f4a_7c15);
    let mut z = *x;
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// 64 seed sets of eight (state, stream) lanes: the first few hold 0, u64::MAX, equal streams
/// (and equal seeds) in different lanes; the rest are random.
fn seed_sets() -> Vec<([u64; 8], [u64; 8])> {
    let mut r = 1u64;
    let mut sets = vec![
        ([0; 8], [0; 8]),
        ([u64::MAX; 8], [u64::MAX; 8]),
        (
            [
                0,
                u64::MAX,
                1,
                u64::MAX - 1,
                1 << 63,
                42,
                0xcafe_f00d_d15e_a5e5,
                7,
            ],
            [54; 8],
        ),
        (
            [42; 8],
            [
                0,
                u64::MAX,
                1,
                1 << 63,
                (1 << 63) | 1,
                54,
                0x0a02_bdbf_7bb3_c0a7,
                2,
            ],
        ),
    ];
    while sets.len() < 64 {
        let states = core::array::from_fn(|_| splitmix(&mut r));
        let mut streams: [u64; 8] = core::array::from_fn(|_| splitmix(&mut r));
        if sets.len() % 3 == 0 {
            streams[5] = streams[2]; // equal streams in different lanes
        }
        sets.push((states, streams));
    }
    sets
}

/// Runs two eight-lane sources side by side for `steps` draws; the first differing (step, lane).
fn first_mismatch(
    steps: usize,
    mut got: impl FnMut() -> [u32; 8],
    mut want: impl FnMut() -> [u32; 8],
) -> Option<(usize, usize, u32, u32)> {
    for step in 0..steps {
        let (g, w) = (got(), want());
        if let Some(lane) = (0..8).find(|&l| g[l] != w[l]) {
            return Some((step, lane, g[lane], w[lane]));
        }
    }
    None
}

fn scalars(states: [u64; 8], streams: [u64; 8]) -> [Pcg32; 8] {
    core::array::from_fn(|i| Pcg32::new(states[i], streams[i]))
}

#[test]
fn lanes_match_rand_pcg_u32() {
    for (k, (states, streams)) in seed_sets().into_iter().enumerate() {
        let mut packet = Pcg32x8::new(states, streams);
        let mut refs = scalars(states, streams);
        let bad = first_mismatch(
            STEPS,
            || packet.next_u32x8().to_array(),
            || core::array::from_fn(|i| refs[i].next_u32()),
        );
        assert_eq!(bad, None, "seed set {k}: {states:x?} / {streams:x?}");
    }
}

#[test]
fn lanes_match_rand_pcg_f32() {
    for (k, (states, streams)) in seed_sets().into_iter().enumerate() {
        let mut packet = Pcg32x8::new(states, streams);
        let mut refs = scalars(states, streams);
        for step in 0..STEPS {
            let got = packet.next_f32x8().to_array();
            for (lane, r) in refs.iter_mut().enumerate() {
                let want = (r.next_u32() >> 8) as f32 * (1.0 / 16_777_216.0);
                assert_eq!(
                    got[lane].to_bits(),
                    want.to_bits(),
                    "seed set {k}, step {step}, lane {lane}"
                );
                assert!((0.0..1.0).contains(&got[lane]));
            }
        }
    }
}

/// A state whose next output is `u32::MAX` (rotation 0, all 32 xorshifted bits set), so the
/// float conversion meets its largest input.
fn state_with_max_output() -> u64 {
    let mut s = 0u64;
    for k in (27..=58).rev() {
        let above = if k + 18 < 64 { (s >> (k + 18)) & 1 } else { 0 };
        s |= (1 ^ above) << k;
    }
    s
}

#[test]
fn largest_output_maps_below_one() {
    let s = state_with_max_output();
    assert_eq!(Pcg32::from_state(s, 9).next_u32(), u32::MAX);
    let lanes = core::array::from_fn(|i| Pcg32::from_state(s, i as u64));
    let mut a = Pcg32x8::from_lanes(lanes.clone());
    assert_eq!(a.next_u32x8().to_array(), [u32::MAX; 8]);
    let mut b = Pcg32x8::from_lanes(lanes);
    let u = b.next_f32x8().to_array();
    assert_eq!(u, [1.0 - 1.0 / 16_777_216.0; 8]);
    assert!(u.iter().all(|&x| x < 1.0));
}

#[test]
fn golden_vector_lane0() {
    let mut packet = Pcg32x8::new([42, 0, 0, 0, 0, 0, 0, 0], [54, 1, 2, 3, 4, 5, 6, 7]);
    let got: [u32; 8] = core::array::from_fn(|_| packet.next_u32x8().to_array()[0]);
    assert_eq!(got, GOLDEN_PCG32);
}

#[test]
fn lane_view_and_from_lanes_roundtrip() {
    for (states, streams) in seed_sets().into_iter().take(16) {
        let mut packet = Pcg32x8::new(states, streams);
        for _ in 0..37 {
            packet.next_u32x8();
        }
        let mut views: [Pcg32; 8] = core::array::from_fn(|i| packet.lane(i));
        assert_eq!(Pcg32x8::from_lanes(views.clone()), packet);
        let bad = first_mismatch(
            1000,
            || packet.next_u32x8().to_array(),
            || core::array::from_fn(|i| views[i].next_u32()),
        );
        assert_eq!(bad, None);
    }
}

#[test]
fn advance_equals_stepping() {
    for (states, streams) in seed_sets().into_iter().take(8) {
        let start = Pcg32x8::new(states, streams);
        for d in [0u64, 1, 2, 3, 1000, 12_345] {
            let mut jumped = start;
            jumped.advance(d);
            let mut stepped = start;
            for _ in 0..d {
                stepped.next_u32x8();
            }
            assert_eq!(jumped, stepped, "delta {d}");
            assert_eq!(
                jumped.next_u32x8().to_array(),
                stepped.next_u32x8().to_array()
            );
        }
    }
}

/// Jump-ahead computed independently in the test: `delta` steps of `s ↦ M·s + c` by repeated
/// squaring of the affine map (a, b) ↦ (a², a·b + b), most significant bit first.
fn reference_advance(state: u64, increment: u64, delta: u64) -> u64 {
    // The affine map s ↦ a·s + b for `delta` steps, built by doubling and adding one step.
    let (mut a, mut b) = (1u64, 0u64);
    for bit in (0..64).rev() {
        // double: (a, b) ∘ (a, b) = (a², a·b + b)
        b = a.wrapping_mul(b).wrapping_add(b);
        a = a.wrapping_mul(a);
        if (delta >> bit) & 1 == 1 {
            // then one more step: s ↦ M·(a·s + b) + c
            a = PCG_MULTIPLIER.wrapping_mul(a);
            b = PCG_MULTIPLIER.wrapping_mul(b).wrapping_add(increment);
        }
    }
    a.wrapping_mul(state).wrapping_add(b)
}

#[test]
fn advance_large_deltas_match_references() {
    let mut r = 99u64;
    let mut deltas = vec![
        1u64 << 40,
        (1 << 40) + 12_345,
        1 << 63,
        u64::MAX,
        u64::MAX - 1,
    ];
    deltas.extend((0..20).map(|_| splitmix(&mut r)));
    for (states, streams) in seed_sets().into_iter().take(8) {
        let start = Pcg32x8::new(states, streams);
        for &d in &deltas {
            let mut jumped = start;
            jumped.advance(d);
            for i in 0..8 {
                let s0 = start.lane(i);
                let inc = (s0.stream() << 1) | 1;
                assert_eq!(
                    jumped.lane(i).state(),
                    reference_advance(s0.state(), inc, d),
                    "lane {i}, delta {d}"
                );
                // and rand_pcg's own jump-ahead
                let mut r = s0.clone();
                r.advance(d);
                assert_eq!(jumped.lane(i), r, "lane {i}, delta {d}");
            }
        }
    }
    // The test-local reference itself agrees with plain stepping.
    let (s, inc) = (0x1234_5678_9abc_def0u64, 0x55u64);
    let mut t = s;
    for d in 0..300u64 {
        assert_eq!(reference_advance(s, inc, d), t);
        t = t.wrapping_mul(PCG_MULTIPLIER).wrapping_add(inc);
    }
}

#[test]
fn advance_powers_of_two_compose() {
    let (states, streams) = seed_sets()[7];
    let start = Pcg32x8::new(states, streams);
    for k in 1..64 {
        let mut a = start;
        a.advance(1 << k);
        let mut b = start;
        b.advance((1 << k) - 1);
        b.advance(1);
        assert_eq!(a, b, "2^{k}");
    }
}

#[test]
fn full_period_returns_to_start() {
    for (states, streams) in seed_sets().into_iter().take(16) {
        let start = Pcg32x8::new(states, streams);
        let mut p = start;
        p.advance(u64::MAX);
        assert_ne!(p, start);
        p.next_u32x8();
        assert_eq!(p, start);
    }
}

/// A test-local scalar PCG32 with a configurable multiplier, for the negative control.
struct LocalPcg {
    state: u64,
    inc: u64,
    mult: u64,
}

impl LocalPcg {
    fn new(state: u64, stream: u64, mult: u64) -> Self {
        let inc = (stream << 1) | 1;
        let mut g = Self {
            state: state.wrapping_add(inc),
            inc,
            mult,
        };
        g.step();
        g
    }
    fn step(&mut self) {
        self.state = self.state.wrapping_mul(self.mult).wrapping_add(self.inc);
    }
    fn next(&mut self) -> u32 {
        let s = self.state;
        self.step();
        let xsh = (((s >> 18) ^ s) >> 27) as u32;
        xsh.rotate_right((s >> 59) as u32)
    }
}

#[test]
fn comparison_detects_a_wrong_multiplier() {
    for (k, (states, streams)) in seed_sets().into_iter().enumerate() {
        let run = |mult: u64| {
            let mut packet = Pcg32x8::new(states, streams);
            let mut local: Vec<LocalPcg> = (0..8)
                .map(|i| LocalPcg::new(states[i], streams[i], mult))
                .collect();
            first_mismatch(
                STEPS,
                || packet.next_u32x8().to_array(),
                || core::array::from_fn(|i| local[i].next()),
            )
        };
        // The faithful copy passes, so the helper is not simply failing everything ...
        assert_eq!(run(PCG_MULTIPLIER), None, "seed set {k}");
        // ... and a multiplier off by 4 (still ≡ 1 mod 4, a full-period LCG) is caught.
        assert!(run(PCG_MULTIPLIER + 4).is_some(), "seed set {k}");
    }
}

/// Sixteen lanes: two seed sets side by side, each lane against its own `rand_pcg::Pcg32`, in
/// u32 and f32 outputs, through the lane views and `from_lanes`, and after a jump.
#[test]
fn sixteen_lanes_match_rand_pcg() {
    let sets = seed_sets();
    for (k, pair) in sets.chunks_exact(2).enumerate() {
        let join = |a: [u64; 8], b: [u64; 8]| -> [u64; 16] {
            core::array::from_fn(|i| if i < 8 { a[i] } else { b[i - 8] })
        };
        let states = join(pair[0].0, pair[1].0);
        let streams = join(pair[0].1, pair[1].1);
        let mut packet = Pcg32x16::new(states, streams);
        let mut refs: [Pcg32; 16] = core::array::from_fn(|i| Pcg32::new(states[i], streams[i]));
        for step in 0..STEPS {
            let (u, f) = if step % 2 == 0 {
                (packet.next_u32x16().to_array(), None)
            } else {
                let f = packet.next_f32x16().to_array();
                ([0; 16], Some(f))
            };
            for (lane, r) in refs.iter_mut().enumerate() {
                let want = r.next_u32();
                match f {
                    None => assert_eq!(u[lane], want, "set {k}, step {step}, lane {lane}"),
                    Some(f) => assert_eq!(
                        f[lane].to_bits(),
                        ((want >> 8) as f32 * (1.0 / 16_777_216.0)).to_bits(),
                        "set {k}, step {step}, lane {lane}"
                    ),
                }
            }
        }
        let mut views: [Pcg32; 16] = core::array::from_fn(|i| packet.lane(i));
        assert_eq!(Pcg32x16::from_lanes(views.clone()), packet);
        let mut jumped = packet;
        jumped.advance(1000);
        for _ in 0..1000 {
            packet.next_u32x16();
        }
        assert_eq!(jumped, packet);
        let got = packet.next_u32x16().to_array();
        for v in &mut views {
            v.advance(1000);
        }
        assert_eq!(got, core::array::from_fn(|i| views[i].next_u32()));
    }
}
