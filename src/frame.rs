//! Orthonormal frames from a unit normal (Duff et al. 2017, "Building an Orthonormal Basis,
//! Revisited").
//!
//! The construction is branch-free: s = copysign(1, n_z), a = −1/(s + n_z), b = n_x n_y a,
//! t = (1 + s n_x² a, s b, −s n_x), b' = (b, s + n_y² a, −n_y). Because s + n_z never falls below
//! 1 in magnitude, it stays orthonormal to about 6e-8 even at n_z = −0.9999999, where Frisvad's
//! original form is off by 0.54. The frame is right-handed: t × b' = n.
//!
//! One [`Frame`] type serves every width: `Frame<Vec3>` (the default), `Frame<Vec3x8>` (eight
//! frames) and `Frame<DVec3>`, as the type of the normal picks.
//!
//! Bad input: `n` is used as given (not normalised). A zero normal gives the frame of +z with
//! n = 0; NaN components give NaN axes (canonical NaN, the same bits in every width).

use glam::Vec3;

use crate::lane::V3;
use crate::math::Math;
use crate::point::{Point3, split_fields};

/// A right-handed orthonormal frame (`t`, `b`, `n`): local +z is `n`. `V` is the width:
/// [`glam::Vec3`] by default, [`Vec3x8`](crate::x8::Vec3x8) for eight frames, [`glam::DVec3`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame<V = Vec3> {
    /// The first tangent.
    pub t: V,
    /// The second tangent, n × t.
    pub b: V,
    /// The normal: local +z.
    pub n: V,
}

split_fields!(Frame<V: Point3> by V::Lane { t: point, b: point, n: point });

impl<V: Point3<Lane = L>, L: Math> Frame<V> {
    /// The frame around unit normal `n` (Duff et al.).
    #[inline]
    pub fn from_normal(n: V) -> Self {
        let n = n.to_lanes();
        let s = L::ONE.copysign(n.z);
        let a = L::c(-1.0) / (s + n.z);
        let b = n.x * n.y * a;
        let t = V3::new((s * n.x * n.x).mul_add(a, L::ONE), s * b, -(s * n.x));
        let bt = V3::new(b, (n.y * n.y).mul_add(a, s), -n.y);
        Self {
            t: V::from_lanes(t.canon()),
            b: V::from_lanes(bt.canon()),
            n: V::from_lanes(n.canon()),
        }
    }

    /// World → local: (v·t, v·b, v·n).
    #[inline]
    pub fn to_local(&self, v: V) -> V {
        let (t, b, n, v) = self.lanes(v);
        V::from_lanes(V3::new(v.dot(t), v.dot(b), v.dot(n)).canon())
    }

    /// Local → world: t·v_x + b·v_y + n·v_z.
    #[inline]
    pub fn to_world(&self, v: V) -> V {
        let (t, b, n, v) = self.lanes(v);
        let w = V3::new(
            t.x.mul_add(v.x, b.x.mul_add(v.y, n.x * v.z)),
            t.y.mul_add(v.x, b.y.mul_add(v.y, n.y * v.z)),
            t.z.mul_add(v.x, b.z.mul_add(v.y, n.z * v.z)),
        );
        V::from_lanes(w.canon())
    }

    #[inline(always)]
    fn lanes(&self, v: V) -> (V3<L>, V3<L>, V3<L>, V3<L>) {
        (
            self.t.to_lanes(),
            self.b.to_lanes(),
            self.n.to_lanes(),
            v.to_lanes(),
        )
    }
}
