//! Property tests (proptest) over u ∈ [0, 1)² and over the warps' parameters: every result lies
//! in its domain, directions are unit, pdfs are positive and finite on the support, and every
//! value is finite.
//!
//! u comes two ways: as 24-bit floats (the generators' output format, multiples of 2⁻²⁴) and as
//! arbitrary f32 in [0, 1) (including values the generators never produce, down to subnormals).
//! Tolerances: |p| ≤ 1 + 1e-6 on disks, | |w| − 1 | ≤ 1e-6 for directions, barycentric sums
//! within 1e-6 of 1, z ≥ 1 − h − 1e-6 in a cone.

use crate::common::*;
use glam::{Vec2, Vec3};
use mcsample::warp::{self, ONE_MINUS_EPS};
use proptest::prelude::*;

const UNIT_TOL: f64 = 1e-6;

fn dv3(v: Vec3) -> D3 {
    [v.x as f64, v.y as f64, v.z as f64]
}

fn len(v: Vec3) -> f64 {
    norm(dv3(v))
}

/// A 24-bit float in [0, 1).
fn u24() -> impl Strategy<Value = f32> {
    (0u32..(1 << 24)).prop_map(|k| k as f32 / 16_777_216.0)
}

/// A 24-bit float in (0, 1): strictly inside, where pdfs must be positive.
fn u24_inner() -> impl Strategy<Value = f32> {
    (1u32..(1 << 24)).prop_map(|k| k as f32 / 16_777_216.0)
}

/// Any f32 in [0, 1), with the edges weighted up.
fn u_any() -> impl Strategy<Value = f32> {
    prop_oneof![
        4 => u24(),
        4 => 0f32..1f32,
        1 => Just(0.0f32),
        1 => Just(ONE_MINUS_EPS),
        1 => (0u32..(1 << 23)).prop_map(f32::from_bits), // subnormal
        1 => (1u32..64).prop_map(|k| 1.0 - k as f32 / 16_777_216.0),
    ]
}

fn uv() -> impl Strategy<Value = Vec2> {
    (u_any(), u_any()).prop_map(|(a, b)| Vec2::new(a, b))
}

fn uv_inner() -> impl Strategy<Value = Vec2> {
    (u24_inner(), u24_inner()).prop_map(|(a, b)| Vec2::new(a, b))
}

/// h ∈ (0, 2]: uniform, log-uniform down to 2⁻⁴⁰, and the ends.
fn cone_h() -> impl Strategy<Value = f32> {
    prop_oneof![
        (1e-6f32..=2.0f32),
        (-40.0f32..1.0).prop_map(|e| 2f32.powf(e)),
        Just(2.0f32),
        Just(f32::MIN_POSITIVE),
    ]
}

/// n ∈ [0, 1e4]: uniform, log-uniform and the integers that renderers use.
fn phong_n() -> impl Strategy<Value = f32> {
    prop_oneof![
        (0.0f32..=1e4),
        (-10.0f32..4.0).prop_map(|e| 10f32.powf(e)),
        (0u32..200).prop_map(|k| k as f32),
        Just(0.0f32),
        Just(1e4f32),
    ]
}

fn check_unit(w: Vec3) -> Result<(), TestCaseError> {
    prop_assert!(w.is_finite(), "non-finite {:?}", w);
    let l = len(w);
    prop_assert!((l - 1.0).abs() <= UNIT_TOL, "|w| = {} for {:?}", l, w);
    Ok(())
}

fn direction() -> impl Strategy<Value = D3> {
    (-1.0f64..=1.0, 0.0f64..std::f64::consts::TAU).prop_map(|(z, phi)| {
        let r = (1.0 - z * z).max(0.0).sqrt();
        [r * phi.cos(), r * phi.sin(), z]
    })
}

/// A triangle (relative to the shading point) with Ω ≥ 1e-6 sr, no vertex closer than 0.05, and
/// no vertex angle of the spherical triangle below 1°.
fn triangle() -> impl Strategy<Value = [Vec3; 3]> {
    (
        direction(),
        direction(),
        direction(),
        (0.05f64..10.0),
        (0.05f64..10.0),
        (0.05f64..10.0),
    )
        .prop_map(|(a, b, c, ra, rb, rc)| {
            [
                Vec3::new((a[0] * ra) as f32, (a[1] * ra) as f32, (a[2] * ra) as f32),
                Vec3::new((b[0] * rb) as f32, (b[1] * rb) as f32, (b[2] * rb) as f32),
                Vec3::new((c[0] * rc) as f32, (c[1] * rc) as f32, (c[2] * rc) as f32),
            ]
        })
        // The crate drops (pdf 0) a triangle whose plane passes within 1e-6 rad of the shading
        // point; keep clear of that documented degenerate zone.
        .prop_filter(
            "solid angle ≥ 1e-6, angles ≥ 1°, plane tilted ≥ 1e-5 rad",
            |t| {
                let (a, b, c) = (dv3(t[0]), dv3(t[1]), dv3(t[2]));
                let omega = triangle_solid_angle_vos(a, b, c);
                let n = normalize(cross(sub(b, a), sub(c, a)));
                let tilt = dot(normalize(a), n).abs();
                omega >= 1e-6 && min_vertex_angle(a, b, c) >= 1f64.to_radians() && tilt >= 1e-5
            },
        )
}

fn min_vertex_angle(a: D3, b: D3, c: D3) -> f64 {
    let (a, b, c) = (normalize(a), normalize(b), normalize(c));
    [(a, b, c), (b, c, a), (c, a, b)]
        .iter()
        .map(|&(p, q, r)| {
            let n1 = normalize(cross(p, q));
            let n2 = normalize(cross(p, r));
            dot(n1, n2).clamp(-1.0, 1.0).acos()
        })
        .fold(f64::INFINITY, f64::min)
}

/// A rectangle (corner, ex, ey) with orthogonal edges of length 0.01–4, whose plane passes at
/// least 1e-3 from the shading point, with Ω ≥ 1e-6 sr.
fn rectangle() -> impl Strategy<Value = [Vec3; 3]> {
    (
        direction(),
        direction(),
        (0.01f64..4.0),
        (0.01f64..4.0),
        (-3.0f64..3.0),
        (-3.0f64..3.0),
        prop_oneof![(-5.0f64..-1e-3), (1e-3f64..5.0)],
    )
        .prop_map(|(n, t, sx, sy, x0, y0, z0)| {
            // The frame of the normal n, rotated by the azimuth of t.
            let (t0, b0) = duff_frame(n);
            let ang = t[1].atan2(t[0]);
            let ex = add(scale(t0, ang.cos()), scale(b0, ang.sin()));
            let ey = cross(n, ex);
            let corner = add(add(scale(ex, x0), scale(ey, y0)), scale(n, z0));
            [
                Vec3::new(corner[0] as f32, corner[1] as f32, corner[2] as f32),
                Vec3::new(
                    (ex[0] * sx) as f32,
                    (ex[1] * sx) as f32,
                    (ex[2] * sx) as f32,
                ),
                Vec3::new(
                    (ey[0] * sy) as f32,
                    (ey[1] * sy) as f32,
                    (ey[2] * sy) as f32,
                ),
            ]
        })
        .prop_filter("solid angle ≥ 1e-6", |r| {
            rectangle_solid_angle(dv3(r[0]), dv3(r[1]), dv3(r[2])) >= 1e-6
        })
}

/// `cases` cases, without a regression file: a failure prints its minimal input and seed.
fn config(cases: u32) -> ProptestConfig {
    ProptestConfig {
        cases,
        failure_persistence: None,
        ..ProptestConfig::default()
    }
}

proptest! {
    #![proptest_config(config(16384))]

    #[test]
    fn disks_stay_in_the_disk(u in uv()) {
        for (name, p) in [("concentric", warp::concentric_disk(u)), ("polar", warp::polar_disk(u))] {
            prop_assert!(p.is_finite(), "{} {:?} → {:?}", name, u, p);
            let r = (p.x as f64).hypot(p.y as f64);
            prop_assert!(r <= 1.0 + 1e-6, "{} {:?} → |p| = {}", name, u, r);
        }
        let back = warp::concentric_disk_inverse(warp::concentric_disk(u));
        prop_assert!(back.is_finite());
        // Every point either map returns, rim included, lies in the pdf's support.
        for p in [warp::concentric_disk(u), warp::polar_disk(u)] {
            prop_assert_eq!(warp::uniform_disk_pdf(p), std::f32::consts::FRAC_1_PI, "{:?}", p);
        }
    }

    #[test]
    fn hemispheres_and_sphere(u in uv()) {
        for w in [warp::uniform_hemisphere(u), warp::cosine_hemisphere(u)] {
            check_unit(w)?;
            prop_assert!(w.z >= 0.0, "{:?} → {:?}", u, w);
        }
        let w = warp::cosine_hemisphere(u);
        let pdf = warp::cosine_hemisphere_pdf(w);
        prop_assert!(pdf >= 0.0 && pdf.is_finite());
        check_unit(warp::uniform_sphere(u))?;
        for back in [
            warp::uniform_hemisphere_inverse(warp::uniform_hemisphere(u)),
            warp::cosine_hemisphere_inverse(w),
            warp::uniform_sphere_inverse(warp::uniform_sphere(u)),
        ] {
            prop_assert!(back.is_finite() && back.x >= 0.0 && back.x <= 1.0 && back.y >= 0.0 && back.y <= 1.0,
                "inverse {:?}", back);
        }
    }

    #[test]
    fn cosine_pdf_positive_inside(u in uv_inner()) {
        // Strictly inside the square the concentric radius is < 1, so z > 0 and the pdf > 0.
        let w = warp::cosine_hemisphere(u);
        prop_assert!(w.z > 0.0, "{:?} → {:?}", u, w);
        let pdf = warp::cosine_hemisphere_pdf(w);
        prop_assert!(pdf > 0.0 && pdf.is_finite());
        prop_assert!(warp::uniform_hemisphere_pdf(warp::uniform_hemisphere(u)) > 0.0);
        prop_assert!(warp::uniform_sphere_pdf(warp::uniform_sphere(u)) > 0.0);
    }

    #[test]
    fn cone_in_its_cap(u in uv(), h in cone_h()) {
        let w = warp::uniform_cone(u, h);
        check_unit(w)?;
        prop_assert!(w.z as f64 >= 1.0 - h as f64 - 1e-6, "h={} {:?} → {:?}", h, u, w);
        prop_assert!(w.z <= 1.0);
        // The sampler's own direction is inside the pdf's support, boundary included.
        let pdf = warp::uniform_cone_pdf(w, h);
        prop_assert!(pdf > 0.0 && pdf.is_finite(), "pdf({:?}, {}) = {}", w, h, pdf);
        let back = warp::uniform_cone_inverse(w, h);
        prop_assert!(back.is_finite() && (0.0..=1.0).contains(&back.x) && (0.0..=1.0).contains(&back.y));
    }

    #[test]
    fn cone_h_helpers(s2 in 0.0f32..=1.0, c in -1.0f32..=1.0) {
        let h = warp::cone_h_from_sin2(s2);
        prop_assert!(h.is_finite() && (0.0..=1.0).contains(&h), "h({}) = {}", s2, h);
        prop_assert!(s2 == 0.0 || h > 0.0);
        let h = warp::cone_h_from_cos(c);
        prop_assert!(h.is_finite() && (0.0..=2.0).contains(&h));
    }

    #[test]
    fn phong_in_the_hemisphere(u in uv(), n in phong_n()) {
        let w = warp::phong_lobe(u, n);
        check_unit(w)?;
        prop_assert!(w.z >= 0.0, "n={} {:?} → {:?}", n, u, w);
        let pdf = warp::phong_lobe_pdf(w, n);
        let peak = (n as f64 + 1.0) / std::f64::consts::TAU;
        prop_assert!(pdf >= 0.0 && pdf as f64 <= peak * (1.0 + 1e-5), "pdf {} peak {}", pdf, peak);
        let back = warp::phong_lobe_inverse(w, n);
        prop_assert!(back.is_finite() && (0.0..=1.0).contains(&back.x) && (0.0..=1.0).contains(&back.y));
    }

    #[test]
    fn phong_pdf_positive_inside(u in uv_inner(), n in phong_n()) {
        // u₀ ≥ 2⁻²⁴ gives cosⁿα = u₀^{n/(n+1)} ≥ 2⁻²⁴: the pdf is positive, and finite.
        let w = warp::phong_lobe(u, n);
        let pdf = warp::phong_lobe_pdf(w, n);
        prop_assert!(pdf > 0.0 && pdf.is_finite(), "n={} {:?} → {:?}, pdf {}", n, u, w, pdf);
    }

    #[test]
    fn triangle_barycentrics(u in uv()) {
        let b = warp::uniform_triangle(u);
        prop_assert!(b.is_finite());
        prop_assert!(b.x >= 0.0 && b.y >= 0.0 && b.z >= 0.0, "{:?} → {:?}", u, b);
        let sum = b.x as f64 + b.y as f64 + b.z as f64;
        prop_assert!((sum - 1.0).abs() <= 1e-6, "{:?} → sum {}", u, sum);
        prop_assert!(warp::uniform_triangle_pdf(b) == 2.0);
        let back = warp::uniform_triangle_inverse(b);
        prop_assert!(back.is_finite() && (0.0..=1.0).contains(&back.x) && (0.0..=1.0).contains(&back.y));
    }

    #[test]
    fn tent_on_its_support(u in u_any()) {
        let x = warp::tent(u);
        prop_assert!((-1.0..=1.0).contains(&x), "tent({}) = {}", u, x);
        let p = warp::tent_pdf(x);
        prop_assert!((0.0..=1.0).contains(&p));
        // From u = 2⁻²⁴ on (the generators' smallest positive value) the sample lies strictly
        // inside (−1, 1): pdf > 0. (A subnormal u rounds to x = −1, pdf 0, which is correct.)
        if u >= 1.0 / 16_777_216.0 {
            prop_assert!(p > 0.0, "tent({}) = {}, pdf {}", u, x, p);
        }
        prop_assert!((0.0..=1.0).contains(&warp::tent_inverse(x)));
    }
}

proptest! {
    #![proptest_config(config(4096))]

    /// 32 samples per random triangle: unit, finite, pdf > 0, inside the triangle within 2e-5 rad;
    /// the pdf function gives the sample's own pdf (bit for bit) for at least 90 % of them (the
    /// others land on an edge, where rounding may put them just outside).
    #[test]
    fn spherical_triangle_samples_inside(t in triangle(), seed in any::<u64>()) {
        let (a, b, c) = (t[0], t[1], t[2]);
        let mut rng = TestRng::new(seed);
        let mut consistent = 0;
        for _ in 0..32 {
            let u = rng.u2();
            let (w, pdf) = warp::spherical_triangle(u, a, b, c);
            check_unit(w)?;
            prop_assert!(pdf > 0.0 && pdf.is_finite(), "u={:?} pdf {}", u, pdf);
            let out = spherical_triangle_outside(dv3(w), dv3(a), dv3(b), dv3(c));
            prop_assert!(out <= 2e-5, "u={:?}: w={:?} is {:e} rad outside", u, w, out);
            let pf = warp::spherical_triangle_pdf(w, a, b, c);
            if pf > 0.0 {
                prop_assert_eq!(pf.to_bits(), pdf.to_bits(), "pdf fn {} vs sample pdf {}", pf, pdf);
                consistent += 1;
            }
            let back = warp::spherical_triangle_inverse(w, a, b, c);
            prop_assert!(back.is_finite() && (0.0..=1.0).contains(&back.x) && (0.0..=1.0).contains(&back.y),
                "inverse {:?}", back);
        }
        prop_assert!(consistent >= 29, "only {}/32 samples have pdf fn > 0", consistent);
    }

    /// 32 samples per random rectangle: a finite point on the rectangle (within 1e-5 of its
    /// (s, t) range), pdf > 0; the pdf function at the point's direction agrees with the sample's
    /// pdf within 1e-5 relative for at least 90 % of them.
    #[test]
    fn spherical_rectangle_samples_inside(r in rectangle(), seed in any::<u64>()) {
        let (corner, ex, ey) = (r[0], r[1], r[2]);
        let mut rng = TestRng::new(seed);
        let mut consistent = 0;
        for _ in 0..32 {
            let u = rng.u2();
            let (p, pdf) = warp::spherical_rectangle(u, corner, ex, ey);
            prop_assert!(p.is_finite(), "u={:?} p={:?}", u, p);
            prop_assert!(pdf > 0.0 && pdf.is_finite(), "u={:?} pdf {}", u, pdf);
            let st = rect_coords(dv3(p), dv3(corner), dv3(ex), dv3(ey));
            prop_assert!(st[0] >= -1e-5 && st[0] <= 1.0 + 1e-5 && st[1] >= -1e-5 && st[1] <= 1.0 + 1e-5,
                "u={:?}: (s, t) = {:?}", u, st);
            // p = corner + s·ex + t·ey rounds relative to the terms' size, not to |p|, which
            // is small when the shading point sits next to the rectangle.
            let scale = len(corner) + len(ex) + len(ey);
            prop_assert!(st[2].abs() <= 1e-5 * scale, "u={:?}: {:e} off the plane", u, st[2]);
            let w = p.normalize();
            check_unit(w)?;
            let pf = warp::spherical_rectangle_pdf(w, corner, ex, ey);
            if pf > 0.0 {
                // The sample's pdf was computed at the crate's own normalisation of p, which may
                // differ from glam's by an ulp; by area the pdf goes as 1/|w·n|³, so allow for
                // that ulp amplified at grazing angles.
                let cos_l = dot(normalize(dv3(w)), normalize(cross(dv3(ex), dv3(ey)))).abs();
                let tol = 1e-5 + 1e-6 / cos_l;
                prop_assert!(rel_err(pf as f64, pdf as f64) <= tol,
                    "pdf fn {} vs sample {} (cos {:e})", pf, pdf, cos_l);
                consistent += 1;
            }
            let back = warp::spherical_rectangle_inverse(p, corner, ex, ey);
            prop_assert!(back.is_finite() && (0.0..=1.0).contains(&back.x) && (0.0..=1.0).contains(&back.y),
                "inverse {:?}", back);
        }
        prop_assert!(consistent >= 29, "only {}/32 samples have pdf fn > 0", consistent);
    }

    /// Any unit direction into a random triangle or rectangle: the pdf functions are finite and
    /// non-negative, and positive well inside.
    #[test]
    fn polygon_pdfs_finite(t in triangle(), r in rectangle(), w in direction()) {
        let wf = Vec3::new(w[0] as f32, w[1] as f32, w[2] as f32);
        let p = warp::spherical_triangle_pdf(wf, t[0], t[1], t[2]);
        prop_assert!(p >= 0.0 && p.is_finite());
        let p = warp::spherical_rectangle_pdf(wf, r[0], r[1], r[2]);
        prop_assert!(p >= 0.0 && p.is_finite());
        // The centroid direction lies well inside: its pdf is positive.
        let cen = ((t[0] + t[1] + t[2]) / 3.0).normalize();
        let inside = spherical_triangle_outside(dv3(cen), dv3(t[0]), dv3(t[1]), dv3(t[2])) == 0.0;
        if inside {
            let p = warp::spherical_triangle_pdf(cen, t[0], t[1], t[2]);
            prop_assert!(p > 0.0 && p.is_finite(), "pdf at centroid {}", p);
        }
        let mid = (r[0] + r[1] * 0.5 + r[2] * 0.5).normalize();
        let p = warp::spherical_rectangle_pdf(mid, r[0], r[1], r[2]);
        prop_assert!(p > 0.0 && p.is_finite(), "pdf at centre {}", p);
    }
}
