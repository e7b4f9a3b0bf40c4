//! Analytic irradiance from lights of radiance 1, in f64: the ground truths that estimators are
//! judged against. `no_std` (libm). Each is checked against brute-force quadrature in
//! `tests/all/estimate/reference.rs`, including the horizon cases.
//!
//! Irradiance here is E = ∫ max(0, n·ω) dω over the directions ω that see the light, for a
//! receiver with normal n; a Lambertian surface of albedo ρ then reflects L = ρE/π.

use libm::{acos, atan2, sin, sqrt};

type V3 = [f64; 3];

fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn length(a: V3) -> f64 {
    sqrt(dot(a, a))
}

/// Irradiance from a sphere of radiance 1 whose angular radius is σ (sin σ = r/d) and whose
/// centre lies at angle θ from the normal.
///
/// - Wholly above the horizon (θ ≤ π/2 − σ): E = π sin²σ cos θ.
/// - Wholly below (θ ≥ π/2 + σ): 0.
/// - Straddling it: Snyder's closed form (1996), as restated by Lagarde and de Rousiers (2014):
///   with x = cot σ, y = −x cot θ and S = sin θ √(1 − y²),
///   E = (cos θ · acos y − x·S)·sin²σ + atan(S/x).
///
/// σ is clamped to [0, π/2] (π/2: the point is on the sphere, which then fills the half-space
/// around its centre direction); θ ∈ [0, π]. NaN gives NaN.
pub fn sphere_irradiance(sigma: f64, theta: f64) -> f64 {
    use core::f64::consts::{FRAC_PI_2, PI};
    if sigma.is_nan() || theta.is_nan() {
        return f64::NAN;
    }
    let sigma = sigma.clamp(0.0, FRAC_PI_2);
    let (s, c) = (sin(sigma), libm::cos(sigma));
    let cos_theta = libm::cos(theta);
    if theta <= FRAC_PI_2 - sigma {
        return PI * s * s * cos_theta;
    }
    if theta >= FRAC_PI_2 + sigma {
        return 0.0;
    }
    let x = c / s;
    let y = (-x * cos_theta / sin(theta)).clamp(-1.0, 1.0);
    let big_s = sin(theta) * sqrt(1.0 - y * y);
    // atan(S/x) written as atan2 so that x = 0 (σ = π/2) gives π/2.
    (cos_theta * acos(y) - x * big_s) * s * s + atan2(big_s, x)
}

/// Irradiance from a planar polygon of radiance 1, by Lambert's formula: E = ½ Σ Θᵢ (n·Γᵢ) over
/// the edges, where Θᵢ is the angle the edge subtends and Γᵢ the unit normal of the plane
/// through it and the point.
///
/// `vertices` are relative to the receiving point, in either winding (the result is the
/// absolute value). The polygon is first clipped to the half-space n·v ≥ 0, as the cosine
/// weighting requires: the part below the tangent plane contributes nothing, and the clip adds
/// edges along the horizon. No allocation: the clipped edges are visited as they are produced.
/// Fewer than three vertices, or all of them below the plane, give 0; NaN gives NaN.
pub fn polygon_irradiance(normal: V3, vertices: &[V3]) -> f64 {
    let n_len = length(normal);
    let n = [normal[0] / n_len, normal[1] / n_len, normal[2] / n_len];
    let count = vertices.len();
    if count < 3 {
        return 0.0;
    }
    // Edge (a, b) of the clipped polygon: its term Θ·(n·Γ), Γ = (a × b)/|a × b|.
    let term = |a: V3, b: V3| {
        let c = cross(a, b);
        let sin_len = length(c);
        if sin_len == 0.0 {
            return 0.0;
        }
        atan2(sin_len, dot(a, b)) * dot(n, c) / sin_len
    };
    // Where the segment from a (above) to b (below), or back, crosses the plane n·v = 0.
    let crossing = |a: V3, b: V3| {
        let (ha, hb) = (dot(n, a), dot(n, b));
        let t = ha / (ha - hb);
        [
            a[0] + t * (b[0] - a[0]),
            a[1] + t * (b[1] - a[1]),
            a[2] + t * (b[2] - a[2]),
        ]
    };
    let mut sum = 0.0;
    // The clipped polygon alternates arcs above the plane with horizon edges from an exit point
    // to the next entry point. The first entry pairs with the last exit.
    let mut first_entry: Option<V3> = None;
    let mut exit: Option<V3> = None;
    for (&a, &b) in vertices.iter().zip(vertices.iter().cycle().skip(1)) {
        let (above_a, above_b) = (dot(n, a) >= 0.0, dot(n, b) >= 0.0);
        match (above_a, above_b) {
            (true, true) => sum += term(a, b),
            (true, false) => {
                let p = crossing(a, b);
                sum += term(a, p);
                exit = Some(p);
            }
            (false, true) => {
                let p = crossing(a, b);
                sum += term(p, b);
                match exit.take() {
                    Some(e) => sum += term(e, p),
                    None => first_entry = Some(p),
                }
            }
            (false, false) => {}
        }
    }
    if let (Some(e), Some(p)) = (exit, first_entry) {
        sum += term(e, p);
    }
    0.5 * sum.abs()
}

/// Irradiance from a disk of radiance 1 and radius R, facing the receiver on its normal axis at
/// height h: E = πR²/(R² + h²). h ≤ 0 (the disk behind or through the point) gives 0; R ≤ 0
/// gives 0; NaN gives NaN.
pub fn disk_irradiance_on_axis(radius: f64, height: f64) -> f64 {
    if radius.is_nan() || height.is_nan() {
        return f64::NAN;
    }
    if radius <= 0.0 || height <= 0.0 {
        return 0.0;
    }
    let r2 = radius * radius;
    core::f64::consts::PI * r2 / (r2 + height * height)
}

/// The solid angle Ω that a disk (centre `center` relative to the point, unit-or-not normal
/// `normal`, radius `radius`) subtends, by its area integral ∫ h/|q|³ dA (h the distance to the
/// disk's plane) in polar coordinates about the centre: along the direction e at angle ψ the
/// radial integral is closed,
///
/// h ∫₀^R ρ dρ / |c + ρe|³ = h R² / (√Q (√(|c|²Q) + |c|² + (c·e)R)),  Q = |c + Re|²,
///
/// with no cancellation for a small disk (and, where |c|² + (c·e)R < 0, in the form
/// h (√(|c|²Q) − |c|² − (c·e)R) / (√Q |c × e|²)), and the periodic integral over ψ is the trapezoid rule,
/// doubled until two agree to 1e-14 (it converges geometrically; at most 2¹⁸ points). A point in
/// the disk's plane, a radius ≤ 0 or a zero normal give 0; NaN gives NaN.
pub fn disk_solid_angle(center: V3, normal: V3, radius: f64) -> f64 {
    use core::f64::consts::TAU;
    if center.iter().chain(normal.iter()).any(|v| v.is_nan()) || radius.is_nan() {
        return f64::NAN;
    }
    let nl = length(normal);
    if radius <= 0.0 || nl == 0.0 {
        return 0.0;
    }
    let n = normal.map(|v| v / nl);
    let h = libm::fabs(dot(center, n));
    if h == 0.0 {
        return 0.0;
    }
    // Any two unit vectors across n.
    let helper = if libm::fabs(n[0]) < 0.6 {
        [1.0, 0.0, 0.0]
    } else {
        [0.0, 1.0, 0.0]
    };
    let t = cross(n, helper);
    let tl = length(t);
    let t = t.map(|v| v / tl);
    let b = cross(n, t);
    let a = dot(center, center);
    let r = radius;
    let f = |psi: f64| {
        let (cs, sn) = (libm::cos(psi), libm::sin(psi));
        let e = [
            t[0] * cs + b[0] * sn,
            t[1] * cs + b[1] * sn,
            t[2] * cs + b[2] * sn,
        ];
        let bdot = dot(center, e);
        let q = r * r + 2.0 * bdot * r + a;
        let (root, lin) = (sqrt(a * q), a + bdot * r);
        if lin >= 0.0 {
            h * r * r / (sqrt(q) * (root + lin))
        } else {
            // Where the rim is nearer than the centre's distance, √(|c|²Q) and |c|² + (c·e)R
            // cancel: multiply through by their difference, which gives R²|c × e|².
            let x = cross(center, e);
            h * (root - lin) / (sqrt(q) * dot(x, x))
        }
    };
    let mut m = 64usize;
    let mut prev = f64::NAN;
    loop {
        let s: f64 = (0..m).map(|i| f(TAU * i as f64 / m as f64)).sum::<f64>() * TAU / m as f64;
        if libm::fabs(s - prev) <= 1e-14 * s || m >= 1 << 18 {
            return s;
        }
        prev = s;
        m *= 2;
    }
}
