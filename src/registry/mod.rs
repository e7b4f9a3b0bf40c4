//! The registry: every sampler of the crate once, as a [`Family`] at the parameters the evidence
//! uses, in one list ([`Sampler::all`]) from which everything that enumerates samplers derives:
//! the std evidence of [`verify::registry`](crate::verify::registry) (lane checks, the
//! special-value sweep, χ², round trips, accuracy, hard cases), the report, the benches, the
//! fuzz targets and the firmware, which iterates it without std or alloc.
//!
//! A family is a type that implements [`Family`] (and, for the evidence, the std trait
//! `verify::registry::Evidence`): the warps' families live next to their math in
//! [`warp`], the lights' and the BSDFs' here ([`LightSampler`], [`BsdfLambert`],
//! [`BsdfPhong`]), since they sit above the scene. Adding a sampler is its family and one line
//! of the list below (`families!`): the variant of [`Sampler`], its family type and its
//! registered instances.
//!
//! Every method is generic over the width, like the warps themselves: `sample(Vec2)`,
//! `sample(Vec2x8)` and `sample(DVec2)` run the same code.
//!
//! ```
//! use glam::Vec2;
//! use mcsample::registry::Sampler;
//!
//! for s in Sampler::all() {
//!     let (x, pdf) = s.sample(Vec2::new(0.3, 0.6));
//!     assert!(s.in_domain(x), "{s}");
//!     assert!(pdf > 0.0 && pdf == s.pdf(x), "{s}");
//! }
//! ```

mod bsdf;
mod lights;

use core::fmt;

use glam::{Vec2, Vec3};

use crate::math::Math;
use crate::point::{Point2, Point3};
use crate::warp::{self, Family};

pub use bsdf::{BsdfLambert, BsdfPhong};
pub use lights::LightSampler;

/// The list of samplers: one line per family, `Variant: FamilyType = [registered instances]`.
/// It hands the list to `$callback`, a macro that generates what needs every family: the
/// [`Sampler`] enum and its dispatch here, the evidence's dispatch in `verify`.
///
/// The instances: the cone at two sizes, the Phong lobe at three exponents, the spherical
/// polygons large (≈ 1 sr), small (6e-5 / 0.035 sr) and below the spherical-sampling threshold
/// (1e-6 sr for both: sampled by area); then the lights seen from the origin (a sphere far, tiny
/// and around the point, a disk large and small, a triangle and a rectangle large and sampled by
/// area) and the BSDFs. The bilinear polygons are the spherical polygons' large and small
/// instances for a receiver's normal ([`TILTED`], and one with a corner below the horizon). The
/// projected triangle is the large one for the normal inside it (+z), [`TILTED`] (decentral) and
/// +x (across the horizon), and a small one (0.2) for [`TILTED`]; the projected rectangle the
/// same with −x across the horizon; the projected hexagon ([`hexagon_axes`]) the large ones, and a
/// tiny one ([`TINY_HEXAGON`], 3.8e-6 sr) sampled through its fan by area. The projected caps are a sphere
/// wholly above the horizon, one with its centre above and one with it below the horizon, each
/// across it, and a small one (0.0035 sr) for [`TILTED`]. The tiny sphere has sin²θmax = 1e-4: smaller ones (down to 1e-12) are
/// tested in the scene's tests, where the χ² judge is the f64 pdf; here the f32 pdf's slack of
/// 2ε in sin θ (a band 5e-5 of this cone's area) stays below what 1e6 samples see.
macro_rules! families {
    ($callback:ident) => {
        $callback! {
            ConcentricDisk: warp::ConcentricDisk = [warp::ConcentricDisk];
            PolarDisk: warp::PolarDisk = [warp::PolarDisk];
            UniformHemisphere: warp::UniformHemisphere = [warp::UniformHemisphere];
            CosineHemisphere: warp::CosineHemisphere = [warp::CosineHemisphere];
            UniformSphere: warp::UniformSphere = [warp::UniformSphere];
            UniformCone: warp::UniformCone = [
                warp::UniformCone { h: 0.3 },
                warp::UniformCone { h: 1e-3 },
            ];
            PhongLobe: warp::PhongLobe = [
                warp::PhongLobe { n: 1.0 },
                warp::PhongLobe { n: 20.0 },
                warp::PhongLobe { n: 500.0 },
            ];
            UniformTriangle: warp::UniformTriangle = [warp::UniformTriangle];
            Tent: warp::TentPair = [warp::TentPair];
            SphericalTriangle: warp::SolidAngleTriangle = [1.0, 0.01, 1e-3]
                .map(|s| warp::SolidAngleTriangle { v: triangle(s) });
            SphericalRectangle: warp::SolidAngleRectangle = [1.0, 0.2, 1e-3]
                .map(|s| warp::SolidAngleRectangle { v: rectangle(s) });
            BilinearTriangle: warp::CosineTriangle = [
                (1.0, TILTED),
                (1.0, Vec3::X),
                (0.01, TILTED),
            ].map(|(s, n)| warp::CosineTriangle { v: triangle(s), n });
            BilinearRectangle: warp::CosineRectangle = [
                (1.0, TILTED),
                (1.0, Vec3::NEG_X),
                (0.2, TILTED),
            ].map(|(s, n)| warp::CosineRectangle { v: rectangle(s), n });
            ProjectedTriangle: warp::ProjectedSolidAngleTriangle = [
                (1.0, Vec3::Z),
                (1.0, TILTED),
                (1.0, Vec3::X),
                (0.2, TILTED),
            ].map(|(s, n)| warp::ProjectedSolidAngleTriangle { v: triangle(s), n });
            ProjectedRectangle: warp::ProjectedSolidAngleRectangle = [
                (1.0, Vec3::Z),
                (1.0, TILTED),
                (1.0, Vec3::NEG_X),
                (0.2, TILTED),
            ].map(|(s, n)| warp::ProjectedSolidAngleRectangle { v: rectangle(s), n });
            ProjectedHexagon: warp::ProjectedSolidAngleHexagon = [
                (hexagon_axes(1.0), Vec3::Z),
                (hexagon_axes(1.0), TILTED),
                (hexagon_axes(1.0), Vec3::X),
                (TINY_HEXAGON, TILTED),
            ].map(|(v, n)| warp::ProjectedSolidAngleHexagon { v, n });
            ProjectedCap: warp::ProjectedSolidAngleCap = [
                (Vec3::new(0.3, 0.1, 1.0), 0.5, Vec3::Z),
                (Vec3::new(2.0, 0.3, 0.5), 1.0, Vec3::Z),
                (Vec3::new(2.0, -0.3, -0.4), 1.0, Vec3::Z),
                (Vec3::new(0.0, 0.0, 30.0), 1.0, TILTED),
            ].map(|(c, r, n)| warp::ProjectedSolidAngleCap { c, r, n });
            SphericalEllipse: warp::SolidAngleDisk = [
                (Vec3::new(0.0, 0.0, 2.0), Vec3::NEG_Z, 1.0),
                (Vec3::new(0.0, 3.0, 3.0), Vec3::NEG_Y, 3.0),
                (Vec3::new(0.5, 0.2, 2.0), Vec3::new(1.0, 0.0, 0.15), 1.0),
                (Vec3::new(0.0, 0.0, 30.0), TILTED, 1.0),
            ].map(|(c, n, r)| warp::SolidAngleDisk { c, n, r });
            Light: LightSampler = LightSampler::REGISTERED;
            BsdfLambert: BsdfLambert = [BsdfLambert { wo: Vec3::new(0.3, -0.2, 0.933_809) }];
            BsdfPhong: BsdfPhong = [
                BsdfPhong { wo: Vec3::new(0.5, 0.1, 0.860_232_5), kd: 0.4, ks: 0.5, n: 20.0 },
                BsdfPhong { wo: Vec3::new(0.0, 0.6, 0.8), kd: 0.0, ks: 0.9, n: 500.0 },
            ];
        }
    };
}
// The evidence in `verify` (std) generates its dispatch from the list too.
#[cfg(feature = "std")]
pub(crate) use families;

/// The receiver's normal of the bilinear polygons: tilted 37° towards +x, so that the cosine
/// varies by a factor 2–9 across the registry's large polygons. Their second instances face +x
/// (the triangle) and −x (the rectangle), which puts a corner below the horizon, at the
/// weight's floor.
pub const TILTED: Vec3 = Vec3::new(0.6, 0.0, 0.8);

/// The test triangle of size `s`, about 1.2 s² sr one unit away from the shading point.
pub const fn triangle(s: f32) -> [Vec3; 3] {
    [
        Vec3::new(-0.6 * s, -0.4 * s, 1.0),
        Vec3::new(0.7 * s, -0.3 * s, 1.0 + 0.2 * s),
        Vec3::new(0.1 * s, 0.8 * s, 1.0 - 0.1 * s),
    ]
}

/// The test rectangle of size `s`, tilted, about 0.8 s² sr.
pub const fn rectangle(s: f32) -> [Vec3; 3] {
    [
        Vec3::new(-0.4 * s, -0.7 * s, 1.0),
        Vec3::new(1.1 * s, 0.0, 0.3 * s),
        Vec3::new(0.0, 0.8 * s, 0.0),
    ]
}

/// A hexagon of 3.8e-6 sr: [`hexagon_axes`] at 0.0025 moved into the plane z = 1, where its f32
/// vertices are exactly coplanar. Its fan's outer triangles (6.4e-7 sr) are below the spherical
/// triangle's threshold and its inner ones (1.3e-6 sr) above, so the fan samples every one by
/// area, and they share one plane and one density.
pub const TINY_HEXAGON: [Vec3; 3] = [
    Vec3::new(0.05 * 0.0025, -0.02 * 0.0025, 1.0),
    Vec3::new(0.5 * 0.0025, 0.1 * 0.0025, 0.0),
    Vec3::new(-0.1 * 0.0025, 0.45 * 0.0025, 0.0),
];

/// The centre and half-axes of the registry's hexagons ([`warp::hexagon`]), scaled by s about
/// (0, 0, 1) as the triangles are.
pub const fn hexagon_axes(s: f32) -> [Vec3; 3] {
    [
        Vec3::new(0.05 * s, -0.02 * s, 1.0),
        Vec3::new(0.5 * s, 0.1 * s, 0.15 * s),
        Vec3::new(-0.1 * s, 0.45 * s, -0.1 * s),
    ]
}

/// Generates [`Sampler`] from the list: one variant per family, `From` each family, and the
/// dispatch of [`Family`]'s items.
macro_rules! define_sampler {
    ($($variant:ident: $family:ty = $instances:expr;)*) => {
        /// One sampler of the registry: a family at its parameters.
        #[derive(Clone, Copy, Debug, PartialEq)]
        pub enum Sampler {
            $(
                #[doc = concat!("[`", stringify!($family), "`].")]
                $variant($family),
            )*
        }

        $(
            impl From<$family> for Sampler {
                fn from(s: $family) -> Self {
                    Sampler::$variant(s)
                }
            }
        )*

        impl Sampler {
            /// Every registered sampler, in the order of the list.
            pub fn all() -> impl Iterator<Item = Sampler> + Clone {
                core::iter::empty()
                    $(.chain($instances.map(Sampler::$variant)))*
            }

            /// The sample of `u` and its pdf, in the width of `u`.
            #[inline]
            pub fn sample<P: Point2<Lane = L>, L: Math>(&self, u: P) -> (P::Vec3, L) {
                match self {
                    $(Sampler::$variant(s) => one(s, u),)*
                }
            }

            /// The samples of every u of `us` into `out` (as many as the shorter of the two),
            /// with the match on the sampler taken once for the whole batch: the loop runs the
            /// map inlined, as a hand-written loop would, which is what the report and the
            /// benches time.
            #[inline]
            pub fn sample_all<P: Point2<Lane = L>, L: Math>(&self, us: &[P], out: &mut [P::Vec3]) {
                match self {
                    $(Sampler::$variant(s) => batch(s, us, out),)*
                }
            }

            /// The pdf of output `x`, in the measure of the sampler.
            #[inline]
            pub fn pdf<P: Point3<Lane = L>, L: Math>(&self, x: P) -> L {
                match self {
                    $(Sampler::$variant(s) => s.pdf(x.to_lanes()),)*
                }
            }

            /// The u that maps to output `x`, or `None` for a sampler without an inverse.
            #[inline]
            pub fn try_inverse<P: Point3<Lane = L>, L: Math>(&self, x: P) -> Option<P::Vec2> {
                match self {
                    $(Sampler::$variant(s) => s.inverse(x.to_lanes()).map(Point2::from_lanes),)*
                }
            }

            /// True when `x` is a point of the sampler's domain, up to f32 rounding.
            pub fn in_domain(&self, x: Vec3) -> bool {
                match self {
                    $(Sampler::$variant(s) => s.in_domain(x),)*
                }
            }

            /// See [`Family::parameter_sensitive`].
            pub fn parameter_sensitive(&self, u: Vec2) -> bool {
                match self {
                    $(Sampler::$variant(s) => s.parameter_sensitive(u),)*
                }
            }
        }

        impl fmt::Display for Sampler {
            /// The name the report and its JSON use.
            fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                match self {
                    $(Sampler::$variant(s) => s.name(f),)*
                }
            }
        }
    };
}

families!(define_sampler);

impl Sampler {
    /// The u that maps to output `x`; NaN for a sampler without an inverse
    /// ([`has_inverse`](Self::has_inverse) says which), so that every sampler can be checked
    /// lane by lane.
    #[inline]
    pub fn inverse<P: Point3<Lane = L>, L: Math>(&self, x: P) -> P::Vec2 {
        let nan = L::c(f64::NAN);
        self.try_inverse(x)
            .unwrap_or_else(|| P::Vec2::from_lanes(crate::lane::V2::new(nan, nan)))
    }

    /// True when the sampler has an inverse.
    pub fn has_inverse(&self) -> bool {
        self.try_inverse(Vec3::Z).is_some()
    }
}

/// One sample of `s`.
#[inline(always)]
fn one<F: Family, P: Point2<Lane = L>, L: Math>(s: &F, u: P) -> (P::Vec3, L) {
    let (x, pdf) = s.sampler::<L>()(u.to_lanes());
    (Point3::from_lanes(x), pdf)
}

/// A loop over a batch, keeping the samples. A function of its own per sampler: inlined into
/// the match, the loops would make one body so large that LLVM stops inlining the bigger warps
/// into theirs.
#[inline(never)]
fn batch<F: Family, P: Point2<Lane = L>, L: Math>(s: &F, us: &[P], out: &mut [P::Vec3]) {
    let map = s.sampler::<L>();
    for (o, &u) in out.iter_mut().zip(us) {
        *o = Point3::from_lanes(map(u.to_lanes()).0);
    }
}
