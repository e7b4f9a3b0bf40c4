//! Every sequence generator and the camera sampler on arbitrary indices, counts, grids,
//! dimensions, seeds, pixels and shutters: no panic, values in [0, 1) (never 1.0), film and lens
//! finite, times in [open, close) for a finite shutter, and packet lanes (eight and sixteen
//! wide) equal to the scalar form bit for bit.

#![no_main]

use glam::Vec2;
use libfuzzer_sys::fuzz_target;
use mcsample::camera::{CameraSample, PixelFilter};
use mcsample::seq;
use mcsample::x8::U32x8;
use mcsample::x16::U32x16;

fn words(data: &[u8]) -> [u32; 16] {
    let mut out = [0u32; 16];
    for (o, c) in out.iter_mut().zip(data.chunks_exact(4)) {
        *o = u32::from_le_bytes([c[0], c[1], c[2], c[3]]);
    }
    out
}

fn unit(v: f32, what: &str) {
    assert!((0.0..1.0).contains(&v), "{what}: {v} outside [0, 1)");
}

fuzz_target!(|data: &[u8]| {
    let w = words(data);
    let indices: [u32; 8] = core::array::from_fn(|k| w[k]);
    let packet = U32x8::new(indices);
    let (count, nx, ny, dim, seed) = (w[8], w[9], w[10], w[11], w[12]);
    let pixel = [w[13], w[14]];
    let shutter = (f32::from_bits(w[15]), f32::from_bits(w[15].rotate_left(7)));

    let s = seq::stratified(packet, count, dim, seed).to_array();
    let l = seq::latin_hypercube(packet, count, dim, seed).to_array();
    let ind = seq::independent(packet, dim, seed).to_array();
    let so = seq::sobol(packet, dim, seed).to_array();
    let pairs: [(&str, [Vec2; 8], fn(u32, u32, u32, u32, u32) -> Vec2); 3] = [
        ("jittered_2d", seq::jittered_2d(packet, nx, ny, dim, seed).to_array(), seq::jittered_2d),
        ("multi_jittered_2d", seq::multi_jittered_2d(packet, nx, ny, dim, seed).to_array(), seq::multi_jittered_2d),
        ("cmj_2d", seq::cmj_2d(packet, nx, ny, dim, seed).to_array(), seq::cmj_2d),
    ];
    let so2 = seq::sobol_2d(packet, dim, seed).to_array();
    let filter = if seed & 1 == 0 { PixelFilter::Box } else { PixelFilter::Tent };
    let cam = CameraSample::<U32x8>::generate(pixel, packet, seed, filter, shutter);
    let (film, lens, time) = (cam.film.to_array(), cam.lens.to_array(), cam.time.to_array());

    // Sixteen lanes: the indices twice over, each lane equal to the eight-wide lane (checked
    // against the scalar form below).
    let p16 = U32x16::new(core::array::from_fn(|k| indices[k % 8]));
    let same16 = |a: &[f32], b: &[f32]| a.iter().enumerate().all(|(k, x)| x.to_bits() == b[k % 8].to_bits());
    let flat = |v: &[Vec2]| v.iter().flat_map(|p| [p.x, p.y]).collect::<Vec<f32>>();
    let flat16 = |v: &[Vec2]| {
        let f = flat(v);
        (0..16).map(|k| [f[2 * k], f[2 * k + 1]]).collect::<Vec<_>>()
    };
    assert!(same16(&seq::stratified(p16, count, dim, seed).to_array(), &s), "stratified x16");
    assert!(same16(&seq::latin_hypercube(p16, count, dim, seed).to_array(), &l), "latin_hypercube x16");
    assert!(same16(&seq::independent(p16, dim, seed).to_array(), &ind), "independent x16");
    assert!(same16(&seq::sobol(p16, dim, seed).to_array(), &so), "sobol x16");
    let pairs16: [(&str, [Vec2; 16], [Vec2; 8]); 4] = [
        ("jittered_2d", seq::jittered_2d(p16, nx, ny, dim, seed).to_array(), pairs[0].1),
        ("multi_jittered_2d", seq::multi_jittered_2d(p16, nx, ny, dim, seed).to_array(), pairs[1].1),
        ("cmj_2d", seq::cmj_2d(p16, nx, ny, dim, seed).to_array(), pairs[2].1),
        ("sobol_2d", seq::sobol_2d(p16, dim, seed).to_array(), so2),
    ];
    for (what, sixteen, eight) in pairs16 {
        let (a, b) = (flat16(&sixteen), flat16(&[eight, eight].concat()));
        assert!(a.iter().zip(&b).all(|(x, y)| x.map(f32::to_bits) == y.map(f32::to_bits)), "{what} x16");
    }
    let cam16 = CameraSample::<U32x16>::generate(pixel, p16, seed, filter, shutter);
    assert!(same16(&cam16.time.to_array(), &time), "camera time x16");
    assert!(flat(&cam16.film.to_array()) == flat(&[film, film].concat()), "camera film x16");
    assert!(flat(&cam16.lens.to_array()) == flat(&[lens, lens].concat()), "camera lens x16");

    for (k, &i) in indices.iter().enumerate() {
        let one = [
            ("stratified", seq::stratified(i, count, dim, seed), s[k]),
            ("latin_hypercube", seq::latin_hypercube(i, count, dim, seed), l[k]),
            ("independent", seq::independent(i, dim, seed), ind[k]),
            ("sobol", seq::sobol(i, dim, seed), so[k]),
        ];
        for (what, scalar, lane) in one {
            unit(scalar, what);
            assert_eq!(scalar.to_bits(), lane.to_bits(), "{what}: lane {k} differs");
        }
        for (what, lanes, scalar) in &pairs {
            let p = scalar(i, nx, ny, dim, seed);
            unit(p.x, what);
            unit(p.y, what);
            assert_eq!([p.x.to_bits(), p.y.to_bits()], [lanes[k].x.to_bits(), lanes[k].y.to_bits()], "{what}: lane {k}");
        }
        let p = seq::sobol_2d(i, dim, seed);
        assert_eq!([p.x.to_bits(), p.y.to_bits()], [so2[k].x.to_bits(), so2[k].y.to_bits()], "sobol_2d: lane {k}");

        let c = CameraSample::generate(pixel, i, seed, filter, shutter);
        assert!(c.film.is_finite() && c.lens.is_finite() && c.lens.length() <= 1.0 + 1e-6, "{c:?}");
        let same = |a: f32, b: f32| a.to_bits() == b.to_bits();
        assert!(same(c.film.x, film[k].x) && same(c.film.y, film[k].y), "film lane {k}");
        assert!(same(c.lens.x, lens[k].x) && same(c.lens.y, lens[k].y), "lens lane {k}");
        assert!(same(c.time, time[k]), "time lane {k}");
        let (open, close) = shutter;
        if open.is_finite() && close.is_finite() {
            if close > open {
                assert!(c.time >= open && c.time < close, "time {} for {shutter:?}", c.time);
            } else {
                assert_eq!(c.time, open);
            }
        } else {
            assert!(c.time.is_nan());
        }
    }
});
