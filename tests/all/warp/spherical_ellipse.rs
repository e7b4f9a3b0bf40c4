//! Disk lights sampled by solid angle (Guillén et al., "Area-Preserving Parameterizations for
//! Spherical Ellipses", EGSR 2017).
//!
//! Facts checked: Ω of the disk matches the values published for two disks and the closed form
//! 2π(1 − h/√(h² + r²)) on its axis, and the area integral ∫ h/|q|³ dA over random disks; every
//! sample lies on the disk with pdf 1/Ω; the density is uniform in solid angle (χ²), and a pdf
//! 1 % off on half of the disk is rejected; a disk seen on its axis, edge-on and at 1e-9 sr; bad
//! input; lane i of the eight-wide form is the scalar call, with a different disk per lane.

use glam::{DVec3, Vec2, Vec3};
use mcsample::reference::disk_solid_angle;
use mcsample::verify::{Cap, ChiSquare};
use mcsample::warp::{
    ELLIPSE_MIN_SR, SphericalEllipse, spherical_ellipse, spherical_ellipse_inverse,
    spherical_ellipse_pdf,
};
use mcsample::x8::{F32x8, Vec2x8, Vec3x8};

use crate::common::TestRng;

/// Ω of the f32 disk by its area integral, in f64.
fn reference(c: Vec3, n: Vec3, r: f32) -> f64 {
    disk_solid_angle(c.as_dvec3().to_array(), n.as_dvec3().to_array(), r as f64)
}

/// True when the ray along unit w meets the disk, within `slack` of its radius and the f32
/// rounding of a direction (2⁻²³ of the distance across the ray, stretched by 1/|w·n| in the
/// plane) (f64).
fn hits(w: Vec3, c: Vec3, n: Vec3, r: f32, slack: f64) -> bool {
    let (w, c, n) = (w.as_dvec3(), c.as_dvec3(), n.as_dvec3().normalize());
    let t = c.dot(n) / w.dot(n);
    t > 0.0 && (w * t - c).length() <= r as f64 * (1.0 + slack) + t * 1.2e-7 / w.dot(n).abs()
}

/// A random disk: centre at distance 1 to 10 in a random direction, a random normal, radius
/// from 1e-4 to 3 times the distance.
fn random_disk(rng: &mut TestRng) -> (Vec3, Vec3, f32) {
    let dir = |rng: &mut TestRng| {
        let (z, phi) = (
            2.0 * rng.u01() as f64 - 1.0,
            rng.u01() as f64 * std::f64::consts::TAU,
        );
        let s = (1.0 - z * z).sqrt();
        DVec3::new(s * phi.cos(), s * phi.sin(), z)
    };
    let d = 1.0 + 9.0 * rng.u01() as f64;
    let c = dir(rng) * d;
    let n = dir(rng);
    let r = d * 3.0 * 10f64.powf(-4.5 * rng.u01() as f64);
    (c.as_vec3(), n.as_vec3(), r as f32)
}

/// The published values: r = 3 at (0, 3, 3) and r = 1 at (0, 2, ½), both with normal −y, and the
/// disk r = 1 one unit along its axis, 2π(1 − 1/√2). The f32 form within 1e-6, its f64 instance
/// within 1e-10 (measured 3e-13).
#[test]
fn solid_angle_matches_the_published_values() {
    for (c, n, r, omega) in [
        (
            Vec3::new(0.0, 3.0, 3.0),
            Vec3::NEG_Y,
            3.0f32,
            1.122_686_833_611,
        ),
        (
            Vec3::new(0.0, 2.0, 0.5),
            Vec3::NEG_Y,
            1.0,
            0.622_856_067_971,
        ),
        (
            Vec3::new(0.0, 1.0, 0.0),
            Vec3::NEG_Y,
            1.0,
            1.840_302_369_021,
        ),
    ] {
        let f32_omega = SphericalEllipse::new(c, n, r).solid_angle() as f64;
        let f64_omega = SphericalEllipse::new(c.as_dvec3(), n.as_dvec3(), r as f64).solid_angle();
        assert!(
            ((f32_omega - omega) / omega).abs() < 1e-6,
            "{c}: {f32_omega} vs {omega}"
        );
        assert!(
            ((f64_omega - omega) / omega).abs() < 1e-10,
            "{c}: {f64_omega} vs {omega}"
        );
        assert!(((reference(c, n, r) - omega) / omega).abs() < 1e-11);
    }
}

/// Ω (the f64 instance) matches the area integral on 20 000 random disks from 1e-12 sr to nearly
/// 2π within 1e-14 sr plus 1e-12 of itself: F(π/2) is a difference of terms of size π/2, so its
/// error is absolute (measured at most 4.6e-15 sr). From ELLIPSE_MIN_SR up that is within 1e-7
/// relative (measured 2.5e-8), and a disk of 1e-10 sr keeps 1e-4.
#[test]
fn solid_angle_matches_the_area_integral() {
    let mut rng = TestRng::new(51);
    let (mut worst_abs, mut worst_rel, mut small) = (0.0f64, 0.0f64, 0);
    for _ in 0..20_000 {
        let (c, n, r) = random_disk(&mut rng);
        let want = reference(c, n, r);
        let got = SphericalEllipse::new(c.as_dvec3(), n.as_dvec3(), r as f64).solid_angle();
        let err = (got - want).abs();
        assert!(err <= 1e-14 + 1e-12 * want, "{c} {n} {r}: {got} vs {want}");
        worst_abs = worst_abs.max(err - 1e-12 * want);
        if want >= f64::from(ELLIPSE_MIN_SR) {
            worst_rel = worst_rel.max(err / want);
        } else {
            small += 1;
        }
    }
    println!(
        "worst absolute {worst_abs:e}, relative from ELLIPSE_MIN_SR {worst_rel:e}, {small} smaller"
    );
    assert!(worst_rel < 1e-7 && small > 100, "{worst_rel:e} {small}");
}

/// The map's density is 1/Ω: Ω (Carlson's integrals) against the map's own table of the
/// sector's solid angle (Gauss–Legendre over each interval of the parametric angle) agree within 1e-9 from 1e-3
/// sr (measured 3.9e-10, at a major half-angle of 83°) and within 1e-7 from ELLIPSE_MIN_SR
/// (measured 1.9e-8, Carlson's absolute error at 1e-7 sr), over 20 000 random disks.
#[test]
fn the_maps_density_is_one_over_omega() {
    let mut rng = TestRng::new(58);
    let (mut large, mut small, mut count) = (0.0f64, 0.0f64, 0);
    for _ in 0..20_000 {
        let (c, n, r) = random_disk(&mut rng);
        let e = SphericalEllipse::new(c.as_dvec3(), n.as_dvec3(), r as f64);
        if e.by_area() {
            continue;
        }
        count += 1;
        let err = e.density_error().abs();
        if e.solid_angle() >= 1e-3 {
            large = large.max(err);
        } else {
            small = small.max(err);
        }
    }
    println!("density error: {large:e} from 1e-3 sr, {small:e} below ({count} disks)");
    assert!(
        count > 10_000 && large < 1e-9 && small < 1e-7,
        "{large:e} {small:e}"
    );
}

/// Every sample of 2000 random disks × 64 u lies on the disk (within 1e-5 of its radius) with
/// pdf 1/Ω where the ellipse is sampled, and the area pdf h²/(|ω·n|³πr²) where Ω is below
/// ELLIPSE_MIN_SR; and it inverts to its u (u₀ above 1e-2) within 2e-5·(1 + 2e-2/b), b the
/// sine of the minor half-angle (the f32 direction's rounding, over b).
#[test]
fn samples_lie_on_the_disk_and_invert() {
    let mut rng = TestRng::new(52);
    let (mut by_area, mut worst) = (0, 0.0f32);
    for _ in 0..2000 {
        let (c, n, r) = random_disk(&mut rng);
        let e = SphericalEllipse::new(c, n, r);
        if e.by_area() {
            by_area += 1;
        }
        for _ in 0..64 {
            let u = rng.u2();
            let (w, pdf) = e.sample(u);
            assert!(
                pdf > 0.0 && hits(w, c, n, r, 1e-5),
                "{c} {n} {r} {u}: {w} {pdf}"
            );
            if e.by_area() {
                let (wd, cd, nd) = (w.as_dvec3(), c.as_dvec3(), n.as_dvec3().normalize());
                let h = cd.dot(nd);
                let area =
                    h * h / (wd.dot(nd).abs().powi(3) * std::f64::consts::PI * (r as f64).powi(2));
                // ω·n of an f32 direction and normal carries 2e-7 absolutely, cubed.
                let tol = 1e-5 + 6e-7 / wd.dot(nd).abs();
                assert!(((pdf as f64 - area) / area).abs() < tol, "{pdf} vs {area}");
            } else {
                assert_eq!(pdf, 1.0 / e.solid_angle());
                if u.x > 1e-2 {
                    let back = e.inverse(w);
                    let d = (back - u).abs();
                    // An f32 direction is known to 6e-8 absolutely, which is 6e-8/b of the
                    // ellipse's minor semi-axis b: u inherits that.
                    let b = e.semi_axes().1;
                    let dd = d.x.max(d.y.min(1.0 - d.y)) / (1.0 + 2e-2 / b);
                    worst = worst.max(dd);
                }
            }
        }
    }
    println!("by area {by_area}, worst round trip {worst:e}");
    assert!(by_area > 20 && worst < 2e-5, "{by_area} {worst:e}");
}

/// χ² over the disk's cap: 10⁶ samples of an oblique, eccentric disk against 1/Ω pass; against
/// a pdf 10 % high on one side of the cone's axis and 10 % low on the other they are rejected.
#[test]
fn uniform_in_solid_angle_and_a_distorted_pdf_is_rejected() {
    let (c, n, r) = (Vec3::new(0.5, 0.2, 2.0), Vec3::new(1.0, 0.0, 0.15), 1.0f32);
    let disk = mcsample::warp::SolidAngleDisk { c, n, r };
    let cap = Cap::around(&mcsample::verify::registry::disk_rim(&disk));
    let e = SphericalEllipse::new(c, n, r);
    let side = c.normalize().cross(Vec3::Y).normalize().as_dvec3();
    let run = |tilt: f64| {
        let mut rng = TestRng::new(53);
        cap.test(
            ChiSquare::sphere().samples(1_000_000).ires(12),
            |_| e.sample(rng.u2()).0,
            |w: DVec3| {
                let p = spherical_ellipse_pdf(w.as_vec3(), c, n, r) as f64;
                p * (1.0 + tilt * w.dot(side).signum())
            },
        )
    };
    let good = run(0.0);
    assert!(good.p_value > 1e-3, "{good}");
    let bad = run(0.1);
    assert!(bad.p_value < 1e-9, "{bad}");
}

/// The irradiance of a disk on the axis of a receiver facing it, πr²/(r² + h²), estimated from
/// 2·10⁵ samples as the mean of cos θ / pdf, is within 2e-3 of the value; with the pdf 1 % off
/// the estimate is rejected (off by more than 5e-3).
#[test]
fn irradiance_estimate_rejects_a_pdf_one_percent_off() {
    let (c, n, r) = (Vec3::new(0.0, 0.0, 1.5), Vec3::NEG_Z, 2.0f32);
    let want = mcsample::reference::disk_irradiance_on_axis(2.0, 1.5);
    let mut rng = TestRng::new(57);
    let e = SphericalEllipse::new(c, n, r);
    let m = 200_000;
    let (mut sum, mut off) = (0.0f64, 0.0f64);
    for _ in 0..m {
        let (w, pdf) = e.sample(rng.u2());
        sum += w.z as f64 / pdf as f64;
        off += w.z as f64 / (1.01 * pdf as f64);
    }
    let (good, bad) = (sum / m as f64, off / m as f64);
    assert!(((good - want) / want).abs() < 2e-3, "{good} vs {want}");
    assert!(((bad - want) / want).abs() > 5e-3, "{bad} vs {want}");
}

/// On its axis the ellipse is a circle (a = b, the cone's axis through the centre) of
/// 2π(1 − h/√(h² + r²)), and samples invert.
#[test]
fn a_disk_seen_on_its_axis() {
    let (c, n, r) = (Vec3::new(0.0, 0.0, 2.0), Vec3::NEG_Z, 1.5f32);
    let e = SphericalEllipse::new(c, n, r);
    let (a, b) = e.semi_axes();
    assert_eq!(a, b);
    let want = std::f64::consts::TAU * (1.0 - 2.0 / (4.0f64 + 2.25).sqrt());
    assert!(((e.solid_angle() as f64 - want) / want).abs() < 1e-6);
    for u in [
        Vec2::new(0.5, 0.0),
        Vec2::new(1.0, 0.3),
        Vec2::new(0.25, 0.99),
    ] {
        let (w, pdf) = e.sample(u);
        assert!(pdf > 0.0 && hits(w, c, n, r, 1e-6));
        let back = e.inverse(w);
        assert!(
            (back.x - u.x).abs() < 1e-6 && (back.y - u.y).abs() < 1e-6,
            "{u} {back}"
        );
    }
}

/// Edge-on: a point in the disk's plane sees nothing (pdf 0, +z); just off the plane the disk is
/// a sliver (b/a ≈ 1e-4) that is still sampled, on the disk.
#[test]
fn a_disk_seen_edge_on() {
    let (c, n, r) = (Vec3::new(0.0, 0.0, 3.0), Vec3::X, 1.0f32);
    assert_eq!(
        spherical_ellipse(Vec2::new(0.3, 0.6), c, n, r),
        (Vec3::Z, 0.0)
    );
    assert_eq!(spherical_ellipse_pdf(c.normalize(), c, n, r), 0.0);
    let c = Vec3::new(3e-4, 0.0, 3.0);
    let e = SphericalEllipse::new(c, n, r);
    let (a, b) = e.semi_axes();
    assert!(b / a < 2e-4 && !e.by_area(), "{a} {b}");
    let want = reference(c, n, r);
    assert!(((e.solid_angle() as f64 - want) / want).abs() < 1e-6);
    let mut rng = TestRng::new(54);
    for _ in 0..1000 {
        let (w, pdf) = e.sample(rng.u2());
        assert!(pdf > 0.0 && hits(w, c, n, r, 1e-4), "{w}");
    }
}

/// A disk of 1e-9 sr: Ω within 1e-5 of the area integral, sampled by area (below
/// ELLIPSE_MIN_SR), every sample on the disk; one of 1e-6 sr by its ellipse.
#[test]
fn a_disk_of_a_billionth_of_a_steradian() {
    let n = Vec3::new(0.3, -0.2, -1.0);
    let c = Vec3::new(0.2, 0.1, 10.0);
    // Ω ≈ πr²cos/d²: r for 1e-9 sr.
    let r = (1e-9f64 * 100.0 / std::f64::consts::PI / 0.95).sqrt() as f32;
    let e = SphericalEllipse::new(c, n, r);
    let want = reference(c, n, r);
    assert!((want - 1e-9).abs() < 2e-10, "{want}");
    assert!(((e.solid_angle() as f64 - want) / want).abs() < 1e-5);
    assert!(e.by_area() && (want as f32) < ELLIPSE_MIN_SR);
    let mut rng = TestRng::new(55);
    for _ in 0..1000 {
        let (w, pdf) = e.sample(rng.u2());
        assert!(pdf > 0.0 && hits(w, c, n, r, 2e-2), "{w}");
    }
    let r = r * 31.6;
    let e = SphericalEllipse::new(c, n, r);
    assert!(!e.by_area());
    for _ in 0..1000 {
        let (w, pdf) = e.sample(rng.u2());
        assert_eq!(pdf, 1.0 / e.solid_angle());
        assert!(hits(w, c, n, r, 1e-3), "{w}");
    }
}

/// Bad input: NaN u, a radius that is 0, negative, ∞ or NaN, a centre that is NaN or at the
/// point, a zero or NaN normal all give pdf 0 and +z; the pdf of NaN is 0 and its inverse NaN.
#[test]
fn bad_input_drops_the_sample() {
    let (c, n, r) = (Vec3::new(0.5, 0.2, 2.0), Vec3::new(1.0, 0.0, 0.15), 1.0f32);
    let z = (Vec3::Z, 0.0);
    let u = Vec2::new(0.3, 0.6);
    assert_eq!(spherical_ellipse(Vec2::new(f32::NAN, 0.5), c, n, r), z);
    for bad in [0.0, -1.0, f32::INFINITY, f32::NAN] {
        assert_eq!(spherical_ellipse(u, c, n, bad), z, "{bad}");
    }
    for bad in [Vec3::NAN, Vec3::ZERO, Vec3::new(f32::INFINITY, 0.0, 1.0)] {
        assert_eq!(spherical_ellipse(u, bad, n, r), z, "{bad}");
        assert_eq!(spherical_ellipse(u, c, bad, r), z, "{bad}");
    }
    assert_eq!(spherical_ellipse_pdf(Vec3::NAN, c, n, r), 0.0);
    assert!(spherical_ellipse_inverse(Vec3::NAN, c, n, r).is_nan());
    // u outside the square clamps to its edge.
    let (w, pdf) = spherical_ellipse(Vec2::new(2.0, -1.0), c, n, r);
    assert_eq!((w, pdf), spherical_ellipse(Vec2::new(1.0, 0.0), c, n, r));
}

/// Lane i of the eight-wide map is the scalar map of lane i's disk, bit for bit, with the
/// ellipse and the area fallback mixed in one packet.
#[test]
fn lanes_are_the_scalar_map() {
    let mut rng = TestRng::new(56);
    for _ in 0..500 {
        let disks: [(Vec3, Vec3, f32); 8] = std::array::from_fn(|_| random_disk(&mut rng));
        let us: [Vec2; 8] = std::array::from_fn(|_| rng.u2());
        let e8 = SphericalEllipse::new(
            Vec3x8::from(disks.map(|d| d.0)),
            Vec3x8::from(disks.map(|d| d.1)),
            F32x8::from(disks.map(|d| d.2)),
        );
        let (w8, pdf8) = e8.sample(Vec2x8::from(us));
        let back8 = e8.inverse(w8);
        for i in 0..8 {
            let e = SphericalEllipse::new(disks[i].0, disks[i].1, disks[i].2);
            let (w, pdf) = e.sample(us[i]);
            assert_eq!(
                w8.lane(i).to_array().map(f32::to_bits),
                w.to_array().map(f32::to_bits)
            );
            assert_eq!(pdf8.to_array()[i].to_bits(), pdf.to_bits());
            assert_eq!(
                back8.lane(i).to_array().map(f32::to_bits),
                e.inverse(w).to_array().map(f32::to_bits)
            );
        }
    }
}
