//! The scene that direct illumination needs, and nothing more: four lights (sphere, disk,
//! triangle, rectangle), light selection over a borrowed slice, and two BSDFs (Lambert and
//! modified Phong). There is no geometry engine: visibility is the caller's.
//!
//! # Shapes and lights
//!
//! A light is a [`Shape`] with emission on top ([`Emitter`]): the shape gives the geometry
//! (prepared at a shading point, it samples directions towards itself and evaluates the pdf and
//! distance of any direction; unprepared, it samples points by area and has an area), and the
//! emitter, written once for every shape, adds the radiance Le on the side the shape faces, the
//! light samples and the power. The shapes are [`Sphere`], [`Disk`], [`Triangle`] and
//! [`Rectangle`] (a parallelogram), one file each; [`SphereLight`] and the others name a shape's
//! light, and [`Light`] is the light of any shape, from one list in `select`.
//!
//! Every light offers, at a shading point p:
//!
//! - `sample(p, u)` → [`LightSample`]: a unit direction towards the light, the distance to the
//!   point it reaches, the radiance Le that arrives from it, and the pdf per steradian;
//! - `sample_area(p, u)` → [`AreaSample`]: a point on the light, its normal, Le towards p and
//!   the pdf per unit area;
//! - `pdf(p, wi)`: the solid-angle pdf of `sample`, in closed form with no ray cast. For every
//!   kept sample (pdf > 0) it returns the same number, bit for bit, that `sample` returned: the
//!   sampler computes its pdf by the same function at the very direction it returns (a dropped
//!   sample, pdf 0, stands at +z, which may well be on the light). A polygon prepared for
//!   [`LightSampling::Bilinear`] is the one exception: its sample returns the density it drew
//!   with, which the pdf function matches to its inverse's round trip;
//! - `hit(p, wi)`: the distance along `wi` to the light, ∞ for a miss. It decides "hit" by the
//!   same test as `pdf`, so the two never disagree on whether a direction is on the light, and
//!   a sample's distance is `hit` at its direction;
//! - `at(p)`: the light prepared at p (solid angle, frames, arcs), with `sample(u)`, `pdf(wi)`
//!   and `hit(wi)`; `at_normal(p, n)` also gives the shape the shading normal. Splitting takes
//!   several samples at one point and pays the set-up once. The unprepared methods are `at(p)`
//!   followed by one call: there is one algorithm.
//!
//! Directions and pdfs are in world space, per steradian unless named "area". Lights emit on
//! one side, the side their normal points to (outwards for the sphere), with constant radiance
//! `le` (RGB). Le is 0 from behind; the pdf is geometric and does not look at the side.
//!
//! # Where f32 cannot see a light's edge
//!
//! A unit f32 direction is resolved to about 6e-8 rad, and world-space rounding moves a sample
//! by a few of those. A sample placed exactly on a light's silhouette can therefore land just
//! outside it. `pdf` and `hit` accept directions within a slack of a few ε·(1 + angular size)
//! outside the silhouette (documented per light), so every sample keeps its pdf and its hit; a
//! direction farther out gets pdf 0 and ∞. For a sphere light 1e-2 rad across the band is 5e-5
//! of its solid angle; for the tiniest lights (a sphere with sin²θmax = 1e-12 spans 2e-6 rad)
//! it widens what a BSDF-sampled ray can hit by a large part of the light, an f32 limit that
//! the f64 instance, whose slack scales with its own ε, does not share.
//!
//! # Choosing a light
//!
//! [`Light`] puts every shape in one slice. [`PowerTable`] chooses in proportion to power
//! (π·area·luminance(Le)) from a cumulative table in storage the caller provides, and
//! [`LightChoice::uniform`] with equal probability; either returns the index, its probability
//! and u rescaled to drive the chosen light's sampler. The probability enters every pdf an
//! estimator sees: [`LightSample::chosen_with`] for light samples, and `pmf(i)·pdf(p, wi)` for a
//! BSDF sample whose ray `hit`s light i.
//!
//! # Widths
//!
//! Each light and BSDF is generic over the width like the warps: `SphereLight<Vec3>` (the
//! default), `SphereLight<Vec3x8>` (eight lights, lane by lane, bit for bit the scalar ones) and
//! `SphereLight<DVec3>`, the f64 reference.
//!
//! # Bad input
//!
//! Nothing panics. A degenerate light (zero radius or area, non-finite geometry), a shading point
//! in a planar light's plane, and NaN in p, u or wi give pdf 0, distance ∞ and Le 0, with a finite
//! direction; callers drop samples with pdf 0.

mod bsdf;
mod disk;
mod emitter;
mod rectangle;
mod select;
mod shape;
mod sphere;
mod triangle;

pub use bsdf::{Bsdf, BsdfSample, Lambert, Phong};
pub use disk::{Disk, DiskLight, PreparedDisk};
pub use emitter::{AreaSample, Emitter, LightSample, PreparedEmitter};
pub use rectangle::{PreparedRectangle, Rectangle, RectangleLight};
#[cfg(feature = "std")]
pub(crate) use select::with_shapes;
pub use select::{AnyPrepared, AnyShape, Light, LightChoice, PowerTable, PreparedLight, luminance};
pub use shape::{AreaPoint, AtPoint, LightSampling, PreparedShape, Shape, ShapeSample};
pub use sphere::{PreparedSphere, Sphere, SphereLight};
pub use triangle::{PreparedTriangle, Triangle, TriangleLight};
