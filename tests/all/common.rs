//! Independent f64 references for the warps, written from the textbook formulas of the papers
//! named at each function: Shirley and Chiu 1997 (concentric disk), Malley's method (cosine
//! hemisphere), Heitz 2019 (triangle), Arvo 1995 and Van Oosterom and Strackee 1983 (spherical
//! triangle and its solid angle), Ureña et al. 2013 (spherical rectangle), Duff et al. 2017
//! (orthonormal frame). They are not written from the crate's generic code and do not call into
//! `mcsample`. Beside them, small helpers the tests share: the tests' one random number generator
//! ([`TestRng`]), stratified grids and f64 vector arithmetic.
//!
//! The references deliberately use the *plain* forms where f64 has the precision to spare
//! (Shirley–Chiu's four-branch concentric map, acos angles, √(1−z²) radii), so that a shared
//! mistake in a robust rewrite cannot hide in both the crate and its reference.

#![allow(dead_code)]

use std::f64::consts::{FRAC_PI_2, FRAC_PI_4, PI, TAU};

use glam::Vec2;
use mcsample::verify::registry::Sampler;
use mcsample::verify::{Scalar, check_lanes, check_lanes16};

/// 1 − 2⁻²⁴, the largest f32 below 1.
pub const ONE_MINUS_EPS_F32: f32 = 1.0 - 1.0 / 16_777_216.0;

// ---------------------------------------------------------------------------------------------
// f64 vectors

pub type D2 = [f64; 2];
pub type D3 = [f64; 3];

pub fn add(a: D3, b: D3) -> D3 {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
pub fn sub(a: D3, b: D3) -> D3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
pub fn scale(a: D3, s: f64) -> D3 {
    [a[0] * s, a[1] * s, a[2] * s]
}
pub fn dot(a: D3, b: D3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
pub fn cross(a: D3, b: D3) -> D3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
pub fn norm(a: D3) -> f64 {
    dot(a, a).sqrt()
}
pub fn normalize(a: D3) -> D3 {
    scale(a, 1.0 / norm(a))
}
pub fn dist3(a: D3, b: D3) -> f64 {
    norm(sub(a, b))
}
/// How far (t, b, n) is from a right-handed orthonormal frame: the largest of the unit-length
/// errors of t and b, their pairwise dot products with each other and n, and |t × b − n|.
pub fn orthonormal_error(t: D3, b: D3, n: D3) -> f64 {
    [
        (norm(t) - 1.0).abs(),
        (norm(b) - 1.0).abs(),
        dot(t, b).abs(),
        dot(t, n).abs(),
        dot(b, n).abs(),
        dist3(cross(t, b), n),
    ]
    .into_iter()
    .fold(0.0, f64::max)
}
pub fn dist2(a: D2, b: D2) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt()
}

/// f32 triple → f64 triple, exactly.
pub fn d3(v: [f32; 3]) -> D3 {
    [v[0] as f64, v[1] as f64, v[2] as f64]
}
/// f32 pair → f64 pair, exactly.
pub fn d2(v: [f32; 2]) -> D2 {
    [v[0] as f64, v[1] as f64]
}
/// f64 triple rounded to f32.
pub fn f3(v: D3) -> [f32; 3] {
    [v[0] as f32, v[1] as f32, v[2] as f32]
}

/// Relative error of `got` against `want` (absolute when `want` is 0).
pub fn rel_err(got: f64, want: f64) -> f64 {
    if want == 0.0 {
        got.abs()
    } else {
        ((got - want) / want).abs()
    }
}

/// Distance between two fractions of a turn, on the circle (so 0.999 999 9 and 0 are close).
pub fn turn_dist(a: f64, b: f64) -> f64 {
    let d = (a - b).abs() % 1.0;
    d.min(1.0 - d)
}

// ---------------------------------------------------------------------------------------------
// Random numbers and input sets

/// The tests' one random number generator: PCG32 (O'Neill 2014: XSH-RR output on a 64-bit LCG),
/// the `rand_pcg` implementation, with a fixed seed so that every run draws the same inputs.
///
/// `new(seed)` is `Pcg32::new(0x853c_49e6_748f_ea9b ^ seed, seed)`, stream `seed`: the sequence
/// of the PCG reference's `pcg32_srandom(0x853c_49e6_748f_ea9b ^ seed, seed)` and of the
/// hand-written PCG32 this file held before, so the inputs drawn from it, and the error bounds
/// measured on them (accuracy.rs), did not change.
#[derive(Clone, Debug)]
pub struct TestRng(rand_pcg::Pcg32);

impl TestRng {
    pub fn new(seed: u64) -> Self {
        TestRng(rand_pcg::Pcg32::new(0x853c_49e6_748f_ea9b ^ seed, seed))
    }
    pub fn next_u32(&mut self) -> u32 {
        rand_core::Rng::next_u32(&mut self.0)
    }
    /// Two outputs, the first in the low half.
    pub fn next_u64(&mut self) -> u64 {
        rand_core::Rng::next_u64(&mut self.0)
    }
    /// A 24-bit float in [0, 1), the generators' output format: (x >> 8)·2⁻²⁴.
    pub fn u01(&mut self) -> f32 {
        (self.next_u32() >> 8) as f32 * (1.0 / 16_777_216.0)
    }
    /// A pair of 24-bit floats in [0, 1), x drawn first.
    pub fn u2(&mut self) -> Vec2 {
        let x = self.u01();
        Vec2::new(x, self.u01())
    }
    /// Uniform in 0..n (by a modulo: the bias, below n/2³², does not matter to the tests).
    pub fn below(&mut self, n: u32) -> u32 {
        self.next_u32() % n
    }
    /// Uniform f64 in [lo, hi), from 53 random bits.
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        let x = ((self.next_u32() as u64) << 21 ^ (self.next_u32() as u64 >> 11)) as f64
            * (1.0 / 9_007_199_254_740_992.0);
        lo + (hi - lo) * x
    }
    /// A uniformly random unit vector (f64): z uniform in [−1, 1), φ uniform in [0, 2π).
    pub fn unit_vector(&mut self) -> D3 {
        let z = self.range(-1.0, 1.0);
        let phi = self.range(0.0, TAU);
        let r = (1.0 - z * z).max(0.0).sqrt();
        [r * phi.cos(), r * phi.sin(), z]
    }
}

/// The n × n stratified grid of cell centres, ((i + ½)/n, (j + ½)/n). For n a power of two up to
/// 2²³ every value is exact in f32 and a multiple of 2⁻²⁴.
pub fn grid(n: usize) -> Vec<[f32; 2]> {
    let mut v = Vec::with_capacity(n * n);
    for j in 0..n {
        for i in 0..n {
            v.push([
                ((i as f64 + 0.5) / n as f64) as f32,
                ((j as f64 + 0.5) / n as f64) as f32,
            ]);
        }
    }
    v
}

/// Values on and next to the square's boundary, its centre and its diagonal lines.
pub fn border() -> Vec<[f32; 2]> {
    let e = 1.0 / 16_777_216.0;
    let vals = [
        0.0,
        e,
        2.0 * e,
        0.25,
        0.5 - e,
        0.5,
        0.5 + e,
        0.75,
        1.0 - 2.0 * e,
        ONE_MINUS_EPS_F32,
    ];
    let mut v = Vec::new();
    for &a in &vals {
        for &b in &vals {
            v.push([a, b]);
        }
    }
    v
}

/// True when the environment sets `MCSAMPLE_TESTS=emulated`. CI sets it where the binary runs
/// emulated (aarch64 under qemu-user, wasm under Node.js), 10 to 20 times slower than native.
/// There the checks over the whole registry ask whether that target's arithmetic is the native
/// build's, which the fixed hard inputs and a sixteenth of the others answer; see
/// [`random_inputs`].
pub fn emulated() -> bool {
    std::env::var("MCSAMPLE_TESTS").is_ok_and(|v| v == "emulated")
}

/// How many inputs a check over the whole registry draws: `n`, or `n / 16` when
/// [`emulated`]. Native runs always draw all of them.
pub fn random_inputs(n: usize) -> usize {
    if emulated() { n / 16 } else { n }
}

/// The standard accuracy input set: the 256 × 256 stratified grid, 2¹⁶ random 24-bit pairs and
/// the border set (131,172 inputs); when [`emulated`], the 64 × 64 grid and 2¹² pairs.
pub fn accuracy_inputs(seed: u64) -> Vec<[f32; 2]> {
    let mut v = grid(if emulated() { 64 } else { 256 });
    let mut rng = TestRng::new(seed);
    for _ in 0..random_inputs(1 << 16) {
        v.push(rng.u2().to_array());
    }
    v.extend(border());
    v
}

// ---------------------------------------------------------------------------------------------
// Disks

/// Shirley & Chiu 1997, the original four-branch form: r and φ per quarter of the square.
pub fn concentric_disk(u: D2) -> D2 {
    let a = 2.0 * u[0] - 1.0;
    let b = 2.0 * u[1] - 1.0;
    let (r, phi);
    if a > -b {
        if a > b {
            r = a;
            phi = FRAC_PI_4 * (b / a);
        } else {
            r = b;
            phi = FRAC_PI_4 * (2.0 - a / b);
        }
    } else if a < b {
        r = -a;
        phi = FRAC_PI_4 * (4.0 + b / a);
    } else {
        r = -b;
        phi = if b != 0.0 {
            FRAC_PI_4 * (6.0 - a / b)
        } else {
            0.0
        };
    }
    [r * phi.cos(), r * phi.sin()]
}

/// Inverse of the four-branch concentric map: the quarter from the polar angle.
pub fn concentric_disk_inverse(p: D2) -> D2 {
    let r = (p[0] * p[0] + p[1] * p[1]).sqrt();
    let mut phi = p[1].atan2(p[0]);
    if phi < -FRAC_PI_4 {
        phi += TAU;
    }
    let (a, b);
    if phi < FRAC_PI_4 {
        a = r;
        b = a * phi / FRAC_PI_4;
    } else if phi < 3.0 * FRAC_PI_4 {
        b = r;
        a = b * (2.0 - phi / FRAC_PI_4);
    } else if phi < 5.0 * FRAC_PI_4 {
        a = -r;
        b = a * (phi / FRAC_PI_4 - 4.0);
    } else {
        b = -r;
        a = b * (6.0 - phi / FRAC_PI_4);
    }
    [(a + 1.0) / 2.0, (b + 1.0) / 2.0]
}

/// r = √u₀, φ = 2πu₁.
pub fn polar_disk(u: D2) -> D2 {
    let r = u[0].sqrt();
    let phi = TAU * u[1];
    [r * phi.cos(), r * phi.sin()]
}

/// The azimuth of (x, y) as a fraction of a turn, in [0, 1).
pub fn azimuth(x: f64, y: f64) -> f64 {
    let v = y.atan2(x) / TAU;
    if v < 0.0 { v + 1.0 } else { v }
}

pub fn polar_disk_inverse(p: D2) -> D2 {
    [p[0] * p[0] + p[1] * p[1], azimuth(p[0], p[1])]
}

// ---------------------------------------------------------------------------------------------
// Hemispheres and the sphere

/// z = u₀, φ = 2πu₁, r = √(1 − z²).
pub fn uniform_hemisphere(u: D2) -> D3 {
    let z = u[0];
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = TAU * u[1];
    [r * phi.cos(), r * phi.sin(), z]
}

pub fn uniform_hemisphere_inverse(w: D3) -> D2 {
    [w[2], azimuth(w[0], w[1])]
}

pub const UNIFORM_HEMISPHERE_PDF: f64 = 1.0 / TAU;

/// Malley: the concentric disk lifted by z = √(1 − x² − y²).
pub fn cosine_hemisphere(u: D2) -> D3 {
    let p = concentric_disk(u);
    let z = (1.0 - p[0] * p[0] - p[1] * p[1]).max(0.0).sqrt();
    [p[0], p[1], z]
}

pub fn cosine_hemisphere_pdf(cos_theta: f64) -> f64 {
    if cos_theta > 0.0 { cos_theta / PI } else { 0.0 }
}

pub fn cosine_hemisphere_inverse(w: D3) -> D2 {
    concentric_disk_inverse([w[0], w[1]])
}

/// z = 1 − 2u₀, r = √(1 − z²), φ = 2πu₁.
pub fn uniform_sphere(u: D2) -> D3 {
    let z = 1.0 - 2.0 * u[0];
    let r = (1.0 - z * z).max(0.0).sqrt();
    let phi = TAU * u[1];
    [r * phi.cos(), r * phi.sin(), z]
}

pub fn uniform_sphere_inverse(w: D3) -> D2 {
    [(1.0 - w[2]) / 2.0, azimuth(w[0], w[1])]
}

pub const UNIFORM_SPHERE_PDF: f64 = 1.0 / (2.0 * TAU);

// ---------------------------------------------------------------------------------------------
// Cone and Phong lobe

/// Cone about +z with h = 1 − cos θmax: 1 − cos θ = u₀h, sin θ = √((1−cos θ)(1+cos θ)).
pub fn uniform_cone(u: D2, h: f64) -> D3 {
    let t = u[0] * h;
    let z = 1.0 - t;
    let r = (t * (2.0 - t)).max(0.0).sqrt();
    let phi = TAU * u[1];
    [r * phi.cos(), r * phi.sin(), z]
}

pub fn uniform_cone_pdf(h: f64) -> f64 {
    1.0 / (TAU * h)
}

/// u₀ = (1 − z)/h with 1 − z = (x² + y²)/(1 + z).
pub fn uniform_cone_inverse(w: D3, h: f64) -> D2 {
    let t = (w[0] * w[0] + w[1] * w[1]) / (1.0 + w[2]);
    [t / h, azimuth(w[0], w[1])]
}

/// h = 1 − cos θmax from sin²θmax.
pub fn cone_h_from_sin2(s2: f64) -> f64 {
    s2 / (1.0 + (1.0 - s2).sqrt())
}

/// Phong lobe cosⁿα about +z. For n ≤ 100, the textbook cos α = u₀^{1/(n+1)} (f64 has the
/// precision); above, 1 − cos α = −expm1(ln u₀/(n+1)).
pub fn phong_lobe(u: D2, n: f64) -> D3 {
    let (z, r) = if n <= 100.0 {
        let c = u[0].powf(1.0 / (n + 1.0));
        (c, (1.0 - c * c).max(0.0).sqrt())
    } else {
        let t = -(u[0].ln() / (n + 1.0)).exp_m1();
        (1.0 - t, (t * (2.0 - t)).max(0.0).sqrt())
    };
    let phi = TAU * u[1];
    [r * phi.cos(), r * phi.sin(), z]
}

/// (n+1)/(2π)·cosⁿα for cos α > 0, else 0.
pub fn phong_lobe_pdf(cos_alpha: f64, n: f64) -> f64 {
    if cos_alpha > 0.0 {
        (n + 1.0) / TAU * cos_alpha.powf(n)
    } else {
        0.0
    }
}

/// u₀ = cos^{n+1}α.
pub fn phong_lobe_inverse(w: D3, n: f64) -> D2 {
    [w[2].max(0.0).powf(n + 1.0), azimuth(w[0], w[1])]
}

// ---------------------------------------------------------------------------------------------
// Planar triangle and tent

/// Heitz 2019's low-distortion map: barycentrics (b₀, b₁, b₂).
pub fn uniform_triangle(u: D2) -> D3 {
    let (b0, b1);
    if u[0] < u[1] {
        b0 = u[0] / 2.0;
        b1 = u[1] - b0;
    } else {
        b1 = u[1] / 2.0;
        b0 = u[0] - b1;
    }
    [b0, b1, 1.0 - b0 - b1]
}

pub fn uniform_triangle_inverse(b: D3) -> D2 {
    if b[0] > b[1] {
        [b[0] + b[1], 2.0 * b[1]]
    } else {
        [2.0 * b[0], b[0] + b[1]]
    }
}

/// Tent on [−1, 1]: each half by inversion of its cdf.
pub fn tent(u: f64) -> f64 {
    if u < 0.5 {
        (2.0 * u).sqrt() - 1.0
    } else {
        1.0 - (2.0 - 2.0 * u).sqrt()
    }
}

pub fn tent_pdf(x: f64) -> f64 {
    (1.0 - x.abs()).max(0.0)
}

pub fn tent_inverse(x: f64) -> f64 {
    if x < 0.0 {
        (1.0 + x) * (1.0 + x) / 2.0
    } else {
        1.0 - (1.0 - x) * (1.0 - x) / 2.0
    }
}

// ---------------------------------------------------------------------------------------------
// Orthonormal basis

/// Duff et al. 2017: the two tangents of unit normal n.
pub fn duff_frame(n: D3) -> (D3, D3) {
    let s = 1.0f64.copysign(n[2]);
    let a = -1.0 / (s + n[2]);
    let b = n[0] * n[1] * a;
    (
        [1.0 + s * n[0] * n[0] * a, s * b, -s * n[0]],
        [b, s + n[1] * n[1] * a, -n[1]],
    )
}

// ---------------------------------------------------------------------------------------------
// Spherical triangle (Arvo 1995)

/// The interior angle at vertex `a` of the spherical triangle of unit vectors a, b, c: the
/// dihedral angle between the planes (a, b) and (a, c), by acos.
fn vertex_angle(a: D3, b: D3, c: D3) -> f64 {
    let n1 = normalize(cross(a, b));
    let n2 = normalize(cross(a, c));
    dot(n1, n2).clamp(-1.0, 1.0).acos()
}

/// Solid angle by Girard's theorem, Ω = α + β + γ − π (acos angles). Fine in f64 for the
/// well-conditioned triangles of the accuracy tests.
pub fn triangle_solid_angle_girard(a: D3, b: D3, c: D3) -> f64 {
    let (a, b, c) = (normalize(a), normalize(b), normalize(c));
    vertex_angle(a, b, c) + vertex_angle(b, c, a) + vertex_angle(c, a, b) - PI
}

/// Solid angle by Van Oosterom–Strackee in f64 on the raw vectors (any size, any winding).
pub fn triangle_solid_angle_vos(a: D3, b: D3, c: D3) -> f64 {
    let (la, lb, lc) = (norm(a), norm(b), norm(c));
    // The triple product from edges keeps its relative precision for small, distant triangles.
    let triple = dot(a, cross(sub(b, a), sub(c, a)));
    let den = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
    2.0 * triple.abs().atan2(den)
}

/// Arvo's map: the unit direction and pdf 1/Ω (Ω by Girard). Arvo's labels are free; like the
/// crate, this puts an arc longer than 154° (cosine below −0.9) at AC, with B opposite it, so
/// that the arc from B to Ĉ never joins nearly opposite points.
pub fn spherical_triangle(u: D2, a: D3, b: D3, c: D3) -> (D3, f64) {
    let (a, b, c) = (normalize(a), normalize(b), normalize(c));
    let (a, b, c) = if dot(a, b) < -0.9 {
        (b, c, a)
    } else if dot(b, c) < -0.9 {
        (c, a, b)
    } else {
        (a, b, c)
    };
    let alpha = vertex_angle(a, b, c);
    let beta = vertex_angle(b, c, a);
    let gamma = vertex_angle(c, a, b);
    let area = alpha + beta + gamma - PI;
    let area_hat = u[0] * area;
    let (s, t) = (area_hat - alpha).sin_cos();
    let uu = t - alpha.cos();
    let vv = s + alpha.sin() * dot(a, b);
    let q = ((vv * t - uu * s) * alpha.cos() - vv) / ((vv * s + uu * t) * alpha.sin());
    let q = q.clamp(-1.0, 1.0);
    let c_perp = normalize(sub(c, scale(a, dot(c, a))));
    let c_hat = add(scale(a, q), scale(c_perp, (1.0 - q * q).max(0.0).sqrt()));
    let z = 1.0 - u[1] * (1.0 - dot(c_hat, b));
    let ch_perp = normalize(sub(c_hat, scale(b, dot(c_hat, b))));
    let w = add(scale(b, z), scale(ch_perp, (1.0 - z * z).max(0.0).sqrt()));
    (w, 1.0 / area)
}

/// Where the ray from the origin along unit `w` meets the plane through `p0` with normal `n`,
/// and the area pdf converted to solid angle there: d²/(|cos θ_l|·area).
pub fn area_pdf_to_solid_angle(w: D3, p0: D3, n: D3, area: f64) -> f64 {
    let nh = normalize(n);
    let dist = dot(p0, nh) / dot(w, nh);
    let cos_l = dot(w, nh).abs();
    dist * dist / (cos_l * area)
}

/// Area sampling of triangle (a, b, c) with Arvo's corners in the plane: the point √u₁ of the
/// way from b to the point u₀ of the way from a to c (the triangle b, a, that point has u₀ of
/// the area, and the density along the segment grows with the distance from b). The unit
/// direction and the converted pdf d²/(cos·A).
pub fn triangle_by_area(u: D2, a: D3, b: D3, c: D3) -> (D3, f64) {
    let on_ac = add(a, scale(sub(c, a), u[0]));
    let p = add(b, scale(sub(on_ac, b), u[1].sqrt()));
    let w = normalize(p);
    let n = cross(sub(b, a), sub(c, a));
    let area = 0.5 * norm(n);
    (w, area_pdf_to_solid_angle(w, a, n, area))
}

/// Barycentrics of the point where the ray along `w` meets the plane of (a, b, c), and the ray
/// parameter (positive in front).
pub fn ray_triangle_barycentrics(w: D3, a: D3, b: D3, c: D3) -> (D3, f64) {
    let n = cross(sub(b, a), sub(c, a));
    let t = dot(a, n) / dot(w, n);
    let p = scale(w, t);
    let nn = dot(n, n);
    let b1 = dot(cross(sub(p, a), sub(c, a)), n) / nn;
    let b2 = dot(cross(sub(b, a), sub(p, a)), n) / nn;
    ([1.0 - b1 - b2, b1, b2], t)
}

/// How far (in radians, approximately) unit `w` lies outside the spherical triangle (a, b, c):
/// the largest violation of the three edge-plane half-spaces, 0 when inside.
pub fn spherical_triangle_outside(w: D3, a: D3, b: D3, c: D3) -> f64 {
    let (a, b, c) = (normalize(a), normalize(b), normalize(c));
    let orient = dot(a, cross(b, c)).signum();
    let mut worst: f64 = 0.0;
    for (p, q) in [(a, b), (b, c), (c, a)] {
        let n = scale(normalize(cross(p, q)), orient);
        worst = worst.max(-dot(w, n));
    }
    worst
}

// ---------------------------------------------------------------------------------------------
// Spherical rectangle (Ureña, Fajardo, King 2013)

/// The rectangle's frame as Ureña sets it up: unit axes and the local coordinates of the corner
/// with z₀ ≤ 0.
pub struct RectFrame {
    pub xh: D3,
    pub yh: D3,
    pub zh: D3,
    pub x0: f64,
    pub y0: f64,
    pub z0: f64,
    pub x1: f64,
    pub y1: f64,
}

pub fn rect_frame(corner: D3, ex: D3, ey: D3) -> RectFrame {
    let xh = normalize(ex);
    let yh = normalize(ey);
    let mut zh = cross(xh, yh);
    let mut z0 = dot(corner, zh);
    if z0 > 0.0 {
        zh = scale(zh, -1.0);
        z0 = -z0;
    }
    let x0 = dot(corner, xh);
    let y0 = dot(corner, yh);
    RectFrame {
        xh,
        yh,
        zh,
        x0,
        y0,
        z0,
        x1: x0 + norm(ex),
        y1: y0 + norm(ey),
    }
}

/// Ureña's solid angle Σγ − 2π from the four edge-plane normals (acos angles).
pub fn rectangle_solid_angle(corner: D3, ex: D3, ey: D3) -> f64 {
    let f = rect_frame(corner, ex, ey);
    urena_angles(&f).4
}

/// (b₀, b₁, k, unused, S) of Ureña's setup.
fn urena_angles(f: &RectFrame) -> (f64, f64, f64, f64, f64) {
    let v00 = [f.x0, f.y0, f.z0];
    let v01 = [f.x0, f.y1, f.z0];
    let v10 = [f.x1, f.y0, f.z0];
    let v11 = [f.x1, f.y1, f.z0];
    let n0 = normalize(cross(v00, v10));
    let n1 = normalize(cross(v10, v11));
    let n2 = normalize(cross(v11, v01));
    let n3 = normalize(cross(v01, v00));
    let g0 = (-dot(n0, n1)).clamp(-1.0, 1.0).acos();
    let g1 = (-dot(n1, n2)).clamp(-1.0, 1.0).acos();
    let g2 = (-dot(n2, n3)).clamp(-1.0, 1.0).acos();
    let g3 = (-dot(n3, n0)).clamp(-1.0, 1.0).acos();
    let k = TAU - g2 - g3;
    let s = g0 + g1 - k;
    (n0[2], n2[2], k, 0.0, s)
}

/// Ureña's map: the point on the rectangle (relative to the shading point) and pdf 1/S.
pub fn spherical_rectangle(u: D2, corner: D3, ex: D3, ey: D3) -> (D3, f64) {
    let f = rect_frame(corner, ex, ey);
    let (b0, b1, k, _, s) = urena_angles(&f);
    let au = u[0] * s + k;
    let fu = (au.cos() * b0 - b1) / au.sin();
    let cu = (fu.signum() / (fu * fu + b0 * b0).sqrt()).clamp(-1.0, 1.0);
    let xu = (-(cu * f.z0) / (1.0 - cu * cu).sqrt()).clamp(f.x0, f.x1);
    let d = (xu * xu + f.z0 * f.z0).sqrt();
    let h0 = f.y0 / (d * d + f.y0 * f.y0).sqrt();
    let h1 = f.y1 / (d * d + f.y1 * f.y1).sqrt();
    let hv = h0 + u[1] * (h1 - h0);
    let hv2 = hv * hv;
    let yv = if hv2 < 1.0 - 1e-12 {
        hv * d / (1.0 - hv2).sqrt()
    } else {
        f.y1
    };
    let p = add(add(scale(f.xh, xu), scale(f.yh, yv)), scale(f.zh, f.z0));
    (p, 1.0 / s)
}

/// Area sampling of the rectangle: p = corner + u₀ex + u₁ey, and the converted pdf.
pub fn rectangle_by_area(u: D2, corner: D3, ex: D3, ey: D3) -> (D3, f64) {
    let p = add(add(corner, scale(ex, u[0])), scale(ey, u[1]));
    let n = cross(ex, ey);
    let w = normalize(p);
    (p, area_pdf_to_solid_angle(w, corner, n, norm(n)))
}

/// The rectangle coordinates (s, t) of point p: p = corner + s·ex + t·ey (+ an offset along the
/// normal, returned third, in units of length).
pub fn rect_coords(p: D3, corner: D3, ex: D3, ey: D3) -> D3 {
    let d = sub(p, corner);
    let n = normalize(cross(ex, ey));
    [
        dot(d, ex) / dot(ex, ex),
        dot(d, ey) / dot(ey, ey),
        dot(d, n),
    ]
}

/// Sanity self-test of the references: used by `warp::accuracy` so a broken reference cannot pass
/// silently (each reference against an independent fact).
pub fn self_check() -> Result<(), String> {
    let mut err = Vec::new();
    // Concentric (Shirley and Chiu 1997): u = (0, 0) is a = b = −1, so r = 1 and φ = 5π/4;
    // u = (0, ½) is a = −1, b = 0, so r = 1 and φ = π.
    let p = concentric_disk([0.0, 0.0]);
    if dist2(p, [-FRAC_PI_4.cos(), -FRAC_PI_4.sin()]) > 1e-15 {
        err.push(format!("concentric(0,0) = {p:?}"));
    }
    let p = concentric_disk([0.0, 0.5]);
    if dist2(p, [-1.0, 0.0]) > 1e-15 {
        err.push(format!("concentric(0,½) = {p:?}"));
    }
    // Concentric inverse undoes the map.
    let mut rng = TestRng::new(99);
    for _ in 0..1000 {
        let u = d2(rng.u2().to_array());
        let back = concentric_disk_inverse(concentric_disk(u));
        if dist2(back, u) > 1e-12 {
            err.push(format!("concentric inverse at {u:?}: {back:?}"));
            break;
        }
    }
    // Girard and VOS agree, and the octant has Ω = π/2.
    let o = triangle_solid_angle_girard([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]);
    if (o - FRAC_PI_2).abs() > 1e-14 {
        err.push(format!("octant Ω = {o}"));
    }
    for _ in 0..100 {
        let (a, b, c) = (rng.unit_vector(), rng.unit_vector(), rng.unit_vector());
        let (g, v) = (
            triangle_solid_angle_girard(a, b, c),
            triangle_solid_angle_vos(a, b, c),
        );
        if g > 1e-3 && rel_err(g, v) > 1e-9 {
            err.push(format!("Girard {g} vs VOS {v}"));
            break;
        }
    }
    // Arvo's map at u = (1, 0) gives B, and at (1, 1) gives C.
    let (a, b, c) = ([1.0, 0.2, 0.3], [0.1, 1.0, 0.2], [0.2, 0.1, 1.0]);
    let (w, _) = spherical_triangle([1.0, 0.0], a, b, c);
    if dist3(w, normalize(b)) > 1e-12 {
        err.push(format!("Arvo (1,0) = {w:?}"));
    }
    let (w, _) = spherical_triangle([1.0, 1.0], a, b, c);
    if dist3(w, normalize(c)) > 1e-12 {
        err.push(format!("Arvo (1,1) = {w:?}"));
    }
    // Ureña's solid angle equals two VOS triangles, and u = (0,0) / (1,1) give the corners.
    let (corner, ex, ey) = ([-0.3, -0.2, -1.0], [1.0, 0.0, 0.0], [0.0, 0.7, 0.0]);
    let s = rectangle_solid_angle(corner, ex, ey);
    let (c1, c2, c3) = (add(corner, ex), add(add(corner, ex), ey), add(corner, ey));
    let v = triangle_solid_angle_vos(corner, c1, c2) + triangle_solid_angle_vos(corner, c2, c3);
    if rel_err(s, v) > 1e-12 {
        err.push(format!("rectangle Ω {s} vs VOS {v}"));
    }
    let (p, _) = spherical_rectangle([0.0, 0.0], corner, ex, ey);
    if dist3(p, corner) > 1e-12 {
        err.push(format!("Ureña (0,0) = {p:?}"));
    }
    let (p, _) = spherical_rectangle([1.0, 1.0], corner, ex, ey);
    if dist3(p, c2) > 1e-12 {
        err.push(format!("Ureña (1,1) = {p:?}"));
    }
    // Duff: orthonormal.
    let (t, b) = duff_frame(normalize([0.3, -0.2, -0.9]));
    if (norm(t) - 1.0).abs() > 1e-14 || dot(t, b).abs() > 1e-14 {
        err.push("Duff frame".into());
    }
    if err.is_empty() {
        Ok(())
    } else {
        Err(err.join("\n"))
    }
}

// ---------------------------------------------------------------------------------------------
// Test geometry

/// An equilateral triangle of side `side` centred at `centre`, in the plane with normal `nrm`.
pub fn equilateral(centre: D3, nrm: D3, side: f64) -> (D3, D3, D3) {
    let (t, b) = duff_frame(normalize(nrm));
    let r = side / 3f64.sqrt();
    let v = |k: f64| {
        let ang = k * TAU / 3.0 + 0.3;
        add(
            centre,
            add(scale(t, r * ang.cos()), scale(b, r * ang.sin())),
        )
    };
    (v(0.0), v(1.0), v(2.0))
}

/// Side of an equilateral triangle facing the origin from distance `d` with solid angle ≈ `omega`
/// (small-angle approximation).
pub fn side_for(omega: f64, d: f64) -> f64 {
    (4.0 * omega * d * d / 3f64.sqrt()).sqrt()
}

/// The triangle of three unit-circle points at height z (Ω → 2π as z → 0).
pub fn ring(z: f64) -> (D3, D3, D3) {
    let v = |k: f64| {
        let ang = k * TAU / 3.0;
        [ang.cos(), ang.sin(), z]
    };
    (v(0.0), v(1.0), v(2.0))
}

/// A rectangle (corner, ex, ey) centred at `centre`, in the plane with normal `nrm`, sides `sx`
/// and `sy`, rotated by `rot` in its plane.
pub fn centred_rectangle(centre: D3, nrm: D3, sx: f64, sy: f64, rot: f64) -> (D3, D3, D3) {
    let (t, b) = duff_frame(normalize(nrm));
    let ex = add(scale(t, rot.cos()), scale(b, rot.sin()));
    let ey = add(scale(t, -rot.sin()), scale(b, rot.cos()));
    let (ex, ey) = (scale(ex, sx), scale(ey, sy));
    let corner = sub(centre, add(scale(ex, 0.5), scale(ey, 0.5)));
    (corner, ex, ey)
}

// ---------------------------------------------------------------------------------------------
// Hard cases: one named test per case, which collects every sub-failure

/// One hard case as its own `#[test]`: `$what` states what the case requires and heads the
/// failure message; the body returns all of the case's sub-failures at once.
macro_rules! hard_case {
    ($name:ident, $what:literal, $body:expr $(,)?) => {
        #[test]
        fn $name() {
            let body: fn() -> Result<(), String> = $body;
            if let Err(e) = body() {
                panic!("{}:\n    {}", $what, e);
            }
        }
    };
}
pub(crate) use hard_case;

/// `Ok` where `cond` holds, else the message.
pub fn check(cond: bool, msg: impl FnOnce() -> String) -> Result<(), String> {
    if cond { Ok(()) } else { Err(msg()) }
}

/// Runs every (name, result) and collects the failures.
pub fn collect(results: impl IntoIterator<Item = Result<(), String>>) -> Result<(), String> {
    let errs: Vec<String> = results.into_iter().filter_map(Result::err).collect();
    match errs.len() {
        0 => Ok(()),
        n if n <= 40 => Err(errs.join("\n    ")),
        n => Err(format!(
            "{}\n    … and {} more",
            errs[..12].join("\n    "),
            n - 12
        )),
    }
}

// ---------------------------------------------------------------------------------------------
// The registry's warps paired with their references

/// How an inverse's error is measured: as a distance, as the larger coordinate error, or as the
/// larger with u₁ an azimuth compared on the circle. Near the pole the azimuth of an f32
/// direction is ill-conditioned in any implementation, so `off_axis_only` compares it only where
/// the direction is off the axis by more than 1e-3 (then atan2's conditioning costs at most
/// ~1e-4·ulp-level error).
#[derive(Clone, Copy)]
pub enum Metric {
    Distance,
    Max,
    Azimuth { off_axis_only: bool },
}

/// A registered warp's independent f64 reference from this file, forward and inverse, at the
/// warp's parameters, with the measure of its inverse's error. The inverse is `None` where an
/// f32 input alone moves u by more than the bound: a Phong lobe sharper than n = 20, whose u₀
/// moves by (n + 1)·ulp(cos α) near its axis (3e-5 at n = 500; its round trip is checked in
/// `warp::roundtrip`).
pub struct Reference {
    pub forward: Box<dyn Fn(D2) -> D3>,
    pub inverse: Option<Box<dyn Fn(D3) -> D2>>,
    pub metric: Metric,
}

/// The pairing of the registry's warps with their references; `None` for the samplers whose
/// references are tested on their own (the spherical polygons, in `warp::accuracy`) or that have
/// no inverse. A new warp's reference is its functions above and its arm here.
pub fn reference(s: Sampler) -> Option<Reference> {
    let r = |forward: Box<dyn Fn(D2) -> D3>, inverse: Box<dyn Fn(D3) -> D2>, metric| {
        Some(Reference {
            forward,
            inverse: Some(inverse),
            metric,
        })
    };
    let planar = |p: D2| [p[0], p[1], 0.0];
    let xy = |w: D3| [w[0], w[1]];
    let azimuth = Metric::Azimuth {
        off_axis_only: true,
    };
    match s {
        Sampler::ConcentricDisk(_) => r(
            Box::new(move |u| planar(concentric_disk(u))),
            Box::new(move |p| concentric_disk_inverse(xy(p))),
            Metric::Distance,
        ),
        Sampler::PolarDisk(_) => r(
            Box::new(move |u| planar(polar_disk(u))),
            Box::new(move |p| polar_disk_inverse(xy(p))),
            Metric::Azimuth {
                off_axis_only: false,
            },
        ),
        Sampler::UniformHemisphere(_) => r(
            Box::new(uniform_hemisphere),
            Box::new(uniform_hemisphere_inverse),
            azimuth,
        ),
        Sampler::CosineHemisphere(_) => r(
            Box::new(cosine_hemisphere),
            Box::new(cosine_hemisphere_inverse),
            Metric::Max,
        ),
        Sampler::UniformSphere(_) => r(
            Box::new(uniform_sphere),
            Box::new(uniform_sphere_inverse),
            azimuth,
        ),
        Sampler::UniformCone(c) => {
            let h = c.h as f64;
            r(
                Box::new(move |u| uniform_cone(u, h)),
                Box::new(move |w| uniform_cone_inverse(w, h)),
                azimuth,
            )
        }
        Sampler::PhongLobe(l) => {
            let n = l.n as f64;
            let inverse: Box<dyn Fn(D3) -> D2> = Box::new(move |w| phong_lobe_inverse(w, n));
            Some(Reference {
                forward: Box::new(move |u| phong_lobe(u, n)),
                inverse: (n <= 20.0).then_some(inverse),
                metric: azimuth,
            })
        }
        Sampler::UniformTriangle(_) => r(
            Box::new(uniform_triangle),
            Box::new(uniform_triangle_inverse),
            Metric::Distance,
        ),
        Sampler::Tent(_) => r(
            Box::new(|u| [tent(u[0]), tent(u[1]), 0.0]),
            Box::new(|x| [tent_inverse(x[0]), tent_inverse(x[1])]),
            Metric::Distance,
        ),
        _ => None,
    }
}

// ---------------------------------------------------------------------------------------------
// Lane equality in both packet widths

/// Checks `x8` and `x16` against their scalar twin `scalar` with `check_lanes` and
/// `check_lanes16`, and records each width's first mismatch under `name`.
pub fn check_both<S: Scalar, T: Scalar>(
    failures: &mut Vec<String>,
    name: &str,
    inputs: &[S],
    x8: impl FnMut(S::X8) -> T::X8,
    x16: impl FnMut(S::X16) -> T::X16,
    scalar: impl Fn(S) -> T,
) {
    if let Err(m) = check_lanes(inputs, x8, &scalar) {
        failures.push(format!("{name} (x8): {m}"));
    }
    if let Err(m) = check_lanes16(inputs, x16, &scalar) {
        failures.push(format!("{name} (x16): {m}"));
    }
}

/// A function checked in both packet widths against its scalar form, written once:
///
/// - `lanes!(failures, "name", &inputs, path::to::generic_fn)`;
/// - `lanes!(failures, "name", &inputs, |pattern: Type| body)`, where `Type` and `body` name the
///   width through `L` (the float lane), `V2`, `V3` and `U` (the u32 lane), which the macro binds
///   to `f32`, `Vec2`, `Vec3`, `u32` for the scalar form and to each packet width in turn.
macro_rules! lanes {
    ($failures:expr, $name:expr, $inputs:expr, $func:path) => {
        $crate::common::check_both($failures, $name, $inputs, $func, $func, $func)
    };
    ($failures:expr, $name:expr, $inputs:expr, |$p:tt : $t:ty| $body:expr) => {{
        let scalar = lanes!(@width f32, u32, glam::Vec2, glam::Vec3, |$p: $t| $body);
        let x8 = lanes!(@width mcsample::x8::F32x8, mcsample::x8::U32x8, mcsample::x8::Vec2x8,
            mcsample::x8::Vec3x8, |$p: $t| $body);
        let x16 = lanes!(@width mcsample::x16::F32x16, mcsample::x16::U32x16,
            mcsample::x16::Vec2x16, mcsample::x16::Vec3x16, |$p: $t| $body);
        $crate::common::check_both($failures, $name, $inputs, x8, x16, scalar)
    }};
    // The closure with L, U, V2 and V3 naming one width's types.
    (@width $l:ty, $u:ty, $v2:ty, $v3:ty, |$p:tt : $t:ty| $body:expr) => {{
        #[allow(dead_code)]
        type L = $l;
        #[allow(dead_code)]
        type U = $u;
        #[allow(dead_code)]
        type V2 = $v2;
        #[allow(dead_code)]
        type V3 = $v3;
        |$p: $t| $body
    }};
}
pub(crate) use lanes;
