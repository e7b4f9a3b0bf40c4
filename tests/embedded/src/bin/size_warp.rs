//! The flash cost of one warp: a cosine-weighted direction and its pdf.

#![no_std]
#![no_main]

use cortex_m_rt::entry;
use glam::Vec2;
use mcsample::warp;

#[entry]
fn main() -> ! {
    let u = core::hint::black_box(Vec2::new(0.3, 0.7));
    let w = warp::cosine_hemisphere(u);
    let pdf = warp::cosine_hemisphere_pdf(w);
    mcsample_firmware::exit(core::hint::black_box(w.z * pdf) > 0.0)
}
