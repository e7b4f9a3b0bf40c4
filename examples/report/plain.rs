//! Plain versions of the warps: the code a user would write from the textbook formula, with glam
//! and std for one sample and `wide::f32x8` for eight, and none of the crate's robustness (no
//! clamping of u, no NaN policy, no guarded cancellation). They are the yardstick of the speed
//! targets: each of the crate's forms against the plain form of the same formula, in one run.
//!
//! The report and `benches/peers.rs` share this file.

#![allow(dead_code)]

use std::f32::consts::{FRAC_PI_4, PI, TAU};

use std::hint::black_box;

use glam::{Vec2, Vec3};
use mcsample::verify::registry::Sampler;
use mcsample::warp::{PhongLobe, SolidAngleRectangle, SolidAngleTriangle, UniformCone};
use wide::f32x8;

/// Shirley–Chiu concentric map, as in pbrt.
#[inline]
pub fn concentric_disk(u: Vec2) -> Vec2 {
    let o = 2.0 * u - Vec2::ONE;
    if o.x == 0.0 && o.y == 0.0 {
        return Vec2::ZERO;
    }
    let (r, theta) = if o.x.abs() > o.y.abs() {
        (o.x, FRAC_PI_4 * (o.y / o.x))
    } else {
        (o.y, PI / 2.0 - FRAC_PI_4 * (o.x / o.y))
    };
    let (s, c) = theta.sin_cos();
    r * Vec2::new(c, s)
}

#[inline]
pub fn polar_disk(u: Vec2) -> Vec2 {
    let r = u.x.sqrt();
    let (s, c) = (TAU * u.y).sin_cos();
    Vec2::new(r * c, r * s)
}

#[inline]
pub fn uniform_hemisphere(u: Vec2) -> Vec3 {
    let z = u.x;
    let r = (1.0 - z * z).max(0.0).sqrt();
    let (s, c) = (TAU * u.y).sin_cos();
    Vec3::new(r * c, r * s, z)
}

/// Malley's method on the concentric disk.
#[inline]
pub fn cosine_hemisphere(u: Vec2) -> Vec3 {
    let d = concentric_disk(u);
    let z = (1.0 - d.length_squared()).max(0.0).sqrt();
    Vec3::new(d.x, d.y, z)
}

#[inline]
pub fn uniform_sphere(u: Vec2) -> Vec3 {
    let z = 1.0 - 2.0 * u.x;
    let r = (1.0 - z * z).max(0.0).sqrt();
    let (s, c) = (TAU * u.y).sin_cos();
    Vec3::new(r * c, r * s, z)
}

/// The cone of 1 − cos θmax = h about +z.
#[inline]
pub fn uniform_cone(u: Vec2, h: f32) -> Vec3 {
    let z = 1.0 - u.x * h;
    let r = (1.0 - z * z).max(0.0).sqrt();
    let (s, c) = (TAU * u.y).sin_cos();
    Vec3::new(r * c, r * s, z)
}

/// cos α = u₀^(1/(n+1)).
#[inline]
pub fn phong_lobe(u: Vec2, n: f32) -> Vec3 {
    let z = u.x.powf(1.0 / (n + 1.0));
    let r = (1.0 - z * z).max(0.0).sqrt();
    let (s, c) = (TAU * u.y).sin_cos();
    Vec3::new(r * c, r * s, z)
}

/// Heitz's low-distortion map (2019), as barycentrics.
#[inline]
pub fn uniform_triangle(u: Vec2) -> Vec3 {
    let (b0, b1) = if u.y > u.x {
        let b0 = u.x / 2.0;
        (b0, u.y - b0)
    } else {
        let b1 = u.y / 2.0;
        (u.x - b1, b1)
    };
    Vec3::new(b0, b1, 1.0 - b0 - b1)
}

#[inline]
pub fn tent(u: f32) -> f32 {
    if u < 0.5 {
        (2.0 * u).sqrt() - 1.0
    } else {
        1.0 - (2.0 - 2.0 * u).sqrt()
    }
}

/// Arvo's spherical triangle sampling as the paper and pbrt-v3 write it: angles by acos of
/// normalised cross products, cos b′ as a ratio and sin b′ = √(1 − cos²b′). Returns the
/// direction and 1/Ω.
#[inline]
pub fn spherical_triangle(u: Vec2, a: Vec3, b: Vec3, c: Vec3) -> (Vec3, f32) {
    let (a, b, c) = (a.normalize(), b.normalize(), c.normalize());
    let n_ab = a.cross(b).normalize();
    let n_bc = b.cross(c).normalize();
    let n_ca = c.cross(a).normalize();
    let alpha = (-n_ab.dot(n_ca)).clamp(-1.0, 1.0).acos();
    let beta = (-n_bc.dot(n_ab)).clamp(-1.0, 1.0).acos();
    let gamma = (-n_ca.dot(n_bc)).clamp(-1.0, 1.0).acos();
    let area = alpha + beta + gamma - PI;
    // φ = (A′ + π) − α, with A′ = u₀·area the sub-triangle's area.
    let (sin_phi, cos_phi) = (u.x * area + PI - alpha).sin_cos();
    let (sin_alpha, cos_alpha) = alpha.sin_cos();
    let k1 = cos_phi + cos_alpha;
    let k2 = sin_phi - sin_alpha * a.dot(b);
    let cos_bp = (k2 + (k2 * cos_phi - k1 * sin_phi) * cos_alpha)
        / ((k2 * sin_phi + k1 * cos_phi) * sin_alpha);
    let cos_bp = cos_bp.clamp(-1.0, 1.0);
    let sin_bp = (1.0 - cos_bp * cos_bp).max(0.0).sqrt();
    let c_p = cos_bp * a + sin_bp * (c - c.dot(a) * a).normalize();
    let cos_theta = 1.0 - u.y * (1.0 - c_p.dot(b));
    let sin_theta = (1.0 - cos_theta * cos_theta).max(0.0).sqrt();
    let w = cos_theta * b + sin_theta * (c_p - c_p.dot(b) * b).normalize();
    (w, 1.0 / area)
}

/// Ureña, Fajardo and King's spherical rectangle sampling as the paper writes it (Σγ − 2π for
/// the solid angle). Returns the point on the rectangle and 1/Ω.
#[inline]
pub fn spherical_rectangle(u: Vec2, corner: Vec3, ex: Vec3, ey: Vec3) -> (Vec3, f32) {
    let exl = ex.length();
    let eyl = ey.length();
    let x = ex / exl;
    let y = ey / eyl;
    // The frame's z points away from the rectangle, so that z0 ≤ 0.
    let z0 = -corner.dot(x.cross(y)).abs();
    let x0 = corner.dot(x);
    let y0 = corner.dot(y);
    let (x1, y1) = (x0 + exl, y0 + eyl);
    let v00 = Vec3::new(x0, y0, z0);
    let v01 = Vec3::new(x0, y1, z0);
    let v10 = Vec3::new(x1, y0, z0);
    let v11 = Vec3::new(x1, y1, z0);
    let n0 = v00.cross(v10).normalize();
    let n1 = v10.cross(v11).normalize();
    let n2 = v11.cross(v01).normalize();
    let n3 = v01.cross(v00).normalize();
    let g0 = (-n0.dot(n1)).acos();
    let g1 = (-n1.dot(n2)).acos();
    let g2 = (-n2.dot(n3)).acos();
    let g3 = (-n3.dot(n0)).acos();
    let k = TAU - g2 - g3;
    let s = g0 + g1 - k;
    let au = u.x * s + k;
    let fu = (au.cos() * n0.z - n2.z) / au.sin();
    let cu = (1.0 / (fu * fu + n0.z * n0.z).sqrt())
        .copysign(fu)
        .clamp(-1.0, 1.0);
    let xu = (-(cu * z0) / (1.0 - cu * cu).max(0.0).sqrt()).clamp(x0, x1);
    let d = (xu * xu + z0 * z0).sqrt();
    let h0 = y0 / (d * d + y0 * y0).sqrt();
    let h1 = y1 / (d * d + y1 * y1).sqrt();
    let hv = h0 + u.y * (h1 - h0);
    let yv = if hv * hv < 1.0 - 1e-6 {
        hv * d / (1.0 - hv * hv).sqrt()
    } else {
        y1
    };
    (corner + (xu - x0) * x + (yv - y0) * y, 1.0 / s)
}

/// A loop of a plain scalar warp over a batch (the yardstick of `scalar_vs_plain`), the warp
/// inlined into it; only the batch is called through the box.
pub type PlainLoop = Box<dyn Fn(&[Vec2], &mut [Vec3])>;

/// The plain glam+std version of a registered sampler's formula, with the same parameters, as a
/// loop; None where there is none. The polygons' geometry passes through `black_box` as in the
/// registry's loop, so both pay their set-up per sample.
pub fn loop_for(s: Sampler) -> Option<PlainLoop> {
    fn each(f: impl Fn(Vec2) -> Vec3 + 'static) -> PlainLoop {
        Box::new(move |us: &[Vec2], out: &mut [Vec3]| {
            for (o, &u) in out.iter_mut().zip(us) {
                *o = f(u);
            }
        })
    }
    Some(match s {
        Sampler::ConcentricDisk(_) => each(|u| concentric_disk(u).extend(0.0)),
        Sampler::PolarDisk(_) => each(|u| polar_disk(u).extend(0.0)),
        Sampler::UniformHemisphere(_) => each(uniform_hemisphere),
        Sampler::CosineHemisphere(_) => each(cosine_hemisphere),
        Sampler::UniformSphere(_) => each(uniform_sphere),
        Sampler::UniformCone(UniformCone { h }) => each(move |u| uniform_cone(u, h)),
        Sampler::PhongLobe(PhongLobe { n }) => each(move |u| phong_lobe(u, n)),
        Sampler::UniformTriangle(_) => each(uniform_triangle),
        Sampler::Tent(_) => each(|u| Vec3::new(tent(u.x), tent(u.y), 0.0)),
        Sampler::SphericalTriangle(SolidAngleTriangle { v }) => each(move |u| {
            let [a, b, c] = black_box(v);
            spherical_triangle(u, a, b, c).0
        }),
        Sampler::SphericalRectangle(SolidAngleRectangle { v }) => each(move |u| {
            let [c, ex, ey] = black_box(v);
            spherical_rectangle(u, c, ex, ey).0
        }),
        // The lights and BSDFs have no plain peer here: their textbook forms are the warps'.
        _ => return None,
    })
}

// ---------------------------------------------------------------------------------------------
// Packets: the same formulas on wide::f32x8.

/// Eight u pairs.
#[derive(Clone, Copy)]
pub struct U8 {
    pub x: f32x8,
    pub y: f32x8,
}

/// Eight directions or points.
#[derive(Clone, Copy)]
pub struct V8 {
    pub x: f32x8,
    pub y: f32x8,
    pub z: f32x8,
}

#[inline]
fn ring(z: f32x8, u1: f32x8) -> V8 {
    let r = (f32x8::ONE - z * z).max(f32x8::ZERO).sqrt();
    let (s, c) = (f32x8::splat(TAU) * u1).sin_cos();
    V8 {
        x: r * c,
        y: r * s,
        z,
    }
}

#[inline]
pub fn polar_disk_x8(u: U8) -> V8 {
    let r = u.x.sqrt();
    let (s, c) = (f32x8::splat(TAU) * u.y).sin_cos();
    V8 {
        x: r * c,
        y: r * s,
        z: f32x8::ZERO,
    }
}

#[inline]
pub fn concentric_disk_x8(u: U8) -> V8 {
    let ox = u.x * 2.0 - f32x8::ONE;
    let oy = u.y * 2.0 - f32x8::ONE;
    let major_x = ox.abs().simd_gt(oy.abs());
    let r = major_x.select(ox, oy);
    let q = major_x.select(oy / ox, ox / oy);
    let theta = major_x.select(
        f32x8::splat(FRAC_PI_4) * q,
        f32x8::splat(PI / 2.0) - f32x8::splat(FRAC_PI_4) * q,
    );
    let (s, c) = theta.sin_cos();
    let zero = ox.simd_eq(f32x8::ZERO) & oy.simd_eq(f32x8::ZERO);
    V8 {
        x: zero.select(f32x8::ZERO, r * c),
        y: zero.select(f32x8::ZERO, r * s),
        z: f32x8::ZERO,
    }
}

#[inline]
pub fn uniform_hemisphere_x8(u: U8) -> V8 {
    ring(u.x, u.y)
}

#[inline]
pub fn cosine_hemisphere_x8(u: U8) -> V8 {
    let d = concentric_disk_x8(u);
    let z = (f32x8::ONE - d.x * d.x - d.y * d.y).max(f32x8::ZERO).sqrt();
    V8 { z, ..d }
}

#[inline]
pub fn uniform_sphere_x8(u: U8) -> V8 {
    ring(f32x8::ONE - u.x * 2.0, u.y)
}

#[inline]
pub fn uniform_cone_x8(u: U8, h: f32x8) -> V8 {
    ring(f32x8::ONE - u.x * h, u.y)
}
