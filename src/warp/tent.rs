//! [0, 1) → tent on [−1, 1] with pdf 1 − |x|: the pixel-filter warp.

use core::fmt;

use glam::Vec3;

use crate::lane::{V2, V3};
use crate::math::Math;
use crate::warp::Family;

/// [0, 1) → [−1, 1] with pdf 1 − |x| (the tent pixel filter, [`tent_pdf`]), by inverting each
/// half on its own: u < ½ gives x = √(2u) − 1, otherwise x = 1 − √(2(1 − u)).
///
/// u is clamped to [0, 1]; NaN gives NaN.
#[inline(always)]
pub fn tent<L: Math>(u: L) -> L {
    tent_uncanonical(u).canon()
}

/// [`tent`] without its last step, the canonical NaN: NaN in u comes out as some NaN, with
/// whatever bits the arithmetic left. For a caller that replaces every NaN output anyway
/// ([`TentPair`], NaN in either coordinate dropping both), which then pays for one NaN test
/// instead of two.
#[inline(always)]
fn tent_uncanonical<L: Math>(u: L) -> L {
    // The distance to the nearer end: u below ½, 1 − u (exact there) above, by a min rather
    // than a select on the half, which the sign needs anyway. Its floor at 0 is the clamp of u
    // to [0, 1], bit for bit (u beyond an end gives that end), in one operation instead of two;
    // 0.max(v) keeps NaN, and −0 stays −0 as clamping would keep it.
    let v = L::ZERO.max(u.min(L::ONE - u));
    let x = L::ONE - (v * L::TWO).sqrt();
    L::select(u.lt(L::HALF), -x, x)
}

/// pdf of [`tent`]: 1 − |x| on [−1, 1], else 0 (also for NaN).
#[inline(always)]
pub fn tent_pdf<L: Math>(x: L) -> L {
    let p = L::ONE - x.abs();
    L::select(p.gt(L::ZERO), p, L::ZERO)
}

/// Inverse of [`tent`]: u = (1 + x)²/2 for x < 0, else 1 − (1 − x)²/2. x is clamped to [−1, 1];
/// NaN gives NaN.
#[inline(always)]
pub fn tent_inverse<L: Math>(x: L) -> L {
    let x = x.clamp(L::c(-1.0), L::ONE);
    let d = L::ONE - x.abs();
    let half_d2 = d * d * L::HALF;
    L::select(x.lt(L::ZERO), half_d2, L::ONE - half_d2).canon()
}

/// The registry's pair of tents, one 2D sample (tent(u₀), tent(u₁), 0) with pdf
/// tent_pdf(x)·tent_pdf(y): NaN in either coordinate of u makes both coordinates NaN.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TentPair;

impl Family for TentPair {
    fn name(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("tent")
    }
    fn sampler<L: Math>(&self) -> impl Fn(V2<L>) -> (V3<L>, L) + Copy {
        // The tent is NaN only for NaN in, so the inputs' mask is the whole story, and the pair
        // makes the canonical NaN itself: `tent` less its own NaN test (the same bits as `tent`
        // wherever u is not NaN).
        #[inline(always)]
        |u: V2<L>| {
            let t = V2::new(tent_uncanonical(u.x), tent_uncanonical(u.y)).nan_if(u.any_nan());
            let x = V3::new(t.x, t.y, L::ZERO);
            (x, tent_pdf(x.x) * tent_pdf(x.y))
        }
    }
    fn pdf<L: Math>(&self, x: V3<L>) -> L {
        tent_pdf(x.x) * tent_pdf(x.y)
    }
    fn inverse<L: Math>(&self, x: V3<L>) -> Option<V2<L>> {
        Some(V2::new(tent_inverse(x.x), tent_inverse(x.y)))
    }
    fn in_domain(&self, x: Vec3) -> bool {
        x.is_finite() && x.x.abs() <= 1.0 && x.y.abs() <= 1.0 && x.z == 0.0
    }
}
