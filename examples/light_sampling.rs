//! Light sampling that sees the surface, as a picture: a diffuse floor under a large tilted
//! rectangle light and a sphere light near the horizon, rendered at one sample of each light per
//! pixel in every mode of `scene::LightSampling`, side by side in one PNG, and each panel's error
//! against a many-sample rendering printed.
//!
//! `cargo run --release --example light_sampling -- [--out PATH] [--width W]`
//! (defaults `light_sampling.png`, 320 pixels per panel). Each pixel is one shading point
//! estimated by `direct::estimate` with light sampling (`Strategy::LightSolidAngle`, one
//! sample) of each light in the panel's mode, the two summed (no light selection, whose own
//! noise would hide the modes'); the reference takes 256 samples of each by solid angle. The
//! sphere is sampled by its cone in every mode but the projected one (by its cap).

use std::time::Instant;

use glam::{Vec2, Vec3};
use mcsample::direct::{self, Config, Lights, ShadingPoint, Strategy};
use mcsample::scene::{Lambert, Light, LightSampling, RectangleLight, SphereLight};
use mcsample::seq::{Generator, Sequence};

/// The lights: a large rectangle, tilted 27° and low over the floor, so that the floor's cosine
/// varies by a factor of several across it; and a sphere low over the floor's right side, whose
/// cap straddles the horizon of the floor around it.
fn lights() -> [Light; 2] {
    [
        Light::from(RectangleLight::new(
            Vec3::new(-2.0, -1.0, 0.6),
            Vec3::new(0.0, 2.5, 0.0),
            Vec3::new(3.0, 0.0, 1.5),
            Vec3::splat(1.5),
        )),
        Light::from(SphereLight::new(
            Vec3::new(2.2, 0.6, 0.45),
            0.4,
            Vec3::new(3.0, 2.4, 1.6),
        )),
    ]
}

/// A pinhole camera looking down at the floor.
struct Camera {
    eye: Vec3,
    forward: Vec3,
    right: Vec3,
    up: Vec3,
    tan_half: f32,
}

impl Camera {
    fn new() -> Self {
        let eye = Vec3::new(0.2, -4.5, 3.2);
        let forward = (Vec3::new(0.2, 0.2, 0.0) - eye).normalize();
        let right = forward.cross(Vec3::Z).normalize();
        Camera {
            eye,
            forward,
            right,
            up: right.cross(forward),
            tan_half: (40f32.to_radians() * 0.5).tan(),
        }
    }

    fn ray(&self, film: Vec2, w: f32, h: f32) -> Vec3 {
        let x = (2.0 * film.x - w) / h * self.tan_half;
        let y = (h - 2.0 * film.y) / h * self.tan_half;
        (self.forward + self.right * x + self.up * y).normalize()
    }
}

/// The floor's radiance at every pixel centre, from `spp` light samples per pixel in `mode`.
fn render(mode: LightSampling, w: u32, h: u32, spp: u32, seed: u32) -> Vec<Vec3> {
    let lights = lights();
    let selections = lights
        .each_ref()
        .map(|l| Lights::uniform(core::slice::from_ref(l)));
    let camera = Camera::new();
    let floor = Lambert::new(Vec3::splat(0.8));
    let config = Config::new(spp, 0).with_light_sampling(mode);
    let mut visible = |_: Vec3, _: Vec3| true;
    let mut image = vec![Vec3::ZERO; (w * h) as usize];
    for py in 0..h {
        for px in 0..w {
            let film = Vec2::new(px as f32 + 0.5, py as f32 + 0.5);
            let d = camera.ray(film, w as f32, h as f32);
            // The floor z = 0; above the horizon the pixel stays black.
            if d.z >= 0.0 {
                continue;
            }
            let p = camera.eye + d * (-camera.eye.z / d.z);
            let at = ShadingPoint {
                p,
                n: Vec3::Z,
                wo: -d,
            };
            let pixel = py * w + px;
            for (k, selection) in selections.iter().enumerate() {
                let mut samples = Sequence {
                    first: pixel.wrapping_mul(config.samples()),
                    seed: seed + 7 * k as u32,
                    generator: Generator::Independent,
                };
                let e = direct::estimate(
                    Strategy::LightSolidAngle,
                    selection,
                    &floor,
                    at,
                    config,
                    &mut samples,
                    &mut visible,
                );
                image[pixel as usize] += e.radiance;
            }
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

/// The relative RMSE of `image` against `reference`, over the lit pixels.
fn rel_rmse(image: &[Vec3], reference: &[Vec3]) -> f64 {
    let (mut se, mut sum, mut n) = (0.0f64, 0.0f64, 0usize);
    for (a, r) in image.iter().zip(reference) {
        if r.x > 0.0 {
            se += f64::from(a.x - r.x).powi(2);
            sum += f64::from(r.x);
            n += 1;
        }
    }
    (se / n as f64).sqrt() / (sum / n as f64)
}

fn main() {
    let mut out = String::from("light_sampling.png");
    let mut w = 320u32;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        let mut value = || args.next().unwrap_or_else(|| panic!("{a} needs a value"));
        match a.as_str() {
            "--out" => out = value(),
            "--width" => w = value().parse().expect("--width W"),
            other => panic!("unknown argument {other}; use --out PATH, --width W"),
        }
    }
    let w = w.max(8);
    let h = w * 3 / 4;
    let gap = 4;
    let t = Instant::now();
    let reference = render(LightSampling::SolidAngle, w, h, 256, 1);
    let panels: Vec<(LightSampling, Vec<Vec3>)> = LightSampling::ALL
        .iter()
        .map(|&m| (m, render(m, w, h, 1, 2)))
        .collect();
    let count = panels.len() as u32;
    let full_w = count * w + (count - 1) * gap;
    let mut rgb = vec![255u8; (full_w * h * 3) as usize];
    for (k, (_, panel)) in panels.iter().enumerate() {
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
    let names: Vec<&str> = panels.iter().map(|(m, _)| m.name()).collect();
    println!(
        "wrote {out}: {} at 1 sample of each light per pixel, {w}×{h} each, {:.1} s",
        names.join(" | "),
        t.elapsed().as_secs_f64()
    );
    for (m, panel) in &panels {
        println!(
            "{:>12}: relative RMSE {:.4} against 256 samples by solid angle",
            m.name(),
            rel_rmse(panel, &reference)
        );
    }
}
