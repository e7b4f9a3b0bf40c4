//! Every sampler of the registry on arbitrary u, parameters and geometry: no panic, the
//! documented bad-input policy of `Sampler::check_sample` and `Sampler::check_point`, and the
//! packet forms' lanes (eight and sixteen wide) equal to the scalar form bit for bit (sample,
//! pdf and inverse).

#![no_main]

use glam::{Vec2, Vec3};
use libfuzzer_sys::fuzz_target;
use mcsample::scene::AnyShape;
use mcsample::verify::registry::{self, LightSampler, Sampler};
use mcsample::x8::{Vec2x8, Vec3x8};
use mcsample::x16::{Vec2x16, Vec3x16};

fn floats(data: &[u8]) -> [f32; 16] {
    let mut out = [0.0f32; 16];
    for (o, c) in out.iter_mut().zip(data.chunks_exact(4)) {
        *o = f32::from_le_bytes([c[0], c[1], c[2], c[3]]);
    }
    out
}

/// One lane of a packet (all lanes carry the same input) against the scalar result, bit for bit.
fn same(s: [f32; 3], p: [f32; 3], what: &str, s_name: &str) {
    assert_eq!(
        s.map(f32::to_bits),
        p.map(f32::to_bits),
        "{s_name}: {what}: packet lane differs from scalar"
    );
}

fuzz_target!(|data: &[u8]| {
    let f = floats(data);
    let u = Vec2::new(f[0], f[1]);
    let geometry = [
        Vec3::new(f[4], f[5], f[6]),
        Vec3::new(f[7], f[8], f[9]),
        Vec3::new(f[10], f[11], f[12]),
    ];
    let point = Vec3::new(f[13], f[14], f[15]);
    for s in registry::registry() {
        // The cone takes f[2] as h, the Phong lobe f[3] as n; the polygons the fuzzed vertices.
        let param = if matches!(s, Sampler::PhongLobe(_)) { f[3] } else { f[2] };
        // The rectangle's contract asks for orthogonal edges: keep the fuzzed light inside it.
        let geometry = match s {
            Sampler::SphericalRectangle(_)
            | Sampler::Light(LightSampler(AnyShape::Rectangle(_))) => {
                let [c, ex, ey] = geometry;
                let ey = ey - ex * (ey.dot(ex) / ex.length_squared());
                // f32 Gram–Schmidt leaves a rounding residue along ex when ey's part along it is
                // huge (ey = (0, −512, −8.8e12) against ex = (0, 0, 8.5e6) came back parallel to
                // ex). Where the edges are not orthogonal to 1e-4, take an exactly orthogonal
                // edge of ey's length instead, so the fuzzed light stays within the contract.
                let (a, b) = (ex.as_dvec3(), ey.as_dvec3());
                let cos = a.dot(b) / (a.length() * b.length());
                let ey = if cos.abs() > 1e-4 && ex.is_finite() && ex != Vec3::ZERO {
                    ex.any_orthogonal_vector() * ey.length()
                } else {
                    ey
                };
                [c, ex, ey]
            }
            _ => geometry,
        };
        let s = s.with_param(param).with_geometry(geometry);
        let name = s.name();

        let (x, pdf) = s.sample(u);
        let (x8, pdf8) = s.sample(Vec2x8::splat(u));
        same(x.to_array(), x8.to_array()[0].to_array(), "sample", &name);
        same([pdf; 3], [pdf8.to_array()[0]; 3], "sample pdf", &name);
        let (x16, pdf16) = s.sample(Vec2x16::splat(u));
        same(x.to_array(), x16.lane(15).to_array(), "x16 sample", &name);
        same([pdf; 3], [pdf16.to_array()[15]; 3], "x16 sample pdf", &name);
        for q in [x, point] {
            let q8 = Vec3x8::splat(q);
            same([s.pdf(q); 3], [s.pdf(q8).to_array()[0]; 3], "pdf", &name);
            let (b, b8) = (s.inverse(q), s.inverse(q8).to_array()[0]);
            same(b.extend(0.0).to_array(), b8.extend(0.0).to_array(), "inverse", &name);
            let q16 = Vec3x16::splat(q);
            same([s.pdf(q); 3], [s.pdf(q16).to_array()[15]; 3], "x16 pdf", &name);
            let b16 = s.inverse(q16).lane(15);
            same(b.extend(0.0).to_array(), b16.extend(0.0).to_array(), "x16 inverse", &name);
        }
        s.check_sample(u).unwrap();
        s.check_point(point).unwrap();
    }
});
