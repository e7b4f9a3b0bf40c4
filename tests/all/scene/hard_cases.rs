//! Hard inputs of the scene's lights and BSDFs: a sphere light from on and inside its surface
//! (16), partly below the horizon (20), just outside its cone (21, pbrt-v3 #319) and of
//! sin²θmax = 1e-12 (22, where Mitsuba's f32 pdf is ∞); a triangle light's sample and pdf at
//! 1e-5 and 1 sr (23, pbrt-v4's Girard/VOS mismatch); antipodal and sliver triangles (24, pbrt
//! #211, #134); Phong samples below the horizon (26). One test per case, which collects every
//! sub-failure; the numbers are the crate's hard-case names.

use crate::common::hard_case;
use crate::common::*;
use glam::{DVec3, Vec2, Vec3};
use mcsample::estimate::MeanVar;
use mcsample::scene::{Light, Phong, SphereLight, TriangleLight};
use mcsample::warp::{self};

// ---------------------------------------------------------------------------------------------
// The scene's lights and BSDFs (16, 20–24, 26).

/// Irradiance at the origin (normal +z) from `light` of radiance 1 by light sampling: the mean
/// of Le·max(0, cos θ)/pdf over stratified u, and its standard error.
fn light_sampled_irradiance(light: &Light, n: usize) -> (f64, f64) {
    let mut acc = MeanVar::new();
    let k = (n as f64).sqrt() as usize;
    let prepared = light.at(Vec3::ZERO);
    for i in 0..k {
        for j in 0..k {
            let mut rng = TestRng::new((i * k + j) as u64);
            let u = Vec2::new(
                (i as f32 + rng.u01()) / k as f32,
                (j as f32 + rng.u01()) / k as f32,
            );
            let s = prepared.sample(u);
            let v = if s.pdf > 0.0 {
                s.le.x as f64 * (s.wi.z as f64).max(0.0) / s.pdf as f64
            } else {
                0.0
            };
            acc.push(v);
        }
    }
    (acc.mean(), (acc.variance() / acc.count() as f64).sqrt())
}

hard_case!(
    case_16_sphere_light_with_the_point_on_or_inside_it_is_finite_and_consistent,
    "16: sphere light with the shading point on the sphere (d = r) or inside it: finite and \
     consistent sample and pdf",
    || {
        let mut r = vec![];
        // On the surface (exactly: |c − p| = r = 2) and inside at several depths.
        let lights = [
            (
                SphereLight::new(Vec3::new(0.0, 0.0, 2.0), 2.0, Vec3::ONE),
                "on",
            ),
            (
                SphereLight::new(Vec3::new(0.0, 0.0, 0.5), 2.0, Vec3::ONE),
                "inside",
            ),
            (
                SphereLight::new(Vec3::ZERO, 2.0, Vec3::ONE),
                "at the centre",
            ),
        ];
        for (l, what) in lights {
            let mut kept = 0;
            for u in grid(64) {
                let s = l.sample(Vec3::ZERO, Vec2::from(u));
                r.push(check(
                    s.pdf.is_finite() && s.pdf >= 0.0 && s.dist.is_finite() == (s.pdf > 0.0),
                    || format!("{what}: u={u:?} pdf {} dist {}", s.pdf, s.dist),
                ));
                if s.pdf > 0.0 {
                    kept += 1;
                    let p = l.pdf(Vec3::ZERO, s.wi);
                    r.push(check(p.to_bits() == s.pdf.to_bits(), || {
                        format!("{what}: pdf {p} vs {}", s.pdf)
                    }));
                    // The point reached lies on the sphere.
                    let x = s.wi.as_dvec3() * s.dist as f64 - l.shape.center.as_dvec3();
                    r.push(check((x.length() - 2.0).abs() < 1e-5, || {
                        format!("{what}: |x − c| = {}", x.length())
                    }));
                }
            }
            // Only u₀ = 1 on the surface draws the shading point itself.
            r.push(check(kept >= 64 * 64 - 64, || {
                format!("{what}: only {kept} samples kept")
            }));
        }
        // From inside, the pdf integrates to 1 over the sphere of directions: the mean of 1/pdf
        // over uniform directions is 4π·E[1/(4π pdf)]… checked as E_uniform[pdf]·4π = 1.
        let l = SphereLight::new(Vec3::new(0.3, -0.2, 0.6), 1.0, Vec3::ONE);
        let mut sum = 0.0;
        let g = grid(400);
        for u in &g {
            let w = warp::uniform_sphere(Vec2::from(*u));
            sum += l.pdf(Vec3::ZERO, w) as f64;
        }
        let integral = sum / g.len() as f64 * 4.0 * std::f64::consts::PI;
        r.push(check((integral - 1.0).abs() < 2e-3, || {
            format!("inside: ∫pdf = {integral}")
        }));
        collect(r)
    }
);

hard_case!(
    case_20_sphere_light_below_the_horizon_converges_to_snyders_closed_form,
    "20: sphere light partly below the horizon: the light-sampling estimate converges to the \
     closed form (Snyder; Lagarde and de Rousiers), not to π sin²σ cos θ",
    || {
        let mut r = vec![];
        for (sigma, theta) in [(0.5f64, 1.4f64), (0.3, 1.7), (1.0, 1.2)] {
            let c = Vec3::new(theta.sin() as f32, 0.0, theta.cos() as f32) * 2.0;
            let light = Light::from(SphereLight::new(c, 2.0 * sigma.sin() as f32, Vec3::ONE));
            let (mean, se) = light_sampled_irradiance(&light, 1 << 20);
            let want = mcsample::reference::sphere_irradiance(sigma, theta);
            let naive = std::f64::consts::PI * sigma.sin().powi(2) * theta.cos();
            r.push(check((mean - want).abs() < 4.0 * se + 1e-6, || {
                format!("σ={sigma} θ={theta}: {mean} ± {se} vs closed form {want}")
            }));
            // The control: the unclipped formula is far outside the error bars.
            r.push(check((mean - naive).abs() > 20.0 * se, || {
                format!("σ={sigma} θ={theta}: also agrees with π sin²σ cos θ = {naive}")
            }));
        }
        collect(r)
    }
);

hard_case!(
    case_21_sphere_light_pdf_is_0_just_outside_the_cone,
    "21: sphere light: pdf(p, wi) for a direction just outside the cone is 0 (pbrt-v3 #319)",
    || {
        let mut r = vec![];
        for (c, radius) in [
            (Vec3::new(0.0, 0.0, 4.0), 1.0f32),
            (Vec3::new(3.0, 1.0, 2.0), 0.01),
        ] {
            let l = SphereLight::new(c, radius, Vec3::ONE);
            let d = c.as_dvec3();
            let theta_max = (radius as f64 / d.length()).asin();
            let (t, b) = d.normalize().any_orthonormal_pair();
            for k in 0..32 {
                let phi = k as f64 * std::f64::consts::PI / 16.0;
                let dir = |theta: f64| {
                    (d.normalize() * theta.cos() + (t * phi.cos() + b * phi.sin()) * theta.sin())
                        .as_vec3()
                };
                // 1e-4 of the cone's angle, or 16 ulp where that is finer than f32 directions
                // resolve (the pdf's documented slack is 2 ulp).
                let off = (1e-4 * theta_max).max(16.0 * f32::EPSILON as f64);
                let (out, inn) = (dir(theta_max + off), dir(theta_max - off));
                let (po, pi) = (l.pdf(Vec3::ZERO, out), l.pdf(Vec3::ZERO, inn));
                r.push(check(
                    po == 0.0 && l.hit(Vec3::ZERO, out) == f32::INFINITY,
                    || format!("r={radius}: {off:e} rad outside the cone: pdf {po}"),
                ));
                r.push(check(pi > 0.0, || {
                    format!("r={radius}: {off:e} rad inside the cone: pdf {pi}")
                }));
            }
        }
        collect(r)
    }
);

hard_case!(
    case_22_sphere_light_of_sin2_1e_12_has_a_finite_pdf_of_one_over_pi_s2,
    "22: sphere light with sin²θmax = 1e-12 (f32): sample pdf = pdf(p, wi), finite, within \
     1e-5 of 1/(π·1e-12) (Mitsuba's f32 pdf becomes ∞)",
    || {
        let mut r = vec![];
        let l = SphereLight::new(Vec3::new(0.0, 0.6, 0.8), 1e-6, Vec3::ONE);
        // s² from the f32 centre and radius, in f64.
        let s2 = (1e-6f32 as f64).powi(2) / Vec3::new(0.0, 0.6, 0.8).as_dvec3().length_squared();
        let h = s2 / (1.0 + (1.0 - s2).sqrt());
        let want = 1.0 / (2.0 * std::f64::consts::PI * h);
        let mut distinct = std::collections::HashSet::new();
        for u in grid(100) {
            let s = l.sample(Vec3::ZERO, Vec2::from(u));
            let p = l.pdf(Vec3::ZERO, s.wi);
            distinct.insert(s.wi.to_array().map(f32::to_bits));
            r.push(check(
                s.pdf.is_finite() && s.pdf.to_bits() == p.to_bits(),
                || format!("u={u:?}: sample pdf {} vs pdf {p}", s.pdf),
            ));
            r.push(check(rel_err(s.pdf as f64, want) < 1e-5, || {
                format!("u={u:?}: pdf {} vs 1/(2πh) = {want}", s.pdf)
            }));
        }
        // The cone is resolved, not collapsed onto its axis: the f32 direction grid leaves
        // about 30 distinct directions across it, hundreds over the cap.
        r.push(check(distinct.len() > 200, || {
            format!("only {} distinct directions", distinct.len())
        }));
        collect(r)
    }
);

hard_case!(
    case_23_triangle_light_sample_pdf_equals_pdf_bit_for_bit_at_1e_5_and_1_sr,
    "23: triangle light: the pdf that sample returns and pdf(p, wi) agree bit for bit at 1e-5 sr \
     and at 1 sr (pbrt-v4 samples with Girard's area and evaluates with Van Oosterom–Strackee)",
    || {
        let mut r = vec![];
        for (s, what) in [(2.55e-3f32, "1e-5 sr"), (0.95, "1 sr")] {
            let l = TriangleLight::new(
                Vec3::new(-s, -0.6 * s, 1.0),
                Vec3::new(s, -0.5 * s, 1.0),
                Vec3::new(0.1 * s, s, 1.0),
                Vec3::ONE,
            );
            let omega = 1.0 / l.pdf(Vec3::ZERO, Vec3::Z) as f64;
            r.push(check(
                rel_err(omega, if s < 0.1 { 1e-5 } else { 1.0 }) < 0.2,
                || format!("{what}: Ω = {omega}"),
            ));
            for u in grid(128).into_iter().chain(border()) {
                let smp = l.sample(Vec3::ZERO, Vec2::from(u));
                let p = l.pdf(Vec3::ZERO, smp.wi);
                r.push(check(
                    smp.pdf > 0.0 && smp.pdf.to_bits() == p.to_bits(),
                    || format!("{what}: u={u:?}: sample pdf {} vs pdf {p}", smp.pdf),
                ));
            }
        }
        collect(r)
    }
);

hard_case!(
    case_24_antipodal_and_sliver_spherical_triangles_are_finite_inside_and_consistent,
    "24: spherical triangle with two vertices 179.99° apart seen from p, and a thin sliver (an \
     angle below 1e-4 rad): finite, in the triangle, pdf = pdf(p, wi) (pbrt #211, #134)",
    || {
        let mut r = vec![];
        let a = 179.99f64.to_radians();
        let antipodal = [
            DVec3::new(1.0, 0.0, 0.0),
            DVec3::new(a.cos(), a.sin(), 0.0),
            DVec3::new(0.0, 0.3, 1.0),
        ];
        let sliver = [
            DVec3::new(-1.0, 0.0, 1.0),
            DVec3::new(1.0, 0.0, 1.0),
            DVec3::new(0.0, 5e-5, 1.0),
        ];
        for (v, what) in [(antipodal, "antipodal"), (sliver, "sliver")] {
            let [p0, p1, p2] = v.map(|x| x.as_vec3());
            let l = TriangleLight::new(p0, p1, p2, Vec3::ONE);
            for u in grid(128).into_iter().chain(border()) {
                let s = l.sample(Vec3::ZERO, Vec2::from(u));
                let p = l.pdf(Vec3::ZERO, s.wi);
                r.push(check(
                    s.wi.is_finite() && s.pdf.is_finite() && s.pdf > 0.0,
                    || format!("{what}: u={u:?}: {s:?}"),
                ));
                r.push(check(s.pdf.to_bits() == p.to_bits(), || {
                    format!("{what}: u={u:?}: pdf {} vs {p}", s.pdf)
                }));
                let out = spherical_triangle_outside(
                    s.wi.as_dvec3().to_array(),
                    v[0].to_array(),
                    v[1].to_array(),
                    v[2].to_array(),
                );
                r.push(check(out < 1e-5, || {
                    format!("{what}: u={u:?}: {out:e} rad outside")
                }));
            }
        }
        collect(r)
    }
);

hard_case!(
    case_26_phong_samples_below_the_horizon_have_f_0_and_keep_the_estimator_unbiased,
    "26: Phong BSDF sample below the horizon: f = 0, pdf = pdf(wo, wi), and the estimator \
     stays unbiased",
    || {
        let mut r = vec![];
        // Grazing incidence: much of the lobe about the mirror direction is below the horizon.
        let wo = Vec3::new(0.98, 0.0, 0.198_997_5);
        let b = Phong::new(Vec3::splat(0.2), Vec3::splat(0.7), 30.0);
        let (mut below, mut acc) = (0, MeanVar::new());
        let k = 1000;
        for i in 0..k {
            for j in 0..k {
                let u = Vec2::new((i as f32 + 0.5) / k as f32, (j as f32 + 0.5) / k as f32);
                let s = b.sample(wo, u);
                let p = b.pdf(wo, s.wi);
                if s.wi.z <= 0.0 {
                    below += 1;
                    r.push(check(s.f == Vec3::ZERO && s.pdf > 0.0, || {
                        format!("u={u}: below, f {} pdf {}", s.f, s.pdf)
                    }));
                }
                r.push(check(s.pdf.to_bits() == p.to_bits(), || {
                    format!("u={u}: pdf {} vs {p}", s.pdf)
                }));
                // The albedo estimator f·cos/pdf, with 0 below the horizon.
                let v = if s.pdf > 0.0 {
                    s.f.x as f64 * (s.wi.z as f64).max(0.0) / s.pdf as f64
                } else {
                    0.0
                };
                acc.push(v);
            }
        }
        r.push(check(below > 10_000, || {
            format!("only {below} samples below the horizon")
        }));
        // The albedo by quadrature of f·cos over the hemisphere.
        let n = 3000;
        let mut q = 0.0;
        for i in 0..n {
            let z = (i as f64 + 0.5) / n as f64;
            let rho = (1.0 - z * z).sqrt();
            for j in 0..n {
                let phi = 2.0 * std::f64::consts::PI * (j as f64 + 0.5) / n as f64;
                let wi = DVec3::new(rho * phi.cos(), rho * phi.sin(), z).as_vec3();
                q += b.eval(wo, wi).x as f64 * z;
            }
        }
        let want = q * 2.0 * std::f64::consts::PI / (n * n) as f64;
        // Stratified samples: the error is far below the iid standard error.
        let se = (acc.variance() / acc.count() as f64).sqrt();
        r.push(check((acc.mean() - want).abs() < 4.0 * se, || {
            format!("estimate {} ± {se} vs quadrature {want}", acc.mean())
        }));
        collect(r)
    }
);
