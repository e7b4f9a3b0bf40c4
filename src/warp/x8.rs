//! The packet faces of the warps: the same names and meaning as [`crate::warp`], on
//! [`Vec2x8`], [`Vec3x8`] and [`F32x8`].

use crate::x8::{F32x8, Vec2x8, Vec3x8};

/// Packet twin of [`super::concentric_disk`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn concentric_disk(u: Vec2x8) -> Vec2x8 {
    super::disk::concentric_disk(u)
}

/// Packet twin of [`super::concentric_disk_inverse`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn concentric_disk_inverse(p: Vec2x8) -> Vec2x8 {
    super::disk::concentric_disk_inverse(p)
}

/// Packet twin of [`super::polar_disk`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn polar_disk(u: Vec2x8) -> Vec2x8 {
    super::disk::polar_disk(u)
}

/// Packet twin of [`super::polar_disk_inverse`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn polar_disk_inverse(p: Vec2x8) -> Vec2x8 {
    super::disk::polar_disk_inverse(p)
}

/// Packet twin of [`super::uniform_disk_pdf`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn uniform_disk_pdf() -> F32x8 {
    super::disk::uniform_disk_pdf::<F32x8>()
}

/// Packet twin of [`super::uniform_hemisphere`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn uniform_hemisphere(u: Vec2x8) -> Vec3x8 {
    super::hemisphere::uniform_hemisphere(u)
}

/// Packet twin of [`super::uniform_hemisphere_pdf`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn uniform_hemisphere_pdf() -> F32x8 {
    super::hemisphere::uniform_hemisphere_pdf::<F32x8>()
}

/// Packet twin of [`super::uniform_hemisphere_inverse`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn uniform_hemisphere_inverse(w: Vec3x8) -> Vec2x8 {
    super::hemisphere::uniform_hemisphere_inverse(w)
}

/// Packet twin of [`super::cosine_hemisphere`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn cosine_hemisphere(u: Vec2x8) -> Vec3x8 {
    super::hemisphere::cosine_hemisphere(u)
}

/// Packet twin of [`super::cosine_hemisphere_pdf`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn cosine_hemisphere_pdf(cos_theta: F32x8) -> F32x8 {
    super::hemisphere::cosine_hemisphere_pdf(cos_theta)
}

/// Packet twin of [`super::cosine_hemisphere_inverse`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn cosine_hemisphere_inverse(w: Vec3x8) -> Vec2x8 {
    super::hemisphere::cosine_hemisphere_inverse(w)
}

/// Packet twin of [`super::uniform_sphere`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn uniform_sphere(u: Vec2x8) -> Vec3x8 {
    super::sphere::uniform_sphere(u)
}

/// Packet twin of [`super::uniform_sphere_pdf`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn uniform_sphere_pdf() -> F32x8 {
    super::sphere::uniform_sphere_pdf::<F32x8>()
}

/// Packet twin of [`super::uniform_sphere_inverse`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn uniform_sphere_inverse(w: Vec3x8) -> Vec2x8 {
    super::sphere::uniform_sphere_inverse(w)
}

/// Packet twin of [`super::uniform_cone`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn uniform_cone(u: Vec2x8, h: F32x8) -> Vec3x8 {
    super::cone::uniform_cone(u, h)
}

/// Packet twin of [`super::uniform_cone_pdf`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn uniform_cone_pdf(h: F32x8) -> F32x8 {
    super::cone::uniform_cone_pdf(h)
}

/// Packet twin of [`super::uniform_cone_inverse`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn uniform_cone_inverse(w: Vec3x8, h: F32x8) -> Vec2x8 {
    super::cone::uniform_cone_inverse(w, h)
}

/// Packet twin of [`super::cone_h_from_cos`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn cone_h_from_cos(cos_max: F32x8) -> F32x8 {
    super::cone::cone_h_from_cos(cos_max)
}

/// Packet twin of [`super::cone_h_from_sin2`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn cone_h_from_sin2(sin2_max: F32x8) -> F32x8 {
    super::cone::cone_h_from_sin2(sin2_max)
}

/// Packet twin of [`super::phong_lobe`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn phong_lobe(u: Vec2x8, n: F32x8) -> Vec3x8 {
    super::phong::phong_lobe(u, n)
}

/// Packet twin of [`super::phong_lobe_pdf`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn phong_lobe_pdf(cos_alpha: F32x8, n: F32x8) -> F32x8 {
    super::phong::phong_lobe_pdf(cos_alpha, n)
}

/// Packet twin of [`super::phong_lobe_inverse`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn phong_lobe_inverse(w: Vec3x8, n: F32x8) -> Vec2x8 {
    super::phong::phong_lobe_inverse(w, n)
}

/// Packet twin of [`super::uniform_triangle`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn uniform_triangle(u: Vec2x8) -> Vec3x8 {
    super::triangle::uniform_triangle(u)
}

/// Packet twin of [`super::uniform_triangle_inverse`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn uniform_triangle_inverse(b: Vec3x8) -> Vec2x8 {
    super::triangle::uniform_triangle_inverse(b)
}

/// Packet twin of [`super::uniform_triangle_pdf`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn uniform_triangle_pdf(b: Vec2x8) -> F32x8 {
    super::triangle::uniform_triangle_pdf(b)
}

/// Packet twin of [`super::spherical_triangle`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn spherical_triangle(u: Vec2x8, a: Vec3x8, b: Vec3x8, c: Vec3x8) -> (Vec3x8, F32x8) {
    super::spherical_triangle::spherical_triangle(u, a, b, c)
}

/// Packet twin of [`super::spherical_triangle_pdf`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn spherical_triangle_pdf(w: Vec3x8, a: Vec3x8, b: Vec3x8, c: Vec3x8) -> F32x8 {
    super::spherical_triangle::spherical_triangle_pdf(w, a, b, c)
}

/// Packet twin of [`super::spherical_triangle_inverse`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn spherical_triangle_inverse(w: Vec3x8, a: Vec3x8, b: Vec3x8, c: Vec3x8) -> Vec2x8 {
    super::spherical_triangle::spherical_triangle_inverse(w, a, b, c)
}

/// Packet twin of [`super::spherical_rectangle`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn spherical_rectangle(u: Vec2x8, corner: Vec3x8, ex: Vec3x8, ey: Vec3x8) -> (Vec3x8, F32x8) {
    super::spherical_rectangle::spherical_rectangle(u, corner, ex, ey)
}

/// Packet twin of [`super::spherical_rectangle_pdf`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn spherical_rectangle_pdf(w: Vec3x8, corner: Vec3x8, ex: Vec3x8, ey: Vec3x8) -> F32x8 {
    super::spherical_rectangle::spherical_rectangle_pdf(w, corner, ex, ey)
}

/// Packet twin of [`super::spherical_rectangle_inverse`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn spherical_rectangle_inverse(p: Vec3x8, corner: Vec3x8, ex: Vec3x8, ey: Vec3x8) -> Vec2x8 {
    super::spherical_rectangle::spherical_rectangle_inverse(p, corner, ex, ey)
}

/// Packet twin of [`super::tent`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn tent(u: F32x8) -> F32x8 {
    super::tent::tent(u)
}

/// Packet twin of [`super::tent_pdf`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn tent_pdf(x: F32x8) -> F32x8 {
    super::tent::tent_pdf(x)
}

/// Packet twin of [`super::tent_inverse`]: lane *i* equals the scalar result on lane *i*'s inputs, bit for bit.
#[inline]
pub fn tent_inverse(x: F32x8) -> F32x8 {
    super::tent::tent_inverse(x)
}
