//! rand's [`Distribution`] for the warps (feature `rand`), so that `rng.sample(CosineHemisphere)`
//! works with any RNG, as rand_distr's `UnitDisc` does, with the crate's pdf and inverse of each
//! warp beside it in [`crate::warp`].
//!
//! Every distribution draws u from two `next_u32` calls, each the top 24 bits scaled to [0, 1)
//! (the sequences' convention: exact, never 1), and returns the warp's value at u. The value is
//! bit for bit `warp::NAME(u)`, so a caller can evaluate its pdf with the warp's pdf function.
//!
//! ```
//! use mcsample::distr::{CosineHemisphere, UniformCone};
//! use mcsample::warp;
//! use rand::RngExt;
//!
//! let mut rng = rand_pcg::Pcg32::new(7, 11);
//! let w: glam::Vec3 = rng.sample(CosineHemisphere);
//! assert!(w.z >= 0.0 && warp::cosine_hemisphere_pdf(w) > 0.0);
//! let v: glam::Vec3 = rng.sample(UniformCone { h: 0.1 });
//! assert!(warp::uniform_cone_pdf(v, 0.1) > 0.0);
//! ```

use glam::{Vec2, Vec3};
use rand::Rng;
use rand::distr::Distribution;

use crate::warp;

/// u in [0, 1)² from two 32-bit outputs: the top 24 bits of each, exactly scaled.
#[inline(always)]
fn u2<R: Rng + ?Sized>(rng: &mut R) -> Vec2 {
    let unit = |x: u32| (x >> 8) as f32 * (1.0 / 16_777_216.0);
    let a = unit(rng.next_u32());
    Vec2::new(a, unit(rng.next_u32()))
}

/// A parameterless distribution: a unit struct whose sample is `warp::$warp(u)`.
macro_rules! unit_distribution {
    ($(#[$doc:meta])* $name:ident -> $out:ty, $warp:ident) => {
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, Default)]
        pub struct $name;

        impl Distribution<$out> for $name {
            #[inline]
            fn sample<R: Rng + ?Sized>(&self, rng: &mut R) -> $out {
                warp::$warp(u2(rng))
            }
        }
    };
}

unit_distribution!(
    /// Uniform points of the unit disk, by [`warp::concentric_disk`] (pdf
    /// [`warp::uniform_disk_pdf`]).
    UnitDisk -> Vec2, concentric_disk
);
unit_distribution!(
    /// Uniform directions of the upper hemisphere, by [`warp::uniform_hemisphere`].
    UniformHemisphere -> Vec3, uniform_hemisphere
);
unit_distribution!(
    /// Cosine-weighted directions of the upper hemisphere, by [`warp::cosine_hemisphere`].
    CosineHemisphere -> Vec3, cosine_hemisphere
);
unit_distribution!(
    /// Uniform directions of the sphere, by [`warp::uniform_sphere`].
    UniformSphere -> Vec3, uniform_sphere
);

/// Uniform directions of the cone 1 − cos θ ≤ h about +z, by [`warp::uniform_cone`] (whose
/// rustdoc gives the domain of h and what bad values give).
#[derive(Clone, Copy, Debug)]
pub struct UniformCone {
    /// 1 − cos θmax, in (0, 2].
    pub h: f32,
}

impl Distribution<Vec3> for UniformCone {
    #[inline]
    fn sample<R: Rng + ?Sized>(&self, rng: &mut R) -> Vec3 {
        warp::uniform_cone(u2(rng), self.h)
    }
}

/// Directions of the Phong lobe cosⁿ about +z, by [`warp::phong_lobe`].
#[derive(Clone, Copy, Debug)]
pub struct PhongLobe {
    /// The exponent n ≥ 0.
    pub n: f32,
}

impl Distribution<Vec3> for PhongLobe {
    #[inline]
    fn sample<R: Rng + ?Sized>(&self, rng: &mut R) -> Vec3 {
        warp::phong_lobe(u2(rng), self.n)
    }
}
