//! Lane equality: a packet function of either width against its scalar twin, lane by lane, bit
//! for bit.
//!
//! See the [module documentation](super) for an example.

use core::fmt;

use glam::{Vec2, Vec3};
use std::boxed::Box;
use std::format;
use std::string::String;
use std::vec::Vec;

use crate::x8::{F32x8, U32x8, Vec2x8, Vec3x8};
use crate::x16::{F32x16, U32x16, Vec2x16, Vec3x16};

/// A value whose identity is its bit pattern: the f32 and u32 components, in order.
///
/// f32 components are compared through `to_bits`, so 0.0 and −0.0 differ, and NaNs compare
/// equal only when their bit patterns (sign and payload included) are identical.
pub trait Bits {
    /// Append the bit patterns of the components to `out`.
    fn push_bits(&self, out: &mut Vec<u32>);

    /// The bit patterns of the components.
    fn bits(&self) -> Vec<u32> {
        let mut out = Vec::new();
        self.push_bits(&mut out);
        out
    }
}

impl Bits for f32 {
    fn push_bits(&self, out: &mut Vec<u32>) {
        out.push(self.to_bits());
    }
}

impl Bits for u32 {
    fn push_bits(&self, out: &mut Vec<u32>) {
        out.push(*self);
    }
}

impl Bits for Vec2 {
    fn push_bits(&self, out: &mut Vec<u32>) {
        out.extend([self.x.to_bits(), self.y.to_bits()]);
    }
}

impl Bits for Vec3 {
    fn push_bits(&self, out: &mut Vec<u32>) {
        out.extend([self.x.to_bits(), self.y.to_bits(), self.z.to_bits()]);
    }
}

/// A scalar value with packet twins of eight and sixteen lanes: how [`check_lanes`] and
/// [`check_lanes16`] split packets into lanes and build them back.
///
/// Implemented for `f32` ([`F32x8`], [`F32x16`]), `u32` ([`U32x8`], [`U32x16`]),
/// [`glam::Vec2`] ([`Vec2x8`], [`Vec2x16`]), [`glam::Vec3`] ([`Vec3x8`], [`Vec3x16`]), and tuples
/// of up to three of them (tuples of packets), which is how a function of several arguments or
/// results is checked.
pub trait Scalar: Copy + fmt::Debug + Bits {
    /// The packet of eight values.
    type X8: Copy;
    /// The packet of sixteen values.
    type X16: Copy;
    /// The packet whose lane `i` is `lanes[i]`.
    fn pack(lanes: [Self; 8]) -> Self::X8;
    /// The eight lanes of a packet.
    fn unpack(packet: Self::X8) -> [Self; 8];
    /// The sixteen-wide packet whose lane `i` is `lanes[i]`.
    fn pack16(lanes: [Self; 16]) -> Self::X16;
    /// The sixteen lanes of a packet.
    fn unpack16(packet: Self::X16) -> [Self; 16];
}

macro_rules! scalar_impls {
    ($($s:ty => $p:ty, $q:ty),+) => {$(
        impl Scalar for $s {
            type X8 = $p;
            type X16 = $q;
            fn pack(lanes: [Self; 8]) -> $p {
                <$p>::from(lanes)
            }
            fn unpack(packet: $p) -> [Self; 8] {
                packet.to_array()
            }
            fn pack16(lanes: [Self; 16]) -> $q {
                <$q>::from(lanes)
            }
            fn unpack16(packet: $q) -> [Self; 16] {
                packet.to_array()
            }
        }
    )+};
}

scalar_impls!(
    f32 => F32x8, F32x16,
    u32 => U32x8, U32x16,
    Vec2 => Vec2x8, Vec2x16,
    Vec3 => Vec3x8, Vec3x16
);

macro_rules! tuple_impls {
    ($(($($t:ident $i:tt),+))+) => {$(
        impl<$($t: Bits),+> Bits for ($($t,)+) {
            fn push_bits(&self, out: &mut Vec<u32>) {
                $(self.$i.push_bits(out);)+
            }
        }

        impl<$($t: Scalar),+> Scalar for ($($t,)+) {
            type X8 = ($($t::X8,)+);
            type X16 = ($($t::X16,)+);
            fn pack(lanes: [Self; 8]) -> Self::X8 {
                ($($t::pack(lanes.map(|l| l.$i)),)+)
            }
            fn unpack(packet: Self::X8) -> [Self; 8] {
                let split = ($($t::unpack(packet.$i),)+);
                core::array::from_fn(|k| ($(split.$i[k],)+))
            }
            fn pack16(lanes: [Self; 16]) -> Self::X16 {
                ($($t::pack16(lanes.map(|l| l.$i)),)+)
            }
            fn unpack16(packet: Self::X16) -> [Self; 16] {
                let split = ($($t::unpack16(packet.$i),)+);
                core::array::from_fn(|k| ($(split.$i[k],)+))
            }
        }
    )+};
}

tuple_impls! {
    (A 0)
    (A 0, B 1)
    (A 0, B 1, C 2)
}

/// The first lane where a packet function and its scalar twin disagree, returned by
/// [`check_lanes`]. Its `Display` prints everything below.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LaneMismatch {
    /// Index into the inputs of the first mismatching lane's input.
    pub index: usize,
    /// Lane of the packet in which it was evaluated (`index` modulo the width).
    pub lane: usize,
    /// The input, Debug-formatted.
    pub input: String,
    /// The packet function's output in that lane, Debug-formatted.
    pub packet: String,
    /// The scalar function's output, Debug-formatted.
    pub scalar: String,
    /// Bit patterns of the packet output's components.
    pub packet_bits: Vec<u32>,
    /// Bit patterns of the scalar output's components.
    pub scalar_bits: Vec<u32>,
    /// How many lanes disagreed in total.
    pub mismatches: usize,
    /// How many lanes were compared.
    pub checked: usize,
}

impl fmt::Display for LaneMismatch {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let hex = |b: &[u32]| {
            b.iter()
                .map(|w| format!("{w:#010x}"))
                .collect::<Vec<_>>()
                .join(", ")
        };
        write!(
            f,
            "packet != scalar in {} of {} lanes; first at input {} (lane {}): input {}: \
             packet {} [{}] vs scalar {} [{}]",
            self.mismatches,
            self.checked,
            self.index,
            self.lane,
            self.input,
            self.packet,
            hex(&self.packet_bits),
            self.scalar,
            hex(&self.scalar_bits),
        )
    }
}

impl std::error::Error for LaneMismatch {}

/// Check that lane *i* of the eight-wide `packet` equals `scalar` applied to lane *i*'s input,
/// bit for bit, for every input.
///
/// The inputs are packed eight at a time in order (input `j` goes to lane `j % 8`); when their
/// number is not a multiple of 8 the last packet is filled by repeating the inputs from the
/// start, and those lanes are checked too. Outputs are compared through [`Bits`]: exact bit
/// patterns, NaNs included (a NaN with another sign or payload is a mismatch; the crate's
/// contract is bit equality, and its packet and scalar forms run the same operations).
///
/// The scalar inputs fix the types, so the crate's generic functions can be passed as they are:
/// `check_lanes(&us, warp::concentric_disk, warp::concentric_disk)`. Several arguments or
/// results: use tuples, e.g. scalar input `(Vec2, f32)` and packet input `(Vec2x8, F32x8)`.
///
/// Returns the number of lanes compared (the number of inputs rounded up to a multiple of 8), or
/// the first mismatch with the total count of mismatching lanes (boxed, as it is large).
pub fn check_lanes<S, T>(
    inputs: &[S],
    mut packet: impl FnMut(S::X8) -> T::X8,
    scalar: impl FnMut(S) -> T,
) -> Result<usize, Box<LaneMismatch>>
where
    S: Scalar,
    T: Scalar,
{
    check_width(inputs, |l: [S; 8]| T::unpack(packet(S::pack(l))), scalar)
}

/// [`check_lanes`] for a sixteen-wide `packet`: input `j` goes to lane `j % 16`, and the count
/// returned is the number of inputs rounded up to a multiple of 16.
pub fn check_lanes16<S, T>(
    inputs: &[S],
    mut packet: impl FnMut(S::X16) -> T::X16,
    scalar: impl FnMut(S) -> T,
) -> Result<usize, Box<LaneMismatch>>
where
    S: Scalar,
    T: Scalar,
{
    check_width(
        inputs,
        |l: [S; 16]| T::unpack16(packet(S::pack16(l))),
        scalar,
    )
}

/// Both checks: `packet` maps N lanes of input to N lanes of output through a packet.
fn check_width<S: Scalar, T: Scalar, const N: usize>(
    inputs: &[S],
    mut packet: impl FnMut([S; N]) -> [T; N],
    mut scalar: impl FnMut(S) -> T,
) -> Result<usize, Box<LaneMismatch>> {
    let n = inputs.len();
    let chunks = n.div_ceil(N);
    let checked = chunks * N;
    let mut first: Option<LaneMismatch> = None;
    let mut mismatches = 0;
    let (mut pb, mut sb) = (Vec::new(), Vec::new());
    for c in 0..chunks {
        let lanes: [S; N] = core::array::from_fn(|k| inputs[(c * N + k) % n]);
        let out = packet(lanes);
        for (k, (&input, got)) in lanes.iter().zip(out).enumerate() {
            let want = scalar(input);
            pb.clear();
            sb.clear();
            got.push_bits(&mut pb);
            want.push_bits(&mut sb);
            if pb != sb {
                mismatches += 1;
                if first.is_none() {
                    first = Some(LaneMismatch {
                        index: (c * N + k) % n,
                        lane: k,
                        input: format!("{input:?}"),
                        packet: format!("{got:?}"),
                        scalar: format!("{want:?}"),
                        packet_bits: pb.clone(),
                        scalar_bits: sb.clone(),
                        mismatches: 0,
                        checked,
                    });
                }
            }
        }
    }
    match first {
        None => Ok(checked),
        Some(m) => Err(Box::new(LaneMismatch { mismatches, ..m })),
    }
}
