//! The sample sources of an estimator: [`Samples`] gives pair `pair` of sample `s`, from a
//! stateless [`Sequence`] or from a PCG32 stream.

use glam::Vec2;

use crate::lane::{U32Lane, V2};
use crate::point::Point2;
use crate::rng::{Pcg32x8, Pcg32x16};
use crate::seq;
use crate::x8::Vec2x8;
use crate::x16::Vec2x16;

/// The source of an estimate's sample values: `get(s, pair)` is pair `pair` of dimensions of
/// sample `s` of the estimate, in [0, 1)².
pub trait Samples<P: Point2> {
    /// Pair `pair` of sample `s`.
    fn get(&mut self, s: u32, pair: u32) -> P;
}

/// Which stateless generator a [`Sequence`] reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Generator {
    /// [`seq::sobol_2d`], Owen-scrambled Sobol: pair k is dimensions 2k and 2k + 1.
    Sobol,
    /// [`seq::independent`], a hash of (index, dimension, seed).
    Independent,
}

/// Samples from a stateless generator: sample s of the estimate is index `first + s` (mod 2³²;
/// per lane for a packet), so consecutive estimates should advance `first` by
/// `direct::Config::samples`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sequence<I: U32Lane = u32> {
    /// The index of sample 0.
    pub first: I,
    /// The scramble seed.
    pub seed: u32,
    /// The generator.
    pub generator: Generator,
}

impl<I: U32Lane> Samples<I::Vec2> for Sequence<I>
where
    I::Vec2: Point2,
{
    #[inline]
    fn get(&mut self, s: u32, pair: u32) -> I::Vec2 {
        let i = self.first.wrapping_add(I::splat(s));
        match self.generator {
            Generator::Sobol => seq::sobol_2d(i, pair, self.seed),
            Generator::Independent => {
                let d = pair.wrapping_mul(2);
                V2::new(
                    seq::independent(i, d, self.seed),
                    seq::independent(i, d.wrapping_add(1), self.seed),
                )
                .into()
            }
        }
    }
}

/// The generator's next two values, whatever s and the pair.
impl Samples<Vec2> for rand_pcg::Pcg32 {
    #[inline]
    fn get(&mut self, _s: u32, _pair: u32) -> Vec2 {
        use rand_core::Rng;
        let x = self.next_u32().to_unit_f32();
        Vec2::new(x, self.next_u32().to_unit_f32())
    }
}

/// The generator's next two packets, whatever s and the pair: lane i draws what
/// `rand_pcg::Pcg32` lane i draws for the scalar form.
impl Samples<Vec2x8> for Pcg32x8 {
    #[inline]
    fn get(&mut self, _s: u32, _pair: u32) -> Vec2x8 {
        let x = self.next_f32x8();
        Vec2x8::new(x, self.next_f32x8())
    }
}

/// Sixteen lanes, as [`Pcg32x8`]'s eight.
impl Samples<Vec2x16> for Pcg32x16 {
    #[inline]
    fn get(&mut self, _s: u32, _pair: u32) -> Vec2x16 {
        let x = self.next_f32x16();
        Vec2x16::new(x, self.next_f32x16())
    }
}
