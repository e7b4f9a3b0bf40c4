//! Projected-solid-angle sampling of triangles and parallelograms (Peters, "BRDF Importance
//! Sampling for Polygonal Lights", ACM TOG 40(4), 2021).
//!
//! Facts checked: the projected area P is Lambert's irradiance ½ Σ Θᵢ (n·Γᵢ) of the polygon
//! clipped to the receiver's horizon; sampling with pdf n·ω / P makes the cosine estimator of
//! irradiance exact for every sample (zero variance); the map inverts (its backward error in u₁);
//! and lane i of the eight-wide form is the scalar call.

use glam::{DVec2, DVec3, Vec2, Vec3};
use mcsample::point::Point3;
use mcsample::reference::polygon_irradiance;
use mcsample::warp::{ProjectedRectangle, ProjectedTriangle};
use mcsample::x8::{Vec2x8, Vec3x8};

use crate::common::{TestRng, border};

fn random_dir(rng: &mut TestRng) -> Vec3 {
    loop {
        let v = Vec3::new(rng.u01(), rng.u01(), rng.u01()) * 2.0 - Vec3::ONE;
        if v.length_squared() < 1.0 && v.length_squared() > 1e-3 {
            return v.normalize();
        }
    }
}

/// Which polygon: a triangle (a, b, c) or a parallelogram (corner, ex, ey).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Shape {
    Triangle,
    Rectangle,
}

const SHAPES: [Shape; 2] = [Shape::Triangle, Shape::Rectangle];

/// Either projected polygon, at any width.
enum Light<P: Point3> {
    T(ProjectedTriangle<P>),
    R(ProjectedRectangle<P>),
}

macro_rules! each {
    ($self:ident, $l:ident => $e:expr) => {
        match $self {
            Light::T($l) => $e,
            Light::R($l) => $e,
        }
    };
}

impl<P: Point3<Lane = L>, L: mcsample::math::Math> Light<P> {
    fn new(shape: Shape, n: P, v: [P; 3]) -> Self {
        match shape {
            Shape::Triangle => Light::T(ProjectedTriangle::new(v[0], v[1], v[2], n)),
            Shape::Rectangle => Light::R(ProjectedRectangle::new(v[0], v[1], v[2], n)),
        }
    }
    fn by_solid_angle(&self) -> L::Mask {
        each!(self, l => l.by_solid_angle())
    }
    fn central(&self) -> L::Mask {
        each!(self, l => l.central())
    }
    fn projected_area(&self) -> L {
        each!(self, l => l.projected_area())
    }
    fn sample(&self, u: P::Vec2) -> (P, L) {
        each!(self, l => l.sample(u))
    }
    fn pdf(&self, w: P) -> L {
        each!(self, l => l.pdf(w))
    }
    fn inverse(&self, w: P) -> P::Vec2 {
        each!(self, l => l.inverse(w))
    }
}

/// The polygon's vertices in f64 (the parallelogram's four corners, summed exactly).
fn vertices(shape: Shape, v: [Vec3; 3]) -> Vec<DVec3> {
    let v = v.map(|x| x.as_dvec3());
    match shape {
        Shape::Triangle => v.to_vec(),
        Shape::Rectangle => vec![v[0], v[0] + v[1], v[0] + v[1] + v[2], v[0] + v[2]],
    }
}

/// A receiver's normal and a polygon 1 to 5 units away, up to 1 across: central and decentral
/// cases, and polygons straddling the horizon. A parallelogram is a rectangle (the spherical
/// rectangle it falls back to asks for orthogonal edges).
fn configuration(rng: &mut TestRng, shape: Shape) -> (Vec3, [Vec3; 3]) {
    let n = random_dir(rng);
    let c = random_dir(rng) * (1.0 + 4.0 * rng.u01());
    match shape {
        Shape::Triangle => {
            let mut corner = || c + random_dir(rng) * rng.u01();
            (n, [corner(), corner(), corner()])
        }
        Shape::Rectangle => {
            let ex = random_dir(rng);
            let ey = ex.any_orthogonal_vector().normalize();
            let ey = (ey + ex.cross(ey) * (2.0 * rng.u01() - 1.0)).normalize();
            let (ex, ey) = (ex * rng.u01() * 0.7, ey * rng.u01() * 0.7);
            (n, [c - (ex + ey) * 0.5, ex, ey])
        }
    }
}

fn irradiance(n: Vec3, v: &[DVec3]) -> f64 {
    let v: Vec<[f64; 3]> = v.iter().map(|x| x.to_array()).collect();
    polygon_irradiance(n.as_dvec3().to_array(), &v)
}

#[test]
fn every_sample_of_a_lambertian_receiver_estimates_its_irradiance_exactly() {
    for shape in SHAPES {
        let mut rng = TestRng::new(7);
        let (mut worst_p, mut worst_est) = (0.0f64, 0.0f64);
        let (mut projected, mut straddling, mut decentral) = (0, 0, 0);
        for _ in 0..340_000 {
            let (n, v) = configuration(&mut rng, shape);
            let t = Light::new(shape, n, v);
            if t.by_solid_angle() {
                continue;
            }
            projected += 1;
            let corners = vertices(shape, v);
            straddling += corners.iter().any(|x| n.as_dvec3().dot(*x) < 0.0) as usize;
            decentral += !t.central() as usize;
            let want = irradiance(n, &corners);
            let e = (t.projected_area() as f64 - want).abs() / want;
            worst_p = worst_p.max(e);
            for _ in 0..5 {
                let (w, pdf) = t.sample(Vec2::new(rng.u01(), rng.u01()));
                assert!(pdf > 0.0, "a sample of {shape:?} {v:?} for {n} dropped");
                let est = n.as_dvec3().normalize().dot(w.as_dvec3()) / pdf as f64;
                worst_est = worst_est.max((est - want).abs() / want);
            }
        }
        println!(
            "{shape:?}: {projected} projected ({straddling} across the horizon, {decentral} with the normal outside): P within {worst_p:e}, estimates within {worst_est:e}"
        );
        assert!(projected > 100_000 && straddling > 4000 && decentral > 90_000);
        assert!(
            worst_p < 1e-6,
            "{shape:?}: P off Lambert's formula by {worst_p:e}"
        );
        assert!(
            worst_est < 1e-5,
            "{shape:?}: a single-sample estimate off by {worst_est:e}"
        );
    }
}

#[test]
fn a_sampler_of_the_unclipped_triangle_is_not_exact() {
    // The negative control of the zero-variance test: without clipping at the horizon, the part
    // below it counts with negative cosine, and "P" is not the irradiance.
    let n = Vec3::Z;
    let v = [
        Vec3::new(-1.0, 0.2, 1.0),
        Vec3::new(1.0, 0.2, 1.0),
        Vec3::new(0.0, 0.4, -2.0),
    ];
    let want = irradiance(n, &vertices(Shape::Triangle, v));
    let t = ProjectedTriangle::new(v[0], v[1], v[2], n);
    let unclipped: f64 = (0..3)
        .map(|i| {
            let (a, b) = (
                v[i].as_dvec3().normalize(),
                v[(i + 1) % 3].as_dvec3().normalize(),
            );
            let m = a.cross(b);
            0.5 * m.length().atan2(a.dot(b)) * m.normalize().dot(DVec3::Z)
        })
        .sum::<f64>()
        .abs();
    assert!((t.projected_area() as f64 - want).abs() < 1e-5 * want);
    assert!(
        (unclipped - want).abs() > 0.05 * want,
        "{unclipped} vs {want}"
    );
}

#[test]
fn the_map_inverts_to_a_few_ulp_of_u0() {
    // The backward error: u₁ minus the u₁ that maps exactly to the returned direction (the f64
    // instance's inverse), in units of how far u₁ moves when the direction moves by an ulp (the
    // least the f32 output can be off).
    for shape in SHAPES {
        let mut rng = TestRng::new(11);
        let (mut worst_abs, mut flat) = (0.0f64, 0);
        let mut ratios = Vec::new();
        for _ in 0..20_000 {
            let (n, v) = configuration(&mut rng, shape);
            let t = Light::new(shape, n, v);
            let t64 = Light::new(shape, n.as_dvec3(), v.map(|x| x.as_dvec3()));
            if t.by_solid_angle() || t64.by_solid_angle() {
                continue;
            }
            for _ in 0..5 {
                let u = Vec2::new(rng.u01(), rng.u01());
                let (w, pdf) = t.sample(u);
                assert!(pdf > 0.0);
                let w64 = w.as_dvec3();
                let exact = t64.inverse(w64).y;
                let step = f32::EPSILON as f64;
                let ulp = [DVec3::X, DVec3::Y, DVec3::Z]
                    .map(|e| (t64.inverse(w64 + e * step).y - exact).abs())
                    .into_iter()
                    .fold(0.0, f64::max);
                // In the central case u₁ is a fraction of a turn about the normal: 0 and 1 meet.
                let err = (u.y as f64 - exact).abs();
                let err = err.min(1.0 - err);
                worst_abs = worst_abs.max(err);
                if ulp == 0.0 {
                    flat += 1;
                    continue;
                }
                ratios.push(err / ulp);
            }
        }
        ratios.sort_by(f64::total_cmp);
        let q = |f: f64| ratios[((ratios.len() - 1) as f64 * f) as usize];
        let (median, p90, p99) = (q(0.5), q(0.9), q(0.99));
        println!(
            "{shape:?}: u1 backward error in ulp of the output: median {median:.2}, 90 % {p90:.2}, 99 % {p99:.2}, worst {worst_abs:e} absolute ({flat} where an ulp moves nothing)"
        );
        // After the last Newton step on the f64 sectors the solve lands within about an ulp of
        // the output; the tail is the f32 planes of edges whose plane passes near the normal.
        assert!(
            median < 0.5 && p90 < 1.5 && p99 < 3.0,
            "{shape:?}: {median} {p90} {p99}"
        );
        // The f64 instance takes the decentral solve wherever P is known (nearly everywhere),
        // and its steps on F go on until they are below √ε of the distance to the nearer tip.
        let (mut worst, mut solved, mut dropped) = (0.0f64, 0, 0);
        for _ in 0..20_000 {
            let (n, v) = configuration(&mut rng, shape);
            let t = Light::new(shape, n.as_dvec3(), v.map(|x| x.as_dvec3()));
            if t.by_solid_angle() {
                continue;
            }
            for _ in 0..4 {
                solved += 1;
                let u = DVec2::new(rng.u01() as f64, rng.u01() as f64);
                let (w, pdf) = t.sample(u);
                if pdf == 0.0 {
                    dropped += 1;
                    continue;
                }
                worst = worst.max((t.inverse(w).y - u.y).abs());
            }
        }
        println!("{shape:?} f64: {solved} solved ({dropped} dropped), u1 round trip {worst:e}");
        // Every f64 sample lands inside the light, at the u₁ asked for to a few thousand ε.
        assert!(solved > 20_000 && dropped == 0, "{dropped} dropped");
        assert!(
            worst < 1e-11,
            "{shape:?}: f64 u1 round trip off by {worst:e}"
        );
    }
}

#[test]
fn lane_i_of_eight_is_the_scalar_call() {
    for shape in SHAPES {
        let mut rng = TestRng::new(3);
        for _ in 0..500 {
            let cfg: [(Vec3, [Vec3; 3]); 8] =
                core::array::from_fn(|_| configuration(&mut rng, shape));
            let u: [Vec2; 8] = core::array::from_fn(|_| Vec2::new(rng.u01(), rng.u01()));
            let wide = |k: usize| Vec3x8::from(cfg.map(|c| c.1[k]));
            let n8 = Vec3x8::from(cfg.map(|c| c.0));
            let t8 = Light::new(shape, n8, [wide(0), wide(1), wide(2)]);
            let (w8, pdf8) = t8.sample(Vec2x8::from(u));
            let back8 = t8.inverse(w8);
            let pdf_again = t8.pdf(w8);
            for i in 0..8 {
                let (n, v) = cfg[i];
                let t = Light::new(shape, n, v);
                let (w, pdf) = t.sample(u[i]);
                assert_eq!(
                    w.to_array().map(f32::to_bits),
                    w8.lane(i).to_array().map(f32::to_bits)
                );
                assert_eq!(pdf.to_bits(), pdf8.to_array()[i].to_bits());
                assert_eq!(pdf.to_bits(), pdf_again.to_array()[i].to_bits());
                assert_eq!(t.pdf(w).to_bits(), pdf.to_bits());
                let b = t.inverse(w);
                assert_eq!(
                    b.to_array().map(f32::to_bits),
                    back8.lane(i).to_array().map(f32::to_bits)
                );
            }
        }
    }
}

#[test]
fn the_edges_of_the_square_land_on_the_light() {
    // u on the square's boundary maps to the polygon's boundary: the extreme azimuths (u₁ = 0
    // and 1, the tips of the region in the decentral case) and its inner and outer edges.
    // (Where the light crosses the horizon a tip can lie on it, where the density n·ω / P is 0.)
    for shape in SHAPES {
        let mut rng = TestRng::new(5);
        let (mut checked, mut total, mut dropped) = (0, 0, 0);
        for _ in 0..4000 {
            let (n, v) = configuration(&mut rng, shape);
            let t = Light::new(shape, n, v);
            if t.by_solid_angle()
                || vertices(shape, v)
                    .iter()
                    .any(|x| n.as_dvec3().dot(*x) <= 0.0)
            {
                continue;
            }
            checked += 1;
            for [x, y] in border() {
                let (w, pdf) = t.sample(Vec2::new(x, y));
                assert!(w.is_finite() && pdf.is_finite());
                total += 1;
                if pdf == 0.0 {
                    dropped += 1;
                }
            }
        }
        // Open: next to a tip, the point between the two ellipses can land an ulp-scale
        // distance outside an edge whose plane passes near the normal (its ellipse's radius is
        // ill-conditioned there), and is dropped.
        println!("{shape:?}: {dropped} of {total} samples on the square's boundary dropped");
        assert!(
            dropped * 400 < total,
            "{shape:?}: {dropped} of {total} dropped"
        );
        assert!(checked > 1000);
    }
}

#[test]
fn a_vertex_exactly_on_the_horizon_is_its_own_crossing() {
    // The normal +y inside the triangle, one vertex at height exactly 0 and another below:
    // the crossing of the edge from the vertex on the horizon is that vertex itself, not a
    // rounded copy whose arc of rounding noise would class the light as decentral.
    let n = Vec3::Y;
    let mut rng = TestRng::new(9);
    for _ in 0..1000 {
        let x = 0.5 + rng.u01();
        let v = [
            Vec3::new(x, 0.0, 0.1 * (rng.u01() - 0.5)),
            Vec3::new(-1.0, 1.0 + rng.u01(), 1.0),
            Vec3::new(-1.0, 1.0 - 2.5 * rng.u01(), -1.0),
        ];
        let t = ProjectedTriangle::new(v[0], v[1], v[2], n);
        let want = irradiance(n, &vertices(Shape::Triangle, v));
        assert!(!t.by_solid_angle(), "{v:?}");
        assert!(
            (t.projected_area() as f64 - want).abs() < 1e-6 * want,
            "{v:?}"
        );
        for _ in 0..8 {
            let (w, pdf) = t.sample(Vec2::new(rng.u01(), rng.u01()));
            assert!(pdf > 0.0, "{v:?}: a sample dropped");
            let est = n.as_dvec3().dot(w.as_dvec3()) / pdf as f64;
            assert!((est - want).abs() < 1e-5 * want, "{v:?}: {est} vs {want}");
        }
    }
}

#[test]
fn a_triangle_below_the_horizon_is_empty() {
    let v = [
        Vec3::new(-1.0, 0.2, -1.0),
        Vec3::new(1.0, 0.2, -1.0),
        Vec3::new(0.0, 1.0, -0.5),
    ];
    let t = ProjectedTriangle::new(v[0], v[1], v[2], Vec3::Z);
    assert_eq!(t.projected_area(), 0.0);
    assert_eq!(t.sample(Vec2::new(0.3, 0.6)), (Vec3::Z, 0.0));
    assert_eq!(t.pdf((v[0] + v[1] + v[2]).normalize()), 0.0);
}

/// A kept sample is a unit direction with the pdf function's value, and its inverse lies in
/// the square; where the polygon is sampled by projected solid angle, the cosine estimate is
/// the irradiance.
fn check_hard_case(name: &str, shape: Shape, n: Vec3, v: [Vec3; 3]) {
    let t = Light::new(shape, n, v);
    // The spherical polygon depends on the vertices' directions alone; unit ones keep the
    // reference's clipping of a vertex 1e21 away from cancelling.
    let unit: Vec<DVec3> = vertices(shape, v).iter().map(|x| x.normalize()).collect();
    let want = irradiance(n, &unit);
    let mut rng = TestRng::new(13);
    let border = border();
    let us = border
        .iter()
        .map(|&[x, y]| Vec2::new(x, y))
        .chain((0..200).map(|_| Vec2::new(rng.u01(), rng.u01())));
    let mut kept = 0;
    for u in us {
        let (w, pdf) = t.sample(u);
        assert!(pdf.is_finite() && pdf >= 0.0, "{name}: pdf {pdf} at {u}");
        if pdf == 0.0 {
            continue;
        }
        kept += 1;
        assert!(
            (w.as_dvec3().length() - 1.0).abs() < 1e-6,
            "{name}: {w} at {u}"
        );
        assert_eq!(t.pdf(w).to_bits(), pdf.to_bits(), "{name}: pdf at {u}");
        let back = t.inverse(w);
        assert!(
            back.cmpge(Vec2::ZERO).all() && back.cmple(Vec2::ONE).all(),
            "{name}: inverse {back} of {u}"
        );
        if !t.by_solid_angle() {
            let est = n.as_dvec3().normalize().dot(w.as_dvec3()) / pdf as f64;
            assert!(
                (est - want).abs() < 1e-5 * want,
                "{name}: {est} vs {want} at {u}"
            );
        }
    }
    assert!(kept > 150, "{name}: {kept} kept");
}

#[test]
fn hard_cases_keep_the_contract() {
    let s = 0.3;
    let tri = |c: Vec3| {
        [
            c + Vec3::new(-s, -s, 0.0),
            c + Vec3::new(s, -s, 0.0),
            c + Vec3::new(0.0, s, 0.0),
        ]
    };
    let rect = |c: Vec3| {
        [
            c + Vec3::new(-s, -s, 0.0),
            Vec3::new(2.0 * s, 0.0, 0.0),
            Vec3::new(0.0, 2.0 * s, 0.0),
        ]
    };
    let up = Vec3::new(0.0, 0.0, 1.0);
    let facing_neg_x = [
        Vec3::new(-1.0, -s, -s),
        Vec3::new(-1.0, s, -s),
        Vec3::new(-1.0, 0.0, s),
    ];
    let cases: Vec<(&str, Shape, Vec3, [Vec3; 3])> = vec![
        // Across the receiver's horizon: the normal +y, half the light below.
        ("straddling the horizon", Shape::Triangle, Vec3::Y, tri(up)),
        (
            "straddling the horizon",
            Shape::Rectangle,
            Vec3::Y,
            rect(up),
        ),
        // An edge whose great circle passes through the normal (+z): y = −s at x from −s to s
        // on the plane z = 1 is not; the edge from (−s, 0, 1) to (s, 0, 1) is.
        (
            "an edge through the zenith",
            Shape::Triangle,
            Vec3::Z,
            [
                Vec3::new(-s, 0.0, 1.0),
                Vec3::new(s, 0.0, 1.0),
                Vec3::new(0.0, s, 1.0),
            ],
        ),
        // The normal exactly on a vertex (the fuzzer's find: its radial edges sweep nothing).
        (
            "the normal on a vertex",
            Shape::Triangle,
            Vec3::new(0.5, 0.5, 0.5),
            [
                Vec3::new(1.2e-38, 0.0, 48.6),
                Vec3::new(-3.5e21, 1.8e-40, -2.5),
                Vec3::new(0.5, 0.5, 0.5),
            ],
        ),
        (
            "the normal on a vertex",
            Shape::Rectangle,
            Vec3::new(-s, -s, 1.0),
            rect(up),
        ),
        // A sliver: 1e-4 wide, a unit long.
        (
            "a sliver",
            Shape::Triangle,
            Vec3::new(0.3, 0.0, 1.0),
            [
                Vec3::new(-0.5, 0.0, 1.0),
                Vec3::new(0.5, 0.0, 1.0),
                Vec3::new(0.0, 1e-4, 1.0),
            ],
        ),
        // 1e-8 sr: sampled by solid angle.
        (
            "a polygon of 1e-8 sr",
            Shape::Triangle,
            Vec3::Z,
            tri(up).map(|x| (x - up) * 1e-4 + up),
        ),
        // A normal whose squares overflow f32, and a light 1e-21 away (fuzzer's finds).
        (
            "a huge normal",
            Shape::Triangle,
            Vec3::new(-6.8e31, 16.0, -2.25),
            facing_neg_x,
        ),
        (
            "a light 1e-21 away",
            Shape::Rectangle,
            Vec3::Z,
            rect(up).map(|x| x * 1e-21),
        ),
    ];
    for (name, shape, n, v) in cases {
        check_hard_case(&format!("{shape:?} {name}"), shape, n, v);
    }
    // The 1e-8 sr triangle falls back; the others are sampled by projected solid angle.
    let tiny = tri(up).map(|x| (x - up) * 1e-4 + up);
    assert!(ProjectedTriangle::new(tiny[0], tiny[1], tiny[2], Vec3::Z).by_solid_angle());
    let v = facing_neg_x;
    assert!(
        !ProjectedTriangle::new(v[0], v[1], v[2], Vec3::new(-6.8e31, 16.0, -2.25)).by_solid_angle()
    );
}

#[test]
fn lanes_agree_where_vertices_tie_at_the_extreme_azimuths() {
    // A vertical window seen from a floor (n = +z): its vertical edges are radial, so two
    // vertices share each extreme azimuth. One lane crossing the horizon makes the packet keep
    // all 2N slots, where the other lanes' scalar calls keep N edges: the same vertex must win.
    let n = Vec3::Z;
    let window = |drop: f32| {
        [
            Vec3::new(1.0, -0.5, 0.2 - drop),
            Vec3::new(0.0, 1.0, 0.0),
            Vec3::new(0.0, 0.0, 1.0),
        ]
    };
    let triangle = |drop: f32| {
        [
            Vec3::new(1.0, 0.2, 0.3 - drop),
            Vec3::new(1.0, 0.2, 1.5 - drop),
            Vec3::new(1.0, -0.5, 0.8 - drop),
        ]
    };
    for shape in SHAPES {
        let geometry = |drop| match shape {
            Shape::Triangle => triangle(drop),
            Shape::Rectangle => window(drop),
        };
        let cfg: [[Vec3; 3]; 8] =
            core::array::from_fn(|i| geometry(if i == 3 { 0.6 } else { 0.0 }));
        let wide = |k: usize| Vec3x8::from(cfg.map(|c| c[k]));
        let t8 = Light::new(shape, Vec3x8::splat(n), [wide(0), wide(1), wide(2)]);
        let mut rng = TestRng::new(17);
        let edges = [0.0, 1e-3, 0.5, 0.999, 1.0];
        let us = edges
            .iter()
            .flat_map(|&x| edges.map(|y| Vec2::new(x, y)))
            .chain((0..200).map(|_| Vec2::new(rng.u01(), rng.u01())));
        for u in us {
            let (w8, pdf8) = t8.sample(Vec2x8::splat(u));
            for (i, v) in cfg.iter().enumerate() {
                let t = Light::new(shape, n, *v);
                let (w, pdf) = t.sample(u);
                assert_eq!(
                    w.to_array().map(f32::to_bits),
                    w8.lane(i).to_array().map(f32::to_bits),
                    "{shape:?} lane {i} at {u}"
                );
                assert_eq!(pdf.to_bits(), pdf8.to_array()[i].to_bits());
            }
        }
    }
}
