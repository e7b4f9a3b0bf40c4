//! Every light and BSDF of `mcsample::scene` on arbitrary shading points, geometry, radiance, u
//! and directions: no panic; pdfs finite and ≥ 0; a kept sample (pdf > 0) has a unit direction,
//! a finite positive distance equal to `hit` at it, and the pdf function's value bit for bit; a
//! dropped one has pdf 0, distance ∞ and Le 0; BSDF values are finite and ≥ 0 where the
//! reflectances are; and the packet form's lanes equal the scalar form bit for bit. The same
//! contract holds for every light prepared with a fuzzed normal in every light-sampling mode
//! (the sphere's cap and the polygons' cosine-following maps), but that in the bilinear mode a
//! sample's pdf (the warp's density at the u′ it drew) and the pdf function's (at the
//! spherical inverse of the direction) agree to the inverse's round trip, not bit for bit.

#![no_main]

use glam::{Vec2, Vec3};
use libfuzzer_sys::fuzz_target;
use mcsample::scene::{
    DiskLight, Lambert, Light, LightSample, LightSampling, Phong, RectangleLight, SphereLight,
    TriangleLight,
};
use mcsample::x8::{F32x8, Vec2x8, Vec3x8};
use mcsample::x16::{F32x16, Vec2x16, Vec3x16};

fn floats(data: &[u8]) -> [f32; 24] {
    let mut out = [0.0f32; 24];
    for (o, c) in out.iter_mut().zip(data.chunks_exact(4)) {
        *o = f32::from_le_bytes([c[0], c[1], c[2], c[3]]);
    }
    out
}

fn bits(v: Vec3) -> [u32; 3] {
    v.to_array().map(f32::to_bits)
}

/// The light with every parameter splatted across eight lanes.
fn splat(l: &Light) -> Light<Vec3x8> {
    l.splat()
}

fn check_light(l: &Light, p: Vec3, u: Vec2, w: Vec3, name: &str) {
    let s: LightSample<Vec3> = l.sample(p, u);
    assert!(s.pdf.is_finite() && s.pdf >= 0.0, "{name}: pdf {s:?}");
    if s.pdf > 0.0 {
        // Unit within 1e-5 where the geometry's scale keeps squares in f32's normal range; for
        // a light 1e-21 away the direction stays finite but is normalised from subnormals.
        if (1e-12..1e12).contains(&s.dist) {
            assert!((s.wi.length() - 1.0).abs() < 1e-5, "{name}: |wi| {s:?}");
        }
        assert!(s.wi.is_finite(), "{name}: wi {s:?}");
        assert!(s.dist.is_finite() && s.dist >= 0.0, "{name}: dist {s:?}");
        assert_eq!(l.pdf(p, s.wi).to_bits(), s.pdf.to_bits(), "{name}: pdf(wi) ≠ sample pdf");
        assert_eq!(l.hit(p, s.wi).to_bits(), s.dist.to_bits(), "{name}: hit(wi) ≠ dist");
    } else {
        assert!(s.dist == f32::INFINITY && s.le == Vec3::ZERO && s.wi.is_finite(), "{name}: dropped {s:?}");
    }
    // Any vector: pdf finite and ≥ 0, hit ≥ 0 (∞ included), no panic.
    let pw = l.pdf(p, w);
    assert!(pw.is_finite() && pw >= 0.0, "{name}: pdf({w}) = {pw}");
    let h = l.hit(p, w);
    assert!(h >= 0.0, "{name}: hit({w}) = {h}");
    // A unit direction: on the light for pdf exactly where it is for hit.
    let wn = w.normalize_or_zero();
    if wn != Vec3::ZERO {
        let (pn, hn) = (l.pdf(p, wn), l.hit(p, wn));
        assert_eq!(pn > 0.0, hn.is_finite(), "{name}: pdf {pn} and hit {hn} disagree at {wn}");
    }
    let a = l.sample_area(p, u);
    assert!(a.pdf.is_finite() && a.pdf >= 0.0, "{name}: area pdf {a:?}");

    // Lane 0 of the packet equals the scalar.
    let l8 = splat(l);
    let (p8, u8, w8) = (Vec3x8::splat(p), Vec2x8::splat(u), Vec3x8::splat(w));
    let s8 = l8.sample(p8, u8);
    assert_eq!(bits(s8.wi.lane(0)), bits(s.wi), "{name}: packet wi");
    assert_eq!(s8.pdf.to_array()[0].to_bits(), s.pdf.to_bits(), "{name}: packet pdf");
    assert_eq!(s8.dist.to_array()[0].to_bits(), s.dist.to_bits(), "{name}: packet dist");
    assert_eq!(bits(s8.le.lane(0)), bits(s.le), "{name}: packet Le");
    assert_eq!(l8.pdf(p8, w8).to_array()[0].to_bits(), pw.to_bits(), "{name}: packet pdf(w)");
    assert_eq!(l8.hit(p8, w8).to_array()[0].to_bits(), h.to_bits(), "{name}: packet hit(w)");
    let a8 = l8.sample_area(p8, u8);
    assert_eq!(bits(a8.p.lane(0)), bits(a.p), "{name}: packet area point");
    assert_eq!(a8.pdf.to_array()[0].to_bits(), a.pdf.to_bits(), "{name}: packet area pdf");

    // Lane 15 of the sixteen-wide packet equals the scalar.
    let l16: Light<Vec3x16> = l.splat();
    let (p16, u16, w16) = (Vec3x16::splat(p), Vec2x16::splat(u), Vec3x16::splat(w));
    let s16 = l16.sample(p16, u16);
    assert_eq!(bits(s16.wi.lane(15)), bits(s.wi), "{name}: x16 wi");
    assert_eq!(s16.pdf.to_array()[15].to_bits(), s.pdf.to_bits(), "{name}: x16 pdf");
    assert_eq!(s16.dist.to_array()[15].to_bits(), s.dist.to_bits(), "{name}: x16 dist");
    assert_eq!(bits(s16.le.lane(15)), bits(s.le), "{name}: x16 Le");
    assert_eq!(l16.pdf(p16, w16).to_array()[15].to_bits(), pw.to_bits(), "{name}: x16 pdf(w)");
    assert_eq!(l16.hit(p16, w16).to_array()[15].to_bits(), h.to_bits(), "{name}: x16 hit(w)");
    let a16 = l16.sample_area(p16, u16);
    assert_eq!(bits(a16.p.lane(15)), bits(a.p), "{name}: x16 area point");
    assert_eq!(a16.pdf.to_array()[15].to_bits(), a.pdf.to_bits(), "{name}: x16 area pdf");
}

/// The light prepared at p for normal n in `mode`: a kept sample with the pdf function's value
/// and `hit`'s distance bit for bit, a dropped one with distance ∞ and Le 0, lane 0 of the packet
/// equal to the scalar. In the bilinear mode the sample's pdf is the warp's density at the u′ it
/// drew, the pdf function's at the spherical inverse of the direction: they differ by the
/// inverse's round trip times the density's relative slope, both unbounded on fuzzed input (a
/// vertex 3e4 away below the point puts the inverse's u₀ 1e-2 off; a normal of length 1e38
/// puts the weights 2⁴⁰ apart), so here they share only the verdict, both positive and finite.
/// The crate's tests bound the difference on sane lights (`scene::lights`).
fn check_mode(l: &Light, p: Vec3, n: Vec3, u: Vec2, mode: LightSampling, name: &str) {
    let prepared = l.at_sampling(p, n, mode);
    let s = prepared.sample(u);
    let name = format!("{name} {}", mode.name());
    assert!(s.pdf.is_finite() && s.pdf >= 0.0, "{name}: pdf {s:?}");
    if s.pdf > 0.0 {
        assert!(s.wi.is_finite() && s.dist.is_finite() && s.dist >= 0.0, "{name}: {s:?}");
        let pdf = prepared.pdf(s.wi);
        if mode == LightSampling::Bilinear {
            assert!(pdf > 0.0 && pdf.is_finite(), "{name}: pdf(wi) {pdf} against sample pdf {}", s.pdf);
        } else {
            assert_eq!(pdf.to_bits(), s.pdf.to_bits(), "{name}: pdf(wi) ≠ sample pdf");
        }
        assert_eq!(prepared.hit(s.wi).to_bits(), s.dist.to_bits(), "{name}: hit(wi) ≠ dist");
    } else {
        assert!(s.dist == f32::INFINITY && s.le == Vec3::ZERO && s.wi.is_finite(), "{name}: dropped {s:?}");
    }
    let l8 = splat(l);
    let s8 = l8.at_sampling(Vec3x8::splat(p), Vec3x8::splat(n), mode).sample(Vec2x8::splat(u));
    assert_eq!(bits(s8.wi.lane(0)), bits(s.wi), "{name}: packet wi");
    assert_eq!(s8.pdf.to_array()[0].to_bits(), s.pdf.to_bits(), "{name}: packet pdf");
    assert_eq!(s8.dist.to_array()[0].to_bits(), s.dist.to_bits(), "{name}: packet dist");
}

fuzz_target!(|data: &[u8]| {
    let f = floats(data);
    let v = |i: usize| Vec3::new(f[i], f[i + 1], f[i + 2]);
    let (p, u, w) = (v(0), Vec2::new(f[3], f[4]), v(5));
    let (a, b, c) = (v(8), v(11), v(14));
    let (le, r) = (v(17).abs(), f[20]);
    // The rectangle's edges made orthogonal, as its contract asks (non-orthogonal edges are a
    // documented degenerate light, also exercised below).
    let ey = c - b * (c.dot(b) / b.length_squared());
    let lights = [
        Light::from(SphereLight::new(a, r, le)),
        Light::from(DiskLight::new(a, b, r, le)),
        Light::from(TriangleLight::new(a, b, c, le)),
        Light::from(RectangleLight::new(a, b, ey, le)),
        Light::from(RectangleLight::new(a, b, c, le)),
    ];
    for (i, l) in lights.iter().enumerate() {
        check_light(l, p, u, w, &format!("light {i}"));
        for mode in LightSampling::ALL {
            check_mode(l, p, w, u, mode, &format!("light {i}"));
        }
    }

    // BSDFs in the local frame, with reflectances in [0, 1].
    let (wo, wi) = (v(5), v(8));
    let kd = f[21].abs().min(1.0);
    let ks = (1.0 - kd) * f[22].abs().min(1.0);
    let phong = Phong::new(Vec3::splat(kd), Vec3::splat(ks), f[23]);
    let lambert = Lambert::new(Vec3::splat(kd));
    let s = phong.sample(wo, u);
    assert!(s.pdf.is_finite() && s.pdf >= 0.0, "phong pdf {s:?}");
    assert!(s.f.is_finite() && s.f.min_element() >= 0.0, "phong f {s:?}");
    if !s.wi.is_nan() {
        assert_eq!(phong.pdf(wo, s.wi).to_bits(), s.pdf.to_bits(), "phong sample pdf ≠ pdf");
    }
    let e = phong.eval(wo, wi);
    assert!(e.is_finite() && e.min_element() >= 0.0, "phong eval {e}");
    if wo.is_finite() && wi.is_finite() {
        assert_eq!(bits(e), bits(phong.eval(wi, wo)), "phong reciprocity");
    }
    let ls = lambert.sample(wo, u);
    assert!(ls.pdf.is_finite() && ls.pdf >= 0.0 && ls.f.is_finite(), "lambert {ls:?}");
    let p8 = Phong::new(Vec3x8::splat(Vec3::splat(kd)), Vec3x8::splat(Vec3::splat(ks)), F32x8::splat(f[23]));
    let s8 = p8.sample(Vec3x8::splat(wo), Vec2x8::splat(u));
    assert_eq!(bits(s8.wi.lane(0)), bits(s.wi), "phong packet wi");
    assert_eq!(s8.pdf.to_array()[0].to_bits(), s.pdf.to_bits(), "phong packet pdf");
    assert_eq!(bits(s8.f.lane(0)), bits(s.f), "phong packet f");
    assert_eq!(bits(p8.eval(Vec3x8::splat(wo), Vec3x8::splat(wi)).lane(0)), bits(e), "phong packet eval");
    let p16 = Phong::new(Vec3x16::splat(Vec3::splat(kd)), Vec3x16::splat(Vec3::splat(ks)), F32x16::splat(f[23]));
    let s16 = p16.sample(Vec3x16::splat(wo), Vec2x16::splat(u));
    assert_eq!(bits(s16.wi.lane(15)), bits(s.wi), "phong x16 wi");
    assert_eq!(s16.pdf.to_array()[15].to_bits(), s.pdf.to_bits(), "phong x16 pdf");
    assert_eq!(bits(s16.f.lane(15)), bits(s.f), "phong x16 f");
    assert_eq!(bits(p16.eval(Vec3x16::splat(wo), Vec3x16::splat(wi)).lane(15)), bits(e), "phong x16 eval");
});
