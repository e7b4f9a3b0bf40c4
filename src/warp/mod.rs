//! Warps: maps from the unit square to the domains of direct illumination, each with its pdf and
//! its inverse, side by side in the file of its family (`disk`, `hemisphere`, `sphere`, `cone`,
//! `phong`, `triangle`, `spherical_triangle`, `spherical_rectangle`, `tent`), the bilinear
//! warp composed with the spherical polygons (`bilinear`), and polygons sampled by projected
//! solid angle for a receiver's normal (`projected`: [`projected_triangle`],
//! [`projected_rectangle`], [`projected_polygon`] of up to eight vertices; `projected_cap`:
//! [`projected_cap`], the sphere's cap).
//!
//! # One function, every width
//!
//! Each warp is one public generic function, documented once; the type of its argument picks the
//! width ([`Point2`](crate::point::Point2), [`Point3`](crate::point::Point3)):
//!
//! ```
//! use glam::{DVec2, Vec2};
//! use mcsample::warp;
//! use mcsample::x8::{F32x8, Vec2x8};
//!
//! let u = Vec2::new(0.25, 0.5);
//! let w: glam::Vec3 = warp::uniform_cone(u, 0.1);
//! let w8 = warp::uniform_cone(Vec2x8::splat(u), F32x8::splat(0.1));
//! let w64 = warp::uniform_cone(DVec2::new(0.25, 0.5), 0.1f32 as f64);
//! assert_eq!(w8.lane(7), w); // lane i is the scalar result, bit for bit
//! assert!((w64 - w.as_dvec3()).length() < 2e-7);
//! assert!(warp::uniform_cone_pdf(w, 0.1) > 0.0);
//! ```
//!
//! The warps of the disk, hemisphere, sphere, cone, lobe, triangle and tent are always inlined:
//! they are a few dozen instructions,
//! and a caller that composes several (a camera sample draws a disk and two tents) would
//! otherwise pay calls. The spherical polygon samplers are `#[inline]`, left to the compiler.
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

mod bilinear;
mod common;
mod cone;
mod disk;
pub(crate) mod family;
mod hemisphere;
mod phong;
mod polygon;
mod projected;
mod projected_cap;
mod solid_angle;
mod sphere;
mod spherical_ellipse;
mod spherical_rectangle;
mod spherical_triangle;
mod tent;
mod triangle;

pub use bilinear::{
    BILINEAR_MIN_WEIGHT, BilinearRectangle, BilinearTriangle, CosineRectangle, CosineTriangle,
    bilinear, bilinear_inverse, bilinear_pdf, bilinear_rectangle, bilinear_rectangle_inverse,
    bilinear_rectangle_pdf, bilinear_triangle, bilinear_triangle_inverse, bilinear_triangle_pdf,
    linear, linear_inverse, linear_pdf,
};
pub use common::ONE_MINUS_EPS;
pub use cone::{
    UniformCone, cone_h_from_cos, cone_h_from_sin2, uniform_cone, uniform_cone_inverse,
    uniform_cone_pdf,
};
pub use disk::{
    ConcentricDisk, PolarDisk, concentric_disk, concentric_disk_inverse, polar_disk,
    polar_disk_inverse, uniform_disk_pdf,
};
pub use family::Family;
pub use hemisphere::{
    CosineHemisphere, UniformHemisphere, cosine_hemisphere, cosine_hemisphere_inverse,
    cosine_hemisphere_pdf, uniform_hemisphere, uniform_hemisphere_inverse, uniform_hemisphere_pdf,
};
pub(crate) use phong::phong_lobe_density;
pub use phong::{PHONG_N_MAX, PhongLobe, phong_lobe, phong_lobe_inverse, phong_lobe_pdf};
pub(crate) use polygon::{dot_wide, plane_dot, wide_cross};
pub use projected::{
    PROJECTED_MAX_SPREAD, PROJECTED_MIN_SR, PROJECTED_POLYGON_MAX_VERTICES, ProjectedPolygon,
    ProjectedRectangle, ProjectedSolidAngleHexagon, ProjectedSolidAngleRectangle,
    ProjectedSolidAngleTriangle, ProjectedTriangle, hexagon, projected_polygon,
    projected_polygon_inverse, projected_polygon_pdf, projected_rectangle,
    projected_rectangle_inverse, projected_rectangle_pdf, projected_triangle,
    projected_triangle_inverse, projected_triangle_pdf,
};
pub use projected_cap::{
    CAP_MAX_SPREAD, ProjectedCap, ProjectedSolidAngleCap, projected_cap, projected_cap_inverse,
    projected_cap_pdf,
};
pub use solid_angle::{SolidAngleRectangle, SolidAngleTriangle, polygon_size};
pub use sphere::{UniformSphere, uniform_sphere, uniform_sphere_inverse, uniform_sphere_pdf};
pub use spherical_ellipse::{
    ELLIPSE_MIN_SR, SolidAngleDisk, SphericalEllipse, spherical_ellipse, spherical_ellipse_inverse,
    spherical_ellipse_pdf,
};
pub use spherical_rectangle::{
    SPHERICAL_RECTANGLE_INVERSE_REACH, SPHERICAL_RECTANGLE_MAX_SR, SPHERICAL_RECTANGLE_MIN_SR,
    SphericalRectangle, spherical_rectangle, spherical_rectangle_inverse, spherical_rectangle_pdf,
    urena_rectangle,
};
pub use spherical_triangle::{
    SPHERICAL_TRIANGLE_MAX_SR, SPHERICAL_TRIANGLE_MIN_SR, SphericalTriangle, arvo_triangle,
    spherical_triangle, spherical_triangle_inverse, spherical_triangle_pdf,
};
pub use tent::{TentPair, tent, tent_inverse, tent_pdf};
pub use triangle::{
    UniformTriangle, uniform_triangle, uniform_triangle_inverse, uniform_triangle_pdf,
};
