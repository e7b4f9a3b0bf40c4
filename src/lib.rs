//! Monte Carlo sampling for direct illumination: warps with their pdfs and inverses, in a scalar
//! form on glam types and an 8-wide packet form on `wide`, written once.
//!
//! `no_std`, allocation-free and free of `unsafe`; the `std` feature (on by default) adds only
//! [`verify`], the distribution-test layer.
//!
//! # Map
//!
//! The modules follow the data flow, and each depends only on those before it:
//!
//! | module | role |
//! |---|---|
//! | [`lane`] | the [`Lane`](lane::Lane) trait (arithmetic, masks, selects) over `f32`, [`F32x8`](x8::F32x8) and `f64`, and the generic vectors [`V2`](lane::V2), [`V3`](lane::V3) |
//! | [`math`] | the [`Math`](math::Math) trait: the crate's own transcendental functions for the f32 lanes, with their ulp bounds, and libm for f64 |
//! | [`x8`] | the public packet types |
//! | [`frame`] | orthonormal frames from a normal |
//! | [`warp`] | square → disk, hemisphere, sphere, cone, Phong lobe, triangle, spherical triangle and rectangle, tent |
//! | [`rng`] | `Pcg32x8`: eight PCG32 streams, lane *i* equal to `rand_pcg::Pcg32` |
//! | [`seq`] | stateless generators of (index, dimension, seed), and point-set quality measures |
//! | [`verify`] | (std) χ² goodness of fit and the packet-vs-scalar lane check |
//!
//! # One source, two widths
//!
//! Each algorithm is one generic function over [`Math`](math::Math) (a [`Lane`](lane::Lane) with
//! transcendental functions). The scalar faces
//! (`warp::cosine_hemisphere(Vec2) -> Vec3`) and the packet faces
//! (`warp::x8::cosine_hemisphere(Vec2x8) -> Vec3x8`) instantiate it, and lane *i* of a packet
//! result equals the scalar result on lane *i*'s input, bit for bit, in any one build: the
//! operations the lanes use are correctly rounded or exact, FMA is fused in both widths or in
//! neither, and NaN outputs are canonical. The `f64` instance, whose transcendental functions come
//! from libm, is the reference the report measures f32 error against.
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

#[cfg(feature = "std")]
extern crate std;

pub mod camera;
pub mod frame;
pub mod lane;
pub mod math;
pub mod point;
pub mod rng;
pub mod seq;
pub mod warp;
pub mod x8;

#[cfg(feature = "std")]
pub mod verify;

/// The README's examples run as doctests, so they stay true.
#[cfg(doctest)]
#[doc = include_str!("../README.md")]
struct ReadmeDoctests;
