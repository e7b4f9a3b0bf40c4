//! The registry of samplers: every warp once, with its parameters, its pdf, its inverse, its
//! domain and its policy on bad input. The evidence (lane checks, the special-value sweep, χ²,
//! round trips, the report, the benches) iterates [`registry`] instead of naming warps one by one,
//! so a new sampler is its math plus one [`Sampler`] variant here.
//!
//! Every method is generic over the width, like the warps themselves: `sample(Vec2)`,
//! `sample(Vec2x8)` and `sample(DVec2)` run the same code.
//!
//! ```
//! use glam::Vec2;
//! use mcsample::verify::registry;
//!
//! for s in registry::registry() {
//!     let (x, pdf) = s.sample(Vec2::new(0.3, 0.6));
//!     assert!(s.in_domain(x), "{}", s.name());
//!     assert!(pdf > 0.0 && pdf == s.pdf(x), "{}", s.name());
//! }
//! ```

use core::hint::black_box;

use glam::{DVec2, DVec3, Vec2, Vec3};
use std::format;
use std::string::String;
use std::vec;
use std::vec::Vec;

use super::{Cap, ChiSquare, ChiSquareResult, PlanarLight, square_to_triangle, triangle_to_square};
use crate::lane::{V2, V3};
use crate::math::Math;
use crate::point::{Point2, Point3};
use crate::scene::{self, DiskLight, Lambert, Phong, RectangleLight, SphereLight, TriangleLight};
use crate::warp;

/// One sampler of the registry, with its parameters. Outputs are widened to 3D: the disks give
/// (x, y, 0), the triangle its barycentrics, the tent the pair (tent(u₀), tent(u₁), 0), the
/// spherical rectangle its point on the light, the other warps their direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Sampler {
    /// [`warp::concentric_disk`].
    ConcentricDisk,
    /// [`warp::polar_disk`].
    PolarDisk,
    /// [`warp::uniform_hemisphere`].
    UniformHemisphere,
    /// [`warp::cosine_hemisphere`].
    CosineHemisphere,
    /// [`warp::uniform_sphere`].
    UniformSphere,
    /// [`warp::uniform_cone`] with h = 1 − cos θmax.
    UniformCone {
        /// 1 − cos θmax.
        h: f32,
    },
    /// [`warp::phong_lobe`] with exponent n.
    PhongLobe {
        /// The exponent.
        n: f32,
    },
    /// [`warp::uniform_triangle`] (barycentrics).
    UniformTriangle,
    /// [`warp::tent`] on each coordinate.
    Tent,
    /// [`warp::spherical_triangle`] towards vertices a, b, c (relative to the shading point).
    SphericalTriangle {
        /// The vertices.
        v: [Vec3; 3],
    },
    /// [`warp::spherical_rectangle`] towards corner + s·ex + t·ey.
    SphericalRectangle {
        /// Corner, ex, ey.
        v: [Vec3; 3],
    },
    /// [`scene::SphereLight::sample`] from the origin (the direction and its pdf).
    LightSphere {
        /// The centre.
        center: Vec3,
        /// The radius.
        radius: f32,
    },
    /// [`scene::DiskLight::sample`] from the origin.
    LightDisk {
        /// The centre.
        center: Vec3,
        /// The normal.
        normal: Vec3,
        /// The radius.
        radius: f32,
    },
    /// [`scene::TriangleLight::sample`] from the origin.
    LightTriangle {
        /// The vertices.
        v: [Vec3; 3],
    },
    /// [`scene::RectangleLight::sample`] from the origin.
    LightRectangle {
        /// Corner, ex, ey (orthogonal).
        v: [Vec3; 3],
    },
    /// [`scene::Lambert::sample`] with ρ = 1, in the local frame.
    BsdfLambert {
        /// The outgoing direction.
        wo: Vec3,
    },
    /// [`scene::Phong::sample`] with the diffuse and specular reflectances kd, ks (grey).
    BsdfPhong {
        /// The outgoing direction.
        wo: Vec3,
        /// kd.
        kd: f32,
        /// ks.
        ks: f32,
        /// The exponent.
        n: f32,
    },
}

/// What a sampler gives for NaN in u (and, for the parametrised ones, a NaN parameter).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NanPolicy {
    /// Every output coordinate is the canonical NaN, and the pdf of the sample is 0.
    NanOut,
    /// The sample is dropped: pdf 0 and a fixed finite point.
    ZeroPdf,
}

/// The test triangle of size `s`, about 1.2 s² sr one unit away from the shading point.
fn triangle(s: f32) -> [Vec3; 3] {
    [
        Vec3::new(-0.6 * s, -0.4 * s, 1.0),
        Vec3::new(0.7 * s, -0.3 * s, 1.0 + 0.2 * s),
        Vec3::new(0.1 * s, 0.8 * s, 1.0 - 0.1 * s),
    ]
}

/// The test rectangle of size `s`, tilted, about 0.8 s² sr.
fn rectangle(s: f32) -> [Vec3; 3] {
    [
        Vec3::new(-0.4 * s, -0.7 * s, 1.0),
        Vec3::new(1.1 * s, 0.0, 0.3 * s),
        Vec3::new(0.0, 0.8 * s, 0.0),
    ]
}

/// Every sampler at the parameters the evidence uses: the cone at two sizes, the Phong lobe at
/// three exponents, the spherical polygons large (≈ 1 sr), small (6e-5 / 0.035 sr) and below the
/// spherical-sampling threshold (1e-6 sr for both: sampled by area); then the lights seen from
/// the origin (a sphere far, tiny and around the point, a disk large and small, a triangle and a
/// rectangle large and sampled by area) and the BSDFs.
pub fn registry() -> Vec<Sampler> {
    use Sampler::*;
    vec![
        ConcentricDisk,
        PolarDisk,
        UniformHemisphere,
        CosineHemisphere,
        UniformSphere,
        UniformCone { h: 0.3 },
        UniformCone { h: 1e-3 },
        PhongLobe { n: 1.0 },
        PhongLobe { n: 20.0 },
        PhongLobe { n: 500.0 },
        UniformTriangle,
        Tent,
        SphericalTriangle { v: triangle(1.0) },
        SphericalTriangle { v: triangle(0.01) },
        SphericalTriangle { v: triangle(1e-3) },
        SphericalRectangle { v: rectangle(1.0) },
        SphericalRectangle { v: rectangle(0.2) },
        SphericalRectangle { v: rectangle(1e-3) },
        LightSphere {
            center: Vec3::new(0.6, -0.3, 3.0),
            radius: 1.0,
        },
        // sin²θmax = 1e-4: smaller lights (down to 1e-12) are tested in `tests/all/scene/lights.rs`, where
        // the χ² judge is the f64 pdf; here the f32 pdf's slack of 2ε in sin θ (a band 5e-5 of
        // this cone's area, 5e-4 of one with sin²θmax = 1e-6) stays below what 1e6 samples see.
        LightSphere {
            center: Vec3::new(0.2, 0.1, 1.0),
            radius: 1.02e-2,
        },
        LightSphere {
            center: Vec3::new(0.3, -0.2, 0.25),
            radius: 1.0,
        },
        LightDisk {
            center: Vec3::new(0.4, 0.3, 2.0),
            normal: Vec3::new(0.2, -0.3, -1.0),
            radius: 1.0,
        },
        LightDisk {
            center: Vec3::new(0.4, 0.3, 2.0),
            normal: Vec3::new(0.2, -0.3, -1.0),
            radius: 0.02,
        },
        LightTriangle { v: triangle(1.0) },
        LightTriangle { v: triangle(1e-3) },
        LightRectangle {
            v: square_light(1.0),
        },
        LightRectangle {
            v: square_light(0.05),
        },
        BsdfLambert {
            wo: Vec3::new(0.3, -0.2, 0.933_809),
        },
        BsdfPhong {
            wo: Vec3::new(0.5, 0.1, 0.860_232_5),
            kd: 0.4,
            ks: 0.5,
            n: 20.0,
        },
        BsdfPhong {
            wo: Vec3::new(0.0, 0.6, 0.8),
            kd: 0.0,
            ks: 0.9,
            n: 500.0,
        },
    ]
}

/// A square light of side `s` one unit up, tilted about x by 0.4 rad: corner and orthogonal edges.
fn square_light(s: f32) -> [Vec3; 3] {
    let (sn, cs) = 0.4f32.sin_cos();
    let ey = Vec3::new(0.0, s * cs, s * sn);
    [
        Vec3::new(-0.5 * s, -0.3 * s, 1.0),
        Vec3::new(s, 0.0, 0.0),
        ey,
    ]
}

/// The special parameter values of the sweep: 0, tiny, 1, huge, ∞ and NaN (and negatives).
pub const SPECIAL_PARAMS: [f32; 9] = [
    0.0,
    -0.0,
    1e-30,
    1.0,
    1e30,
    f32::INFINITY,
    -1.0,
    f32::NEG_INFINITY,
    f32::NAN,
];

/// Degenerate and extreme geometry for the spherical polygons: coincident and collinear
/// vertices, the shading point in the plane, on a vertex, tiny and huge lights, and non-finite
/// coordinates.
pub fn degenerate_polygons() -> Vec<[Vec3; 3]> {
    let a = Vec3::new(-0.3, -0.2, 1.0);
    let b = Vec3::new(0.4, -0.1, 1.1);
    let c = Vec3::new(0.0, 0.5, 0.9);
    vec![
        [a, a, c],
        [a, b, b],
        [a, a, a],
        [a, (a + b) * 0.5, b],
        [
            Vec3::new(-1.0, 0.0, 0.0),
            Vec3::new(1.0, 0.0, 0.0),
            Vec3::new(0.0, 1.0, 0.0),
        ],
        [Vec3::ZERO, b, c],
        [Vec3::ZERO; 3],
        [a * 1e-30, b * 1e-30, c * 1e-30],
        [a * 1e30, b * 1e30, c * 1e30],
        [a * 1e-20, b * 1e-20, c * 1e-20],
        [Vec3::new(f32::NAN, 0.0, 1.0), b, c],
        [Vec3::new(f32::INFINITY, 0.0, 1.0), b, c],
        [a, Vec3::new(0.0, f32::NEG_INFINITY, 1.0), c],
    ]
}

impl Sampler {
    /// The name the report and the JSON use: the function, and its parameters where it has any.
    pub fn name(&self) -> String {
        use Sampler::*;
        match self {
            ConcentricDisk => "concentric_disk".into(),
            PolarDisk => "polar_disk".into(),
            UniformHemisphere => "uniform_hemisphere".into(),
            CosineHemisphere => "cosine_hemisphere".into(),
            UniformSphere => "uniform_sphere".into(),
            UniformCone { h } => format!("uniform_cone h={h}"),
            PhongLobe { n } => format!("phong_lobe n={n}"),
            UniformTriangle => "uniform_triangle".into(),
            Tent => "tent".into(),
            SphericalTriangle { .. } => format!("spherical_triangle {}", self.polygon_size()),
            SphericalRectangle { .. } => format!("spherical_rectangle {}", self.polygon_size()),
            LightSphere { center, radius } => {
                let s2 = (*radius as f64 / center.as_dvec3().length()).powi(2);
                if s2 >= 1.0 {
                    "light_sphere inside".into()
                } else {
                    format!("light_sphere sin2={s2:.0e}")
                }
            }
            LightDisk { radius, .. } => format!("light_disk r={radius}"),
            LightTriangle { .. } => format!("light_triangle {}", self.polygon_size()),
            LightRectangle { .. } => format!("light_rectangle {}", self.polygon_size()),
            BsdfLambert { .. } => "bsdf_lambert".into(),
            BsdfPhong { kd, n, .. } => format!("bsdf_phong n={n} kd={kd}"),
        }
    }

    /// How a spherical polygon is sampled, by the solid angle 1/pdf of its sample at u = (½, ½):
    /// "area" below the spherical-sampling threshold (or degenerate), "small" up to 0.5 sr,
    /// "large" above; "" for the other samplers.
    pub fn polygon_size(&self) -> &'static str {
        let min = match self {
            Sampler::SphericalTriangle { .. } | Sampler::LightTriangle { .. } => {
                warp::SPHERICAL_TRIANGLE_MIN_SR
            }
            Sampler::SphericalRectangle { .. } | Sampler::LightRectangle { .. } => {
                warp::SPHERICAL_RECTANGLE_MIN_SR
            }
            _ => return "",
        };
        let pdf = self.sample(Vec2::splat(0.5)).1;
        let omega = 1.0 / pdf as f64;
        if omega.is_nan() || omega < min as f64 {
            "area"
        } else if omega > 0.5 {
            "large"
        } else {
            "small"
        }
    }

    /// The same sampler with its parameter replaced by `p` (the sweep's special values); the
    /// samplers without a scalar parameter come back unchanged.
    pub fn with_param(self, p: f32) -> Self {
        match self {
            Sampler::UniformCone { .. } => Sampler::UniformCone { h: p },
            Sampler::PhongLobe { .. } => Sampler::PhongLobe { n: p },
            Sampler::LightSphere { center, .. } => Sampler::LightSphere { center, radius: p },
            Sampler::LightDisk { center, normal, .. } => Sampler::LightDisk {
                center,
                normal,
                radius: p,
            },
            Sampler::BsdfPhong { wo, kd, ks, .. } => Sampler::BsdfPhong { wo, kd, ks, n: p },
            other => other,
        }
    }

    /// The same sampler towards other geometry (the spherical polygons only).
    pub fn with_geometry(self, v: [Vec3; 3]) -> Self {
        match self {
            Sampler::SphericalTriangle { .. } => Sampler::SphericalTriangle { v },
            Sampler::SphericalRectangle { .. } => Sampler::SphericalRectangle { v },
            Sampler::LightTriangle { .. } => Sampler::LightTriangle { v },
            Sampler::LightRectangle { .. } => Sampler::LightRectangle { v },
            other => other,
        }
    }

    /// What NaN in u gives.
    pub fn nan_policy(&self) -> NanPolicy {
        match self {
            Sampler::SphericalTriangle { .. } | Sampler::SphericalRectangle { .. } => {
                NanPolicy::ZeroPdf
            }
            _ if self.is_light() => NanPolicy::ZeroPdf,
            _ => NanPolicy::NanOut,
        }
    }

    /// The coordinates of a point that its pdf and inverse read: (x, y) for the disks, the tent
    /// pair and the barycentric density; z alone for the cosine and Phong pdfs, which cos θ
    /// decides; all three otherwise. NaN in a coordinate that is read gives pdf 0.
    pub fn pdf_reads(&self) -> &'static [usize] {
        match self {
            Sampler::ConcentricDisk | Sampler::PolarDisk | Sampler::Tent => &[0, 1],
            Sampler::UniformTriangle => &[0, 1],
            Sampler::CosineHemisphere | Sampler::PhongLobe { .. } | Sampler::BsdfLambert { .. } => {
                &[2]
            }
            _ => &[0, 1, 2],
        }
    }

    /// The coordinates of a point that the inverse reads: (x, y) for the disks, the tent pair and
    /// the cosine hemisphere (its concentric inverse); all three otherwise.
    pub fn inverse_reads(&self) -> &'static [usize] {
        match self {
            Sampler::ConcentricDisk
            | Sampler::PolarDisk
            | Sampler::Tent
            | Sampler::CosineHemisphere => &[0, 1],
            _ => &[0, 1, 2],
        }
    }

    /// True when the parameters and geometry are valid, so that every non-NaN u must give a
    /// sample with a positive, finite pdf. Degenerate lights and cones (h ≤ 0) give pdf 0.
    pub fn is_proper(&self) -> bool {
        match *self {
            Sampler::UniformCone { h } => h > 0.0,
            Sampler::PhongLobe { n } => !n.is_nan(),
            // A light is proper when it is sampled at all: the sampler, not the pdf function,
            // decides (they disagree at the edges of huge or grazing lights, see `check_sample`).
            Sampler::SphericalTriangle { .. } | Sampler::SphericalRectangle { .. } => {
                self.sample(Vec2::splat(0.5)).1 > 0.0
            }
            Sampler::BsdfPhong { n, .. } => !n.is_nan(),
            _ if self.is_light() => self.sample(Vec2::splat(0.5)).1 > 0.0,
            _ => true,
        }
    }

    /// The parameter of the sampler as a lane value (the f64 instance sees the same f32 value).
    #[inline(always)]
    fn param<L: Math>(x: f32) -> L {
        L::c(x as f64)
    }

    #[inline(always)]
    fn verts<L: Math>(v: &[Vec3; 3]) -> [V3<L>; 3] {
        v.map(Self::vec)
    }

    #[inline(always)]
    fn vec<L: Math>(p: Vec3) -> V3<L> {
        V3::new(Self::param(p.x), Self::param(p.y), Self::param(p.z))
    }

    /// The light of a light sampler, with Le = 1, in any width; `None` for the other samplers.
    #[inline(always)]
    fn light<V: Point3<Lane = L>, L: Math>(&self) -> Option<scene::Light<V>> {
        let v = |p: Vec3| V::from_lanes(Self::vec(p));
        let one = V::from_lanes(V3::all(L::ONE));
        Some(match *self {
            Sampler::LightSphere { center, radius } => {
                scene::Light::from(SphereLight::new(v(center), Self::param(radius), one))
            }
            Sampler::LightDisk {
                center,
                normal,
                radius,
            } => scene::Light::from(DiskLight::new(
                v(center),
                v(normal),
                Self::param(radius),
                one,
            )),
            Sampler::LightTriangle { v: [a, b, c] } => {
                scene::Light::from(TriangleLight::new(v(a), v(b), v(c), one))
            }
            Sampler::LightRectangle { v: [c, ex, ey] } => {
                scene::Light::from(RectangleLight::new(v(c), v(ex), v(ey), one))
            }
            _ => return None,
        })
    }

    /// The scene light of a light sampler (Le = 1, seen from the origin), for callers that time
    /// or test its other methods (the prepared form, `hit`); `None` for the other samplers.
    pub fn scene_light(&self) -> Option<scene::Light> {
        self.light()
    }

    /// True for the four lights, sampled from the origin.
    pub fn is_light(&self) -> bool {
        matches!(
            self,
            Sampler::LightSphere { .. }
                | Sampler::LightDisk { .. }
                | Sampler::LightTriangle { .. }
                | Sampler::LightRectangle { .. }
        )
    }

    /// True where the map is so sensitive to the rounding of its parameters that the f32 map and
    /// its f64 instance differ by more than rounding of the map itself: the Phong BSDF just
    /// around its lobe choice at u₀ = P = kd/(kd + ks). The two instances' P differ by rounding
    /// (1e-7 relative), so next to P they may pick different lobes; and above it the lobe's
    /// rescaled u₀, v = (u₀ − P)/(1 − P), carries P's rounding into a map that is steep for small
    /// v (dt/dv ∝ v^(−n/(n+1))): 1e-5 of direction at v = 0.01; below it, v = u₀/P near 1 puts
    /// the cosine lobe's sample at the rim, where z = √(1 − r²) is steep in r; and at u₀ → 1 the
    /// rescaled u₀'s own rounding moves the lobe's peak, where sin α ∝ √(1 − v). Error
    /// measurements skip u whose rescaled u₀ lies within 5 % of P's side of the choice, or u₀
    /// within 1e-5 of 1.
    pub fn parameter_sensitive(&self, u: Vec2) -> bool {
        match *self {
            Sampler::BsdfPhong { kd, ks, .. } => {
                let p = kd as f64 / (kd as f64 + ks as f64);
                let u0 = u.x as f64;
                (u0 > 0.95 * p && u0 < p + 0.05 * (1.0 - p)) || u0 > 1.0 - 1e-5
            }
            _ => false,
        }
    }

    /// True for the two BSDFs.
    pub fn is_bsdf(&self) -> bool {
        matches!(
            self,
            Sampler::BsdfLambert { .. } | Sampler::BsdfPhong { .. }
        )
    }

    /// False for the lights and BSDFs, which have no inverse: [`inverse`](Self::inverse) gives
    /// NaN for them.
    pub fn has_inverse(&self) -> bool {
        !(self.is_light() || self.is_bsdf())
    }

    /// The sample of `u` and its pdf (the pdf the warp returns, or its pdf function at the
    /// sample), in the width of `u`.
    #[inline]
    pub fn sample<P: Point2<Lane = L>, L: Math>(&self, u: P) -> (P::Vec3, L) {
        let (x, pdf) = self.dispatch(One(u.to_lanes()));
        (Point3::from_lanes(x), pdf)
    }

    /// The samples of every u of `us` into `out` (as many as the shorter of the two), with the
    /// match on the sampler taken once for the whole batch: the loop runs the warp inlined, as a
    /// hand-written loop would, which is what the report and the benches time.
    #[inline]
    pub fn sample_all<P: Point2<Lane = L>, L: Math>(&self, us: &[P], out: &mut [P::Vec3]) {
        self.dispatch(All(us, out))
    }

    /// Hands the sampler's map u ↦ (sample, pdf) to `visit`, as a closure of its own type for
    /// each sampler, so that whatever `visit` does with it (one call, a loop) is monomorphic.
    /// The closures are `#[inline(always)]`: each is called from both visitors, and LLVM would
    /// otherwise keep it out of line, which stops the vectoriser in the batch loop (the AVX2
    /// build's scalar sphere ran 3-5x slower than a user's own loop over the warp).
    #[inline(always)]
    fn dispatch<L: Math, V: Visit<L>>(&self, visit: V) -> V::Out {
        match *self {
            Sampler::ConcentricDisk => visit.visit(
                #[inline(always)]
                |u| {
                    let p = warp::concentric_disk(u);
                    (V3::new(p.x, p.y, L::ZERO), warp::uniform_disk_pdf(p))
                },
            ),
            Sampler::PolarDisk => visit.visit(
                #[inline(always)]
                |u| {
                    let p = warp::polar_disk(u);
                    (V3::new(p.x, p.y, L::ZERO), warp::uniform_disk_pdf(p))
                },
            ),
            Sampler::UniformHemisphere => visit.visit(
                #[inline(always)]
                |u| {
                    let w = warp::uniform_hemisphere(u);
                    (w, warp::uniform_hemisphere_pdf(w))
                },
            ),
            Sampler::CosineHemisphere => visit.visit(
                #[inline(always)]
                |u| {
                    let w = warp::cosine_hemisphere(u);
                    (w, warp::cosine_hemisphere_pdf(w))
                },
            ),
            Sampler::UniformSphere => visit.visit(
                #[inline(always)]
                |u| {
                    let w = warp::uniform_sphere(u);
                    (w, warp::uniform_sphere_pdf(w))
                },
            ),
            Sampler::UniformCone { h } => {
                let h = Self::param(h);
                visit.visit(
                    #[inline(always)]
                    move |u| {
                        let w = warp::uniform_cone(u, h);
                        (w, warp::uniform_cone_pdf(w, h))
                    },
                )
            }
            Sampler::PhongLobe { n } => {
                let n = Self::param(n);
                visit.visit(
                    #[inline(always)]
                    move |u| {
                        let w = warp::phong_lobe(u, n);
                        (w, warp::phong_lobe_pdf(w, n))
                    },
                )
            }
            Sampler::UniformTriangle => visit.visit(
                #[inline(always)]
                |u| {
                    let b = warp::uniform_triangle(u);
                    (b, warp::uniform_triangle_pdf(b))
                },
            ),
            Sampler::Tent => visit.visit(
                #[inline(always)]
                |u: V2<L>| {
                    // A pair of tents is one 2D sample: NaN in either coordinate drops both.
                    // The tent is NaN only for NaN in, so the inputs' mask is the whole story,
                    // and the pair makes the canonical NaN itself: `warp::tent` less its own
                    // NaN test (the same bits as `warp::tent` wherever u is not NaN).
                    let t = V2::new(warp::tent_uncanonical(u.x), warp::tent_uncanonical(u.y))
                        .nan_if(u.any_nan());
                    let x = V3::new(t.x, t.y, L::ZERO);
                    (x, warp::tent_pdf(x.x) * warp::tent_pdf(x.y))
                },
            ),
            // The geometry passes through `black_box` so that a loop over a batch pays the
            // per-light set-up at every sample, as a renderer does when each sample has its own
            // shading point; hoisted out of the loop, it would time a third of the call.
            Sampler::SphericalTriangle { v } => {
                let v = Self::verts(&v);
                visit.visit(
                    #[inline(always)]
                    move |u| {
                        let [a, b, c] = black_box(v);
                        warp::spherical_triangle(u, a, b, c)
                    },
                )
            }
            Sampler::SphericalRectangle { v } => {
                let v = Self::verts(&v);
                visit.visit(
                    #[inline(always)]
                    move |u| {
                        let [a, b, c] = black_box(v);
                        warp::spherical_rectangle(u, a, b, c)
                    },
                )
            }
            // The lights, sampled from the origin: the light through `black_box`, as above.
            Sampler::LightSphere { .. }
            | Sampler::LightDisk { .. }
            | Sampler::LightTriangle { .. }
            | Sampler::LightRectangle { .. } => {
                let light = self.light::<V3<L>, L>();
                visit.visit(
                    #[inline(always)]
                    move |u| match black_box(light) {
                        Some(l) => {
                            let s = l.sample(V3::all(L::ZERO), u);
                            (s.wi, s.pdf)
                        }
                        None => (V3::all(L::ZERO), L::ZERO),
                    },
                )
            }
            Sampler::BsdfLambert { wo } => {
                let wo = Self::vec(wo);
                visit.visit(
                    #[inline(always)]
                    move |u| {
                        let s = Lambert::new(V3::all(L::ONE)).sample(wo, u);
                        (s.wi, s.pdf)
                    },
                )
            }
            Sampler::BsdfPhong { wo, kd, ks, n } => {
                let wo = Self::vec(wo);
                let bsdf = Phong::new(
                    V3::all(Self::param(kd)),
                    V3::all(Self::param(ks)),
                    Self::param(n),
                );
                visit.visit(
                    #[inline(always)]
                    move |u| {
                        let s = bsdf.sample(wo, u);
                        (s.wi, s.pdf)
                    },
                )
            }
        }
    }

    /// The pdf of output `x` (in the measure of the sampler: per unit area for the disks, the
    /// barycentric square and the tent pair, per steradian for directions).
    #[inline]
    pub fn pdf<P: Point3<Lane = L>, L: Math>(&self, x: P) -> L {
        let x = x.to_lanes();
        match *self {
            Sampler::ConcentricDisk | Sampler::PolarDisk => {
                let inside = x.z.eq(L::ZERO);
                L::select(inside, warp::uniform_disk_pdf(V2::new(x.x, x.y)), L::ZERO)
            }
            Sampler::UniformHemisphere => warp::uniform_hemisphere_pdf(x),
            Sampler::CosineHemisphere => warp::cosine_hemisphere_pdf(x),
            Sampler::UniformSphere => warp::uniform_sphere_pdf(x),
            Sampler::UniformCone { h } => warp::uniform_cone_pdf(x, Self::param(h)),
            Sampler::PhongLobe { n } => warp::phong_lobe_pdf(x, Self::param(n)),
            Sampler::UniformTriangle => warp::uniform_triangle_pdf(x),
            Sampler::Tent => warp::tent_pdf(x.x) * warp::tent_pdf(x.y),
            Sampler::SphericalTriangle { v } => {
                let [a, b, c] = Self::verts(&v);
                warp::spherical_triangle_pdf(x, a, b, c)
            }
            Sampler::SphericalRectangle { v } => {
                let [a, b, c] = Self::verts(&v);
                warp::spherical_rectangle_pdf(x.normalize(), a, b, c)
            }
            Sampler::LightSphere { .. }
            | Sampler::LightDisk { .. }
            | Sampler::LightTriangle { .. }
            | Sampler::LightRectangle { .. } => match self.light::<V3<L>, L>() {
                Some(l) => l.pdf(V3::all(L::ZERO), x),
                None => L::ZERO,
            },
            Sampler::BsdfLambert { wo } => Lambert::new(V3::all(L::ONE)).pdf(Self::vec(wo), x),
            Sampler::BsdfPhong { wo, kd, ks, n } => Phong::new(
                V3::all(Self::param(kd)),
                V3::all(Self::param(ks)),
                Self::param(n),
            )
            .pdf(Self::vec(wo), x),
        }
    }

    /// The u that maps to output `x`.
    #[inline]
    pub fn inverse<P: Point3<Lane = L>, L: Math>(&self, x: P) -> P::Vec2 {
        let x = x.to_lanes();
        let u: V2<L> = match *self {
            Sampler::ConcentricDisk => warp::concentric_disk_inverse(V2::new(x.x, x.y)),
            Sampler::PolarDisk => warp::polar_disk_inverse(V2::new(x.x, x.y)),
            Sampler::UniformHemisphere => warp::uniform_hemisphere_inverse(x),
            Sampler::CosineHemisphere => warp::cosine_hemisphere_inverse(x),
            Sampler::UniformSphere => warp::uniform_sphere_inverse(x),
            Sampler::UniformCone { h } => warp::uniform_cone_inverse(x, Self::param(h)),
            Sampler::PhongLobe { n } => warp::phong_lobe_inverse(x, Self::param(n)),
            Sampler::UniformTriangle => warp::uniform_triangle_inverse(x),
            Sampler::Tent => V2::new(warp::tent_inverse(x.x), warp::tent_inverse(x.y)),
            Sampler::SphericalTriangle { v } => {
                let [a, b, c] = Self::verts(&v);
                warp::spherical_triangle_inverse(x, a, b, c)
            }
            Sampler::SphericalRectangle { v } => {
                let [a, b, c] = Self::verts(&v);
                warp::spherical_rectangle_inverse(x, a, b, c)
            }
            _ => V2::new(L::c(f64::NAN), L::c(f64::NAN)),
        };
        Point2::from_lanes(u)
    }

    /// True when `x` is a point of the sampler's domain, up to f32 rounding: the unit disk, the
    /// upper hemisphere, the sphere, the cone, the triangle of barycentrics, the square [−1, 1]²,
    /// or (for the polygons) a unit direction or a point of the light.
    pub fn in_domain(&self, x: Vec3) -> bool {
        let x64 = x.as_dvec3();
        let unit = (x64.length() - 1.0).abs() <= 1e-6;
        let finite = x.is_finite();
        finite
            && match *self {
                Sampler::ConcentricDisk | Sampler::PolarDisk => {
                    x.z == 0.0 && x64.truncate().length_squared() <= 1.0 + 1e-6
                }
                Sampler::UniformHemisphere | Sampler::CosineHemisphere => unit && x.z >= 0.0,
                Sampler::UniformSphere => unit,
                Sampler::UniformCone { h } => {
                    let h = (h as f64).clamp(0.0, 2.0);
                    unit && 1.0 - x64.z <= h * (1.0 + 1e-6) + 1e-7
                }
                Sampler::PhongLobe { .. } => unit && x.z >= 0.0,
                Sampler::UniformTriangle => {
                    x.min_element() >= 0.0 && (x64.x + x64.y + x64.z - 1.0).abs() <= 1e-6
                }
                Sampler::Tent => x.x.abs() <= 1.0 && x.y.abs() <= 1.0 && x.z == 0.0,
                Sampler::SphericalTriangle { .. } => unit,
                // A light's direction is unit and on the light (its f32 pdf says so); a
                // BSDF's is unit.
                Sampler::LightSphere { .. }
                | Sampler::LightDisk { .. }
                | Sampler::LightTriangle { .. }
                | Sampler::LightRectangle { .. } => unit && self.pdf(x) > 0.0,
                Sampler::BsdfLambert { .. } | Sampler::BsdfPhong { .. } => unit,
                Sampler::SphericalRectangle { v } => {
                    // Within 1e-5 of the light's size and distance of its parallelogram, in the
                    // plane and across it: an f32 point far from the origin is rounded on the
                    // scale of its distance, not of the light.
                    let d = x64 - v[0].as_dvec3();
                    let (ex, ey) = (v[1].as_dvec3(), v[2].as_dvec3());
                    // (s, t) from the 2×2 Gram system, so that edges only nearly orthogonal
                    // (as rounding leaves them) do not leak one coordinate into the other.
                    let (xx, xy, yy) = (ex.dot(ex), ex.dot(ey), ey.dot(ey));
                    let (dx, dy) = (d.dot(ex), d.dot(ey));
                    let det = xx * yy - xy * xy;
                    let s = (dx * yy - dy * xy) / det;
                    let t = (dy * xx - dx * xy) / det;
                    let off = (d - ex * s - ey * t).length();
                    let tol = 1e-5 * (ex.length() + ey.length() + v[0].as_dvec3().length());
                    let (ms, mt) = (tol / ex.length(), tol / ey.length());
                    (-ms..=1.0 + ms).contains(&s) && (-mt..=1.0 + mt).contains(&t) && off <= tol
                }
            }
    }

    /// Checks the documented bad-input policy on one u, any value at all (the special-value sweep
    /// and the fuzz target run it):
    ///
    /// - the returned pdf is finite and ≥ 0, and (but for the spherical polygons, see below)
    ///   equal bit for bit to the pdf function at the sample;
    /// - NaN in u, or a NaN parameter, gives what [`nan_policy`](Self::nan_policy) says;
    /// - otherwise, for proper parameters, u is clamped: the sample is in the domain, and its
    ///   inverse lies in [0, 1]²; degenerate parameters give pdf 0 and a finite point;
    /// - a spherical polygon's sample either lies on the light with a positive pdf or is dropped
    ///   (pdf 0) at a finite point, a degenerate rectangle's corner (which may be non-finite).
    ///
    /// The spherical polygons are exempt from the pdf-function and inverse checks at their
    /// vertices and edges, where those functions do not yet agree with the sampler.
    pub fn check_sample(&self, u: Vec2) -> Result<(), String> {
        let s = *self;
        let (x, pdf) = s.sample(u);
        let ctx = || format!("{} {s:?}: u = {u:?} → x = {x:?}, pdf = {pdf:e}", s.name());
        if !(pdf.is_finite() && pdf >= 0.0) {
            return Err(format!("pdf not finite and ≥ 0: {}", ctx()));
        }
        // A light's dropped sample (pdf 0) sits at +z, which may be on the light.
        let dropped_light = s.is_light() && pdf == 0.0;
        if !s.is_polygon() && !dropped_light && pdf.to_bits() != s.pdf(x).to_bits() {
            return Err(format!("returned pdf ≠ pdf(x) = {:e}: {}", s.pdf(x), ctx()));
        }
        let param_nan = match s {
            Sampler::UniformCone { h } => h.is_nan(),
            Sampler::PhongLobe { n } | Sampler::BsdfPhong { n, .. } => n.is_nan(),
            _ => false,
        };
        if u.is_nan() || param_nan {
            let ok = match s.nan_policy() {
                NanPolicy::NanOut => s.is_canonical_nan(x) && pdf == 0.0,
                NanPolicy::ZeroPdf => pdf == 0.0 && (x.is_finite() || s.is_corner(x)),
            };
            if !ok {
                return Err(format!("NaN in: not {:?}: {}", s.nan_policy(), ctx()));
            }
        } else if s.is_polygon() || s.is_light() {
            // A light either gives a sample on it with a positive pdf or drops it (pdf 0, as
            // for degenerate geometry, or where the area pdf would overflow) at a finite point.
            let on_light = pdf > 0.0 && s.in_domain(x);
            let dropped = pdf == 0.0 && (x.is_finite() || s.is_corner(x));
            if !(on_light || dropped) {
                return Err(format!(
                    "not a sample on the light nor a dropped one: {}",
                    ctx()
                ));
            }
        } else if s.is_proper() {
            if !s.in_domain(x) {
                return Err(format!(
                    "clamped u gives a point outside the domain: {}",
                    ctx()
                ));
            }
            let back = s.inverse(x);
            let unit =
                back.is_finite() && back.cmpge(Vec2::ZERO).all() && back.cmple(Vec2::ONE).all();
            if s.has_inverse() && !unit {
                return Err(format!("inverse {back:?} outside [0, 1]²: {}", ctx()));
            }
        } else if pdf != 0.0 || !(x.is_finite() || s.is_corner(x)) {
            return Err(format!(
                "degenerate parameters: not pdf 0 at a finite point: {}",
                ctx()
            ));
        }
        Ok(())
    }

    /// Checks the policy of the pdf and the inverse at any point `p`, returned by the sampler or
    /// not: the pdf is finite and ≥ 0, and 0 where a coordinate it reads is NaN; the inverse of a
    /// point with NaN where it reads is NaN (for the samplers whose policy is NaN out).
    pub fn check_point(&self, p: Vec3) -> Result<(), String> {
        let pdf = self.pdf(p);
        let read_nan = |reads: &[usize]| reads.iter().any(|&k| p[k].is_nan());
        if !(pdf.is_finite() && pdf >= 0.0) || (read_nan(self.pdf_reads()) && pdf != 0.0) {
            return Err(format!("{}: pdf({p:?}) = {pdf:e}", self.name()));
        }
        let back = self.inverse(p);
        if read_nan(self.inverse_reads())
            && self.nan_policy() == NanPolicy::NanOut
            && !back.is_nan()
        {
            return Err(format!(
                "{}: inverse({p:?}) = {back:?}, not NaN",
                self.name()
            ));
        }
        Ok(())
    }

    /// True for the spherical triangle and rectangle, the samplers with geometry.
    pub fn is_polygon(&self) -> bool {
        matches!(
            self,
            Sampler::SphericalTriangle { .. } | Sampler::SphericalRectangle { .. }
        )
    }

    /// A degenerate rectangle returns its corner as the point (documented), NaN corner included.
    fn is_corner(&self, x: Vec3) -> bool {
        match self {
            Sampler::SphericalRectangle { v } => x
                .to_array()
                .iter()
                .zip(v[0].to_array())
                .all(|(a, b)| a.to_bits() == b.to_bits()),
            _ => false,
        }
    }

    /// Every coordinate the sampler returns is the canonical NaN (the disks and the tent pair
    /// return two; the registry pads them with z = 0).
    fn is_canonical_nan(&self, v: Vec3) -> bool {
        let k = match self {
            Sampler::ConcentricDisk | Sampler::PolarDisk | Sampler::Tent => 2,
            _ => 3,
        };
        v.to_array()[..k].iter().all(|c| c.to_bits() == 0x7fc0_0000)
    }

    /// The largest |inverse(sample(u)) − u| per coordinate, over the whole square: a few ulp
    /// for the simple warps, more where the map compresses. The spherical polygons sampled by
    /// area resolve only the f32 direction grid over the light (6e-8/√Ω: 1e-4 at 5e-7 sr);
    /// Ureña's map forms Ω as Σγ − 2π, which cancels as the rectangle shrinks (1.5e-5 in u₀ at
    /// 0.035 sr).
    pub fn roundtrip_bound(&self) -> [f32; 2] {
        match self {
            Sampler::ConcentricDisk | Sampler::CosineHemisphere => [5e-7, 5e-7],
            Sampler::PolarDisk | Sampler::UniformHemisphere | Sampler::UniformSphere => {
                [3e-7, 3e-7]
            }
            Sampler::UniformCone { .. } => [5e-7, 1.2e-7],
            Sampler::PhongLobe { .. } => [1e-6, 3e-7],
            Sampler::UniformTriangle | Sampler::Tent => [1.2e-7, 1.2e-7],
            Sampler::SphericalTriangle { .. } => match self.polygon_size() {
                "area" => [1.5e-4, 1.5e-4],
                _ => [4e-6, 1.5e-6],
            },
            Sampler::SphericalRectangle { .. } => match self.polygon_size() {
                "area" => [1.5e-4, 1.5e-4],
                _ => [2e-6, 5e-7],
            },
            // No inverse.
            _ => [0.0, 0.0],
        }
    }

    /// True where u₁ is an azimuth, periodic with period 1: its round-trip error is taken
    /// modulo 1.
    pub fn u1_periodic(&self) -> bool {
        matches!(
            self,
            Sampler::PolarDisk
                | Sampler::UniformHemisphere
                | Sampler::UniformSphere
                | Sampler::UniformCone { .. }
                | Sampler::PhongLobe { .. }
        )
    }

    /// Which coordinates of u the sample x = sample(u) determines. Within 1e-3 of a pole of the
    /// parameterisation (1e-6 in u₀), one does not: u₁ at the polar disk's centre and at the
    /// axis of the hemisphere, sphere, cone and lobe; u₀ at the spherical triangle's apex B
    /// (u₁ → 0).
    pub fn determined(&self, u: Vec2, x: Vec3) -> [bool; 2] {
        match self {
            Sampler::PolarDisk => [true, x.truncate().length() > 1e-3],
            Sampler::UniformHemisphere | Sampler::PhongLobe { .. } => [true, u.x < 1.0 - 1e-6],
            Sampler::UniformSphere => [true, u.x > 1e-6 && u.x < 1.0 - 1e-6],
            Sampler::UniformCone { .. } => [true, u.x > 1e-6],
            Sampler::SphericalTriangle { .. } => [u.y > 1e-3, true],
            _ => [true, true],
        }
    }

    /// The cap of directions that holds every sample of a light or BSDF, for the χ² zoom and
    /// for quadrature: the cone of a sphere seen from outside (2 % wider), a cap 20 % wider
    /// than a disk's rim or a polygon's vertices, the hemisphere of Lambert, the whole sphere for
    /// a Phong BSDF with a diffuse part, and for a pure Phong lobe the cap about the mirror
    /// direction outside which cosⁿα is below e⁻¹⁵ (1 − cos α > 15/n).
    pub fn cap(&self) -> Cap {
        let cap_of_points = |pts: &[Vec3]| Cap::around(pts);
        match *self {
            Sampler::LightSphere { center, radius } => {
                let c = center.as_dvec3();
                let s2 = (radius as f64 / c.length()).powi(2);
                if s2 < 1.0 {
                    // 50/49 of the cone: its edge then falls on the edge of the χ² grid's
                    // last row of 50, where no cell straddles the discontinuity.
                    Cap::new(c, 50.0 / 49.0 * s2 / (1.0 + (1.0 - s2).sqrt()))
                } else {
                    Cap::z(2.0)
                }
            }
            Sampler::LightDisk {
                center,
                normal,
                radius,
            } => {
                let (t, b) = normal.normalize().any_orthonormal_pair();
                let rim: Vec<Vec3> = (0..64)
                    .map(|k| {
                        let (sn, cs) = (k as f32 * core::f32::consts::TAU / 64.0).sin_cos();
                        center + (t * cs + b * sn) * radius
                    })
                    .collect();
                cap_of_points(&rim)
            }
            Sampler::LightTriangle { v } | Sampler::SphericalTriangle { v } => cap_of_points(&v),
            Sampler::LightRectangle { v: [c, ex, ey] }
            | Sampler::SphericalRectangle { v: [c, ex, ey] } => {
                cap_of_points(&[c, c + ex, c + ey, c + ex + ey])
            }
            Sampler::BsdfLambert { .. } => Cap::z(1.0),
            Sampler::BsdfPhong { wo, kd, n, .. } if kd == 0.0 && n >= 100.0 => {
                let r = DVec3::new(-wo.x as f64, -wo.y as f64, wo.z as f64);
                Cap::new(r, 15.0 / n as f64)
            }
            _ => Cap::z(2.0),
        }
    }

    /// Mitsuba's χ² test of `samples` samples from the sequence `u` against this sampler's pdf,
    /// on the domain that suits it: the disk, a cap of the sphere zoomed onto the whole (narrow
    /// lobes and cones), the square through an equal-area map (triangle, tent pair), or the
    /// light's own parameter square ([`PlanarLight`]).
    pub fn chi_square(&self, samples: usize, u: impl Fn(usize) -> Vec2) -> ChiSquareResult {
        self.chi_square_against(self, samples, u)
    }

    /// [`chi_square`](Self::chi_square) of this sampler's samples against `judge`'s pdf, through
    /// the same domain and binning: with a different judge, the negative control that shows
    /// the test rejects a wrong pdf.
    pub fn chi_square_against(
        &self,
        judge: &Sampler,
        samples: usize,
        u: impl Fn(usize) -> Vec2,
    ) -> ChiSquareResult {
        let (s, judge) = (*self, *judge);
        let sample = move |i: usize| s.sample(u(i)).0;
        match s {
            Sampler::ConcentricDisk | Sampler::PolarDisk => ChiSquare::disk().samples(samples).run(
                |i| sample(i).truncate(),
                |p: DVec2| judge.pdf(p.extend(0.0)),
            ),
            Sampler::UniformHemisphere
            | Sampler::CosineHemisphere
            | Sampler::UniformSphere
            | Sampler::UniformCone { .. }
            | Sampler::PhongLobe { .. } => {
                let hs = match s {
                    Sampler::UniformSphere => 2.0,
                    Sampler::UniformCone { h } => h as f64,
                    // A cap holding all but (1 − hs)^(n+1) of the lobe, far below 1/N.
                    Sampler::PhongLobe { n } if n >= 500.0 => 0.06,
                    Sampler::PhongLobe { n } if n >= 20.0 => 0.8,
                    _ => 1.0,
                };
                Cap::z(hs).test(
                    ChiSquare::sphere().samples(samples).ires(6),
                    sample,
                    |w: DVec3| judge.pdf(w.as_vec3()) as f64,
                )
            }
            Sampler::UniformTriangle => ChiSquare::square().samples(samples).run(
                |i| {
                    let b = sample(i).as_dvec3();
                    triangle_to_square(b.x, b.y)
                },
                // The equal-area map (s, f) = ((b₀+b₁)², b₁/(b₀+b₁)) has Jacobian ½.
                |st: DVec2| 0.5 * judge.pdf(square_to_triangle(st).extend(0.0).as_vec3()) as f64,
            ),
            Sampler::Tent => ChiSquare::square().samples(samples).run(
                |i| {
                    let x = sample(i).as_dvec3();
                    DVec2::new((x.x + 1.0) / 2.0, (x.y + 1.0) / 2.0)
                },
                |p: DVec2| {
                    let x = (2.0 * p - 1.0).as_vec2().extend(0.0);
                    4.0 * judge.pdf(x) as f64
                },
            ),
            Sampler::SphericalTriangle { v } => PlanarLight::triangle(v[0], v[1], v[2]).test(
                ChiSquare::square().samples(samples),
                sample,
                |w: DVec3| judge.pdf(w.as_vec3()) as f64,
            ),
            Sampler::SphericalRectangle { v } | Sampler::LightRectangle { v } => {
                PlanarLight::parallelogram(v[0], v[1], v[2]).test(
                    ChiSquare::square().samples(samples),
                    sample,
                    |w: DVec3| judge.pdf(w.as_vec3()) as f64,
                )
            }
            Sampler::LightTriangle { v } => PlanarLight::triangle(v[0], v[1], v[2]).test(
                ChiSquare::square().samples(samples),
                sample,
                |w: DVec3| judge.pdf(w.as_vec3()) as f64,
            ),
            _ => self.cap().test(
                ChiSquare::sphere().samples(samples).ires(6),
                sample,
                |w: DVec3| judge.pdf(w.as_vec3()) as f64,
            ),
        }
    }
}

/// What [`Sampler::dispatch`] does with a sampler's map.
trait Visit<L: Math> {
    type Out;
    fn visit(self, map: impl Fn(V2<L>) -> (V3<L>, L)) -> Self::Out;
}

/// One call.
struct One<L>(V2<L>);

impl<L: Math> Visit<L> for One<L> {
    type Out = (V3<L>, L);
    #[inline(always)]
    fn visit(self, map: impl Fn(V2<L>) -> (V3<L>, L)) -> Self::Out {
        map(self.0)
    }
}

/// A loop over a batch, keeping the samples.
struct All<'a, P: Point2>(&'a [P], &'a mut [P::Vec3]);

impl<P: Point2<Lane = L>, L: Math> Visit<L> for All<'_, P> {
    type Out = ();
    // A function of its own per sampler: inlined into `dispatch`, eleven loops would make one
    // body so large that LLVM stops inlining the bigger warps into theirs (13 % on the scalar
    // spherical rectangle).
    #[inline(never)]
    fn visit(self, map: impl Fn(V2<L>) -> (V3<L>, L)) {
        for (o, &u) in self.1.iter_mut().zip(self.0) {
            *o = Point3::from_lanes(map(u.to_lanes()).0);
        }
    }
}
