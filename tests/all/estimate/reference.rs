//! The analytic irradiance references against quadrature that shares none of their algebra,
//! including the horizon: spheres at θ = 90° ± σ, polygons straddling the tangent plane and below
//! it. Each has a negative control: the formula without its horizon handling must fail.

use mcsample::reference::{disk_irradiance_on_axis, polygon_irradiance, sphere_irradiance};
use std::f64::consts::{FRAC_PI_2, PI};

/// ∫ₐᵇ g by composite Simpson on n (even) intervals.
fn simpson(a: f64, b: f64, n: usize, g: impl Fn(f64) -> f64) -> f64 {
    let h = (b - a) / n as f64;
    let mut sum = g(a) + g(b);
    for i in 1..n {
        sum += g(a + i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
    }
    sum * h / 3.0
}

/// E of a sphere cap by quadrature in the cap's own frame: over the angle β from the centre
/// direction, with the azimuth integrated exactly. At angle β the cap's circle is the set of
/// directions with n·ω = A − B cos φ, A = cos β cos θ, B = sin β sin θ, whose positive part
/// integrates over φ to 2πA, 0, or A(2π − 2φ₀) + 2B sin φ₀ with cos φ₀ = A/B.
fn sphere_by_quadrature(sigma: f64, theta: f64) -> f64 {
    simpson(0.0, sigma, 200_000, |beta| {
        let a = beta.cos() * theta.cos();
        let b = beta.sin() * theta.sin();
        let ring = if a >= b {
            2.0 * PI * a
        } else if a <= -b {
            0.0
        } else {
            let phi0 = (a / b).acos();
            a * (2.0 * PI - 2.0 * phi0) + 2.0 * b * phi0.sin()
        };
        ring * beta.sin()
    })
}

#[test]
fn sphere_matches_quadrature_across_the_horizon() {
    let mut worst = 0f64;
    let mut control_worst = 0f64;
    for sigma in [0.01, 0.05, 0.3, 0.8, 1.2, 1.5] {
        let h = FRAC_PI_2;
        for theta in [
            0.0,
            0.4,
            h - sigma,
            h - sigma + 1e-3,
            h - 0.5 * sigma,
            h,
            h + 0.5 * sigma,
            h + sigma - 1e-3,
            h + sigma,
            2.9,
        ] {
            let theta: f64 = theta.clamp(0.0, PI);
            let want = sphere_by_quadrature(sigma, theta);
            let got = sphere_irradiance(sigma, theta);
            let scale = PI * sigma.sin().powi(2);
            let e = (got - want).abs() / scale;
            worst = worst.max(e);
            assert!(e < 1e-9, "σ {sigma} θ {theta}: {got} against {want}");
            let naive = (PI * sigma.sin().powi(2) * theta.cos()).max(0.0);
            control_worst = control_worst.max((naive - want).abs() / scale);
        }
    }
    println!(
        "sphere: worst error {worst:e} of π sin²σ; the unclipped form errs by {control_worst:e}"
    );
    assert!(
        control_worst > 1e-2,
        "the control should fail across the horizon"
    );
    assert_eq!(sphere_irradiance(0.3, 3.0), 0.0);
    assert!(sphere_irradiance(f64::NAN, 1.0).is_nan());
    // On the sphere (σ = π/2) with the centre on the normal: the whole hemisphere, π.
    assert!((sphere_irradiance(FRAC_PI_2, 0.0) - PI).abs() < 1e-15);
}

type V3 = [f64; 3];

fn sub(a: V3, b: V3) -> V3 {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// E of a triangle by quadrature over its area: ∫ max(0, n·ω)·|n_l·ω|/d² dA, on an m × m midpoint
/// grid of the square mapped onto the triangle by (s, t) = (u, v(1 − u)), dA = 2A(1 − u) du dv.
fn triangle_by_quadrature(n: V3, a: V3, b: V3, c: V3, m: usize) -> f64 {
    let (e1, e2) = (sub(b, a), sub(c, a));
    let nl = cross(e1, e2);
    let area2 = dot(nl, nl).sqrt();
    let nl = [nl[0] / area2, nl[1] / area2, nl[2] / area2];
    let mut sum = 0.0;
    for i in 0..m {
        let u = (i as f64 + 0.5) / m as f64;
        for j in 0..m {
            let v = (j as f64 + 0.5) / m as f64;
            let (s, t) = (u, v * (1.0 - u));
            let p = [
                a[0] + s * e1[0] + t * e2[0],
                a[1] + s * e1[1] + t * e2[1],
                a[2] + s * e1[2] + t * e2[2],
            ];
            let d2 = dot(p, p);
            let d = d2.sqrt();
            let cos_r = dot(n, p) / d;
            if cos_r > 0.0 {
                sum += cos_r * (dot(nl, p) / d).abs() / d2 * (1.0 - u);
            }
        }
    }
    sum * area2 / (m * m) as f64
}

/// Lambert's formula without the clip to the tangent plane: the negative control.
fn unclipped(n: V3, v: &[V3]) -> f64 {
    let mut sum = 0.0;
    for i in 0..v.len() {
        let (a, b) = (v[i], v[(i + 1) % v.len()]);
        let c = cross(a, b);
        let s = dot(c, c).sqrt();
        sum += s.atan2(dot(a, b)) * dot(n, c) / s;
    }
    0.5 * sum.abs()
}

#[test]
fn polygon_matches_quadrature_above_straddling_and_below() {
    let n = [0.0, 0.0, 1.0];
    // (name, triangle): well above, tilted, one vertex below, two below, all below, and near.
    let cases: [(&str, [V3; 3]); 6] = [
        (
            "above",
            [[-0.5, -0.4, 1.0], [0.6, -0.3, 1.2], [0.1, 0.7, 0.9]],
        ),
        (
            "tilted",
            [[0.5, 0.0, 0.3], [1.5, 0.2, 1.4], [0.8, 1.1, 0.6]],
        ),
        (
            "one below",
            [[-0.8, -0.2, 0.7], [0.9, -0.5, 0.5], [0.2, 0.9, -0.6]],
        ),
        (
            "two below",
            [[-0.8, -0.2, -0.7], [0.9, -0.5, 0.5], [0.2, 0.9, -0.4]],
        ),
        (
            "below",
            [[-0.8, -0.2, -0.7], [0.9, -0.5, -0.5], [0.2, 0.9, -0.4]],
        ),
        (
            "near",
            [[-0.05, -0.04, 0.1], [0.06, -0.03, 0.12], [0.01, 0.07, 0.09]],
        ),
    ];
    let mut control_fails = 0;
    for (name, [a, b, c]) in cases {
        let want = triangle_by_quadrature(n, a, b, c, 1500);
        for winding in [[a, b, c], [c, b, a]] {
            let got = polygon_irradiance(n, &winding);
            assert!(
                (got - want).abs() <= 2e-6 * want.max(1e-3),
                "{name}: {got} against {want}"
            );
        }
        if (unclipped(n, &[a, b, c]) - want).abs() > 1e-3 {
            control_fails += 1;
        }
        println!(
            "{name}: {want:.9} (Lambert {:.9})",
            polygon_irradiance(n, &[a, b, c])
        );
    }
    assert_eq!(polygon_irradiance(n, &cases[4].1), 0.0);
    assert!(
        control_fails >= 3,
        "the unclipped formula should fail on the three horizon cases"
    );

    // A quadrilateral straddling the plane equals the sum of its two triangles.
    let q = [
        [-0.7, -0.6, 0.4],
        [0.8, -0.5, -0.3],
        [0.9, 0.6, 0.5],
        [-0.5, 0.8, 0.9],
    ];
    let halves =
        polygon_irradiance(n, &[q[0], q[1], q[2]]) + polygon_irradiance(n, &[q[0], q[2], q[3]]);
    assert!((polygon_irradiance(n, &q) - halves).abs() < 1e-14);
    assert_eq!(polygon_irradiance(n, &q[..2]), 0.0);
}

#[test]
fn disk_on_axis_matches_quadrature() {
    for (r, h) in [(1.0, 1.0), (0.01, 3.0), (5.0, 0.2), (1.0, 1e-3)] {
        // E = 2π ∫₀ᴿ h² ρ/(ρ² + h²)² dρ: cos at the receiver and at the disk are both h/d.
        let want = 2.0
            * PI
            * simpson(0.0, r, 200_000, |rho| {
                h * h * rho / (rho * rho + h * h).powi(2)
            });
        let got = disk_irradiance_on_axis(r, h);
        assert!(
            (got - want).abs() < 1e-9 * want,
            "R {r} h {h}: {got} against {want}"
        );
    }
    // The disk as a 4096-gon through Lambert's formula: the inscribed polygon's deficit is
    // (2π/4096)²/6 of its solid angle, about 4e-7.
    let (r, h) = (0.7, 0.9);
    let v: Vec<V3> = (0..4096)
        .map(|k| {
            let a = 2.0 * PI * k as f64 / 4096.0;
            [r * a.cos(), r * a.sin(), h]
        })
        .collect();
    let e = polygon_irradiance([0.0, 0.0, 1.0], &v);
    assert!((e - disk_irradiance_on_axis(r, h)).abs() < 1e-6 * e);
    assert_eq!(disk_irradiance_on_axis(1.0, -1.0), 0.0);
    assert_eq!(disk_irradiance_on_axis(0.0, 1.0), 0.0);
}
