//! Square → unit sphere, uniform by area.

use crate::lane::{V2, V3};
use crate::math::Math;
use crate::point::{Point2, Point3};
use crate::warp::common::{azimuth_fraction, clamp_u, one_minus_z};
use crate::warp::family::is_unit;
use crate::warp::family::plain_family;

/// Square → unit sphere, uniform (pdf 1/(4π) per steradian, [`uniform_sphere_pdf`]).
///
/// z = 1 − 2u₀, r = 2√(u₀(1 − u₀)), φ = 2πu₁. The product form keeps r right near the poles: at
/// u₀ = 1e-8, √(1 − z²) gives 0 where the true radius is 2e-4. u is clamped to [0, 1]²; NaN
/// gives NaN.
#[inline(always)]
pub fn uniform_sphere<P: Point2<Lane = L>, L: Math>(u: P) -> P::Vec3 {
    let u = clamp_u(u.to_lanes());
    let z = u.x.mul_add(L::c(-2.0), L::ONE);
    let r = L::TWO * (u.x * (L::ONE - u.x)).max(L::ZERO).sqrt();
    let (s, c) = u.y.sincos_2pi_unit();
    Point3::from_lanes(V3::new(r * c, r * s, z).nan_if(u.any_nan()))
}

/// pdf per steradian of [`uniform_sphere`] at direction `w`: 1/(4π), and 0 for NaN in any
/// component.
#[inline(always)]
pub fn uniform_sphere_pdf<P: Point3<Lane = L>, L: Math>(w: P) -> L {
    let nan = w.to_lanes().any_nan();
    L::select(nan, L::ZERO, L::c(0.25 * core::f64::consts::FRAC_1_PI))
}

/// Inverse of [`uniform_sphere`] for a unit direction, in [0, 1] × [0, 1): u₀ = (1 − z)/2, with
/// 1 − z computed as (x² + y²)/(1 + z) in the upper half, where the subtraction would cancel.
/// NaN gives NaN.
#[inline(always)]
pub fn uniform_sphere_inverse<P: Point3<Lane = L>, L: Math>(w: P) -> P::Vec2 {
    let w = w.to_lanes();
    let u0 = (one_minus_z(w) * L::HALF).clamp(L::ZERO, L::ONE);
    Point2::from_lanes(V2::new(u0, azimuth_fraction(w.x, w.y)).nan_where(w.any_nan()))
}

/// The registry's [`uniform_sphere`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct UniformSphere;

plain_family!(
    UniformSphere,
    "uniform_sphere",
    uniform_sphere,
    uniform_sphere_pdf,
    uniform_sphere_inverse,
    is_unit,
);
