//! Convex polygons of up to eight vertices sampled by projected solid angle (Peters, "BRDF
//! Importance Sampling for Polygonal Lights", ACM TOG 40(4), 2021), and by solid angle through
//! their fan of spherical triangles where the projected form cancels.
//!
//! Facts checked: P is Lambert's irradiance ½ Σ Θᵢ (n·Γᵢ) of the polygon clipped to the
//! receiver's horizon; sampling with pdf n·ω / P makes every single-sample estimate of the
//! irradiance exact; three vertices give the projected triangle bit for bit where the projected
//! map samples; the winding comes from the whole polygon; a small polygon is
//! sampled uniformly in solid angle, pdf 1/Ω, and a tiny one, whose fan has triangles below the
//! spherical threshold, by area with the whole polygon's area density; lane i of eight is the
//! scalar call; polygons that are not convex, or have a vertex that is not finite or far out in
//! f32's range, keep the bad-input rules.

use glam::{DVec3, Vec2, Vec3};
use mcsample::reference::polygon_irradiance;
use mcsample::warp::{
    PROJECTED_MIN_SR, ProjectedPolygon, ProjectedTriangle, projected_polygon, projected_polygon_pdf,
};
use mcsample::x8::{Vec2x8, Vec3x8};

use crate::common::TestRng;

fn random_dir(rng: &mut TestRng) -> Vec3 {
    loop {
        let v = Vec3::new(rng.u01(), rng.u01(), rng.u01()) * 2.0 - Vec3::ONE;
        if v.length_squared() < 1.0 && v.length_squared() > 1e-3 {
            return v.normalize();
        }
    }
}

/// A receiver's normal and a convex N-gon 1 to 5 units away, up to 1 across: N points of an
/// ellipse at increasing angles, so convex and coplanar up to the rounding of its f32 vertices
/// (the sampler's polygon is the spherical one through them either way).
fn configuration<const N: usize>(rng: &mut TestRng) -> (Vec3, [Vec3; N]) {
    let n = random_dir(rng);
    let c = random_dir(rng) * (1.0 + 4.0 * rng.u01());
    let ex = random_dir(rng);
    let ey = ex.cross(random_dir(rng)).normalize();
    let (ex, ey) = (ex * (0.05 + 0.5 * rng.u01()), ey * (0.05 + 0.5 * rng.u01()));
    // Angles spread over the turn, each jittered within its own N-th of it.
    let phase = rng.u01();
    let v = core::array::from_fn(|k| {
        let a = core::f32::consts::TAU * (k as f32 + 0.1 + 0.8 * rng.u01() + phase) / N as f32;
        c + ex * a.cos() + ey * a.sin()
    });
    (n, v)
}

/// N points c + ex·cos a + ey·sin a at a = 2πk/N: a regular N-gon's affine image, convex, and
/// in the plane of ex and ey up to the rounding of its f32 vertices.
fn ring<const N: usize>(c: Vec3, ex: Vec3, ey: Vec3) -> [Vec3; N] {
    core::array::from_fn(|k| {
        let a = core::f32::consts::TAU * k as f32 / N as f32;
        c + ex * a.cos() + ey * a.sin()
    })
}

fn irradiance(n: Vec3, v: &[Vec3]) -> f64 {
    let v: Vec<[f64; 3]> = v.iter().map(|x| x.as_dvec3().to_array()).collect();
    polygon_irradiance(n.as_dvec3().to_array(), &v)
}

/// `v` for the normal `n` takes the projected map, P is Lambert's within 1e-6, and each of
/// `samples` samples is kept with the pdf function's pdf and estimates P within 1e-5.
fn assert_exact<const N: usize>(name: &str, v: [Vec3; N], n: Vec3, samples: usize, seed: u64) {
    let t = ProjectedPolygon::new(v, n);
    assert!(!t.by_solid_angle(), "{name}: falls back");
    let want = irradiance(n, &v);
    let p = t.projected_area() as f64;
    assert!(
        (p - want).abs() < 1e-6 * want,
        "{name}: P {p} against {want}"
    );
    let mut rng = TestRng::new(seed);
    for _ in 0..samples {
        let (w, pdf) = t.sample(rng.u2());
        assert!(w.is_finite() && pdf > 0.0, "{name}: {w} {pdf}");
        assert_eq!(t.pdf(w).to_bits(), pdf.to_bits(), "{name}: {w}");
        let est = n.as_dvec3().normalize().dot(w.as_dvec3()) / pdf as f64;
        assert!(
            (est - want).abs() < 1e-5 * want,
            "{name}: {est} against {want}"
        );
    }
}

/// Random N-gons, where they take the projected map: P against Lambert's formula, and every
/// sample's estimate against P.
fn exact_for<const N: usize>(seed: u64, configurations: usize) {
    let mut rng = TestRng::new(seed);
    let (mut worst_p, mut worst_est) = (0.0f64, 0.0f64);
    let (mut projected, mut straddling, mut decentral) = (0, 0, 0);
    for _ in 0..configurations {
        let (n, v) = configuration::<N>(&mut rng);
        let t = ProjectedPolygon::new(v, n);
        if t.by_solid_angle() {
            continue;
        }
        projected += 1;
        straddling += v.iter().any(|x| n.dot(*x) < 0.0) as usize;
        decentral += !t.central() as usize;
        let want = irradiance(n, &v);
        worst_p = worst_p.max((t.projected_area() as f64 - want).abs() / want);
        for _ in 0..4 {
            let (w, pdf) = t.sample(rng.u2());
            assert!(pdf > 0.0, "a sample of {v:?} for {n} dropped");
            let est = n.as_dvec3().normalize().dot(w.as_dvec3()) / pdf as f64;
            worst_est = worst_est.max((est - want).abs() / want);
        }
    }
    println!(
        "{N}-gon: {projected} projected ({straddling} across the horizon, {decentral} with the normal outside): P within {worst_p:e}, estimates within {worst_est:e}"
    );
    assert!(
        projected > configurations / 3 && straddling > configurations / 40,
        "{projected} {straddling}"
    );
    assert!(decentral > configurations / 4, "{decentral}");
    assert!(
        worst_p < 1e-6,
        "{N}-gon: P off Lambert's formula by {worst_p:e}"
    );
    assert!(
        worst_est < 1e-5,
        "{N}-gon: a single-sample estimate off by {worst_est:e}"
    );
}

#[test]
fn every_sample_of_a_lambertian_receiver_estimates_its_irradiance_exactly() {
    exact_for::<5>(3, 40_000);
    exact_for::<6>(4, 40_000);
    exact_for::<8>(5, 40_000);
}

#[test]
fn three_vertices_are_the_projected_triangle() {
    // The same set-up and map for N = 3 with the polygon's sixteen slots as with the
    // triangle's six: every sampled bit agrees where the projected form samples.
    let mut rng = TestRng::new(9);
    let mut compared = 0;
    for _ in 0..20_000 {
        let (n, v) = configuration::<3>(&mut rng);
        let (p, t) = (
            ProjectedPolygon::new(v, n),
            ProjectedTriangle::new(v[0], v[1], v[2], n),
        );
        assert_eq!(p.projected_area().to_bits(), t.projected_area().to_bits());
        assert_eq!(p.by_solid_angle(), t.by_solid_angle());
        if p.by_solid_angle() {
            continue;
        }
        compared += 1;
        let u = rng.u2();
        let ((wp, pp), (wt, pt)) = (p.sample(u), t.sample(u));
        assert_eq!(
            wp.to_array().map(f32::to_bits),
            wt.to_array().map(f32::to_bits)
        );
        assert_eq!(pp.to_bits(), pt.to_bits());
        assert_eq!(p.inverse(wp), t.inverse(wt));
    }
    assert!(compared > 5000, "{compared}");
}

/// Ω of the convex polygon `v` in f64: Van Oosterom–Strackee over its fan.
fn solid_angle(v: &[Vec3]) -> f64 {
    let v: Vec<DVec3> = v.iter().map(|x| x.as_dvec3().normalize()).collect();
    (1..v.len() - 1)
        .map(|i| {
            let (a, b, c) = (v[0], v[i], v[i + 1]);
            let num = a.dot(b.cross(c)).abs();
            let den = 1.0 + a.dot(b) + b.dot(c) + c.dot(a);
            2.0 * num.atan2(den)
        })
        .sum()
}

#[test]
fn a_small_polygon_is_uniform_in_solid_angle_through_its_fan() {
    // P below PROJECTED_MIN_SR: the fan of spherical triangles, each above the spherical
    // triangle's area threshold, gives pdf 1/Ω everywhere on the polygon.
    let c = Vec3::new(0.2, -0.1, 1.0);
    let (ex, ey) = (
        Vec3::new(0.004, 0.001, 0.0),
        Vec3::new(-0.001, 0.003, 0.0005),
    );
    let v: [Vec3; 7] = ring(c, ex, ey);
    let n = Vec3::new(0.6, 0.0, 0.8);
    let t = ProjectedPolygon::new(v, n);
    assert!(t.by_solid_angle() && t.projected_area() < PROJECTED_MIN_SR);
    let omega = solid_angle(&v);
    let mut rng = TestRng::new(2);
    let mut worst = 0.0f64;
    for _ in 0..20_000 {
        let (w, pdf) = t.sample(rng.u2());
        assert!(pdf > 0.0);
        worst = worst.max((pdf as f64 * omega - 1.0).abs());
        // Inside the polygon: on the inner side of each edge's great circle.
        let w = w.as_dvec3();
        let inside = (0..7).all(|k| {
            let (a, b) = (v[k].as_dvec3(), v[(k + 1) % 7].as_dvec3());
            a.cross(b).dot(w) * a.cross(b).dot(c.as_dvec3()) > 0.0
        });
        assert!(inside, "{w} outside");
    }
    assert!(worst < 1e-5, "pdf off 1/Ω by {worst:e}");
    // Off the polygon: 0.
    assert_eq!(t.pdf(-c.normalize()), 0.0);
    assert_eq!(t.pdf((c + ex * 2.0).normalize()), 0.0);
}

#[test]
fn a_tiny_polygon_is_uniform_by_area_through_its_fan() {
    // A heptagon of 5e-6 sr whose outer fan triangles are below the spherical triangle's
    // threshold (1e-6 sr) and inner ones above: every one is sampled by area, chosen by its area, so
    // the pdf is the area density d²/(A·cos θ_l) of the whole heptagon (PBR 4th ed., §4.2.3).
    // Triangles sampled by solid angle beside them would give 1/Ω there, 1e-3 away across
    // this heptagon's tilt. u comes back through the inverse across the fan's diagonals.
    let c = Vec3::new(0.2, -0.1, 1.0);
    // In the plane z = 1, where its f32 vertices are exactly coplanar.
    let (ex, ey) = (
        Vec3::new(0.0015, 0.0004, 0.0),
        Vec3::new(-0.0004, 0.0011, 0.0),
    );
    let v: [Vec3; 7] = ring(c, ex, ey);
    let omega = solid_angle(&v);
    assert!((1e-6..1e-5).contains(&omega), "{omega}");
    let n = Vec3::new(0.6, 0.0, 0.8);
    let t = ProjectedPolygon::new(v, n);
    assert!(t.by_solid_angle());
    // The plane and area of the heptagon in f64, from its fan.
    let d: Vec<DVec3> = v.iter().map(|x| x.as_dvec3()).collect();
    let normal: DVec3 = (1..6).map(|i| (d[i] - d[0]).cross(d[i + 1] - d[0])).sum();
    let area = normal.length() / 2.0;
    let normal = normal.normalize();
    let mut rng = TestRng::new(6);
    let (mut worst, mut worst_back, mut spread) = (0.0f64, 0.0f32, 0.0f64);
    for _ in 0..20_000 {
        let u = rng.u2();
        let (w, pdf) = t.sample(u);
        assert!(pdf > 0.0, "{u} dropped");
        let w = w.as_dvec3();
        let dist = d[0].dot(normal) / w.dot(normal);
        let want = dist * dist / (area * w.dot(normal).abs());
        worst = worst.max((pdf as f64 - want).abs() / want);
        spread = spread.max((want * omega - 1.0).abs());
        if u.y > 1e-2 {
            worst_back = worst_back.max((t.inverse(w.as_vec3()) - u).abs().max_element());
        }
    }
    println!("area pdf within {worst:e} (1/Ω {spread:e} away), u back within {worst_back:e}");
    assert!(worst < 1e-5, "pdf off the area density by {worst:e}");
    assert!(
        spread > 1e-4,
        "the area density is 1/Ω here ({spread:e}): no control"
    );
    assert!(worst_back < 1e-3, "inverse off by {worst_back:e}");
}

#[test]
fn hard_cases_keep_the_contract() {
    // An octagon straddling the horizon, its first vertex exactly on it, and one whose first
    // vertex is the normal's direction: finite samples, the pdf returned equal to the pdf at
    // the sample, P Lambert's, every estimate exact.
    let n = Vec3::Z;
    let straddling: [Vec3; 8] = ring(Vec3::new(0.0, 1.0, 0.0), Vec3::X, Vec3::new(0.0, 0.3, 1.0));
    assert_eq!(straddling[0].z, 0.0);
    let on_normal: [Vec3; 8] = ring(Vec3::new(-0.5, 0.0, 1.0), Vec3::X * 0.5, Vec3::Y * 0.4);
    assert_eq!(on_normal[0], Vec3::Z);
    assert_exact(
        "straddling, a vertex on the horizon",
        straddling,
        n,
        20_000,
        5,
    );
    assert_exact("a vertex on the normal", on_normal, n, 20_000, 5);
}

#[test]
fn lane_i_of_eight_is_the_scalar_call() {
    // Eight different hexagons and normals, one per lane, through the free functions.
    let mut rng = TestRng::new(13);
    for _ in 0..300 {
        let configs: [(Vec3, [Vec3; 6]); 8] =
            core::array::from_fn(|_| configuration::<6>(&mut rng));
        let us: [Vec2; 8] = core::array::from_fn(|_| rng.u2());
        let n8 = Vec3x8::from(configs.map(|c| c.0));
        let v8: [Vec3x8; 6] = core::array::from_fn(|k| Vec3x8::from(configs.map(|c| c.1[k])));
        let (w8, p8) = projected_polygon(Vec2x8::from(us), v8, n8);
        let q8 = projected_polygon_pdf(w8, v8, n8);
        for (i, (n, v)) in configs.iter().enumerate() {
            let (w, p) = projected_polygon(us[i], *v, *n);
            assert_eq!(
                w8.lane(i).to_array().map(f32::to_bits),
                w.to_array().map(f32::to_bits)
            );
            assert_eq!(p8.to_array()[i].to_bits(), p.to_bits());
            assert_eq!(
                q8.to_array()[i].to_bits(),
                projected_polygon_pdf(w, *v, *n).to_bits()
            );
        }
    }
}

#[test]
fn the_winding_comes_from_the_whole_polygon() {
    // A square with a vertex on its first side: v₀, v₁, v₂ are collinear, so the first
    // triangle's determinant is 0. In either winding P is the irradiance and every estimate
    // exact (with the winding taken from that triangle alone, the clockwise one had P = −P and
    // dropped every sample).
    let ccw = [
        Vec3::new(1.0, -1.0, 1.0),
        Vec3::new(0.0, -1.0, 1.0),
        Vec3::new(-1.0, -1.0, 1.0),
        Vec3::new(-1.0, 1.0, 1.0),
        Vec3::new(1.0, 1.0, 1.0),
    ];
    let mut cw = ccw;
    cw.reverse();
    let n = Vec3::new(0.3, 0.1, 0.9).normalize();
    assert_exact("counter-clockwise", ccw, n, 10_000, 8);
    assert_exact("clockwise", cw, n, 10_000, 8);
}

/// The rules that hold for any polygon: eight samples each a unit direction whose pdf is the
/// pdf function's, finite and > 0, with its inverse in [0, 1]², or dropped at +z with pdf 0;
/// lane i of eight the scalar call. Returns how many were kept, and whether it fell back.
fn keeps_the_rules<const N: usize>(
    name: &str,
    v: [Vec3; N],
    n: Vec3,
    us: [Vec2; 8],
) -> (usize, bool) {
    let t = ProjectedPolygon::new(v, n);
    let t8 = ProjectedPolygon::new(v.map(Vec3x8::splat), Vec3x8::splat(n));
    let (w8, p8) = t8.sample(Vec2x8::from(us));
    let b8 = t8.inverse(w8);
    let mut kept = 0;
    for (i, u) in us.into_iter().enumerate() {
        let (x, pdf) = t.sample(u);
        let back = t.inverse(x);
        let ctx = format!("{name} n {n}: u {u} → {x} pdf {pdf:e} back {back}");
        assert!(pdf.is_finite() && pdf >= 0.0, "{ctx}");
        if pdf > 0.0 {
            kept += 1;
            assert!((x.as_dvec3().length() - 1.0).abs() < 1e-6, "{ctx}");
            assert_eq!(pdf.to_bits(), t.pdf(x).to_bits(), "{ctx}");
            assert!(
                back.cmpge(Vec2::ZERO).all() && back.cmple(Vec2::ONE).all(),
                "{ctx}"
            );
        } else {
            assert_eq!(x, Vec3::Z, "{ctx}");
        }
        let bits = |v: Vec3| v.to_array().map(f32::to_bits);
        assert_eq!(bits(w8.lane(i)), bits(x), "{ctx}: lane");
        assert_eq!(p8.to_array()[i].to_bits(), pdf.to_bits(), "{ctx}: lane");
        assert_eq!(
            b8.lane(i).to_array().map(f32::to_bits),
            back.to_array().map(f32::to_bits),
            "{ctx}: lane"
        );
    }
    (kept, t.by_solid_angle())
}

#[test]
fn a_polygon_that_is_not_convex_keeps_the_bad_input_rules() {
    // Outside the contract's density, not its rules: a dart (one reflex vertex), a bow tie (its
    // edges cross), a pentagon folded out of its plane, each for a normal facing it and one
    // across it, large enough for the projected map and small enough for the fan.
    let dart = [
        Vec3::new(-1.0, -1.0, 1.0),
        Vec3::new(0.0, -0.2, 1.0),
        Vec3::new(1.0, -1.0, 1.0),
        Vec3::new(0.0, 1.0, 1.0),
    ];
    let bow_tie = [
        Vec3::new(-1.0, -1.0, 1.0),
        Vec3::new(1.0, 1.0, 1.0),
        Vec3::new(1.0, -1.0, 1.0),
        Vec3::new(-1.0, 1.0, 1.0),
    ];
    let folded = [
        Vec3::new(-1.0, -1.0, 1.0),
        Vec3::new(1.0, -1.0, 1.0),
        Vec3::new(1.0, 1.0, 2.5),
        Vec3::new(0.0, 0.3, 0.4),
        Vec3::new(-1.0, 1.0, 1.0),
    ];
    let scaled = |x: Vec3, s: f32| (x - Vec3::Z) * s + Vec3::Z;
    let mut rng = TestRng::new(21);
    let (mut kept, mut fan, mut projected) = (0, 0, 0);
    for n in [
        Vec3::new(0.1, 0.2, 1.0).normalize(),
        Vec3::new(1.0, 0.0, 0.2).normalize(),
    ] {
        for s in [1.0, 1e-3] {
            let mut tally = |(k, f): (usize, bool)| {
                kept += k;
                fan += f as usize;
                projected += !f as usize;
            };
            let mut us = || core::array::from_fn(|_| rng.u2());
            tally(keeps_the_rules("dart", dart.map(|x| scaled(x, s)), n, us()));
            tally(keeps_the_rules(
                "bow tie",
                bow_tie.map(|x| scaled(x, s)),
                n,
                us(),
            ));
            tally(keeps_the_rules(
                "folded",
                folded.map(|x| scaled(x, s)),
                n,
                us(),
            ));
        }
    }
    println!("{kept} of 96 kept; {projected} polygons projected, {fan} through the fan");
    assert!(
        kept >= 48 && fan >= 3 && projected >= 3,
        "{kept} kept, {fan} fan, {projected} projected"
    );
}

#[test]
fn the_fan_keeps_the_rules_at_the_ends_of_f32() {
    // Two pentagons through the fan by area (the first found by the `bilinear` fuzz target):
    // one with a vertex of NaN and infinities beside one 10⁻³⁹ from the point, which is
    // degenerate, as a triangle with such a vertex is (every sample dropped at +z, pdf 0, not
    // the NaN of its triangle's area); and one 10³⁷ away and 10³¹ across, whose fan areas
    // (10⁶² and up) overflow f32 but not their shares (every sample kept).
    let broken = [
        Vec3::new(6.269303e-39, 0.0, 3.9443045e-31),
        Vec3::new(785.0469, 0.0, 48.564705),
        Vec3::new(777.0353, 1.8332037e-12, 0.5),
        Vec3::new(f32::NEG_INFINITY, f32::NAN, f32::NEG_INFINITY),
        Vec3::new(777.0353, 1.8332037e-12, 0.5),
    ];
    let n = Vec3::splat(0.5);
    let far: [Vec3; 5] = core::array::from_fn(|k| {
        let a = core::f32::consts::TAU * k as f32 / 5.0;
        Vec3::new(1e31 * a.cos(), 2e31 * a.sin(), 3e37)
    });
    let mut rng = TestRng::new(4);
    for _ in 0..50 {
        let us = core::array::from_fn(|_| rng.u2());
        assert_eq!(keeps_the_rules("a NaN vertex", broken, n, us), (0, true));
        assert_eq!(keeps_the_rules("far", far, Vec3::Z, us), (8, true));
    }
}
