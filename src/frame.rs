//! Orthonormal frames from a unit normal (Duff et al. 2017, "Building an Orthonormal Basis,
//! Revisited").
//!
//! The construction is branch-free: s = copysign(1, n_z), a = −1/(s + n_z), b = n_x n_y a,
//! t = (1 + s n_x² a, s b, −s n_x), b' = (b, s + n_y² a, −n_y). Because s + n_z never falls below
//! 1 in magnitude, it stays orthonormal to about 6e-8 even at n_z = −0.9999999, where Frisvad's
//! original form is off by 0.54. The frame is right-handed: t × b' = n.
//!
//! Bad input: `n` is used as given (not normalised). A zero normal gives the frame of +z with
//! n = 0; NaN components give NaN axes.

use glam::Vec3;

use crate::lane::{Lane, V3};
use crate::x8::Vec3x8;

/// The two tangents of the Duff et al. basis for unit normal `n`.
#[inline(always)]
pub(crate) fn basis<L: Lane>(n: V3<L>) -> (V3<L>, V3<L>) {
    let s = L::c(1.0).copysign(n.z);
    let a = L::c(-1.0) / (s + n.z);
    let b = n.x * n.y * a;
    let t = V3::new((s * n.x * n.x).mul_add(a, L::c(1.0)), s * b, -(s * n.x));
    let bt = V3::new(b, (n.y * n.y).mul_add(a, s), -n.y);
    (t.canon(), bt.canon())
}

#[inline(always)]
fn to_local<L: Lane>(t: V3<L>, b: V3<L>, n: V3<L>, v: V3<L>) -> V3<L> {
    V3::new(v.dot(t), v.dot(b), v.dot(n)).canon()
}

#[inline(always)]
fn to_world<L: Lane>(t: V3<L>, b: V3<L>, n: V3<L>, v: V3<L>) -> V3<L> {
    V3::new(
        t.x.mul_add(v.x, b.x.mul_add(v.y, n.x * v.z)),
        t.y.mul_add(v.x, b.y.mul_add(v.y, n.y * v.z)),
        t.z.mul_add(v.x, b.z.mul_add(v.y, n.z * v.z)),
    )
    .canon()
}

/// A right-handed orthonormal frame (`t`, `b`, `n`): local +z is `n`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    pub t: Vec3,
    pub b: Vec3,
    pub n: Vec3,
}

impl Frame {
    /// The frame around unit normal `n` (Duff et al.).
    #[inline]
    pub fn from_normal(n: Vec3) -> Self {
        let (t, b) = basis::<f32>(n.into());
        Self {
            t: t.into(),
            b: b.into(),
            n,
        }
    }
    /// World → local: (v·t, v·b, v·n).
    #[inline]
    pub fn to_local(&self, v: Vec3) -> Vec3 {
        to_local::<f32>(self.t.into(), self.b.into(), self.n.into(), v.into()).into()
    }
    /// Local → world: t·v_x + b·v_y + n·v_z.
    #[inline]
    pub fn to_world(&self, v: Vec3) -> Vec3 {
        to_world::<f32>(self.t.into(), self.b.into(), self.n.into(), v.into()).into()
    }
}

/// The packet twin of [`crate::frame::Frame`]: eight frames, one per lane.
pub mod x8 {
    use super::*;

    /// Eight right-handed orthonormal frames.
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Frame {
        pub t: Vec3x8,
        pub b: Vec3x8,
        pub n: Vec3x8,
    }

    impl Frame {
        /// The frames around eight unit normals (Duff et al.).
        #[inline]
        pub fn from_normal(n: Vec3x8) -> Self {
            let (t, b) = basis(n);
            Self { t, b, n: n.canon() }
        }
        /// World → local, lane by lane.
        #[inline]
        pub fn to_local(&self, v: Vec3x8) -> Vec3x8 {
            to_local(self.t, self.b, self.n, v)
        }
        /// Local → world, lane by lane.
        #[inline]
        pub fn to_world(&self, v: Vec3x8) -> Vec3x8 {
            to_world(self.t, self.b, self.n, v)
        }
    }
}
