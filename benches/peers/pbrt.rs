//! pbrt-v4's spherical triangle and rectangle samplers (Pharr, Jakob and Humphreys, *Physically
//! Based Rendering*, 4th edition, §6.5.4 and §6.5.5), ported to f32 glam from the book's
//! equations, as the yardstick a renderer would otherwise use. Each returns the direction (the
//! triangle) or the point (the rectangle) and 1/Ω, relative to the shading point at the origin;
//! the triangle stops before the book's barycentric coordinates, which our sampler does not
//! compute either.

use std::f32::consts::PI;

use glam::Vec3;

/// The angle between unit vectors from the length of their sum or difference (the book's
/// `AngleBetween`), accurate near 0 and π where acos of the dot product is not.
#[inline]
fn angle_between(a: Vec3, b: Vec3) -> f32 {
    if a.dot(b) < 0.0 {
        PI - 2.0 * ((a + b).length() / 2.0).min(1.0).asin()
    } else {
        2.0 * ((b - a).length() / 2.0).min(1.0).asin()
    }
}

/// a·b − c·d with the rounding error of c·d recovered by a fused multiply-add.
#[inline]
fn difference_of_products(a: f32, b: f32, c: f32, d: f32) -> f32 {
    let cd = c * d;
    a.mul_add(b, -cd) + (-c).mul_add(d, cd)
}

/// a·b + c·d likewise.
#[inline]
fn sum_of_products(a: f32, b: f32, c: f32, d: f32) -> f32 {
    let cd = c * d;
    a.mul_add(b, cd) + c.mul_add(d, -cd)
}

#[inline]
fn gram_schmidt(v: Vec3, w: Vec3) -> Vec3 {
    v - v.dot(w) * w
}

/// Arvo's map as pbrt-v4 writes it: angles from the edge planes' normals, A′ + π interpolated
/// between π and the angle sum, and cos b′ from the two products above.
#[inline]
pub fn spherical_triangle(u: [f32; 2], a: Vec3, b: Vec3, c: Vec3) -> (Vec3, f32) {
    let (a, b, c) = (a.normalize(), b.normalize(), c.normalize());
    let (n_ab, n_bc, n_ca) = (a.cross(b), b.cross(c), c.cross(a));
    if n_ab.length_squared() == 0.0 || n_bc.length_squared() == 0.0 || n_ca.length_squared() == 0.0
    {
        return (Vec3::Z, 0.0);
    }
    let (n_ab, n_bc, n_ca) = (n_ab.normalize(), n_bc.normalize(), n_ca.normalize());
    let alpha = angle_between(n_ab, -n_ca);
    let beta = angle_between(n_bc, -n_ab);
    let gamma = angle_between(n_ca, -n_bc);
    let a_pi = alpha + beta + gamma;
    let ap_pi = (1.0 - u[0]) * PI + u[0] * a_pi;
    let area = a_pi - PI;
    let pdf = if area <= 0.0 { 0.0 } else { 1.0 / area };

    let (sin_alpha, cos_alpha) = alpha.sin_cos();
    let (sin_ap, cos_ap) = ap_pi.sin_cos();
    let sin_phi = sin_ap * cos_alpha - cos_ap * sin_alpha;
    let cos_phi = cos_ap * cos_alpha + sin_ap * sin_alpha;
    let k1 = cos_phi + cos_alpha;
    let k2 = sin_phi - sin_alpha * a.dot(b);
    let cos_bp = (k2 + difference_of_products(k2, cos_phi, k1, sin_phi) * cos_alpha)
        / (sum_of_products(k2, sin_phi, k1, cos_phi) * sin_alpha);
    let cos_bp = cos_bp.clamp(-1.0, 1.0);
    let sin_bp = (1.0 - cos_bp * cos_bp).max(0.0).sqrt();
    let cp = cos_bp * a + sin_bp * gram_schmidt(c, a).normalize();

    let cos_theta = 1.0 - u[1] * (1.0 - cp.dot(b));
    let sin_theta = (1.0 - cos_theta * cos_theta).max(0.0).sqrt();
    (
        cos_theta * b + sin_theta * gram_schmidt(cp, b).normalize(),
        pdf,
    )
}

/// Ureña, Fajardo and King's map as pbrt-v4 writes it: a frame along the edges, the solid angle
/// as the angle sum minus 2π, by area below 1e-3 sr.
#[inline]
pub fn spherical_rectangle(u: [f32; 2], s: Vec3, ex: Vec3, ey: Vec3) -> (Vec3, f32) {
    let (exl, eyl) = (ex.length(), ey.length());
    let (rx, ry) = (ex / exl, ey / eyl);
    let mut rz = rx.cross(ry);
    let mut z0 = s.dot(rz);
    if z0 > 0.0 {
        rz = -rz;
        z0 = -z0;
    }
    let (x0, y0) = (s.dot(rx), s.dot(ry));
    let (x1, y1) = (x0 + exl, y0 + eyl);

    let v00 = Vec3::new(x0, y0, z0);
    let v01 = Vec3::new(x0, y1, z0);
    let v10 = Vec3::new(x1, y0, z0);
    let v11 = Vec3::new(x1, y1, z0);
    let n0 = v00.cross(v10).normalize();
    let n1 = v10.cross(v11).normalize();
    let n2 = v11.cross(v01).normalize();
    let n3 = v01.cross(v00).normalize();
    let g0 = angle_between(-n0, n1);
    let g1 = angle_between(-n1, n2);
    let g2 = angle_between(-n2, n3);
    let g3 = angle_between(-n3, n0);

    let solid_angle = g0 + g1 + g2 + g3 - 2.0 * PI;
    if solid_angle <= 0.0 {
        return (s + u[0] * ex + u[1] * ey, 0.0);
    }
    let pdf = (1.0 / solid_angle).max(0.0);
    if solid_angle < 1e-3 {
        return (s + u[0] * ex + u[1] * ey, pdf);
    }

    let (b0, b1) = (n0.z, n2.z);
    let au = u[0] * (g0 + g1 - 2.0 * PI) + (u[0] - 1.0) * (g2 + g3);
    let (sin_au, cos_au) = au.sin_cos();
    let fu = (cos_au * b0 - b1) / sin_au;
    let cu = (1.0 / (fu * fu + b0 * b0).sqrt()).copysign(fu);
    let cu = cu.clamp(-(1.0 - f32::EPSILON / 2.0), 1.0 - f32::EPSILON / 2.0);

    let xu = (-(cu * z0) / (1.0 - cu * cu).max(0.0).sqrt()).clamp(x0, x1);
    let dd = (xu * xu + z0 * z0).sqrt();
    let h0 = y0 / (dd * dd + y0 * y0).sqrt();
    let h1 = y1 / (dd * dd + y1 * y1).sqrt();
    let hv = h0 + u[1] * (h1 - h0);
    let hvsq = hv * hv;
    let yv = if hvsq < 1.0 - 1e-6 {
        hv * dd / (1.0 - hvsq).sqrt()
    } else {
        y1
    };
    (xu * rx + yv * ry + z0 * rz, pdf)
}
