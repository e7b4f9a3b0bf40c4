//! Every warp on arbitrary floats: no panic, pdfs are never NaN or negative, finite non-NaN input
//! gives finite output, and the packet form's lanes equal the scalar form bit for bit.

#![no_main]

use glam::{Vec2, Vec3};
use libfuzzer_sys::fuzz_target;
use mcsample::warp::{self, x8};
use mcsample::x8::{F32x8, Vec2x8, Vec3x8};

fn floats(data: &[u8]) -> [f32; 16] {
    let mut out = [0.0f32; 16];
    for (o, c) in out.iter_mut().zip(data.chunks_exact(4)) {
        *o = f32::from_le_bytes([c[0], c[1], c[2], c[3]]);
    }
    out
}

fn same3(s: Vec3, p: Vec3x8, what: &str) {
    for l in p.to_array() {
        assert_eq!(
            [s.x.to_bits(), s.y.to_bits(), s.z.to_bits()],
            [l.x.to_bits(), l.y.to_bits(), l.z.to_bits()],
            "{what}: packet lane differs from scalar"
        );
    }
}

fn same1(s: f32, p: F32x8, what: &str) {
    for l in p.to_array() {
        assert_eq!(s.to_bits(), l.to_bits(), "{what}: packet lane differs from scalar");
    }
}

fn pdf_ok(p: f32, what: &str) {
    assert!(p >= 0.0, "{what}: pdf {p} is negative or NaN");
}

fuzz_target!(|data: &[u8]| {
    let f = floats(data);
    let u = Vec2::new(f[0], f[1]);
    let u8 = Vec2x8::splat(u);
    let (h, n) = (f[2], f[3]);
    let (a, b, c) = (Vec3::new(f[4], f[5], f[6]), Vec3::new(f[7], f[8], f[9]), Vec3::new(f[10], f[11], f[12]));
    let (a8, b8, c8) = (Vec3x8::splat(a), Vec3x8::splat(b), Vec3x8::splat(c));
    let u_finite = !u.is_nan();

    let d = warp::concentric_disk(u);
    same3(d.extend(0.0), { let p = x8::concentric_disk(u8); Vec3x8::new(p.x, p.y, F32x8::ZERO) }, "concentric_disk");
    if u_finite {
        assert!(d.length() <= 1.0 + 1e-6, "concentric_disk({u}) = {d} outside the disk");
    }
    let w = warp::cosine_hemisphere(u);
    same3(w, x8::cosine_hemisphere(u8), "cosine_hemisphere");
    if u_finite {
        assert!(w.is_finite() && w.z >= 0.0, "cosine_hemisphere({u}) = {w}");
    }
    pdf_ok(warp::cosine_hemisphere_pdf(w.z), "cosine_hemisphere_pdf");
    let w = warp::uniform_sphere(u);
    same3(w, x8::uniform_sphere(u8), "uniform_sphere");
    let w = warp::uniform_cone(u, h);
    same3(w, x8::uniform_cone(u8, F32x8::splat(h)), "uniform_cone");
    if u_finite && !h.is_nan() {
        assert!(w.is_finite(), "uniform_cone({u}, {h}) = {w}");
    }
    let pdf = warp::uniform_cone_pdf(w, h);
    assert_eq!(
        pdf.to_bits(),
        x8::uniform_cone_pdf(Vec3x8::splat(w), F32x8::splat(h)).to_array()[0].to_bits(),
        "uniform_cone_pdf lanes"
    );
    pdf_ok(pdf, "uniform_cone_pdf");
    // Below about 4.6e-40, 1/(2πh) overflows and the cone counts as degenerate (pdf 0,
    // documented); the check starts at 1e-38, clear of that edge.
    if u_finite && h > 1e-38 && !h.is_nan() {
        assert!(pdf > 0.0, "uniform_cone_pdf({w}, {h}) = 0 at its own sample");
    }
    let w = warp::phong_lobe(u, n);
    same3(w, x8::phong_lobe(u8, F32x8::splat(n)), "phong_lobe");
    if u_finite && !n.is_nan() {
        assert!(w.is_finite() && w.z >= 0.0, "phong_lobe({u}, {n}) = {w}");
    }
    let p = warp::phong_lobe_pdf(f[4], n);
    pdf_ok(p, "phong_lobe_pdf");
    same1(p, x8::phong_lobe_pdf(F32x8::splat(f[4]), F32x8::splat(n)), "phong_lobe_pdf");
    let bary = warp::uniform_triangle(u);
    same3(bary, x8::uniform_triangle(u8), "uniform_triangle");
    if u_finite {
        assert!(bary.min_element() >= 0.0, "uniform_triangle({u}) = {bary}");
    }

    let (w, p) = warp::spherical_triangle(u, a, b, c);
    let (w8, p8) = x8::spherical_triangle(u8, a8, b8, c8);
    same3(w, w8, "spherical_triangle");
    same1(p, p8, "spherical_triangle pdf");
    pdf_ok(p, "spherical_triangle");
    assert!(w.is_finite(), "spherical_triangle direction {w} for {a} {b} {c}");
    let q = warp::spherical_triangle_pdf(w, a, b, c);
    pdf_ok(q, "spherical_triangle_pdf");
    assert!(q.is_finite() && p.is_finite());
    let v = warp::spherical_triangle_inverse(w, a, b, c);
    same3(v.extend(0.0), { let t = x8::spherical_triangle_inverse(w8, a8, b8, c8); Vec3x8::new(t.x, t.y, F32x8::ZERO) }, "spherical_triangle_inverse");

    let (pt, p) = warp::spherical_rectangle(u, a, b, c);
    let (pt8, p8) = x8::spherical_rectangle(u8, a8, b8, c8);
    same3(pt, pt8, "spherical_rectangle");
    same1(p, p8, "spherical_rectangle pdf");
    pdf_ok(p, "spherical_rectangle");
    assert!(p.is_finite());
    pdf_ok(warp::spherical_rectangle_pdf(pt.normalize_or_zero(), a, b, c), "spherical_rectangle_pdf");
});
