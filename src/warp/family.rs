//! [`Family`]: a sampler as the registry sees it (its name, its map u ↦ (sample, pdf), its pdf,
//! its inverse and its domain), written next to the warp it wraps, in every width.
//!
//! Outputs are widened to 3D so that every sampler has one output type: a planar point is
//! (x, y, 0), the triangle its barycentrics. Parameters are stored as `f32`, and each width
//! converts them with [`lane`]: the f64 instance sees the same f32 values, so that it measures
//! the f32 map's rounding and nothing else.

use core::fmt;

use glam::{Vec2, Vec3};

use crate::lane::{V2, V3};
use crate::math::Math;

/// A sampler of the registry, at its parameters. Every item but one exemption is required: a
/// new sampler states each fact about itself, and a sampler without an inverse says so by
/// returning `None` from [`inverse`](Family::inverse).
pub trait Family: Copy + fmt::Debug + PartialEq {
    /// Writes the name the report and its JSON use: the function, then its parameters where it
    /// has any.
    fn name(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result;

    /// The map u ↦ (sample, pdf) in the lane `L`, with the parameters converted once: the pdf
    /// is the one the warp returns, or its pdf function at the sample. A loop over a batch
    /// calls the returned closure at every sample, so that it runs inlined, as a loop written
    /// by hand would.
    fn sampler<L: Math>(&self) -> impl Fn(V2<L>) -> (V3<L>, L) + Copy;

    /// The pdf of output `x`, in the measure of the sampler (per unit area for planar points
    /// and barycentrics, per steradian for directions).
    fn pdf<L: Math>(&self, x: V3<L>) -> L;

    /// The u that maps to output `x`; `None` for a sampler without an inverse, at every `x`.
    fn inverse<L: Math>(&self, x: V3<L>) -> Option<V2<L>>;

    /// True when `x` is a point of the sampler's domain, up to f32 rounding.
    fn in_domain(&self, x: Vec3) -> bool;

    /// True where the f32 map and its f64 instance differ by more than the map's rounding,
    /// through the rounding of the parameters themselves: error measurements skip such u. The
    /// default, false, exempts nothing, so a sampler that needs the exemption fails its
    /// accuracy checks until it states it.
    fn parameter_sensitive(&self, _u: Vec2) -> bool {
        false
    }
}

/// The map u ↦ (x, pdf(x)) of a warp whose returned pdf is its pdf function at the sample.
#[inline(always)]
pub(crate) fn with_pdf<L: Math>(
    warp: impl Fn(V2<L>) -> V3<L> + Copy,
    pdf: impl Fn(V3<L>) -> L + Copy,
) -> impl Fn(V2<L>) -> (V3<L>, L) + Copy {
    #[inline(always)]
    move |u| {
        let x = warp(u);
        (x, pdf(x))
    }
}

/// An f32 parameter as a lane value.
#[inline(always)]
pub(crate) fn lane<L: Math>(x: f32) -> L {
    L::c(x as f64)
}

/// An f32 point as a lane vector.
#[inline(always)]
pub(crate) fn lanes3<L: Math>(p: Vec3) -> V3<L> {
    V3::new(lane(p.x), lane(p.y), lane(p.z))
}

/// A unit vector, within 1e-6 in f64.
pub(crate) fn is_unit(x: Vec3) -> bool {
    x.is_finite() && (x.as_dvec3().length() - 1.0).abs() <= 1e-6
}

/// The [`Family`] of a warp without parameters whose sampler returns its pdf function's value at
/// the sample: `plain_family!(Type, "name", warp, pdf, inverse, in_domain)`. Every item of the
/// contract is named at the call; the macro only writes the impl around them.
macro_rules! plain_family {
    ($ty:ty, $name:literal, $warp:expr, $pdf:expr, $inverse:expr, $in_domain:expr $(,)?) => {
        impl $crate::warp::Family for $ty {
            fn name(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
                f.write_str($name)
            }
            fn sampler<L: $crate::math::Math>(
                &self,
            ) -> impl Fn($crate::lane::V2<L>) -> ($crate::lane::V3<L>, L) + Copy {
                $crate::warp::family::with_pdf($warp, $pdf)
            }
            fn pdf<L: $crate::math::Math>(&self, x: $crate::lane::V3<L>) -> L {
                ($pdf)(x)
            }
            fn inverse<L: $crate::math::Math>(
                &self,
                x: $crate::lane::V3<L>,
            ) -> Option<$crate::lane::V2<L>> {
                Some(($inverse)(x))
            }
            fn in_domain(&self, x: glam::Vec3) -> bool {
                ($in_domain)(x)
            }
        }
    };
}
pub(crate) use plain_family;
