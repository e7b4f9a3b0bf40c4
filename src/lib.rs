//! Monte Carlo sampling for direct illumination: warps with their pdfs and inverses, in a scalar
//! form on glam types and 8- and 16-wide packet forms on `wide`, written once.
//!
//! `no_std`, allocation-free and free of `unsafe`; the `std` feature (on by default) adds only
//! [`verify`], the distribution-test layer, and the `rand` feature (off by default, no_std) adds
//! `distr`, rand's `Distribution` for the warps.
//!
//! # Map
//!
//! The modules follow the data flow. Each imports only from the floors below its own (and from
//! core, glam, wide and libm); nothing points back up.
//!
//! | floor | module | role | may import |
//! |---|---|---|---|
//! | 1 | [`lane`] | the [`Lane`](lane::Lane) traits (arithmetic, masks, selects, bits) over `f32`, [`F32x8`](x8::F32x8), [`F32x16`](x16::F32x16) and `f64`, the integer lane [`U32Lane`](lane::U32Lane), and the generic vectors [`V2`](lane::V2), [`V3`](lane::V3) | — |
//! | 2 | [`math`] | [`Math`](math::Math): the crate's own transcendental functions, with their ulp bounds, and libm for f64 | lane |
//! | 2 | [`point`] | [`Point2`](point::Point2), [`Point3`](point::Point3): the argument type that picks a call's width; [`Split`](point::Split), [`Join`](point::Join): a width as two halves and back, which the long algorithms and some set-ups run where the build has no AVX-512 | lane, math |
//! | 2 | [`x8`], [`x16`] | the public packet types of each width | lane |
//! | 2 | [`rng`] | `Pcg32x8`, `Pcg32x16`: eight or sixteen PCG32 streams, lane *i* equal to `rand_pcg::Pcg32` | lane |
//! | 3 | [`seq`] | stateless generators of (index, dimension, seed), the estimators' sample sources, and point-set quality measures | lane, rng |
//! | 3 | [`frame`] | orthonormal frames from a normal | lane, math, point |
//! | 3 | [`warp`] | square → disk, hemisphere, sphere, cone, Phong lobe, triangle, spherical triangle and rectangle, tent; each family's [`Family`](warp::Family) for the registry | lane, math, point |
//! | 4 | [`camera`] | film, lens and time samples of a pixel | seq, warp |
//! | 4 | `distr` (feature `rand`) | rand's `Distribution` for the warps | warp |
//! | 4 | [`estimate`], [`mis`] | accumulators, roulette, splitting; MIS weights, optimal MIS, the RIS reservoir | lane, math, warp |
//! | 4 | [`reference`](mod@reference) | analytic f64 irradiance references | core and libm only |
//! | 5 | [`scene`] | light shapes (sphere, disk, triangle, parallelogram) behind one [`Shape`](scene::Shape) trait, emission written once over them, light selection, Lambert and modified Phong BSDFs | lane, math, point, frame, warp |
//! | 6 | [`direct`] | the direct-lighting estimator and its strategies | every floor below |
//! | 6 | [`registry`] | every sampler once, in one list: the warps' families, the lights' and the BSDFs' ([`Family`](warp::Family): name, sample, pdf, inverse, domain), without std, for the evidence and the firmware | warp, scene and the floors below |
//! | — | [`verify`] | (std) χ² goodness of fit, the packet-vs-scalar lane check, the registry's evidence (one file per family) and the direct-lighting test scenes | anything below |
//!
//! # One source, every width
//!
//! Each algorithm is one public generic function, written over [`Math`](math::Math) (a
//! [`Lane`](lane::Lane) with transcendental functions) and documented once. The type of its
//! argument picks the width ([`point`]): `warp::cosine_hemisphere(Vec2) -> Vec3`,
//! `warp::cosine_hemisphere(Vec2x8) -> Vec3x8`, `warp::cosine_hemisphere(Vec2x16) -> Vec3x16`,
//! and `warp::cosine_hemisphere(DVec2) -> DVec3`, the f64 reference whose transcendental
//! functions come from libm and against which the report measures f32 error. Sequence generators do the same over the index lane (`u32`, `U32x8` or
//! `U32x16`). [`x8`] and [`x16`] hold the packet types only; there is no second path to the
//! functions.
//!
//! Lane *i* of a packet result equals the scalar result on lane *i*'s input, bit for bit, in any
//! one build: the operations the lanes use are correctly rounded or exact, FMA is fused in both
//! widths or in neither, and NaN outputs are canonical.
//!
//! # Bad input
//!
//! Nothing panics, loops or allocates on any input.
//!
//! - A sample u is clamped to [0, 1]²: u = 1, negative and infinite values give a finite point of
//!   the domain.
//! - NaN in gives NaN out, always the canonical quiet NaN, or a documented value (pdfs give 0).
//! - Degenerate geometry gives pdf 0, which means "drop the sample", never NaN or ∞.
//!
//! Each function's rustdoc states its mapping, the measure of its pdf, its domain and what it does
//! with bad input; the tests hold both widths to it.

#![no_std]
#![forbid(unsafe_code)]
#![warn(missing_docs)]
// No panic paths in the library: no unwrap or expect, no explicit panic, no indexing that the
// compiler cannot prove in bounds, and no integer division without a comment that shows its
// divisor is not 0. Constant tables built at compile time and the std-only `verify` layer are
// the allowed exceptions, each marked where it is.
#![cfg_attr(
    not(test),
    deny(
        clippy::unwrap_used,
        clippy::expect_used,
        clippy::panic,
        clippy::indexing_slicing,
        clippy::integer_division
    )
)]

#[cfg(feature = "std")]
extern crate std;

pub mod camera;
pub mod direct;
#[cfg(feature = "rand")]
pub mod distr;
pub mod estimate;
pub mod frame;
pub mod lane;
pub mod math;
pub mod mis;
pub mod point;
pub mod reference;
pub mod registry;
pub mod rng;
pub mod scene;
pub mod seq;
pub mod warp;
pub mod x16;
pub mod x8;

// The test layer: std, and free to index and to panic (its failures are test failures).
#[cfg(feature = "std")]
#[allow(
    clippy::unwrap_used,
    clippy::expect_used,
    clippy::panic,
    clippy::indexing_slicing,
    clippy::integer_division
)]
pub mod verify;

/// The README's examples run as doctests, so they stay true.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
