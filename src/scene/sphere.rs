//! The sphere: uniform in the cone it subtends from outside, uniform by area from inside.

use core::f64::consts::PI;

use glam::Vec3;

use super::emitter::Emitter;
use super::select::{splat_lane, splat_vec};
use super::shape::{AreaPoint, LightSampling, PreparedShape, Shape, ShapeSample, on_shape};
use crate::frame::Frame;
use crate::lane::{Lane, Mask, V2, V3};
use crate::math::Math;
use crate::point::{Point2, Point3, Split, by_halves, split_fields};
use crate::warp::{ProjectedCap, cone_h_from_sin2, uniform_cone, uniform_sphere};

/// A sphere of radius `radius` about `center`; as a light ([`SphereLight`](super::SphereLight))
/// it emits outwards.
///
/// - **From outside** (|c − p| > r) it samples the cone of directions the sphere subtends,
///   uniformly: pdf 1/(2πh) per steradian with h = 1 − cos θmax built from sin²θmax = r²/d² by
///   the exact identity h = s²/(1 + √(1 − s²)), which has no cancellation and no threshold, so a
///   tiny sphere (s² = 1e-12) gets a finite pdf within 1e-6 of 1/(π s²), and the cone's width is
///   not quantised. `pdf` and `hit` call a direction on the light when
///   sin θ ≤ sin θmax + 2ε (ε the lane's epsilon: 2.4e-7 rad in f32), θ measured from the centre;
///   for a cone narrower than that slack, a BSDF ray finds the light slightly wider than it is.
/// - **From inside or on the surface** it samples a point uniformly by area and converts to
///   solid angle: pdf t²/(|cos θ_l|·4πr²), which along a direction wi is t²/(4πr·√disc), with t
///   the forward hit and disc the ray's discriminant. From inside, the point is behind the
///   surface it sees (`front` is false).
///
/// Prepared for [`LightSampling::Projected`] with a shading normal, it samples from outside by
/// projected solid angle ([`ProjectedCap`]): pdf n·ω / P over the cap's part above the
/// receiver's horizon, 0 (and no distance) below it, in all three cases (the cap above, across,
/// or with its centre below the horizon), unless the cap falls back to its cone (a lune too thin
/// for f32, [`CAP_MAX_SPREAD`](crate::warp::CAP_MAX_SPREAD)). Other modes keep the cone.
///
/// A zero, negative or non-finite radius, and non-finite input, give pdf 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere<V: Point3 = Vec3> {
    /// The centre.
    pub center: V,
    /// The radius.
    pub radius: V::Lane,
}

split_fields!(Sphere<V: Point3> by V::Lane { center: point, radius });

/// A sphere light: a [`Sphere`] emitting outwards.
pub type SphereLight<V = Vec3> = Emitter<Sphere<V>, V>;

impl<V: Point3> SphereLight<V> {
    /// The light of radius `radius` about `center`, emitting `le`.
    #[inline]
    pub fn new(center: V, radius: V::Lane, le: V) -> Self {
        Emitter {
            shape: Sphere { center, radius },
            le,
        }
    }
}

impl Sphere<Vec3> {
    /// The same sphere in every lane of width `W`, exactly.
    #[inline]
    pub fn splat<W: Point3>(&self) -> Sphere<W> {
        Sphere {
            center: splat_vec(self.center),
            radius: splat_lane(self.radius),
        }
    }
}

/// A [`Sphere`] prepared at one shading point.
#[derive(Clone, Copy)]
pub struct PreparedSphere<V: Point3 = Vec3> {
    /// Centre minus shading point.
    d: V3<V::Lane>,
    r: V::Lane,
    /// (|d| − r)(|d| + r), the product of the near and far hits along any ray.
    c0: V::Lane,
    /// The slack-widened bound on sin²θ, θ from the axis.
    sin2_bound: V::Lane,
    frame: Frame<V3<V::Lane>>,
    h: V::Lane,
    cone_pdf: V::Lane,
    area_pdf: V::Lane,
    outside: <V::Lane as Lane>::Mask,
    valid: <V::Lane as Lane>::Mask,
    /// The cap by projected solid angle ([`LightSampling::Projected`]), and the lanes where it
    /// samples (outside, with a normal, and not falling back to the cone).
    cap: Option<ProjectedCap<V3<V::Lane>>>,
    by_cap: <V::Lane as Lane>::Mask,
}

impl<V: Point3<Lane = L>, L: Math> Shape<V> for Sphere<V> {
    type Prepared = PreparedSphere<V>;
    type Half = Sphere<V::Half>;

    #[inline(always)]
    fn halves(&self) -> (Sphere<V::Half>, Sphere<V::Half>) {
        Split::halves(*self)
    }

    #[inline(always)]
    fn at(&self, p: V, n: V, sampling: LightSampling) -> PreparedSphere<V> {
        let (c, p) = (self.center.to_lanes(), p.to_lanes());
        let r = self.radius;
        let d = c - p;
        let dist2 = d.dot(d);
        let dist = dist2.sqrt();
        let r2 = r * r;
        let s2 = r2 / dist2;
        let outside = s2.lt(L::ONE);
        let h = cone_h_from_sin2(s2);
        let slack = L::TWO * L::EPSILON;
        let sin_max = s2.min(L::ONE).sqrt();
        let sin2_bound = (sin_max + slack) * (sin_max + slack);
        let axis = d.scale(L::ONE / dist);
        let valid = r.gt(L::ZERO) & r2.is_finite() & dist2.is_finite() & !p.any_nan();
        let cap: Option<ProjectedCap<V3<L>>> = match sampling {
            // In halves at sixteen lanes without AVX-512 (`point::Split`). The free function
            // `projected_cap` splits at its top already.
            LightSampling::Projected => Some(by_halves(
                (d, r, n.to_lanes()),
                #[inline(always)]
                |(d, r, n)| ProjectedCap::new(d, r, n),
            )),
            _ => None,
        };
        let by_cap = match &cap {
            Some(cap) => outside & valid & !cap.by_solid_angle(),
            None => outside & !outside,
        };
        Prepared {
            d,
            r,
            c0: (dist - r) * (dist + r),
            sin2_bound,
            frame: Frame::from_normal(axis),
            h,
            cone_pdf: L::c(0.5 / PI) / h,
            area_pdf: L::c(0.25 / PI) / r2,
            outside,
            valid,
            cap,
            by_cap,
        }
    }

    /// A point uniform on the surface (the uniform sphere map), its outward normal and the area
    /// pdf 1/(4πr²).
    #[inline]
    fn sample_area(&self, u: V::Vec2) -> AreaPoint<V> {
        let r = self.radius;
        let n: V3<L> = uniform_sphere(u.to_lanes());
        let x = self.center.to_lanes() + n.scale(r);
        let pdf = L::select(r.gt(L::ZERO), L::c(0.25 / PI) / (r * r), L::ZERO);
        AreaPoint {
            p: V::from_lanes(x),
            n: V::from_lanes(n),
            pdf,
        }
    }

    /// 4πr².
    #[inline]
    fn area(&self) -> L {
        let r = self.radius;
        L::c(4.0 * PI) * r * r
    }

    #[inline]
    fn modes(&self) -> &'static [LightSampling] {
        &[LightSampling::SolidAngle, LightSampling::Projected]
    }
}

type Prepared<V> = PreparedSphere<V>;

impl<V: Point3<Lane = L>, L: Math> PreparedShape<V> for PreparedSphere<V> {
    // Always inlined: where sixteen lanes run as two calls of eight, the eight-lane sample has two
    // callers, and out of line it costs the sphere light 7 % more instructions at width 8.
    #[inline(always)]
    fn sample(&self, u: V::Vec2) -> ShapeSample<V> {
        let u: V2<L> = u.to_lanes();
        // Each path only where some lane takes it (a predictable branch: the shading point
        // decides). From outside: the cone about the axis, in the axis's frame.
        let zero = V3::all(L::ZERO);
        let w_cone = if (self.outside & !self.by_cap).any() {
            self.frame.to_world(uniform_cone(u, self.h))
        } else {
            zero
        };
        // From inside: a point by area, its direction from the shading point.
        let w_area = if (!self.outside).any() {
            (self.d + uniform_sphere(u).scale(self.r)).normalize_scaled()
        } else {
            zero
        };
        let mut wi = V3::select(self.outside, w_cone, w_area);
        // By projected solid angle: the cap's sample and its pdf (the pdf function's value).
        let mut cap_pdf = None;
        if let Some(cap) = self.cap.as_ref().filter(|_| self.by_cap.any()) {
            let (w, pdf) = cap.sample(u);
            wi = V3::select(self.by_cap, w, wi);
            cap_pdf = Some(pdf);
        }
        let (pdf, dist) = self.eval_with(wi, cap_pdf);
        ShapeSample {
            wi: V::from_lanes(wi),
            pdf,
            dist,
        }
    }

    #[inline]
    fn eval(&self, wi: V) -> (L, L) {
        self.eval_lanes(wi.to_lanes())
    }

    /// The shading point is outside the sphere.
    #[inline(always)]
    fn front(&self) -> L::Mask {
        self.outside
    }
}

impl<V: Point3<Lane = L>, L: Math> PreparedSphere<V> {
    /// The cosine of the direction with the axis, and the ray's discriminant r² − |q|², where
    /// q = d − (d·wi)wi is the centre's offset from the ray.
    #[inline(always)]
    fn ray(&self, wi: V3<L>) -> (L, L) {
        let b = self.d.dot(wi);
        let q = self.d - wi.scale(b);
        (b, (self.r - q.length()) * (self.r + q.length()))
    }

    /// True where `wi` is on the light from outside: within the slack-widened cone.
    #[inline(always)]
    fn in_cone(&self, wi: V3<L>) -> L::Mask {
        let axis = self.frame.n;
        let s = wi.cross(axis);
        wi.dot(axis).gt(L::ZERO) & s.dot(s).le(self.sin2_bound)
    }

    /// [`PreparedShape::eval`]: from outside, 1/(2πh) inside the cone (or the cap's pdf) and
    /// the near hit; from inside, the converted area pdf and the far hit.
    #[inline(always)]
    fn eval_lanes(&self, wi: V3<L>) -> (L, L) {
        let cap = self.cap.as_ref().filter(|_| self.by_cap.any());
        self.eval_with(wi, cap.map(|cap| cap.pdf(wi)))
    }

    /// [`eval_lanes`](Self::eval_lanes) with the cap's pdf at `wi` given (where prepared for
    /// it).
    #[inline(always)]
    fn eval_with(&self, wi: V3<L>, cap_pdf: Option<L>) -> (L, L) {
        let (b, disc) = self.ray(wi);
        let root = disc.max(L::ZERO).sqrt();
        // From outside: the cone's pdf, and the near hit as c0/(b + √disc), with no
        // cancellation when the sphere is small or far.
        let near = self.c0 / (b + root);
        // From inside: the far hit t, where |cos θ_l| = √disc / r, so the area pdf converts to
        // t²/(4πr√disc).
        let far = b + root;
        let area = if (!self.outside).any() {
            far * far * self.area_pdf * self.r / root
        } else {
            L::ZERO
        };
        // No lane outside: every lane's cone test is false anyway.
        let cone = if (self.outside & !self.by_cap).any() {
            self.outside & self.in_cone(wi)
        } else {
            self.outside
        };
        let (pdf, t, on) = (
            L::select(self.outside, self.cone_pdf, area),
            L::select(self.outside, near, far),
            cone | (!self.outside & far.gt(L::ZERO)),
        );
        let pdf = L::select(self.valid & on & !wi.any_nan(), pdf, L::ZERO);
        // By projected solid angle: the cap's own pdf, 0 below the horizon.
        let pdf = match cap_pdf {
            Some(cap) => L::select(self.by_cap, cap, pdf),
            None => pdf,
        };
        on_shape(pdf, t)
    }
}
