//! The lecture's picture: Veach's multiple importance sampling scene (Veach and Guibas 1995;
//! Veach 1997, fig. 9.2). Four glossy plates of increasing sharpness under four sphere lights of
//! increasing size and equal power, seen through a pinhole camera, rendered three times at equal
//! samples per pixel: light sampling, BSDF sampling and MIS with the power heuristic. The three
//! renderings go side by side into one PNG.
//!
//! `cargo run --release --example mis_plates -- [--out PATH] [--width W] [--spp S]`
//! (defaults `mis_plates.png`, 360 pixels per panel, 8 samples per pixel). Each sample is one
//! shading point with two samples of its strategy (one light and one BSDF sample for MIS).
//!
//! The ray caster for plates and spheres lives here, not in the library. Camera samples come
//! from `camera::CameraSample` and shading from `mcsample::direct` through its packet path:
//! the eight samples of a pixel are eight lanes.

use std::time::Instant;

use glam::{Vec2, Vec3};
use mcsample::camera::{CameraSample, PixelFilter};
use mcsample::direct::{self, Config, Lights, ShadingPoint, Strategy};
use mcsample::scene::{Light, Phong, SphereLight};
use mcsample::seq::{Generator, Sequence};
use mcsample::x8::{F32x8, U32x8, Vec3x8};

/// A plate: the parallelogram corner + s·ex + t·ey, s, t ∈ [0, 1], facing `n`, with its
/// Phong exponent.
struct Plate {
    corner: Vec3,
    ex: Vec3,
    ey: Vec3,
    n: Vec3,
    exponent: f32,
}

/// The scene's geometry, after Veach's: plates spanning x ∈ [−4, 4], from the back (the sharpest,
/// top of the image) to the front; lights on the x axis with radius r and radiance ∝ 1/r².
fn plates() -> [Plate; 4] {
    // (y, z) of the near and far edges, and the exponent.
    let rows = [
        (-2.70651, 0.25609, -2.08375, -0.526323, 10000.0),
        (-3.28825, 1.36972, -2.83856, 0.476536, 1500.0),
        (-3.73096, 2.70046, -3.43378, 1.74564, 300.0),
        (-3.99615, 4.0667, -3.82069, 3.08221, 60.0),
    ];
    rows.map(|(y0, z0, y1, z1, exponent)| {
        let corner = Vec3::new(-4.0, y0, z0);
        let ex = Vec3::new(8.0, 0.0, 0.0);
        let ey = Vec3::new(0.0, y1 - y0, z1 - z0);
        let n = ex.cross(ey).normalize();
        // Face the camera, which is up and in front.
        let n = if n.y < 0.0 { -n } else { n };
        Plate {
            corner,
            ex,
            ey,
            n,
            exponent,
        }
    })
}

fn lights() -> [Light; 4] {
    [(3.75, 0.03), (1.25, 0.1), (-1.25, 0.3), (-3.75, 0.9)].map(|(x, r): (f32, f32)| {
        // Equal power: Le·r² the same for every light.
        let le = 0.81 / (r * r);
        Light::from(SphereLight::new(Vec3::new(x, 0.0, 0.0), r, Vec3::splat(le)))
    })
}

/// The nearest plate along o + t·d for t in (t_min, t_max): (t, plate index).
fn hit_plate(plates: &[Plate], o: Vec3, d: Vec3, t_min: f32, t_max: f32) -> Option<(f32, usize)> {
    let mut best = None;
    let mut t_best = t_max;
    for (i, pl) in plates.iter().enumerate() {
        let denom = d.dot(pl.n);
        if denom.abs() < 1e-12 {
            continue;
        }
        let t = (pl.corner - o).dot(pl.n) / denom;
        if !(t > t_min && t < t_best) {
            continue;
        }
        let q = o + d * t - pl.corner;
        let (s, v) = (
            q.dot(pl.ex) / pl.ex.length_squared(),
            q.dot(pl.ey) / pl.ey.length_squared(),
        );
        if (0.0..=1.0).contains(&s) && (0.0..=1.0).contains(&v) {
            best = Some((t, i));
            t_best = t;
        }
    }
    best
}

/// The nearest light seen along the ray, its distance and radiance.
fn hit_light(lights: &[Light], o: Vec3, d: Vec3) -> Option<(f32, Vec3)> {
    let mut best: Option<(f32, Vec3)> = None;
    for l in lights {
        let t = l.hit(o, d);
        if t.is_finite() && best.is_none_or(|(b, _)| t < b) {
            best = Some((t, l.le));
        }
    }
    best
}

struct Camera {
    eye: Vec3,
    forward: Vec3,
    right: Vec3,
    up: Vec3,
    /// tan(fov/2) for the image height.
    tan_half: f32,
}

impl Camera {
    fn new() -> Self {
        let eye = Vec3::new(0.0, 2.0, 15.0);
        let forward = (Vec3::new(0.0, -2.0, 2.5) - eye).normalize();
        let right = forward.cross(Vec3::Y).normalize();
        let up = right.cross(forward);
        Camera {
            eye,
            forward,
            right,
            up,
            tan_half: (28f32.to_radians() * 0.5).tan(),
        }
    }

    /// The ray through film position `film` (pixels) of a `w` × `h` image.
    fn ray(&self, film: Vec2, w: f32, h: f32) -> Vec3 {
        let x = (2.0 * film.x - w) / h * self.tan_half;
        let y = (h - 2.0 * film.y) / h * self.tan_half;
        (self.forward + self.right * x + self.up * y).normalize()
    }
}

/// One panel rendered with `strategy`: linear RGB, row major.
fn render(strategy: Strategy, w: u32, h: u32, spp: u32) -> Vec<Vec3> {
    let (plates, lights) = (plates(), lights());
    let selection = Lights::uniform(&lights);
    let camera = Camera::new();
    let config = Config::new(1, 1);
    let n = config.samples();
    let mut image = vec![Vec3::ZERO; (w * h) as usize];
    // Shadow rays: blocked by a plate between the shading point and the light.
    let mut visible = |m: F32x8, from: Vec3x8, to: Vec3x8| {
        let (m, from, to) = (m.to_array(), from.to_array(), to.to_array());
        F32x8::new(std::array::from_fn(|i| {
            let d = to[i] - from[i];
            let len = d.length();
            let open = m[i] != 0.0
                && hit_plate(&plates, from[i], d / len, 1e-4 * len, len * (1.0 - 1e-4)).is_none();
            if open { f32::from_bits(!0) } else { 0.0 }
        }))
    };
    for py in 0..h {
        for px in 0..w {
            let pixel = py * w + px;
            let mut color = Vec3::ZERO;
            for pass in 0..spp.div_ceil(8) {
                let index = U32x8::new(std::array::from_fn(|i| pass * 8 + i as u32));
                let cs = CameraSample::generate([px, py], index, 7, PixelFilter::Box, (0.0, 0.0));
                let films = cs.film.to_array();
                // Per lane: the shading point and material where the ray meets a plate; a lane
                // that sees a light or nothing gets ωo below its normal, which the estimator
                // answers with 0.
                let mut p = [Vec3::ZERO; 8];
                let mut nrm = [Vec3::Z; 8];
                let mut wo = [Vec3::NEG_Z; 8];
                let mut exps = [1.0f32; 8];
                let lanes = (spp - pass * 8).min(8) as usize;
                for i in 0..lanes {
                    let d = camera.ray(films[i], w as f32, h as f32);
                    let plate = hit_plate(&plates, camera.eye, d, 0.0, f32::INFINITY);
                    let light = hit_light(&lights, camera.eye, d);
                    match (plate, light) {
                        (Some((t, k)), l) if l.is_none_or(|(tl, _)| t < tl) => {
                            p[i] = camera.eye + d * t;
                            nrm[i] = plates[k].n;
                            wo[i] = -d;
                            exps[i] = plates[k].exponent;
                        }
                        (_, Some((_, le))) => color += le,
                        _ => {}
                    }
                }
                let at = ShadingPoint {
                    p: Vec3x8::from(p),
                    n: Vec3x8::from(nrm),
                    wo: Vec3x8::from(wo),
                };
                let bsdf = Phong::new(
                    Vec3x8::splat(Vec3::splat(0.03)),
                    Vec3x8::splat(Vec3::splat(0.9)),
                    F32x8::new(exps),
                );
                let mut samples = Sequence {
                    first: U32x8::new(std::array::from_fn(|i| {
                        (pixel.wrapping_mul(spp) + pass * 8 + i as u32).wrapping_mul(n)
                    })),
                    seed: 11,
                    generator: Generator::Independent,
                };
                let e = direct::estimate(
                    strategy, &selection, &bsdf, at, config, &mut samples, &mut visible,
                );
                color += e.radiance.to_array()[..lanes].iter().sum::<Vec3>();
            }
            image[pixel as usize] = color / spp as f32;
        }
    }
    image
}

/// Linear to 8-bit sRGB, clamped.
fn srgb(x: f32) -> u8 {
    let x = x.clamp(0.0, 1.0);
    let s = if x <= 0.003_130_8 {
        12.92 * x
    } else {
        1.055 * x.powf(1.0 / 2.4) - 0.055
    };
    (s * 255.0 + 0.5) as u8
}

fn main() {
    let mut out = String::from("mis_plates.png");
    let (mut w, mut spp) = (360u32, 8u32);
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        let mut value = || args.next().unwrap_or_else(|| panic!("{a} needs a value"));
        match a.as_str() {
            "--out" => out = value(),
            "--width" => w = value().parse().expect("--width W"),
            "--spp" => spp = value().parse().expect("--spp S"),
            other => panic!("unknown argument {other}; use --out PATH, --width W, --spp S"),
        }
    }
    let (w, spp) = (w.max(8), spp.max(1));
    let h = w * 2 / 3;
    let gap = 4;
    let t = Instant::now();
    let panels = [
        Strategy::LightSolidAngle,
        Strategy::Bsdf,
        Strategy::MisPower,
    ]
    .map(|s| render(s, w, h, spp));
    let full_w = 3 * w + 2 * gap;
    let mut rgb = vec![255u8; (full_w * h * 3) as usize];
    for (k, panel) in panels.iter().enumerate() {
        for y in 0..h {
            for x in 0..w {
                let c = panel[(y * w + x) as usize];
                let o = ((y * full_w + k as u32 * (w + gap) + x) * 3) as usize;
                rgb[o..o + 3].copy_from_slice(&[srgb(c.x), srgb(c.y), srgb(c.z)]);
            }
        }
    }
    let file = std::fs::File::create(&out).unwrap_or_else(|e| panic!("cannot create {out}: {e}"));
    let mut enc = png::Encoder::new(std::io::BufWriter::new(file), full_w, h);
    enc.set_color(png::ColorType::Rgb);
    enc.set_depth(png::BitDepth::Eight);
    let mut writer = enc.write_header().expect("PNG header");
    writer.write_image_data(&rgb).expect("PNG data");
    println!(
        "wrote {out}: light sampling | BSDF sampling | MIS (power), {w}×{h} each, {spp} spp, {:.1} s",
        t.elapsed().as_secs_f64()
    );
}
