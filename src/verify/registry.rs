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

use glam::{DVec2, DVec3, Vec2, Vec3};
use std::format;
use std::string::String;
use std::vec;
use std::vec::Vec;

use super::{Cap, ChiSquare, ChiSquareResult, PlanarLight, square_to_triangle, triangle_to_square};
use crate::lane::{V2, V3};
use crate::math::Math;
use crate::point::{Point2, Point3};
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
/// spherical-sampling threshold (sampled by area).
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
        SphericalRectangle { v: rectangle(0.05) },
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
        let size = |v: &[Vec3; 3], rect: bool| {
            let pdf = if rect {
                warp::spherical_rectangle_pdf(Self::centre(v, rect), v[0], v[1], v[2])
            } else {
                warp::spherical_triangle_pdf(Self::centre(v, rect), v[0], v[1], v[2])
            };
            let omega = 1.0 / pdf as f64;
            let min = if rect {
                warp::SPHERICAL_RECTANGLE_MIN_SR
            } else {
                warp::SPHERICAL_TRIANGLE_MIN_SR
            };
            if omega.is_nan() || omega < min as f64 {
                "area"
            } else if omega > 0.5 {
                "large"
            } else {
                "small"
            }
        };
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
            SphericalTriangle { v } => format!("spherical_triangle {}", size(v, false)),
            SphericalRectangle { v } => format!("spherical_rectangle {}", size(v, true)),
        }
    }

    /// The direction to the light's centre, for naming its size.
    fn centre(v: &[Vec3; 3], rect: bool) -> Vec3 {
        if rect {
            (v[0] + 0.5 * v[1] + 0.5 * v[2]).normalize()
        } else {
            ((v[0] + v[1] + v[2]) / 3.0).normalize()
        }
    }

    /// The same sampler with its parameter replaced by `p` (the sweep's special values); the
    /// samplers without a scalar parameter come back unchanged.
    pub fn with_param(self, p: f32) -> Self {
        match self {
            Sampler::UniformCone { .. } => Sampler::UniformCone { h: p },
            Sampler::PhongLobe { .. } => Sampler::PhongLobe { n: p },
            other => other,
        }
    }

    /// The same sampler towards other geometry (the spherical polygons only).
    pub fn with_geometry(self, v: [Vec3; 3]) -> Self {
        match self {
            Sampler::SphericalTriangle { .. } => Sampler::SphericalTriangle { v },
            Sampler::SphericalRectangle { .. } => Sampler::SphericalRectangle { v },
            other => other,
        }
    }

    /// What NaN in u gives.
    pub fn nan_policy(&self) -> NanPolicy {
        match self {
            Sampler::SphericalTriangle { .. } | Sampler::SphericalRectangle { .. } => {
                NanPolicy::ZeroPdf
            }
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
            Sampler::CosineHemisphere | Sampler::PhongLobe { .. } => &[2],
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
            Sampler::SphericalTriangle { v } => {
                warp::spherical_triangle_pdf(Self::centre(&v, false), v[0], v[1], v[2]) > 0.0
            }
            Sampler::SphericalRectangle { v } => {
                warp::spherical_rectangle_pdf(Self::centre(&v, true), v[0], v[1], v[2]) > 0.0
            }
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
        v.map(|p| V3::new(Self::param(p.x), Self::param(p.y), Self::param(p.z)))
    }

    /// The sample of `u` and its pdf (the pdf the warp returns, or its pdf function at the
    /// sample), in the width of `u`.
    #[inline]
    pub fn sample<P: Point2<Lane = L>, L: Math>(&self, u: P) -> (P::Vec3, L) {
        let u = u.to_lanes();
        let (x, pdf): (V3<L>, L) = match *self {
            Sampler::ConcentricDisk | Sampler::PolarDisk => {
                let p = if *self == Sampler::ConcentricDisk {
                    warp::concentric_disk(u)
                } else {
                    warp::polar_disk(u)
                };
                (V3::new(p.x, p.y, L::c(0.0)), warp::uniform_disk_pdf(p))
            }
            Sampler::UniformHemisphere => {
                let w = warp::uniform_hemisphere(u);
                (w, warp::uniform_hemisphere_pdf(w))
            }
            Sampler::CosineHemisphere => {
                let w = warp::cosine_hemisphere(u);
                (w, warp::cosine_hemisphere_pdf(w.z))
            }
            Sampler::UniformSphere => {
                let w = warp::uniform_sphere(u);
                (w, warp::uniform_sphere_pdf(w))
            }
            Sampler::UniformCone { h } => {
                let w = warp::uniform_cone(u, Self::param(h));
                (w, warp::uniform_cone_pdf(w, Self::param(h)))
            }
            Sampler::PhongLobe { n } => {
                let w = warp::phong_lobe(u, Self::param(n));
                (w, warp::phong_lobe_pdf(w.z, Self::param(n)))
            }
            Sampler::UniformTriangle => {
                let b = warp::uniform_triangle(u);
                (b, warp::uniform_triangle_pdf(V2::new(b.x, b.y)))
            }
            Sampler::Tent => {
                // A pair of tents is one 2D sample: NaN in either coordinate drops both.
                let t = V2::new(warp::tent(u.x), warp::tent(u.y)).nan_where(u.any_nan());
                let x = V3::new(t.x, t.y, L::c(0.0));
                (x, warp::tent_pdf(x.x) * warp::tent_pdf(x.y))
            }
            Sampler::SphericalTriangle { v } => {
                let [a, b, c] = Self::verts(&v);
                warp::spherical_triangle(u, a, b, c)
            }
            Sampler::SphericalRectangle { v } => {
                let [a, b, c] = Self::verts(&v);
                warp::spherical_rectangle(u, a, b, c)
            }
        };
        (Point3::from_lanes(x), pdf)
    }

    /// The pdf of output `x` (in the measure of the sampler: per unit area for the disks, the
    /// barycentric square and the tent pair, per steradian for directions).
    #[inline]
    pub fn pdf<P: Point3<Lane = L>, L: Math>(&self, x: P) -> L {
        let x = x.to_lanes();
        match *self {
            Sampler::ConcentricDisk | Sampler::PolarDisk => {
                let inside = x.z.eq(L::c(0.0));
                L::select(inside, warp::uniform_disk_pdf(V2::new(x.x, x.y)), L::c(0.0))
            }
            Sampler::UniformHemisphere => warp::uniform_hemisphere_pdf(x),
            Sampler::CosineHemisphere => warp::cosine_hemisphere_pdf(x.z),
            Sampler::UniformSphere => warp::uniform_sphere_pdf(x),
            Sampler::UniformCone { h } => warp::uniform_cone_pdf(x, Self::param(h)),
            Sampler::PhongLobe { n } => warp::phong_lobe_pdf(x.z, Self::param(n)),
            Sampler::UniformTriangle => warp::uniform_triangle_pdf(V2::new(x.x, x.y)),
            Sampler::Tent => warp::tent_pdf(x.x) * warp::tent_pdf(x.y),
            Sampler::SphericalTriangle { v } => {
                let [a, b, c] = Self::verts(&v);
                warp::spherical_triangle_pdf(x, a, b, c)
            }
            Sampler::SphericalRectangle { v } => {
                let [a, b, c] = Self::verts(&v);
                warp::spherical_rectangle_pdf(x.normalize(), a, b, c)
            }
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
                Sampler::SphericalRectangle { v } => {
                    // On the light's plane, within its parallelogram (a relative 1e-5 margin).
                    let d = x64 - v[0].as_dvec3();
                    let (ex, ey) = (v[1].as_dvec3(), v[2].as_dvec3());
                    let s = d.dot(ex) / ex.length_squared();
                    let t = d.dot(ey) / ey.length_squared();
                    let off = (d - ex * s - ey * t).length();
                    let size = ex.length() + ey.length() + v[0].as_dvec3().length();
                    (-1e-5..=1.0 + 1e-5).contains(&s)
                        && (-1e-5..=1.0 + 1e-5).contains(&t)
                        && off <= 1e-5 * size
                }
            }
    }

    /// The largest |inverse(sample(u)) − u| expected on u inside the square away from the
    /// ill-conditioned edges: a few ulp for the simple warps, more where the map compresses.
    pub fn roundtrip_tolerance(&self) -> f32 {
        match self {
            Sampler::SphericalTriangle { .. } => 2e-4,
            Sampler::SphericalRectangle { .. } => 1e-4,
            Sampler::PhongLobe { .. } => 2e-5,
            Sampler::UniformCone { .. } => 1e-5,
            _ => 2e-6,
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
            Sampler::SphericalRectangle { v } => PlanarLight::parallelogram(v[0], v[1], v[2]).test(
                ChiSquare::square().samples(samples),
                sample,
                |w: DVec3| judge.pdf(w.as_vec3()) as f64,
            ),
        }
    }
}
