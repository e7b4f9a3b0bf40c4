//! Small pieces that several warps share: the input contract and the angle of a direction.

use crate::lane::{Lanes, V2, V3};
use crate::math::Math;

/// 1 − 2⁻²⁴, the largest f32 below 1.
pub const ONE_MINUS_EPS: f32 = 0.999_999_94;

/// The input contract of every warp: u is clamped to [0, 1], so u = 1, negative values and ±inf
/// land on the domain's boundary. NaN passes through and makes every output NaN.
#[inline(always)]
pub(crate) fn clamp_u<L: Math>(u: V2<L>) -> V2<L> {
    V2::new(clamp01(u.x), clamp01(u.y))
}

#[inline(always)]
pub(crate) fn clamp01<L: Math>(x: L) -> L {
    x.clamp(L::ZERO, L::ONE)
}

/// Field `f` of entry k of `table` in each lane (k a whole number in each): a load in the
/// scalar form and a lane-by-lane fetch in the packets, rather than a select through every
/// entry. An index past the table gives 0.
#[inline(always)]
pub(crate) fn pick<S, T: Lanes, K: Lanes<Scalar = f64>>(
    table: &[S],
    k: K,
    f: impl Fn(&S) -> T,
) -> T {
    T::from_fn(|i| {
        table
            .get(k.lane(i) as usize)
            .map_or(T::Scalar::default(), |s| f(s).lane(i))
    })
}

/// The azimuth of (x, y) as a fraction of a turn, in [0, 1).
///
/// atan2/2π lies in [−½, ½]; negative values wrap by adding 1, and a tiny negative angle, whose
/// wrapped value would round to 1, is kept just below 1 so the result honours the u < 1 contract.
#[inline(always)]
pub(crate) fn azimuth_fraction<L: Math>(x: L, y: L) -> L {
    let v = y.atan2(x) * L::c(1.0 / core::f64::consts::TAU);
    let v = L::select(v.lt(L::ZERO), v + L::ONE, v);
    // NaN goes in the second operand of min, which returns it.
    L::c(ONE_MINUS_EPS as f64).min(v)
}

/// sin θ from t = 1 − cos θ, as √(t(2 − t)): no cancellation near the pole, unlike √(1 − cos²θ).
#[inline(always)]
pub(crate) fn sin_from_one_minus_cos<L: Math>(t: L) -> L {
    (t * (L::TWO - t)).max(L::ZERO).sqrt()
}

/// 1 − z of a unit vector, as (x² + y²)/(1 + z) in the upper half, where 1 − z would cancel
/// near the pole, and as 1 − z below.
#[inline(always)]
pub(crate) fn one_minus_z<L: Math>(w: V3<L>) -> L {
    let rho2 = w.x.mul_add(w.x, w.y * w.y);
    L::select(w.z.gt(L::ZERO), rho2 / (L::ONE + w.z), L::ONE - w.z)
}
