//! Square → cone of directions about +z, uniform in solid angle.
//!
//! The cone is given by h = 1 − cos θmax, never by cos θmax: near the axis cos θmax rounds to 1
//! and loses h entirely (cos θmax = 1 − 1e-7 stored in f32 gives an h that is 19 % wrong).

use core::fmt;

use glam::Vec3;

use crate::lane::{V2, V3};
use crate::math::Math;
use crate::point::{Point2, Point3};
use crate::warp::Family;
use crate::warp::common::{azimuth_fraction, clamp_u, one_minus_z, sin_from_one_minus_cos};
use crate::warp::family::{is_unit, lane, with_pdf};

/// The largest meaningful h: the whole sphere.
const H_MAX: f64 = 2.0;

/// h = 1 − cos θmax, clamped to [0, 2]. NaN gives NaN.
///
/// Loses precision for narrow cones, where cos θmax rounds towards 1: prefer
/// [`cone_h_from_sin2`] when sin²θmax is at hand.
#[inline(always)]
pub fn cone_h_from_cos<L: Math>(cos_max: L) -> L {
    (L::ONE - cos_max).clamp(L::ZERO, L::c(H_MAX)).canon()
}

/// h = 1 − cos θmax from sin²θmax (θmax ≤ π/2), as s²/(1 + √(1 − s²)): exact algebra, with no
/// cancellation at any size and no threshold. s² is clamped to [0, 1]; NaN gives NaN.
#[inline(always)]
pub fn cone_h_from_sin2<L: Math>(sin2_max: L) -> L {
    let s2 = sin2_max.clamp(L::ZERO, L::ONE);
    (s2 / (L::ONE + (L::ONE - s2).sqrt())).canon()
}

/// Square → cone about +z with h = 1 − cos θmax, uniform in solid angle (pdf 1/(2πh) per
/// steradian, [`uniform_cone_pdf`]).
///
/// t = u₀h is 1 − cos θ, so z = 1 − t and sin θ = √(t(2 − t)) keep full relative precision for
/// the narrowest cones; φ = 2πu₁. Build h with [`cone_h_from_sin2`] or [`cone_h_from_cos`].
/// u is clamped to [0, 1]² and h to [0, 2]; h = 0 puts every sample on the axis (pdf 0); NaN in u
/// or h gives NaN.
#[inline(always)]
pub fn uniform_cone<P: Point2<Lane = L>, L: Math>(u: P, h: L) -> P::Vec3 {
    let u = clamp_u(u.to_lanes());
    let h = h.clamp(L::ZERO, L::c(H_MAX));
    let t = u.x * h;
    let sin_theta = sin_from_one_minus_cos(t);
    let (s, c) = u.y.sincos_2pi_unit();
    let w = V3::new(sin_theta * c, sin_theta * s, L::ONE - t);
    Point3::from_lanes(w.nan_if(u.any_nan() | h.is_nan()))
}

/// pdf per steradian of [`uniform_cone`] at direction `w`: 1/(2πh) inside the cone, 0 outside,
/// for h ≤ 0 (a degenerate cone) and for NaN in `w` or `h`. h is clamped to at most 2; an h so
/// small that 1/(2πh) overflows (below about 4.6e-40 in f32) is degenerate too, and gives 0.
///
/// Inside means 1 − cos θ ≤ h·(1 + 2⁻²⁰) + 2⁻¹²⁶, with 1 − cos θ taken as (x² + y²)/(1 + z) so
/// that it keeps its precision near the axis. The relative margin is a few ulp, and the absolute
/// one covers x² + y² rounded in the subnormal range: every direction [`uniform_cone`] returns,
/// including at u₀ = 1 and for the tiniest h, gets the non-zero pdf, and the pdf drops to 0
/// within a relative 1e-6 of the true boundary (for h above 1e-32).
#[inline(always)]
pub fn uniform_cone_pdf<P: Point3<Lane = L>, L: Math>(w: P, h: L) -> L {
    // NaN must reach the select below as NaN, so it goes in the second operand of min.
    let h = L::c(H_MAX).min(h);
    let bound = h * L::c(1.0 + 1.0 / 1_048_576.0) + L::c(f32::MIN_POSITIVE as f64);
    let w = w.to_lanes();
    // 1 − cos θ reads x and y only above the equator: NaN there must still give 0.
    let inside = one_minus_z(w).le(bound) & !w.any_nan();
    let p = L::c(0.5 * core::f64::consts::FRAC_1_PI) / h;
    L::select(h.gt(L::ZERO) & inside & p.is_finite(), p, L::ZERO)
}

/// Inverse of [`uniform_cone`]: u₀ = t/h with t = 1 − z = (x² + y²)/(1 + z) (no cancellation near
/// the axis), clamped to [0, 1]; u₁ = azimuth/2π. NaN gives NaN.
#[inline(always)]
pub fn uniform_cone_inverse<P: Point3<Lane = L>, L: Math>(w: P, h: L) -> P::Vec2 {
    let w = w.to_lanes();
    let u0 = (one_minus_z(w) / h).clamp(L::ZERO, L::ONE);
    let u = V2::new(u0, azimuth_fraction(w.x, w.y));
    Point2::from_lanes(u.nan_where(w.any_nan() | h.is_nan()))
}

/// The registry's [`uniform_cone`] with h = 1 − cos θmax.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UniformCone {
    /// 1 − cos θmax.
    pub h: f32,
}

impl Family for UniformCone {
    fn name(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "uniform_cone h={}", self.h)
    }
    fn sampler<L: Math>(&self) -> impl Fn(V2<L>) -> (V3<L>, L) + Copy {
        let h = lane(self.h);
        with_pdf(move |u| uniform_cone(u, h), move |w| uniform_cone_pdf(w, h))
    }
    fn pdf<L: Math>(&self, x: V3<L>) -> L {
        uniform_cone_pdf(x, lane(self.h))
    }
    fn inverse<L: Math>(&self, x: V3<L>) -> Option<V2<L>> {
        Some(uniform_cone_inverse(x, lane(self.h)))
    }
    fn in_domain(&self, x: Vec3) -> bool {
        let h = (self.h as f64).clamp(0.0, H_MAX);
        is_unit(x) && 1.0 - x.z as f64 <= h * (1.0 + 1e-6) + 1e-7
    }
}
