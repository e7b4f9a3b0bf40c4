//! The registry's evidence: [`Evidence`], what the tests need to know about a sampler beyond its
//! map (its policy on bad input, its round-trip bound, the domain of its χ² test), implemented
//! once per family in a file of its own here, beside [`Family`](crate::warp::Family), its
//! no_std part. The evidence (lane checks, the special-value sweep, χ², round trips, accuracy,
//! hard cases, the report, the benches, the fuzz targets) iterates [`registry`] instead of
//! naming samplers one by one.
//!
//! [`Sampler`] and the registry's list live in [`crate::registry`], without std, so that the
//! firmware iterates them too; this module adds the std methods that dispatch [`Evidence`].
//!
//! ```
//! use glam::Vec2;
//! use mcsample::verify::registry;
//!
//! for s in registry::registry() {
//!     let (x, pdf) = s.sample(Vec2::new(0.3, 0.6));
//!     assert!(s.in_domain(x), "{}", s.name());
//!     assert!(pdf > 0.0 && pdf == s.pdf(x), "{}", s.name());
//!     assert!(s.check_sample(Vec2::new(f32::NAN, 0.5)).is_ok());
//! }
//! ```

mod bilinear;
mod bsdf;
mod cone;
mod disk;
mod hemisphere;
mod lights;
mod phong;
mod projected;
mod projected_cap;
mod sphere;
mod spherical_ellipse;
mod spherical_rectangle;
mod spherical_triangle;
mod tent;
mod triangle;

use glam::{DVec2, DVec3, Vec2, Vec3};
use std::boxed::Box;
use std::format;
use std::string::{String, ToString};
use std::vec;
use std::vec::Vec;

use super::{Cap, ChiSquare, ChiSquareResult, PlanarLight};
use crate::scene;

pub use crate::registry::{BsdfLambert, BsdfPhong, LightSampler, Sampler, rectangle, triangle};
pub use spherical_ellipse::rim as disk_rim;

/// What a sampler gives for NaN in u (and, for the parametrised ones, a NaN parameter).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NanPolicy {
    /// Every output coordinate is the canonical NaN, and the pdf of the sample is 0.
    NanOut,
    /// The sample is dropped: pdf 0 and a fixed finite point.
    ZeroPdf,
}

/// What a sampler is, which decides its policy on bad input and whether it has an inverse.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    /// A warp of the square: NaN in u gives NaN out, clamped u a point of the domain, and its
    /// inverse comes back within the round trip's bound.
    Warp(RoundTrip),
    /// A spherical polygon: NaN in u drops the sample, and its sample lies on the light with a
    /// positive pdf or is dropped; an inverse as for a warp.
    Polygon(RoundTrip),
    /// A light of the scene seen from the origin: as a polygon, without an inverse.
    Light,
    /// A BSDF: as a warp, without an inverse.
    Bsdf,
}

/// The round trip inverse(sample(u)) ≈ u of a sampler with an inverse.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RoundTrip {
    /// The largest |inverse(sample(u)) − u| per coordinate over the whole square.
    pub bound: [f32; 2],
    /// True where u₁ is an azimuth, periodic with period 1: its error is taken modulo 1.
    pub u1_periodic: bool,
}

impl RoundTrip {
    /// An inverse whose u₁ is an azimuth.
    pub fn azimuth(bound: [f32; 2]) -> Self {
        RoundTrip {
            bound,
            u1_periodic: true,
        }
    }
    /// An inverse whose u₁ is not periodic.
    pub fn plain(bound: [f32; 2]) -> Self {
        RoundTrip {
            bound,
            u1_periodic: false,
        }
    }
}

/// The domain of a sampler's χ² test (Mitsuba's method, [`ChiSquare`]).
#[derive(Clone, Copy, Debug)]
pub enum TestDomain {
    /// The unit disk, on the point's (x, y).
    Disk,
    /// A cap of the sphere of directions, zoomed onto the whole sphere.
    Cap(Cap),
    /// The unit square, through an equal-area map of the samples.
    Square {
        /// Sample → square.
        to: fn(DVec3) -> DVec2,
        /// Square → sample.
        from: fn(DVec2) -> Vec3,
        /// The density on the square over the sampler's pdf (the map's Jacobian).
        jacobian: f64,
    },
    /// A planar light's own parameter square.
    Light(PlanarLight),
}

impl From<Cap> for TestDomain {
    fn from(cap: Cap) -> Self {
        TestDomain::Cap(cap)
    }
}

impl From<PlanarLight> for TestDomain {
    fn from(light: PlanarLight) -> Self {
        TestDomain::Light(light)
    }
}

/// What the sweep and the fuzz targets vary, with the sampler rebuilt around a new value.
pub enum Param {
    /// Nothing to vary.
    None,
    /// A scalar parameter.
    Scalar(f32, Box<dyn Fn(f32) -> Sampler>),
    /// The geometry: vertices, or a corner and edges.
    Geometry([Vec3; 3], Box<dyn Fn([Vec3; 3]) -> Sampler>),
}

/// The facts of a sampler ([`Evidence::facts`]): a struct without a default, so that the
/// compiler names each one a new sampler leaves out.
pub struct Facts {
    /// What it is.
    pub kind: Kind,
    /// What the sweep and the fuzz targets vary.
    pub param: Param,
    /// The domain of its χ² test.
    pub test: TestDomain,
}

impl Facts {
    /// A warp's facts.
    pub fn warp(roundtrip: RoundTrip, param: Param, test: impl Into<TestDomain>) -> Self {
        Self::new(Kind::Warp(roundtrip), param, test)
    }
    /// The facts of any kind of sampler.
    pub fn new(kind: Kind, param: Param, test: impl Into<TestDomain>) -> Self {
        let test = test.into();
        Facts { kind, param, test }
    }
}

/// The coordinates that a sampler's pdf and inverse read, and how many coordinates of its point
/// NaN in u makes NaN.
#[derive(Clone, Copy, Debug)]
pub struct Reads {
    /// The coordinates of a point that the pdf reads: NaN in one gives pdf 0.
    pub pdf: &'static [usize],
    /// The coordinates of a point that the inverse reads: NaN in one gives NaN (for the policy
    /// [`NanPolicy::NanOut`]).
    pub inverse: &'static [usize],
    /// How many output coordinates NaN in u makes the canonical NaN.
    pub nan: usize,
}

impl Reads {
    /// Every coordinate, the strictest claim.
    pub const ALL: Reads = Reads {
        pdf: &[0, 1, 2],
        inverse: &[0, 1, 2],
        nan: 3,
    };
    /// A planar sampler's (x, y), its point padded with z = 0.
    pub const PLANAR: Reads = Reads {
        pdf: &[0, 1],
        inverse: &[0, 1],
        nan: 2,
    };
}

/// The std part of a sampler of the registry: what the evidence checks it against.
///
/// [`facts`](Evidence::facts) states what differs from sampler to sampler. The provided items
/// are exemptions, and their defaults grant none: each is the strictest claim (every coordinate
/// read, every coordinate NaN, u determined everywhere), so that a sampler that needs one fails
/// its checks until it states it.
pub trait Evidence {
    /// What it is, what may vary, and the domain of its χ² test.
    fn facts(&self) -> Facts;

    /// The coordinates that the pdf and the inverse read, and those NaN in u makes NaN.
    fn reads(&self) -> Reads {
        Reads::ALL
    }
    /// Where a polygon's dropped sample points (NaN u, degenerate geometry): +z, or a
    /// rectangle's corner, which may be non-finite.
    fn dropped_at(&self) -> Vec3 {
        Vec3::Z
    }
    /// Which coordinates of u the sample x = sample(u) determines (not at a pole of the
    /// parameterisation).
    fn determined(&self, _u: Vec2, _x: Vec3) -> [bool; 2] {
        [true, true]
    }
}

/// Generates [`Sampler::evidence`] from the registry's list.
macro_rules! define_evidence {
    ($($variant:ident: $family:ty = $instances:expr;)*) => {
        impl Sampler {
            /// The sampler's [`Evidence`].
            pub fn evidence(&self) -> &dyn Evidence {
                match self {
                    $(Sampler::$variant(s) => s,)*
                }
            }
        }
    };
}
crate::registry::families!(define_evidence);

/// Every sampler of the registry, at its registered parameters.
pub fn registry() -> Vec<Sampler> {
    Sampler::all().collect()
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
        self.to_string()
    }

    /// What it is.
    pub fn kind(&self) -> Kind {
        self.evidence().facts().kind
    }

    /// True for the spherical triangle and rectangle, the warps with geometry.
    pub fn is_polygon(&self) -> bool {
        matches!(self.kind(), Kind::Polygon(_))
    }

    /// The documented point of a polygon's dropped sample ([`Evidence::dropped_at`]); None
    /// for the other kinds.
    pub fn dropped_at(&self) -> Option<Vec3> {
        self.is_polygon().then(|| self.evidence().dropped_at())
    }

    /// True for the lights, sampled from the origin.
    pub fn is_light(&self) -> bool {
        self.kind() == Kind::Light
    }

    /// True for the BSDFs.
    pub fn is_bsdf(&self) -> bool {
        self.kind() == Kind::Bsdf
    }

    /// The scene light of a light sampler (Le = 1, seen from the origin), for callers that time
    /// or test its other methods (the prepared form, `hit`); `None` for the other samplers.
    pub fn scene_light(&self) -> Option<scene::Light> {
        match self {
            Sampler::Light(l) => Some(l.light()),
            _ => None,
        }
    }

    /// What NaN in u, or a NaN parameter, gives: the canonical NaN for warps and BSDFs, a
    /// dropped sample for polygons and lights.
    pub fn nan_policy(&self) -> NanPolicy {
        match self.kind() {
            Kind::Warp(_) | Kind::Bsdf => NanPolicy::NanOut,
            Kind::Polygon(_) | Kind::Light => NanPolicy::ZeroPdf,
        }
    }

    /// True when the scalar parameter is NaN, so that every sample follows the NaN policy.
    pub fn nan_param(&self) -> bool {
        matches!(self.evidence().facts().param, Param::Scalar(p, _) if p.is_nan())
    }

    /// The coordinates of a point that the pdf reads ([`Evidence::reads`]).
    pub fn pdf_reads(&self) -> &'static [usize] {
        self.evidence().reads().pdf
    }

    /// The coordinates of a point that the inverse reads ([`Evidence::reads`]).
    pub fn inverse_reads(&self) -> &'static [usize] {
        self.evidence().reads().inverse
    }

    /// How many coordinates of its point NaN in u makes NaN ([`Evidence::reads`]).
    pub fn nan_coords(&self) -> usize {
        self.evidence().reads().nan
    }

    /// True when the parameters and geometry are valid, so that every non-NaN u must give a
    /// sample with a positive, finite pdf: for a BSDF, a parameter that is not NaN; for the
    /// others, a sample of the square's centre with a positive pdf (the sampler, not the pdf
    /// function, decides: they disagree at the edges of huge or grazing lights).
    pub fn is_proper(&self) -> bool {
        match self.kind() {
            Kind::Bsdf => !self.nan_param(),
            _ => self.sample(Vec2::splat(0.5)).1 > 0.0,
        }
    }

    /// The same sampler with its scalar parameter replaced by `p`; the samplers without one
    /// come back unchanged.
    pub fn with_param(self, p: f32) -> Self {
        match self.evidence().facts().param {
            Param::Scalar(_, with) => with(p),
            _ => self,
        }
    }

    /// True for a sampler with a scalar parameter.
    pub fn has_param(&self) -> bool {
        matches!(self.evidence().facts().param, Param::Scalar(..))
    }

    /// The same sampler towards other geometry; the samplers without geometry come back
    /// unchanged.
    pub fn with_geometry(self, v: [Vec3; 3]) -> Self {
        match self.evidence().facts().param {
            Param::Geometry(_, with) => with(v),
            _ => self,
        }
    }

    /// The round trip of the inverse; `None` exactly for the samplers without one.
    pub fn roundtrip(&self) -> Option<RoundTrip> {
        match self.kind() {
            Kind::Warp(r) | Kind::Polygon(r) => Some(r),
            Kind::Light | Kind::Bsdf => None,
        }
    }

    /// The largest |inverse(sample(u)) − u| per coordinate; `None` without an inverse.
    pub fn roundtrip_bound(&self) -> Option<[f32; 2]> {
        self.roundtrip().map(|r| r.bound)
    }

    /// True where u₁ is an azimuth, periodic with period 1.
    pub fn u1_periodic(&self) -> bool {
        self.roundtrip().is_some_and(|r| r.u1_periodic)
    }

    /// See [`Evidence::determined`].
    pub fn determined(&self, u: Vec2, x: Vec3) -> [bool; 2] {
        self.evidence().determined(u, x)
    }

    /// Mitsuba's χ² test of `samples` samples from the sequence `u` against this sampler's pdf,
    /// on its [`TestDomain`].
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
        // A sample returned with pdf exactly 0 is dropped (the Phong lobe's at u₀ = 0 exactly, a
        // cosine-weighted one on the rim): it carries no density, and the test bins the others.
        // Dropping more than one sample in 10⁵ is a defect, reported as invalid samples.
        let mut kept = Vec::with_capacity(samples);
        let mut dropped = Vec::new();
        for i in 0..samples {
            let (x, p) = self.sample(u(i));
            if p == 0.0 {
                dropped.push(i);
            } else {
                kept.push(x);
            }
        }
        let mut result = self.chi_square_kept(judge, &kept);
        if dropped.len() * 100_000 > samples {
            result.invalid_samples += dropped.len();
            result.p_value = 0.0;
            if result.first_invalid.is_none() {
                result.first_invalid = dropped
                    .first()
                    .map(|&i| (i, std::format!("u = {:?} dropped (pdf 0)", u(i))));
            }
        }
        result
    }

    /// The χ² test of the samples `kept` against `judge`'s pdf in this sampler's domain.
    fn chi_square_kept(&self, judge: &Sampler, kept: &[Vec3]) -> ChiSquareResult {
        let samples = kept.len();
        let sample = |i: usize| kept.get(i).copied().unwrap_or(Vec3::NAN);
        let pdf = |x: Vec3| judge.pdf(x) as f64;
        match self.evidence().facts().test {
            TestDomain::Disk => ChiSquare::disk().samples(samples).run(
                |i| sample(i).truncate(),
                |p: DVec2| pdf(p.extend(0.0).as_vec3()),
            ),
            TestDomain::Cap(cap) => cap.test(
                ChiSquare::sphere().samples(samples).ires(12),
                sample,
                |w: DVec3| pdf(w.as_vec3()),
            ),
            TestDomain::Square { to, from, jacobian } => ChiSquare::square()
                .samples(samples)
                .run(|i| to(sample(i).as_dvec3()), |st| jacobian * pdf(from(st))),
            TestDomain::Light(light) => {
                light.test(ChiSquare::square().samples(samples), sample, |w: DVec3| {
                    pdf(w.as_vec3())
                })
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
    /// - a spherical polygon's or a light's sample either lies on the light with a positive pdf
    ///   or is dropped (pdf 0) at a finite point, a degenerate rectangle's corner (which may be
    ///   non-finite).
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
        let kind = s.kind();
        // A light's dropped sample (pdf 0) sits at +z, which may be on the light.
        let dropped_light = kind == Kind::Light && pdf == 0.0;
        let polygon = matches!(kind, Kind::Polygon(_));
        if !polygon && !dropped_light && pdf.to_bits() != s.pdf(x).to_bits() {
            return Err(format!("returned pdf ≠ pdf(x) = {:e}: {}", s.pdf(x), ctx()));
        }
        let at_corner = x.to_array().map(f32::to_bits)
            == s.evidence().dropped_at().to_array().map(f32::to_bits);
        let dropped = |pdf: f32| pdf == 0.0 && (x.is_finite() || at_corner);
        if u.is_nan() || s.nan_param() {
            let ok = match s.nan_policy() {
                NanPolicy::NanOut => s.is_canonical_nan(x) && pdf == 0.0,
                NanPolicy::ZeroPdf => dropped(pdf),
            };
            if !ok {
                return Err(format!("NaN in: not {:?}: {}", s.nan_policy(), ctx()));
            }
        } else if polygon || kind == Kind::Light {
            // A light either gives a sample on it with a positive pdf or drops it (pdf 0, as
            // for degenerate geometry, or where the area pdf would overflow) at a finite point.
            if !((pdf > 0.0 && s.in_domain(x)) || dropped(pdf)) {
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
        } else if !dropped(pdf) {
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

    /// Every coordinate the sampler returns is the canonical NaN.
    fn is_canonical_nan(&self, v: Vec3) -> bool {
        let k = self.nan_coords();
        v.to_array()[..k].iter().all(|c| c.to_bits() == 0x7fc0_0000)
    }
}
