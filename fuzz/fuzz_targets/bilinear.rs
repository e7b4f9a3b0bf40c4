//! The bilinear warp on arbitrary weights, and the polygons that follow a receiver's cosine
//! (bilinear and projected) on arbitrary geometry and normals (NaN, ±∞, subnormals, zeros and
//! negatives included). Checked:
//! - the warp: a point of [0, 1]² for any u that is not NaN, its pdf finite and ≥ 0, and its
//!   inverse back within 1e-6 of u (the round trip holds for any admissible weights, whose ratio
//!   does not matter to it); inadmissible weights (≤ 0, NaN, ∞) act as the identity with pdf 1;
//! - the polygons: the pdf of a sample finite and ≥ 0; a kept sample finite, its pdf function
//!   finite and ≥ 0, and within 1e-3 relative of the sample's pdf where the light is sampled
//!   spherically and the spherical inverse returns the sample's u′ to 2e-6; a dropped sample at the documented point (+z, or
//!   the corner); the zero normal giving the plain spherical sampler bit for bit;
//! - the projected polygons (triangle, parallelogram, and a hexagon about the fuzzed centre with
//!   the fuzzed half-axes): a kept sample a unit direction whose pdf is the pdf function's bit for
//!   bit, finite and > 0, its inverse in [0, 1]² (or NaN where it falls back to a spherical
//!   rectangle beyond the inverse's reach); a dropped one +z with pdf 0; and the same for an
//!   arbitrary pentagon (not convex, planar or simple in general), whose density is outside the
//!   contract but whose bad-input rules are not;
//! - the projected cap (a sphere about a fuzzed centre, of a fuzzed radius): as the projected
//!   polygons, except that a sample on the horizon keeps its direction with pdf 0;
//! - every lane of the x8 and x16 forms equal to the scalar form, bit for bit, with a different
//!   light in every other lane (other vertex orders, scales, normals, degenerate ones), so that a
//!   path one lane takes cannot change another's bits.

#![no_main]

use glam::{Vec2, Vec3};
use libfuzzer_sys::fuzz_target;
use mcsample::lane::{F32x8, F32x16};
use mcsample::warp::{
    self, BilinearRectangle, BilinearTriangle, ProjectedCap, ProjectedPolygon, ProjectedRectangle,
    ProjectedTriangle, SphericalRectangle, SphericalTriangle,
};
use mcsample::x8::{Vec2x8, Vec3x8};
use mcsample::x16::{Vec2x16, Vec3x16};

/// Per-lane parameters: `main` in the even lanes, `others` in turn (from the k-th) in the odd
/// ones, as packets of each of the four vectors.
fn mixed<const N: usize, P: From<[Vec3; N]>>(
    main: [Vec3; 4],
    others: &[[Vec3; 4]],
    k: usize,
) -> [P; 4] {
    let lanes: [[Vec3; 4]; N] =
        core::array::from_fn(|i| if i % 2 == 0 { main } else { others[(i / 2 + k) % others.len()] });
    core::array::from_fn(|j| P::from(lanes.map(|q| q[j])))
}

fn floats<const N: usize>(data: &[u8]) -> [f32; N] {
    let mut out = [0.5f32; N];
    for (o, c) in out.iter_mut().zip(data.chunks_exact(4)) {
        *o = f32::from_le_bytes([c[0], c[1], c[2], c[3]]);
    }
    out
}

fn bits2(v: Vec2) -> [u32; 2] {
    v.to_array().map(f32::to_bits)
}

fn bits3(v: Vec3) -> [u32; 3] {
    v.to_array().map(f32::to_bits)
}

fn in_unit_square(u: Vec2) -> bool {
    u.cmpge(Vec2::ZERO).all() && u.cmple(Vec2::ONE).all()
}

fn check_warp(u: Vec2, w: [f32; 4]) {
    let x = warp::bilinear(u, w);
    let pdf = warp::bilinear_pdf(x, w);
    let back = warp::bilinear_inverse(x, w);
    let ctx = || format!("u {u:?}, w {w:?}: x {x:?}, pdf {pdf:e}, back {back:?}");
    assert!(pdf.is_finite() && pdf >= 0.0, "{}", ctx());
    let admissible = w.iter().all(|&v| v > 0.0 && v.is_finite());
    if !admissible && !u.is_nan() {
        let clamped = u.clamp(Vec2::ZERO, Vec2::ONE);
        // As values: the crate's clamp keeps −0, glam's may not.
        assert!(x == clamped, "{}: not the identity", ctx());
    }
    if u.is_nan() {
        let canonical = f32::NAN.to_bits();
        assert!(
            x.to_array().iter().any(|c| c.to_bits() == canonical),
            "{}: NaN bits",
            ctx()
        );
        assert!(
            x.to_array()
                .iter()
                .all(|c| !c.is_nan() || c.to_bits() == canonical),
            "{}",
            ctx()
        );
    } else {
        assert!(in_unit_square(x), "{}", ctx());
        // Positive in the square: the weights' floor keeps the density above 2⁻⁴⁰.
        assert!(pdf > 0.0 || !admissible, "{}", ctx());
        let u = u.clamp(Vec2::ZERO, Vec2::ONE);
        assert!(
            (back - u).abs().max_element() <= 1e-6,
            "{}: round trip",
            ctx()
        );
    }
    let (u8, x8) = (Vec2x8::splat(u), Vec2x8::splat(x));
    let w8 = w.map(F32x8::splat);
    assert_eq!(
        bits2(warp::bilinear(u8, w8).lane(5)),
        bits2(x),
        "{}: x8",
        ctx()
    );
    assert_eq!(
        warp::bilinear_pdf(x8, w8).to_array()[3].to_bits(),
        pdf.to_bits(),
        "{}: x8 pdf",
        ctx()
    );
    assert_eq!(
        bits2(warp::bilinear_inverse(x8, w8).lane(7)),
        bits2(back),
        "{}: x8 inverse",
        ctx()
    );
    let (u16, x16) = (Vec2x16::splat(u), Vec2x16::splat(x));
    let w16 = w.map(F32x16::splat);
    assert_eq!(
        bits2(warp::bilinear(u16, w16).lane(13)),
        bits2(x),
        "{}: x16",
        ctx()
    );
    assert_eq!(
        warp::bilinear_pdf(x16, w16).to_array()[11].to_bits(),
        pdf.to_bits(),
        "{}: x16 pdf",
        ctx()
    );
    assert_eq!(
        bits2(warp::bilinear_inverse(x16, w16).lane(15)),
        bits2(back),
        "{}: x16 inverse",
        ctx()
    );
}

/// A polygon's sample checked against its pdf function, and its lanes against the scalar form.
fn check_sample(
    name: &str,
    (x, pdf): (Vec3, f32),
    pdf_fn: f32,
    spherical: bool,
    dropped_at: Vec3,
    lanes: [(Vec3, f32); 2],
) {
    let ctx = || format!("{name}: x {x:?}, pdf {pdf:e}, pdf(x) {pdf_fn:e}");
    assert!(pdf.is_finite() && pdf >= 0.0, "{}", ctx());
    if pdf > 0.0 {
        assert!(x.is_finite(), "{}", ctx());
        assert!(pdf_fn.is_finite() && pdf_fn >= 0.0, "{}", ctx());
        // The inside test can round either way at an edge; a kept spherical sample's own pdf
        // and the pdf function's agree to the inverse's round trip.
        if spherical && pdf_fn > 0.0 {
            assert!(((pdf - pdf_fn) / pdf_fn).abs() < 1e-3, "{}", ctx());
        }
    } else {
        assert_eq!(bits3(x), bits3(dropped_at), "{}: dropped sample", ctx());
    }
    for (i, (xl, pl)) in lanes.into_iter().enumerate() {
        assert_eq!(bits3(xl), bits3(x), "{}: lanes ({i})", ctx());
        assert_eq!(pl.to_bits(), pdf.to_bits(), "{}: lane pdf ({i})", ctx());
    }
}

/// A projected polygon's sample (scalar, and lanes of x8 and x16: sample, pdf and inverse).
fn check_projected(
    name: &str,
    (x, pdf): (Vec3, f32),
    pdf_fn: f32,
    (back, fallback): (Vec2, bool),
    lanes: [(Vec3, f32, Vec2); 2],
) {
    let ctx = || format!("{name}: x {x:?}, pdf {pdf:e}, pdf(x) {pdf_fn:e}, back {back:?}");
    assert!(pdf.is_finite() && pdf >= 0.0, "{}", ctx());
    if pdf > 0.0 {
        let len = x.as_dvec3().length();
        assert!((len - 1.0).abs() <= 1e-6, "{}: not unit", ctx());
        assert_eq!(pdf.to_bits(), pdf_fn.to_bits(), "{}: pdf function", ctx());
        // Where it falls back, the spherical inverse's own NaN (a rectangle beyond its reach).
        assert!(
            in_unit_square(back) || (fallback && back.is_nan()),
            "{}: inverse",
            ctx()
        );
    } else {
        assert_eq!(bits3(x), bits3(Vec3::Z), "{}: dropped sample", ctx());
    }
    for (i, (xl, pl, bl)) in lanes.into_iter().enumerate() {
        assert_eq!(bits3(xl), bits3(x), "{}: lanes ({i})", ctx());
        assert_eq!(pl.to_bits(), pdf.to_bits(), "{}: lane pdf ({i})", ctx());
        assert_eq!(bits2(bl), bits2(back), "{}: lane inverse ({i})", ctx());
    }
}

/// The projected cap's sample: as `check_projected`, but a sample exactly on the horizon keeps
/// its direction (pdf 0) so that it inverts.
fn check_cap(
    name: &str,
    cap: &ProjectedCap<Vec3>,
    u: Vec2,
    n: Vec3,
    lanes: [(Vec3, f32, Vec2); 2],
) {
    let (x, pdf) = cap.sample(u);
    let back = cap.inverse(x);
    let ctx = || format!("{name}: x {x:?}, pdf {pdf:e}, back {back:?}");
    assert!(pdf.is_finite() && pdf >= 0.0, "{}", ctx());
    let on_horizon = || {
        let cos = x.as_dvec3().dot(n.as_dvec3().normalize());
        (x.as_dvec3().length() - 1.0).abs() <= 1e-6 && cos.abs() <= 1e-6
    };
    if pdf > 0.0 {
        assert!((x.as_dvec3().length() - 1.0).abs() <= 1e-6, "{}: not unit", ctx());
        assert_eq!(pdf.to_bits(), cap.pdf(x).to_bits(), "{}: pdf function", ctx());
        assert!(in_unit_square(back), "{}: inverse", ctx());
    } else {
        assert!(bits3(x) == bits3(Vec3::Z) || on_horizon(), "{}: dropped sample", ctx());
    }
    for (i, (xl, pl, bl)) in lanes.into_iter().enumerate() {
        assert_eq!(bits3(xl), bits3(x), "{}: lanes ({i})", ctx());
        assert_eq!(pl.to_bits(), pdf.to_bits(), "{}: lane pdf ({i})", ctx());
        assert_eq!(bits2(bl), bits2(back), "{}: lane inverse ({i})", ctx());
    }
}

/// The zero normal's sample equals the plain sampler's, bit for bit.
fn same(name: &str, (x, p): (Vec3, f32), (y, q): (Vec3, f32)) {
    assert_eq!(
        (bits3(x), p.to_bits()),
        (bits3(y), q.to_bits()),
        "{name}: the zero normal is not the plain sampler"
    );
}

fuzz_target!(|data: &[u8]| {
    let f: [f32; 18] = floats(data);
    let u = Vec2::new(f[0], f[1]);
    check_warp(u, [f[2], f[3], f[4], f[5]]);
    // Weights spread by powers of two from the fuzzed ones, which are mostly far apart.
    check_warp(u, [f[2], f[2] * 3.0, f[2] * 0.25, f[2] * 100.0]);

    let v = |i: usize| Vec3::new(f[i], f[i + 1], f[i + 2]);
    let (a, b, c, n) = (v(6), v(9), v(12), v(15));
    let un = n.normalize_or_zero();
    let s8 = |p: Vec3| Vec3x8::splat(p);
    let s16 = |p: Vec3| Vec3x16::splat(p);
    let turn = |p: Vec3| Vec3::new(p.y, p.z, p.x);
    // The other lanes' triangles and rectangles (ex ⟂ ey kept) and normals.
    let ey = b - a * (b.dot(a) / a.length_squared());
    let tris = |n: Vec3| {
        [
            [b, c, a, turn(n)],
            [c, a, -b, -n],
            [a * 1e-3, b, c, n],
            [a, a, c, n],
            [b, a, c, Vec3::ZERO],
        ]
    };
    let rects = |n: Vec3| {
        [
            [c + a, -a, ey, n],
            [c * 2.0, a, ey, turn(n)],
            [-c, ey, a, -n],
            [c, a * 1e-4, ey, n],
            [c, Vec3::ZERO, ey, n],
        ]
    };

    let t = BilinearTriangle::new(a, b, c, un);
    let plain = SphericalTriangle::new(a, b, c);
    let (x, pdf) = t.sample(u);
    let [a8, b8, c8, n8] = mixed::<8, Vec3x8>([a, b, c, un], &tris(un), 0);
    let t8 = BilinearTriangle::new(a8, b8, c8, n8).sample(Vec2x8::splat(u));
    let [a16, b16, c16, n16] = mixed::<16, Vec3x16>([a, b, c, un], &tris(un), 1);
    let t16 = BilinearTriangle::new(a16, b16, c16, n16).sample(Vec2x16::splat(u));
    // The pdfs agree to the spherical inverse's round trip (whose accuracy is the `spherical`
    // target's business): where it returns u′ to 2e-6, the density, whose relative slope is at
    // most 4·100, moves by under 1e-3.
    let v = warp::bilinear(u, t.weights());
    let spherical = !plain.by_area() && (plain.inverse(x) - v).abs().max_element() <= 2e-6;
    check_sample(
        &format!("triangle {:?} n {un:?} u {u:?}", [a, b, c]),
        (x, pdf),
        t.pdf(x),
        spherical,
        Vec3::Z,
        [
            (t8.0.lane(6), t8.1.to_array()[6]),
            (t16.0.lane(14), t16.1.to_array()[14]),
        ],
    );
    same(
        "triangle",
        BilinearTriangle::new(a, b, c, Vec3::ZERO).sample(u),
        plain.sample(u),
    );

    // The rectangle with ey made orthogonal to ex, as its contract asks.
    let r = BilinearRectangle::new(c, a, ey, un);
    let plain = SphericalRectangle::new(c, a, ey);
    let (x, pdf) = r.sample(u);
    let [c8, a8, e8, n8] = mixed::<8, Vec3x8>([c, a, ey, un], &rects(un), 2);
    let r8 = BilinearRectangle::new(c8, a8, e8, n8).sample(Vec2x8::splat(u));
    let [c16, a16, e16, n16] = mixed::<16, Vec3x16>([c, a, ey, un], &rects(un), 3);
    let r16 = BilinearRectangle::new(c16, a16, e16, n16).sample(Vec2x16::splat(u));
    // The pdf function takes the point as its direction (`BilinearRectangle::pdf`), which at a
    // grazing angle moves u′ by ε·|p|/d: held where the light is within 100 times its distance.
    let v = warp::bilinear(u, r.weights());
    let d = c
        .as_dvec3()
        .dot(a.as_dvec3().cross(ey.as_dvec3()).normalize())
        .abs();
    let reach = c.as_dvec3().length() + a.as_dvec3().length() + ey.as_dvec3().length();
    let spherical = !plain.by_area()
        && reach <= 100.0 * d
        && (plain.inverse(x) - v).abs().max_element() <= 2e-6;
    check_sample(
        &format!("rectangle {:?} n {un:?} u {u:?}", [c, a, ey]),
        (x, pdf),
        r.pdf(x),
        spherical,
        c,
        [
            (r8.0.lane(2), r8.1.to_array()[2]),
            (r16.0.lane(10), r16.1.to_array()[10]),
        ],
    );
    same(
        "rectangle",
        BilinearRectangle::new(c, a, ey, Vec3::ZERO).sample(u),
        plain.sample(u),
    );

    // The projected polygons, for the fuzzed normal as given (not normalised: the sampler
    // normalises it).
    let t = ProjectedTriangle::new(a, b, c, n);
    let [a8, b8, c8, n8] = mixed::<8, Vec3x8>([a, b, c, n], &tris(n), 4);
    let t8 = ProjectedTriangle::new(a8, b8, c8, n8);
    let [a16, b16, c16, n16] = mixed::<16, Vec3x16>([a, b, c, n], &tris(n), 0);
    let t16 = ProjectedTriangle::new(a16, b16, c16, n16);
    let (x, pdf) = t.sample(u);
    let (x8, p8) = t8.sample(Vec2x8::splat(u));
    let (x16, p16) = t16.sample(Vec2x16::splat(u));
    check_projected(
        &format!("projected triangle {:?} n {n:?} u {u:?}", [a, b, c]),
        (x, pdf),
        t.pdf(x),
        (t.inverse(x), t.by_solid_angle()),
        [
            (x8.lane(2), p8.to_array()[2], t8.inverse(x8).lane(2)),
            (x16.lane(12), p16.to_array()[12], t16.inverse(x16).lane(12)),
        ],
    );
    let r = ProjectedRectangle::new(c, a, ey, n);
    let [c8, a8, e8, n8] = mixed::<8, Vec3x8>([c, a, ey, n], &rects(n), 1);
    let r8 = ProjectedRectangle::new(c8, a8, e8, n8);
    let [c16, a16, e16, n16] = mixed::<16, Vec3x16>([c, a, ey, n], &rects(n), 2);
    let r16 = ProjectedRectangle::new(c16, a16, e16, n16);
    let (x, pdf) = r.sample(u);
    let (x8, p8) = r8.sample(Vec2x8::splat(u));
    let (x16, p16) = r16.sample(Vec2x16::splat(u));
    check_projected(
        &format!("projected rectangle {:?} n {n:?} u {u:?}", [c, a, ey]),
        (x, pdf),
        r.pdf(x),
        (r.inverse(x), r.by_solid_angle()),
        [
            (x8.lane(4), p8.to_array()[4], r8.inverse(x8).lane(4)),
            (x16.lane(8), p16.to_array()[8], r16.inverse(x16).lane(8)),
        ],
    );

    // The hexagon about c with half-axes a and ey (convex; degenerate where they are
    // parallel), among the other lanes' hexagons from the rectangles' vectors.
    let hex = |q: [Vec3; 4]| warp::hexagon([q[0], q[1], q[2]]);
    let h = ProjectedPolygon::new(hex([c, a, ey, n]), n);
    let lanes8: [[Vec3; 4]; 8] =
        core::array::from_fn(|i| if i % 2 == 0 { [c, a, ey, n] } else { rects(n)[(i / 2 + 3) % rects(n).len()] });
    let lanes16: [[Vec3; 4]; 16] =
        core::array::from_fn(|i| if i % 2 == 0 { [c, a, ey, n] } else { rects(n)[(i / 2) % rects(n).len()] });
    let h8 = ProjectedPolygon::new(
        core::array::from_fn::<_, 6, _>(|k| Vec3x8::from(lanes8.map(|q| hex(q)[k]))),
        Vec3x8::from(lanes8.map(|q| q[3])),
    );
    let h16 = ProjectedPolygon::new(
        core::array::from_fn::<_, 6, _>(|k| Vec3x16::from(lanes16.map(|q| hex(q)[k]))),
        Vec3x16::from(lanes16.map(|q| q[3])),
    );
    let (x, pdf) = h.sample(u);
    let (x8, p8) = h8.sample(Vec2x8::splat(u));
    let (x16, p16) = h16.sample(Vec2x16::splat(u));
    check_projected(
        &format!("projected hexagon {:?} n {n:?} u {u:?}", [c, a, ey]),
        (x, pdf),
        h.pdf(x),
        (h.inverse(x), h.by_solid_angle()),
        [
            (x8.lane(2), p8.to_array()[2], h8.inverse(x8).lane(2)),
            (x16.lane(14), p16.to_array()[14], h16.inverse(x16).lane(14)),
        ],
    );

    // An arbitrary pentagon: in general not convex, not planar, or crossing itself. Its density
    // is outside the contract, its bad-input rules are not: a unit direction whose pdf is the
    // pdf function's, or +z dropped, and the same bits in every lane. The other lanes hold it
    // from other first vertices and in the other winding, for other normals.
    let pent = [a, b, c, ey, a + c];
    let turn = |k: usize, back: bool| -> [Vec3; 5] {
        core::array::from_fn(|i| pent[if back { (5 + k - i) % 5 } else { (i + k) % 5 }])
    };
    let lane = |i: usize| match i % 4 {
        0 | 2 => (pent, n),
        1 => (turn(i / 4 + 1, false), Vec3::Z),
        _ => (turn(i / 4, true), -n),
    };
    let g = ProjectedPolygon::new(pent, n);
    let l8: [([Vec3; 5], Vec3); 8] = core::array::from_fn(lane);
    let l16: [([Vec3; 5], Vec3); 16] = core::array::from_fn(lane);
    let g8 = ProjectedPolygon::new(
        core::array::from_fn::<_, 5, _>(|k| Vec3x8::from(l8.map(|q| q.0[k]))),
        Vec3x8::from(l8.map(|q| q.1)),
    );
    let g16 = ProjectedPolygon::new(
        core::array::from_fn::<_, 5, _>(|k| Vec3x16::from(l16.map(|q| q.0[k]))),
        Vec3x16::from(l16.map(|q| q.1)),
    );
    let (x, pdf) = g.sample(u);
    let (x8, p8) = g8.sample(Vec2x8::splat(u));
    let (x16, p16) = g16.sample(Vec2x16::splat(u));
    check_projected(
        &format!("projected pentagon {pent:?} n {n:?} u {u:?}"),
        (x, pdf),
        g.pdf(x),
        (g.inverse(x), g.by_solid_angle()),
        [
            (x8.lane(2), p8.to_array()[2], g8.inverse(x8).lane(2)),
            (x16.lane(14), p16.to_array()[14], g16.inverse(x16).lane(14)),
        ],
    );

    // The cap about a, of radius |b.x|, among other spheres in the other lanes (b and c as
    // centres, radii from the weights), so that each lane runs its own case and solve.
    let r = f[9].abs();
    let cap = ProjectedCap::new(a, r, n);
    let others = [(b, f[2]), (c, f[3]), (a, f[4]), (b, r), (c, f[5])];
    let mixed = |k: usize, i: usize| if i % 2 == 0 { (a, r) } else { others[(i / 2 + k) % 5] };
    let c8: [(Vec3, f32); 8] = core::array::from_fn(|i| mixed(0, i));
    let c16: [(Vec3, f32); 16] = core::array::from_fn(|i| mixed(1, i));
    let cap8 = ProjectedCap::new(
        Vec3x8::from(c8.map(|p| p.0)),
        F32x8::from(c8.map(|p| p.1)),
        s8(n),
    );
    let cap16 = ProjectedCap::new(
        Vec3x16::from(c16.map(|p| p.0)),
        F32x16::from(c16.map(|p| p.1)),
        s16(n),
    );
    let (x8, p8) = cap8.sample(Vec2x8::splat(u));
    let (x16, p16) = cap16.sample(Vec2x16::splat(u));
    check_cap(
        &format!("projected cap {a:?} r {r:e} n {n:?} u {u:?}"),
        &cap,
        u,
        n,
        [
            (x8.lane(2), p8.to_array()[2], cap8.inverse(x8).lane(2)),
            (x16.lane(12), p16.to_array()[12], cap16.inverse(x16).lane(12)),
        ],
    );
});
