//! Warps: maps from the unit square to the domains of direct illumination, each with its pdf and
//! its inverse, side by side. This module holds the scalar (glam) faces; [`x8`] the packet faces.
//!
//! Every warp is one generic function over [`Math`](crate::math::Math) in a file of its family
//! (`disk`, `hemisphere`, `sphere`, `cone`, `phong`, `triangle`, `spherical_triangle`,
//! `spherical_rectangle`, `tent`); both faces are thin instantiations of it, so lane *i* of a
//! packet result equals the scalar result on lane *i*'s input, bit for bit.
//!
//! # Conventions
//!
//! - The local frame has +z along the normal or axis; use [`Frame`](crate::frame::Frame) to move
//!   to and from world space.
//! - "pdf" is per steradian for directions, per unit area for planar points.
//! - Every pdf is 0 outside its support, and 0 for NaN input.
//!
//! # Bad input (the same in both widths, tested)
//!
//! - u is clamped to [0, 1]²: u = 1, negative values and ±∞ land on the domain's boundary and
//!   give a finite point of the domain.
//! - NaN in u gives NaN in every coordinate of the result, always the canonical quiet NaN
//!   (bits 0x7fc0_0000), so that both widths return the same bits; spherical polygon samplers
//!   then return pdf 0 and a fixed finite direction.
//! - Degenerate geometry (a zero-size cone, coincident vertices, a light seen edge-on) gives
//!   pdf 0, never NaN or ∞: callers drop samples with pdf 0.
//! - Nothing panics, loops or allocates on any input.

use glam::{Vec2, Vec3};

mod common;
mod cone;
mod disk;
mod hemisphere;
mod phong;
mod polygon;
mod sphere;
mod spherical_rectangle;
mod spherical_triangle;
mod tent;
mod triangle;
pub mod x8;

pub use common::ONE_MINUS_EPS;
pub use phong::PHONG_N_MAX;
pub use spherical_rectangle::{SPHERICAL_RECTANGLE_MAX_SR, SPHERICAL_RECTANGLE_MIN_SR};
pub use spherical_triangle::{SPHERICAL_TRIANGLE_MAX_SR, SPHERICAL_TRIANGLE_MIN_SR};

/// The generic forms, for code that is itself generic over [`Math`](crate::math::Math) (the f64
/// instance is the reference the report measures against).
pub mod generic {
    pub use super::cone::{
        cone_h_from_cos, cone_h_from_sin2, uniform_cone, uniform_cone_inverse, uniform_cone_pdf,
    };
    pub use super::disk::{
        concentric_disk, concentric_disk_inverse, polar_disk, polar_disk_inverse, uniform_disk_pdf,
    };
    pub use super::hemisphere::{
        cosine_hemisphere, cosine_hemisphere_inverse, cosine_hemisphere_pdf, uniform_hemisphere,
        uniform_hemisphere_inverse, uniform_hemisphere_pdf,
    };
    pub use super::phong::{phong_lobe, phong_lobe_inverse, phong_lobe_pdf};
    pub use super::sphere::{uniform_sphere, uniform_sphere_inverse, uniform_sphere_pdf};
    pub use super::spherical_rectangle::{
        spherical_rectangle, spherical_rectangle_inverse, spherical_rectangle_pdf, urena_rectangle,
    };
    pub use super::spherical_triangle::{
        arvo_triangle, spherical_triangle, spherical_triangle_inverse, spherical_triangle_pdf,
    };
    pub use super::tent::{tent, tent_inverse, tent_pdf};
    pub use super::triangle::{uniform_triangle, uniform_triangle_inverse, uniform_triangle_pdf};
}

/// Square → unit disk, Shirley–Chiu concentric map (area pdf 1/π, [`uniform_disk_pdf`]).
///
/// u is clamped to [0, 1]²; (½, ½) ↦ (0, 0) exactly; NaN in either coordinate gives NaN.
#[inline]
pub fn concentric_disk(u: Vec2) -> Vec2 {
    disk::concentric_disk::<f32>(u.into()).into()
}

/// Inverse of [`concentric_disk`]: disk point → u ∈ [0, 1]². Round trip within 3e-7 (f32).
///
/// Points outside the disk map as if radially scaled onto the square's boundary; NaN gives NaN.
#[inline]
pub fn concentric_disk_inverse(p: Vec2) -> Vec2 {
    disk::concentric_disk_inverse::<f32>(p.into()).into()
}

/// Square → unit disk by r = √u₀, φ = 2πu₁ (area pdf 1/π). u is clamped to [0, 1]²; NaN gives NaN.
#[inline]
pub fn polar_disk(u: Vec2) -> Vec2 {
    disk::polar_disk::<f32>(u.into()).into()
}

/// Inverse of [`polar_disk`]: u₀ = |p|², u₁ = azimuth/2π in [0, 1). NaN gives NaN.
#[inline]
pub fn polar_disk_inverse(p: Vec2) -> Vec2 {
    disk::polar_disk_inverse::<f32>(p.into()).into()
}

/// Area pdf of a uniform point in the unit disk: 1/π.
#[inline]
pub fn uniform_disk_pdf() -> f32 {
    disk::uniform_disk_pdf::<f32>()
}

/// Square → upper hemisphere (+z), uniform in solid angle: z = u₀, φ = 2πu₁ (pdf 1/(2π) per sr).
///
/// u is clamped to [0, 1]²; NaN gives NaN.
#[inline]
pub fn uniform_hemisphere(u: Vec2) -> Vec3 {
    hemisphere::uniform_hemisphere::<f32>(u.into()).into()
}

/// pdf per steradian of [`uniform_hemisphere`]: 1/(2π).
#[inline]
pub fn uniform_hemisphere_pdf() -> f32 {
    hemisphere::uniform_hemisphere_pdf::<f32>()
}

/// Inverse of [`uniform_hemisphere`] for a unit direction: u = (z, azimuth/2π) in [0, 1]×[0, 1).
#[inline]
pub fn uniform_hemisphere_inverse(w: Vec3) -> Vec2 {
    hemisphere::uniform_hemisphere_inverse::<f32>(w.into()).into()
}

/// Square → upper hemisphere (+z) with pdf cos θ/π per sr (Malley: concentric disk lifted by
/// z = √((1−r)(1+r))).
///
/// u is clamped to [0, 1]²; boundary u gives z ≥ 0, finite; NaN gives NaN. A rim sample can have
/// z = 0 and so pdf 0: callers drop it.
#[inline]
pub fn cosine_hemisphere(u: Vec2) -> Vec3 {
    hemisphere::cosine_hemisphere::<f32>(u.into()).into()
}

/// pdf per steradian of [`cosine_hemisphere`]: cos θ/π for cos θ > 0, else 0 (also for NaN).
#[inline]
pub fn cosine_hemisphere_pdf(cos_theta: f32) -> f32 {
    hemisphere::cosine_hemisphere_pdf::<f32>(cos_theta)
}

/// Inverse of [`cosine_hemisphere`]: the concentric inverse of (w.x, w.y).
#[inline]
pub fn cosine_hemisphere_inverse(w: Vec3) -> Vec2 {
    hemisphere::cosine_hemisphere_inverse::<f32>(w.into()).into()
}

/// Square → unit sphere, uniform: z = 1 − 2u₀, r = 2√(u₀(1−u₀)), φ = 2πu₁ (pdf 1/(4π) per sr).
///
/// u is clamped to [0, 1]²; NaN gives NaN.
#[inline]
pub fn uniform_sphere(u: Vec2) -> Vec3 {
    sphere::uniform_sphere::<f32>(u.into()).into()
}

/// pdf per steradian of [`uniform_sphere`]: 1/(4π).
#[inline]
pub fn uniform_sphere_pdf() -> f32 {
    sphere::uniform_sphere_pdf::<f32>()
}

/// Inverse of [`uniform_sphere`] for a unit direction, in [0, 1]×[0, 1).
#[inline]
pub fn uniform_sphere_inverse(w: Vec3) -> Vec2 {
    sphere::uniform_sphere_inverse::<f32>(w.into()).into()
}

/// Square → cone about +z with h = 1 − cos θmax, uniform in solid angle (pdf 1/(2πh) per sr):
/// t = u₀h, z = 1 − t, sin θ = √(t(2−t)), φ = 2πu₁.
///
/// Build h with [`cone_h_from_sin2`] or [`cone_h_from_cos`]. u is clamped to [0, 1]², h to [0, 2];
/// h = 0 puts every sample on the axis (pdf 0); NaN gives NaN.
#[inline]
pub fn uniform_cone(u: Vec2, h: f32) -> Vec3 {
    cone::uniform_cone::<f32>(u.into(), h).into()
}

/// pdf per steradian inside the cone of [`uniform_cone`]: 1/(2πh); 0 for h ≤ 0 or NaN.
#[inline]
pub fn uniform_cone_pdf(h: f32) -> f32 {
    cone::uniform_cone_pdf::<f32>(h)
}

/// Inverse of [`uniform_cone`]: u₀ = (1 − z)/h with 1 − z = (x²+y²)/(1+z), clamped to [0, 1].
#[inline]
pub fn uniform_cone_inverse(w: Vec3, h: f32) -> Vec2 {
    cone::uniform_cone_inverse::<f32>(w.into(), h).into()
}

/// h = 1 − cos θmax, clamped to [0, 2]. Loses precision for narrow cones: prefer
/// [`cone_h_from_sin2`] when sin²θmax is at hand.
#[inline]
pub fn cone_h_from_cos(cos_max: f32) -> f32 {
    cone::cone_h_from_cos::<f32>(cos_max)
}

/// h = 1 − cos θmax from sin²θmax (θmax ≤ π/2) as s²/(1 + √(1−s²)): no cancellation at any size.
/// s² is clamped to [0, 1]; NaN gives NaN.
#[inline]
pub fn cone_h_from_sin2(sin2_max: f32) -> f32 {
    cone::cone_h_from_sin2::<f32>(sin2_max)
}

/// Square → Phong lobe about +z, pdf (n+1)/(2π)·cosⁿα per sr: 1 − cos α = −expm1(ln(u₀)/(n+1)).
///
/// u is clamped to [0, 1]², n to [0, 1e20]; u₀ = 0 gives a horizon direction (pdf 0); NaN gives NaN.
#[inline]
pub fn phong_lobe(u: Vec2, n: f32) -> Vec3 {
    phong::phong_lobe::<f32>(u.into(), n).into()
}

/// pdf per steradian of [`phong_lobe`]: (n+1)/(2π)·cosⁿα for cos α > 0, else 0 (also for NaN).
#[inline]
pub fn phong_lobe_pdf(cos_alpha: f32, n: f32) -> f32 {
    phong::phong_lobe_pdf::<f32>(cos_alpha, n)
}

/// Inverse of [`phong_lobe`]: u₀ = cos^{n+1}α, u₁ = azimuth/2π. Below the horizon u₀ = 0.
#[inline]
pub fn phong_lobe_inverse(w: Vec3, n: f32) -> Vec2 {
    phong::phong_lobe_inverse::<f32>(w.into(), n).into()
}

/// Square → barycentrics (b₀, b₁, b₂) of a uniform point in a triangle (Heitz's low-distortion map).
///
/// b₂ ≥ 0 for every u, including u₀ = u₁. u is clamped to [0, 1]²; NaN gives NaN.
#[inline]
pub fn uniform_triangle(u: Vec2) -> Vec3 {
    triangle::uniform_triangle::<f32>(u.into()).into()
}

/// Inverse of [`uniform_triangle`]: barycentrics → u, clamped to [0, 1]².
#[inline]
pub fn uniform_triangle_inverse(b: Vec3) -> Vec2 {
    triangle::uniform_triangle_inverse::<f32>(b.into()).into()
}

/// Density of (b₀, b₁) from [`uniform_triangle`] over the unit square: 2 inside b₀, b₁ ≥ 0,
/// b₀ + b₁ ≤ 1, else 0. Per unit area of a real triangle, the pdf is 1/area.
#[inline]
pub fn uniform_triangle_pdf(b: Vec2) -> f32 {
    triangle::uniform_triangle_pdf::<f32>(b.into())
}

/// A direction towards triangle (a, b, c) (vertices relative to the shading point, either winding)
/// and its pdf per steradian.
///
/// Arvo's map, uniform in solid angle, with pdf 1/Ω (Ω by Van Oosterom–Strackee on edges); below
/// [`SPHERICAL_TRIANGLE_MIN_SR`] or above [`SPHERICAL_TRIANGLE_MAX_SR`] it samples by area instead
/// and returns the exact converted pdf. Degenerate triangles (coincident or collinear vertices,
/// the shading point within 1e-6 rad of the triangle's plane, non-finite input) give pdf 0 and
/// direction +z. NaN u gives a pdf of 0.
#[inline]
pub fn spherical_triangle(u: Vec2, a: Vec3, b: Vec3, c: Vec3) -> (Vec3, f32) {
    let (w, pdf) =
        spherical_triangle::spherical_triangle::<f32>(u.into(), a.into(), b.into(), c.into());
    (w.into(), pdf)
}

/// pdf per steradian that [`spherical_triangle`] returns unit direction `w`; 0 outside the
/// triangle and for degenerate triangles. Same formula, hence the same number, as the sampler's.
#[inline]
pub fn spherical_triangle_pdf(w: Vec3, a: Vec3, b: Vec3, c: Vec3) -> f32 {
    spherical_triangle::spherical_triangle_pdf::<f32>(w.into(), a.into(), b.into(), c.into())
}

/// Inverse of [`spherical_triangle`]: the u that maps to unit direction `w`, clamped to [0, 1]².
#[inline]
pub fn spherical_triangle_inverse(w: Vec3, a: Vec3, b: Vec3, c: Vec3) -> Vec2 {
    spherical_triangle::spherical_triangle_inverse::<f32>(w.into(), a.into(), b.into(), c.into())
        .into()
}

/// A point on rectangle corner + s·ex + t·ey (relative to the shading point; ex ⟂ ey) and its pdf
/// per steradian.
///
/// Ureña et al.'s map, uniform in solid angle (pdf 1/Ω, Ω by Van Oosterom–Strackee); below
/// [`SPHERICAL_RECTANGLE_MIN_SR`] or above [`SPHERICAL_RECTANGLE_MAX_SR`] it samples by area
/// and returns the exact converted pdf. Seen edge-on, or degenerate, the pdf is 0 and the point
/// is `corner` (edge-on means the shading point within 1e-6 rad of the plane). NaN u gives a
/// pdf of 0.
#[inline]
pub fn spherical_rectangle(u: Vec2, corner: Vec3, ex: Vec3, ey: Vec3) -> (Vec3, f32) {
    let (w, pdf) = spherical_rectangle::spherical_rectangle::<f32>(
        u.into(),
        corner.into(),
        ex.into(),
        ey.into(),
    );
    (w.into(), pdf)
}

/// pdf per steradian that [`spherical_rectangle`] returns a point in unit direction `w`; 0 when `w`
/// misses the rectangle or it is degenerate.
#[inline]
pub fn spherical_rectangle_pdf(w: Vec3, corner: Vec3, ex: Vec3, ey: Vec3) -> f32 {
    spherical_rectangle::spherical_rectangle_pdf::<f32>(
        w.into(),
        corner.into(),
        ex.into(),
        ey.into(),
    )
}

/// Inverse of [`spherical_rectangle`]: the u that maps to point `p` of the rectangle, in [0, 1]².
#[inline]
pub fn spherical_rectangle_inverse(p: Vec3, corner: Vec3, ex: Vec3, ey: Vec3) -> Vec2 {
    spherical_rectangle::spherical_rectangle_inverse::<f32>(
        p.into(),
        corner.into(),
        ex.into(),
        ey.into(),
    )
    .into()
}

/// [0, 1) → [−1, 1] with pdf 1 − |x| (the tent pixel filter), by inverting each half.
/// u is clamped to [0, 1]; NaN gives NaN.
#[inline]
pub fn tent(u: f32) -> f32 {
    tent::tent::<f32>(u)
}

/// pdf of [`tent`]: 1 − |x| on [−1, 1], else 0 (also for NaN).
#[inline]
pub fn tent_pdf(x: f32) -> f32 {
    tent::tent_pdf::<f32>(x)
}

/// Inverse of [`tent`]; x is clamped to [−1, 1].
#[inline]
pub fn tent_inverse(x: f32) -> f32 {
    tent::tent_inverse::<f32>(x)
}
