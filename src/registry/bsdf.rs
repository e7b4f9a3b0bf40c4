//! The BSDFs of the scene as families of the registry: each sampled in its local frame at a
//! fixed outgoing direction, its sample the incident direction and its pdf per steradian.

use core::fmt;

use glam::{Vec2, Vec3};

use crate::lane::{V2, V3};
use crate::math::Math;
use crate::scene::{Lambert, Phong};
use crate::warp::Family;
use crate::warp::family::{is_unit, lane, lanes3};

/// [`Lambert::sample`] with ρ = 1, at outgoing direction `wo`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BsdfLambert {
    /// The outgoing direction.
    pub wo: Vec3,
}

/// [`Phong::sample`] with the grey reflectances kd and ks, at outgoing direction `wo`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BsdfPhong {
    /// The outgoing direction.
    pub wo: Vec3,
    /// The diffuse reflectance.
    pub kd: f32,
    /// The specular reflectance.
    pub ks: f32,
    /// The exponent.
    pub n: f32,
}

impl BsdfPhong {
    /// The BSDF in the width of `L`.
    #[inline(always)]
    fn bsdf<L: Math>(&self) -> Phong<V3<L>> {
        Phong::new(V3::all(lane(self.kd)), V3::all(lane(self.ks)), lane(self.n))
    }
}

impl Family for BsdfLambert {
    fn name(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("bsdf_lambert")
    }
    fn sampler<L: Math>(&self) -> impl Fn(V2<L>) -> (V3<L>, L) + Copy {
        let wo = lanes3(self.wo);
        #[inline(always)]
        move |u| {
            let s = Lambert::new(V3::all(L::ONE)).sample(wo, u);
            (s.wi, s.pdf)
        }
    }
    fn pdf<L: Math>(&self, x: V3<L>) -> L {
        Lambert::new(V3::all(L::ONE)).pdf(lanes3(self.wo), x)
    }
    fn inverse<L: Math>(&self, _: V3<L>) -> Option<V2<L>> {
        None
    }
    fn in_domain(&self, x: Vec3) -> bool {
        is_unit(x)
    }
}

impl Family for BsdfPhong {
    fn name(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "bsdf_phong n={} kd={}", self.n, self.kd)
    }
    fn sampler<L: Math>(&self) -> impl Fn(V2<L>) -> (V3<L>, L) + Copy {
        let (wo, bsdf) = (lanes3(self.wo), self.bsdf::<L>());
        #[inline(always)]
        move |u| {
            let s = bsdf.sample(wo, u);
            (s.wi, s.pdf)
        }
    }
    fn pdf<L: Math>(&self, x: V3<L>) -> L {
        self.bsdf().pdf(lanes3(self.wo), x)
    }
    fn inverse<L: Math>(&self, _: V3<L>) -> Option<V2<L>> {
        None
    }
    fn in_domain(&self, x: Vec3) -> bool {
        is_unit(x)
    }
    /// Around its lobe choice at u₀ = P = kd/(kd + ks) the map is sensitive to the rounding of
    /// its parameters: the f32 and f64 instances' P differ by rounding (1e-7 relative), so next
    /// to P they may pick different lobes; and above it the lobe's rescaled u₀,
    /// v = (u₀ − P)/(1 − P), carries P's rounding into a map that is steep for small v
    /// (dt/dv ∝ v^(−n/(n+1))): 1e-5 of direction at v = 0.01; below it, v = u₀/P near 1 puts
    /// the cosine lobe's sample at the rim, where z = √(1 − r²) is steep in r; and at u₀ → 1 the
    /// rescaled u₀'s own rounding moves the lobe's peak, where sin α ∝ √(1 − v). Error
    /// measurements skip u whose rescaled u₀ lies within 5 % of P's side of the choice, or u₀
    /// within 1e-5 of 1.
    fn parameter_sensitive(&self, u: Vec2) -> bool {
        let p = self.kd as f64 / (self.kd as f64 + self.ks as f64);
        let u0 = u.x as f64;
        (u0 > 0.95 * p && u0 < p + 0.05 * (1.0 - p)) || u0 > 1.0 - 1e-5
    }
}
