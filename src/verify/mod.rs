//! The verification layer (feature `std`): a χ² goodness-of-fit test for samplers, and a check that
//! a packet function equals its scalar twin lane by lane, bit for bit.
//!
//! The crate's own tests and its report use this module; it is public so that you can test your
//! own samplers the same way. Unlike the rest of the crate it uses std and allocates.
//!
//! # Chi-square goodness of fit
//!
//! [`ChiSquare`] follows Mitsuba 3's method:
//!
//! 1. Draw N samples (10⁶ by default) and bin them in a 2D box that parameterises the domain.
//!    Every box is **equal-area**, so a pdf in the domain's own measure integrates over a cell
//!    with a constant Jacobian:
//!    - [`Square`]: the unit square itself, 101 × 101 cells;
//!    - [`Disk`]: (φ, r²), 101 × 101 cells. Cells are annular sectors of equal area, and the rim of
//!      the disk is a cell edge rather than a curve cutting through cells;
//!    - [`Sphere`]: (φ, cos θ) over [−π, π] × [−1, 1], 50 × 101 cells.
//! 2. Integrate the pdf over each cell with an `ires` × `ires` trapezoid rule whose nodes include
//!    the cell edges, times N, to get the expected counts.
//! 3. Sort the cells by expected count; pool cells expecting fewer than 5 until the pool exceeds
//!    5; Pearson's statistic Σ (O − E)²/E has dof = contributions − 1; p = P(χ²_dof ≥ statistic),
//!    from [`chi2_sf`].
//! 4. Reject when p is below the Šidák-corrected level [`sidak_alpha`]`(0.01, k)` for k tests.
//!
//! A sampler is never given the benefit of the doubt: a NaN sample, a sample outside the domain,
//! samples in a cell whose pdf integrates to 0, or a pdf that is NaN, infinite or negative make
//! the test fail with p = 0 (the counts are in [`ChiSquareResult`], and its `Display` says what
//! went wrong). [`ChiSquareResult::pdf_integral`] reports ∫ pdf, which should be 1.
//!
//! Two adapters make hard cases testable: [`Cap`] zooms a narrow lobe or a small light onto the
//! whole sphere, and [`PlanarLight`] moves directions towards a triangle or parallelogram onto
//! the light's own parameter square, so that no support edge cuts a cell.
//!
//! # Lane equality
//!
//! [`check_lanes`] runs a packet function on inputs packed eight at a time ([`check_lanes16`]:
//! sixteen) and its scalar twin on each input, and compares every lane's output by its bit pattern ([`Bits`]). Scalars and their
//! packets are related by [`Scalar`]; tuples give functions of several arguments.
//!
//! # Example: testing your own warp
//!
//! A polar map from the square to the disk, tested against the uniform density 1/π, and an 8-wide
//! version of a small function checked against its scalar form:
//!
//! ```
//! use glam::{DVec2, Vec2};
//! use mcsample::verify::{check_lanes, sidak_alpha, ChiSquare};
//! use mcsample::x8::F32x8;
//!
//! // The sample points: a simple hash of the index (any deterministic sequence will do).
//! fn u(i: usize) -> Vec2 {
//!     let h = |k: u32| {
//!         let mut x = (i as u32).wrapping_mul(0x9E37_79B9) ^ k;
//!         x ^= x >> 16;
//!         x = x.wrapping_mul(0x7FEB_352D);
//!         x ^= x >> 15;
//!         x = x.wrapping_mul(0x846C_A68B);
//!         x ^= x >> 16;
//!         (x >> 8) as f32 * (1.0 / 16_777_216.0)
//!     };
//!     Vec2::new(h(0x1234_5678), h(0x8765_4321))
//! }
//!
//! // The warp under test: r = √u₀, φ = 2πu₁.
//! fn my_disk(u: Vec2) -> Vec2 {
//!     let (s, c) = (2.0 * std::f32::consts::PI * u.y).sin_cos();
//!     u.x.sqrt() * Vec2::new(c, s)
//! }
//!
//! let test = ChiSquare::disk().samples(200_000).res(40, 40);
//! let result = test.run(|i| my_disk(u(i)), |_p: DVec2| 1.0 / std::f64::consts::PI);
//! assert!(result.passes(sidak_alpha(0.01, 2)), "{result}");
//! assert!((result.pdf_integral - 1.0).abs() < 1e-9);
//!
//! // The broken warp r = u₀ crowds the centre, and the test says so.
//! let broken = test.run(
//!     |i| {
//!         let p = my_disk(u(i));
//!         p * p.length()
//!     },
//!     |_p: DVec2| 1.0 / std::f64::consts::PI,
//! );
//! assert!(broken.p_value < 1e-6, "{broken}");
//!
//! // Lane equality of a packet function and its scalar twin (two arguments: a tuple).
//! let inputs: Vec<(f32, f32)> = (0..100).map(|i| (i as f32 * 0.37, 1.5 - i as f32)).collect();
//! let lanes = check_lanes(
//!     &inputs,
//!     |(a, b): (F32x8, F32x8)| a * a + b,
//!     |(a, b): (f32, f32)| a * a + b,
//! );
//! assert_eq!(lanes, Ok(104)); // 100 inputs, padded to 13 packets
//! ```

mod cap;
mod chi2;
pub mod direct;
mod gamma;
mod lanes;
pub mod mis1d;
mod planar;
pub mod registry;
mod shapes;

pub use cap::Cap;
pub use chi2::{ChiSquare, ChiSquareResult, Disk, Domain, ExpectedCounts, Sphere, Square};
pub use gamma::{chi2_sf, gamma_p, gamma_q, ln_gamma, sidak_alpha};
pub use lanes::{Bits, LaneMismatch, Scalar, check_lanes, check_lanes16};
pub use planar::{PlanarLight, square_to_triangle, triangle_to_square};
pub use shapes::ShapeFacts;
