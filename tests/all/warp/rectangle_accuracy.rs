//! Spherical rectangle sampling (Ureña et al. 2013) in f32 against the f64 instance of the same
//! generic code, on random rectangles of every kind, per solid-angle band.

use glam::{DVec2, DVec3, Vec2, Vec3};
use mcsample::lane::{V2, V3};
use mcsample::math::Math;
use mcsample::warp::{self, SphericalRectangle};

// ---------------------------------------------------------------------------------------------
// Random rectangles

/// SplitMix64: the test's own generator, so that the file depends on nothing else in `tests/`.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }
    /// Uniform in [0, 1), 53 bits.
    fn f(&mut self) -> f64 {
        (self.next() >> 11) as f64 * (1.0 / 9_007_199_254_740_992.0)
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.f()
    }
    /// 10^U(lo, hi).
    fn log(&mut self, lo: f64, hi: f64) -> f64 {
        10f64.powf(self.range(lo, hi))
    }
    /// A 24-bit u in [0, 1), the generators' format.
    fn u01(&mut self) -> f32 {
        (self.next() >> 40) as f32 * (1.0 / 16_777_216.0)
    }
    fn unit(&mut self) -> DVec3 {
        let z = self.range(-1.0, 1.0);
        let phi = self.range(0.0, std::f64::consts::TAU);
        let r = (1.0 - z * z).max(0.0).sqrt();
        DVec3::new(r * phi.cos(), r * phi.sin(), z)
    }
}

/// Two unit vectors orthogonal to unit `n` and to each other (Duff et al. 2017).
fn basis(n: DVec3) -> (DVec3, DVec3) {
    let s = 1f64.copysign(n.z);
    let a = -1.0 / (s + n.z);
    let b = n.x * n.y * a;
    (
        DVec3::new(1.0 + s * n.x * n.x * a, s * b, -s * n.x),
        DVec3::new(b, s + n.y * n.y * a, -n.y),
    )
}

/// The kinds of rectangle the bounds are claimed for.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    /// Anywhere above the horizon, any size up to its distance, tilted up to 80°.
    General,
    /// Far and small: 1e-4 to 3e-2 of its distance across.
    FarSmall,
    /// Seen at a grazing angle: the plane tilted 80°–89.5° from facing the shading point.
    Grazing,
    /// Straddling the foot of the perpendicular from the shading point, in x, y or both.
    Straddling,
    /// Larger than its distance: 1 to 30 times.
    LargeNear,
    /// Nearly edge-on: the plane 3e-6 to 1e-2 rad from containing the shading point.
    EdgeOn,
}

const KINDS: [Kind; 6] = [
    Kind::General,
    Kind::FarSmall,
    Kind::Grazing,
    Kind::Straddling,
    Kind::LargeNear,
    Kind::EdgeOn,
];

/// A rectangle (corner, ex, ey) in f32, relative to the shading point, of kind `k`. The scale
/// (its distance) is random over 1e-2..1e3.
fn random_rectangle(g: &mut Rng, k: Kind) -> (Vec3, Vec3, Vec3) {
    let dist = g.log(-2.0, 3.0);
    // The centre's direction: above the horizon (z > 0).
    let mut c = g.unit();
    c.z = c.z.abs().max(1e-3);
    let c = c.normalize();
    let rel = match k {
        Kind::General => g.log(-3.5, 0.3),
        Kind::FarSmall => g.log(-4.0, -1.5),
        Kind::Grazing => g.log(-3.0, 0.5),
        Kind::Straddling => g.log(-3.5, 0.5),
        Kind::LargeNear => g.log(0.0, 1.5),
        Kind::EdgeOn => g.log(-2.0, 1.0),
    };
    let aspect = g.log(-1.0, 1.0);
    let (sx, sy) = (dist * rel * aspect.sqrt(), dist * rel / aspect.sqrt());
    // The normal: tilted from −c (facing the shading point) by `tilt`, about a random axis.
    let tilt = match k {
        Kind::Grazing => g.range(80.0, 89.5).to_radians(),
        Kind::LargeNear => g.range(0.0, 60.0).to_radians(),
        Kind::EdgeOn => std::f64::consts::FRAC_PI_2 - g.log(-5.5, -2.0),
        _ => g.range(0.0, 80.0).to_radians(),
    };
    let (t, b) = basis(-c);
    let az = g.range(0.0, std::f64::consts::TAU);
    let n = (-c * tilt.cos() + (t * az.cos() + b * az.sin()) * tilt.sin()).normalize();
    let (t, b) = basis(n);
    let rot = g.range(0.0, std::f64::consts::TAU);
    let xh = t * rot.cos() + b * rot.sin();
    let yh = n.cross(xh);
    let centre = if k == Kind::Straddling {
        // The plane through dist·c; the foot of the perpendicular from the origin is
        // (centre·n)n. Put the centre so that the foot lies within the rectangle's x extent, y
        // extent, or both.
        let foot = n * (dist * c).dot(n);
        let which = g.next() % 3;
        let fx = if which != 1 {
            g.range(-0.5, 0.5)
        } else {
            g.range(0.5, 3.0)
        } * sx;
        let fy = if which != 0 {
            g.range(-0.5, 0.5)
        } else {
            g.range(0.5, 3.0)
        } * sy;
        foot - xh * fx - yh * fy
    } else {
        dist * c
    };
    let ex = xh * sx;
    let ey = yh * sy;
    let corner = centre - ex * 0.5 - ey * 0.5;
    (corner.as_vec3(), ex.as_vec3(), ey.as_vec3())
}

/// Solid angle of the f32 rectangle in f64, as two Van Oosterom–Strackee triangles.
fn omega64(corner: Vec3, ex: Vec3, ey: Vec3) -> f64 {
    let (c, ex, ey) = (corner.as_dvec3(), ex.as_dvec3(), ey.as_dvec3());
    let vos = |a: DVec3, b: DVec3, c: DVec3, triple: f64| {
        let (la, lb, lc) = (a.length(), b.length(), c.length());
        let den = la * lb * lc + a.dot(b) * lc + a.dot(c) * lb + b.dot(c) * la;
        2.0 * triple.abs().atan2(den)
    };
    let t = c.dot(ex.cross(ey));
    vos(c, c + ex, c + ex + ey, t) + vos(c, c + ex + ey, c + ey, t)
}

/// Solid-angle bands (sr): [lo, hi).
const BANDS: [(f64, f64); 11] = [
    (6.0, 6.3),
    (1.0, 6.0),
    (0.1, 1.0),
    (1e-2, 0.1),
    (1e-3, 1e-2),
    (1e-4, 1e-3),
    (1e-5, 1e-4),
    (1e-6, 1e-5),
    (1e-7, 1e-6),
    (1e-8, 1e-7),
    (1e-9, 1e-8),
];

fn band_of(omega: f64) -> Option<usize> {
    BANDS.iter().position(|&(lo, hi)| omega >= lo && omega < hi)
}

/// The u of every rectangle: the corners and edges of the square (0, ½, 1 − 2⁻²⁴, 1) and
/// random 24-bit pairs.
fn us(g: &mut Rng, n: usize) -> Vec<Vec2> {
    let edge = [0.0, 0.5, 1.0 - 1.0 / 16_777_216.0, 1.0];
    let mut v: Vec<Vec2> = edge
        .iter()
        .flat_map(|&a| edge.iter().map(move |&b| Vec2::new(a, b)))
        .collect();
    v.extend((0..n).map(|_| Vec2::new(g.u01(), g.u01())));
    v
}

/// A map from u to a point of the rectangle, f32 and f64.
type Map32 = fn(Vec2, Vec3, Vec3, Vec3) -> Vec3;
type Map64 = fn(DVec2, DVec3, DVec3, DVec3) -> DVec3;

/// Direction error |w32 − w64| of unit directions.
fn dir_err(p32: Vec3, p64: DVec3) -> f64 {
    let e = (p32.as_dvec3().normalize() - p64.normalize()).length();
    if e.is_nan() { f64::INFINITY } else { e }
}

/// Worst error per band and kind: (band, kind) → (worst, rectangle, u, count).
struct Table {
    worst: Vec<Vec<(f64, String, usize)>>,
}

impl Table {
    fn new() -> Self {
        Table {
            worst: vec![vec![(0.0, String::new(), 0); KINDS.len()]; BANDS.len()],
        }
    }
    fn band(&self, b: usize) -> f64 {
        self.worst[b].iter().map(|w| w.0).fold(0.0, f64::max)
    }
    fn count(&self, b: usize) -> usize {
        self.worst[b].iter().map(|w| w.2).sum()
    }
}

/// Runs `map32`/`map64` on `n_rects` random rectangles of each kind, `n_u` random u each (plus
/// the 16 on the square's edges).
fn measure(map32: Map32, map64: Map64, n_rects: usize, n_u: usize, seed: u64) -> Table {
    let mut t = Table::new();
    let mut g = Rng(seed);
    for (ki, &k) in KINDS.iter().enumerate() {
        for _ in 0..n_rects {
            let (c, ex, ey) = random_rectangle(&mut g, k);
            let omega = omega64(c, ex, ey);
            let Some(b) = band_of(omega) else { continue };
            let (cd, exd, eyd) = (c.as_dvec3(), ex.as_dvec3(), ey.as_dvec3());
            let entry = &mut t.worst[b][ki];
            entry.2 += 1;
            for u in us(&mut g, n_u) {
                let e = dir_err(map32(u, c, ex, ey), map64(u.as_dvec2(), cd, exd, eyd));
                if e > entry.0 {
                    *entry = (
                        e,
                        format!("Ω={omega:.3e} corner={c:?} ex={ex:?} ey={ey:?} u={u:?}"),
                        entry.2,
                    );
                }
            }
        }
    }
    t
}

fn print_table(name: &str, t: &Table) {
    println!("{name}");
    print!("{:>16} {:>9}", "Ω band (sr)", "worst");
    for k in KINDS {
        print!(" {:>11}", format!("{k:?}"));
    }
    println!("  rects");
    for (b, &(lo, hi)) in BANDS.iter().enumerate() {
        print!(
            "{:>16} {:>9.2e}",
            format!("[{lo:.0e}, {hi:.0e})"),
            t.band(b)
        );
        for w in &t.worst[b] {
            print!(" {:>11.2e}", w.0);
        }
        println!("  {}", t.count(b));
    }
    for (b, row) in t.worst.iter().enumerate() {
        if let Some(w) = row
            .iter()
            .max_by(|a, b| a.0.total_cmp(&b.0))
            .filter(|w| w.0 > 0.0)
        {
            println!("  band {b} worst at {}", w.1);
        }
    }
}

// ---------------------------------------------------------------------------------------------
// The old map: Ureña's Σγ − 2π form, as the crate had it before (a private copy, the negative
// control).

#[allow(clippy::type_complexity)]
fn old_map<L: Math>(u: V2<L>, corner: V3<L>, ex: V3<L>, ey: V3<L>) -> V3<L> {
    let u = V2::new(u.x.clamp(L::ZERO, L::ONE), u.y.clamp(L::ZERO, L::ONE));
    let exl = ex.length();
    let eyl = ey.length();
    let xh = ex.scale(L::ONE / exl);
    let yh = ey.scale(L::ONE / eyl);
    let zh = xh.cross(yh);
    let x0 = corner.dot(xh);
    let y0 = corner.dot(yh);
    let z0 = -corner.dot(zh).abs();
    let x1 = x0 + exl;
    let y1 = y0 + eyl;
    let az = z0.abs();
    let len = |x: L, y: L| x.mul_add(x, y.mul_add(y, z0 * z0)).sqrt();
    let g0 = (az * len(x1, y0)).atan2(y0 * x1);
    let g1 = (az * len(x1, y1)).atan2(-(x1 * y1));
    let g2 = (az * len(x0, y1)).atan2(x0 * y1);
    let g3 = (az * len(x0, y0)).atan2(-(x0 * y0));
    let b0 = -y0 / z0.mul_add(z0, y0 * y0).sqrt();
    let b1 = y1 / z0.mul_add(z0, y1 * y1).sqrt();
    let k = L::c(std::f64::consts::TAU) - g2 - g3;
    let s_map = g0 + g1 - k;
    let au = u.x.mul_add(s_map, k);
    let (sa, ca) = au.sin_cos();
    let fu = ca.mul_add(b0, -b1) / sa;
    let cu = (L::ONE.copysign(fu) / fu.mul_add(fu, b0 * b0).sqrt()).clamp(L::c(-1.0), L::ONE);
    let sin_u = ((L::ONE - cu) * (L::ONE + cu)).max(L::ZERO).sqrt();
    let xu = (-(cu * z0) / sin_u).clamp(x0, x1);
    let d = xu.mul_add(xu, z0 * z0).sqrt();
    let h0 = y0 / d.mul_add(d, y0 * y0).sqrt();
    let h1 = y1 / d.mul_add(d, y1 * y1).sqrt();
    let hv = u.y.mul_add(h1 - h0, h0);
    let hv2 = hv * hv;
    let yv = L::select(
        hv2.ge(L::c(1.0 - 1e-6)),
        y1,
        (hv * d) / (L::ONE - hv2).sqrt(),
    );
    let yv = yv.clamp(y0, y1);
    corner + xh.scale(xu - x0) + yh.scale(yv - y0)
}

fn old32(u: Vec2, c: Vec3, ex: Vec3, ey: Vec3) -> Vec3 {
    old_map::<f32>(u.into(), c.into(), ex.into(), ey.into()).into()
}
fn old64(u: DVec2, c: DVec3, ex: DVec3, ey: DVec3) -> DVec3 {
    old_map::<f64>(u.into(), c.into(), ex.into(), ey.into()).into()
}
fn new32(u: Vec2, c: Vec3, ex: Vec3, ey: Vec3) -> Vec3 {
    warp::urena_rectangle(u, c, ex, ey)
}
fn new64(u: DVec2, c: DVec3, ex: DVec3, ey: DVec3) -> DVec3 {
    warp::urena_rectangle(u, c, ex, ey)
}

/// The table of worst direction errors, old map and the crate's, on `RECTS` rectangles of each
/// kind (default 4000): `cargo test --release --test all rectangle_accuracy -- --ignored
/// --nocapture`.
#[test]
#[ignore = "prints the error tables"]
fn print_error_tables() {
    let n: usize = std::env::var("RECTS")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(4000);
    print_table("old Σγ − 2π map", &measure(old32, old64, n, 64, 1));
    print_table("crate map", &measure(new32, new64, n, 64, 1));
    // The report's stability rows: the facing square and the tilted 2:1 rectangle of side s.
    println!(
        "{:>8} {:>11} {:>10} {:>10} {:>11} {:>10} {:>10}",
        "s", "Ω square", "old", "new", "Ω tilted", "old", "new"
    );
    let mut g = Rng(9);
    let pts = us(&mut g, 16384);
    for s in [
        1e-4f32, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0,
    ] {
        let square = (
            Vec3::new(-s / 2.0, -s / 2.0, 1.0),
            Vec3::new(s, 0.0, 0.0),
            Vec3::new(0.0, s, 0.0),
        );
        let (a, b) = (s * std::f32::consts::SQRT_2, s / std::f32::consts::SQRT_2);
        let (ex, ey) = (
            Vec3::new(a, 0.0, 0.0),
            Vec3::new(0.0, b * 0.5, b * 0.75f32.sqrt()),
        );
        let centre = Vec3::new(0.64, 0.2, 0.74).normalize();
        let tilted = (centre - ex * 0.5 - ey * 0.5, ex, ey);
        print!("{s:>8}");
        for (c, ex, ey) in [square, tilted] {
            let worst = |m32: Map32, m64: Map64| {
                pts.iter()
                    .map(|&u| {
                        dir_err(
                            m32(u, c, ex, ey),
                            m64(u.as_dvec2(), c.as_dvec3(), ex.as_dvec3(), ey.as_dvec3()),
                        )
                    })
                    .fold(0.0, f64::max)
            };
            print!(
                " {:>11.3e} {:>10.2e} {:>10.2e}",
                omega64(c, ex, ey),
                worst(old32, old64),
                worst(new32, new64)
            );
        }
        println!();
    }
}

/// The claimed bound on the f32 direction error of the spherical map against its f64 instance,
/// for every rectangle from 2π down to 1e-9 sr (measured: 4.6e-7 on 2.4e5 random rectangles of
/// every kind, 80 u each).
const DIRECTION_BOUND: f64 = 1e-6;

#[test]
fn map_direction_error_is_within_the_bound_in_every_band() {
    let t = measure(new32, new64, 1500, 32, 2);
    print_table("crate map", &t);
    let mut failures = Vec::new();
    for (b, row) in t.worst.iter().enumerate() {
        assert!(
            t.count(b) >= 20,
            "band {:?} has only {} rectangles",
            BANDS[b],
            t.count(b)
        );
        for (k, w) in row.iter().enumerate() {
            if w.0 > DIRECTION_BOUND {
                failures.push(format!(
                    "{:?} {:?}: {:.2e} at {}",
                    BANDS[b], KINDS[k], w.0, w.1
                ));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// Negative control: the old Σγ − 2π form, on the same rectangles, exceeds the bound tenfold
/// from 1e-2 sr down to 1e-6 sr, and on the report's facing square at 1e-3 sr (5.6e-6), so the
/// test above can fail.
#[test]
fn old_form_exceeds_the_bound() {
    let t = measure(old32, old64, 1500, 32, 2);
    for (b, &(lo, _)) in BANDS.iter().enumerate() {
        if (1e-6..=1e-3).contains(&lo) {
            assert!(
                t.band(b) > 10.0 * DIRECTION_BOUND,
                "old form within 10× the bound in {:?}: {:.2e}",
                BANDS[b],
                t.band(b)
            );
        }
    }
    // And on the report's square at 1e-3 sr, facing the shading point at distance 1.
    let s = 1e-3f32.sqrt();
    let (c, ex, ey) = (
        Vec3::new(-s / 2.0, -s / 2.0, 1.0),
        Vec3::new(s, 0.0, 0.0),
        Vec3::new(0.0, s, 0.0),
    );
    let mut g = Rng(3);
    let worst = |m32: Map32, m64: Map64, g: &mut Rng| {
        us(g, 4096)
            .into_iter()
            .map(|u| {
                dir_err(
                    m32(u, c, ex, ey),
                    m64(u.as_dvec2(), c.as_dvec3(), ex.as_dvec3(), ey.as_dvec3()),
                )
            })
            .fold(0.0, f64::max)
    };
    let (old, new) = (worst(old32, old64, &mut g), worst(new32, new64, &mut g));
    println!("square at 1e-3 sr: old {old:.2e}, new {new:.2e}");
    assert!(old > 4.0 * DIRECTION_BOUND, "old {old:e}");
    assert!(new < DIRECTION_BOUND, "new {new:e}");
}

// ---------------------------------------------------------------------------------------------
// The pdf: the sampler's, bit for bit

/// Rectangles for the pdf and inverse tests: the random kinds above (sampled spherically, and by
/// area below the threshold), plus skewed edges, a few degenerate and edge-on ones.
fn any_rectangle(g: &mut Rng, i: usize) -> (Vec3, Vec3, Vec3) {
    let (c, ex, ey) = random_rectangle(g, KINDS[i % KINDS.len()]);
    match g.next() % 64 {
        0 => (c, ex, Vec3::ZERO),
        1 => (ex * 0.3 - ey * 0.2, ex, ey),
        2 => (c, ex, ey + ex * 1e-3),
        _ => (c, ex, ey),
    }
}

/// The u of the pdf test: the corners and edges of the square at 0, 1 − 2⁻²⁴ and 1, and three
/// random pairs.
fn boundary_us(g: &mut Rng) -> Vec<Vec2> {
    let edge = [0.0, warp::ONE_MINUS_EPS, 1.0];
    let mut v: Vec<Vec2> = edge
        .iter()
        .flat_map(|&a| edge.iter().map(move |&b| Vec2::new(a, b)))
        .collect();
    v.extend((0..3).map(|_| Vec2::new(g.u01(), g.u01())));
    v
}

/// On 200 000 random rectangles × 12 u (9 on the square's corners and edges): the pdf function
/// at the returned point, and at twice it, is the returned pdf bit for bit; a light with Ω > 0
/// never drops a sample (pdf 0); the free functions are the prepared type's.
#[test]
fn sampler_pdf_is_the_pdf_function_bit_for_bit() {
    let mut g = Rng(4);
    let (mut n, mut spherical, mut area) = (0usize, 0usize, 0usize);
    let mut failures = Vec::new();
    for i in 0..200_000 {
        let (c, ex, ey) = any_rectangle(&mut g, i);
        let rect = SphericalRectangle::new(c, ex, ey);
        let omega = rect.solid_angle();
        for u in boundary_us(&mut g) {
            n += 1;
            let (p, pdf) = rect.sample(u);
            let (pf, pdff) = warp::spherical_rectangle(u, c, ex, ey);
            let q = warp::spherical_rectangle_pdf(p, c, ex, ey);
            let q2 = rect.pdf(p * 2.0);
            if omega > 0.0 && pdf > 0.0 {
                if rect.by_area() {
                    area += 1;
                } else {
                    spherical += 1;
                }
            }
            let bad = q.to_bits() != pdf.to_bits()
                || q2.to_bits() != pdf.to_bits()
                || pf.to_array().map(f32::to_bits) != p.to_array().map(f32::to_bits)
                || pdff.to_bits() != pdf.to_bits()
                || (omega > 0.0 && pdf <= 0.0)
                || !p.is_finite()
                || !(pdf >= 0.0 && pdf.is_finite());
            if bad && failures.len() < 20 {
                failures.push(format!(
                    "corner={c:?} ex={ex:?} ey={ey:?} Ω={omega:e} by_area={} u={u:?}: \
                     p={p:?} pdf={pdf:e}, pdf(p)={q:e}, pdf(2p)={q2:e}",
                    rect.by_area()
                ));
            }
        }
    }
    println!("{n} samples: {spherical} spherical, {area} by area");
    assert!(spherical > n / 2 && area > n / 20, "{spherical} {area}");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

// ---------------------------------------------------------------------------------------------
// The prepared type: packets, the inverse, bad input

/// Packets: lane i of `SphericalRectangle<Vec3x8>` is the scalar type's result on lane i's
/// rectangle and u, bit for bit (sample, pdf, inverse, solid angle, by_area).
#[test]
fn packets_match_scalars_bit_for_bit() {
    use mcsample::x8::{F32x8, Vec2x8, Vec3x8};
    let mut g = Rng(5);
    let bits3 = |v: Vec3| v.to_array().map(f32::to_bits);
    let bits2 = |v: Vec2| v.to_array().map(f32::to_bits);
    for i in 0..20_000 {
        let r: [(Vec3, Vec3, Vec3); 8] = std::array::from_fn(|k| any_rectangle(&mut g, i * 8 + k));
        let u: [Vec2; 8] = std::array::from_fn(|k| match k {
            0 => Vec2::ZERO,
            1 => Vec2::ONE,
            2 => Vec2::new(warp::ONE_MINUS_EPS, 0.0),
            3 => Vec2::new(f32::NAN, 0.5),
            _ => Vec2::new(g.u01(), g.u01()),
        });
        let rect8 = SphericalRectangle::new(
            Vec3x8::from(r.map(|r| r.0)),
            Vec3x8::from(r.map(|r| r.1)),
            Vec3x8::from(r.map(|r| r.2)),
        );
        let (p8, pdf8) = rect8.sample(Vec2x8::from(u));
        let w8 = p8;
        let q8 = rect8.pdf(w8);
        let back8 = rect8.inverse(p8);
        let (om8, area8): (F32x8, F32x8) = (rect8.solid_angle(), rect8.by_area());
        for k in 0..8 {
            let rect = SphericalRectangle::new(r[k].0, r[k].1, r[k].2);
            let (p, pdf) = rect.sample(u[k]);
            let ok = bits3(p8.lane(k)) == bits3(p)
                && pdf8.to_array()[k].to_bits() == pdf.to_bits()
                && q8.to_array()[k].to_bits() == rect.pdf(p).to_bits()
                && bits2(back8.lane(k)) == bits2(rect.inverse(p))
                && om8.to_array()[k].to_bits() == rect.solid_angle().to_bits()
                && (area8.to_array()[k].to_bits() != 0) == rect.by_area();
            assert!(ok, "lane {k}: rectangle {:?} u {:?}", r[k], u[k]);
        }
    }
}

/// The inverse undoes the sampler, to within what the f32 point itself determines: for each sample
/// p, with c the change of u when p moves by its own rounding δ (δ = ε|p|, or ε·(|corner| + |ex| +
/// |ey|) by area; c = δ·|row i of J⁺| for the map's Jacobian J), both the f32 inverse against the
/// f64 inverse of the same p and the f64 inverse against u are within 8c + 2e-6. (Near the horizon
/// of a rectangle seen almost edge-on, c reaches 0.1: the planes x = const all contain the y axis,
/// so there a rounding-sized move of p is a large move in u₀.)
#[test]
fn inverse_undoes_the_sampler() {
    let mut g = Rng(6);
    let mut worst = [(0.0f64, String::new()), (0.0f64, String::new())];
    let mut failures = Vec::new();
    for i in 0..20_000 {
        let (c, ex, ey) = random_rectangle(&mut g, KINDS[i % KINDS.len()]);
        let rect = SphericalRectangle::new(c, ex, ey);
        let r64 = SphericalRectangle::new(c.as_dvec3(), ex.as_dvec3(), ey.as_dvec3());
        let omega = rect.solid_angle() as f64;
        if omega <= 0.0 {
            continue;
        }
        let reach = (c.length() + ex.length() + ey.length()) as f64;
        for u in us(&mut g, 8) {
            let (p, pdf) = rect.sample(u);
            assert!(pdf > 0.0);
            let back = rect.inverse(p);
            assert_eq!(
                back.to_array().map(f32::to_bits),
                warp::spherical_rectangle_inverse(p, c, ex, ey)
                    .to_array()
                    .map(f32::to_bits)
            );
            let pd = p.as_dvec3();
            let u64 = r64.inverse(pd);
            let delta = f32::EPSILON as f64 * if rect.by_area() { reach } else { pd.length() };
            // How far u moves when p moves by δ: δ times the row norms of the pseudo-inverse
            // of the map's Jacobian J (√ of the diagonal of (JᵀJ)⁻¹), J from the f64 map by
            // differences over ±1e-4 (one-sided at the square's edges).
            let ud = u.as_dvec2();
            let column = |i: usize| {
                let (mut a, mut b) = (ud, ud);
                a[i] = (ud[i] - 1e-4).max(0.0);
                b[i] = (ud[i] + 1e-4).min(1.0);
                (r64.sample(b).0 - r64.sample(a).0) / (b[i] - a[i])
            };
            let (j0, j1) = (column(0), column(1));
            let (g00, g01, g11) = (j0.dot(j0), j0.dot(j1), j1.dot(j1));
            let det = g00 * g11 - g01 * g01;
            let cond = DVec2::new((g11 / det).sqrt(), (g00 / det).sqrt()) * delta;
            let bound = cond * 8.0 + DVec2::splat(2e-6);
            let e32 = (back.as_dvec2() - u64).abs();
            let e64 = (u64 - u.as_dvec2()).abs();
            for (k, e) in [e32, e64].into_iter().enumerate() {
                let r = (e / bound).max_element();
                if r > worst[k].0 {
                    worst[k] = (r, format!("{e:?} (cond {cond:?}) at Ω={omega:.2e} u={u:?}"));
                }
                if r > 1.0 && failures.len() < 10 {
                    failures.push(format!(
                        "{}: Ω={omega:e} by_area={} corner={c:?} ex={ex:?} ey={ey:?} u={u:?}: \
                         back {back:?}, f64 {u64:?}, cond {cond:?}",
                        ["f32 inverse", "f64 inverse"][k],
                        rect.by_area()
                    ));
                }
            }
        }
    }
    println!(
        "worst f32 inverse error / bound: {:.3} ({})",
        worst[0].0, worst[0].1
    );
    println!(
        "worst f64 round trip error / bound: {:.3} ({})",
        worst[1].0, worst[1].1
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// NaN, ±∞, zero and huge edges, coincident or edge-on geometry: never a panic, always a finite
/// point and a pdf that is 0 or finite, and pdf 0 with the corner for NaN u.
#[test]
fn bad_input_gives_pdf_0_and_a_finite_point() {
    let specials = [
        0.0,
        -0.0,
        1e-30,
        -1e-30,
        1e-45,
        1.0,
        -1.0,
        1e30,
        -1e30,
        f32::MAX,
        f32::INFINITY,
        f32::NEG_INFINITY,
        f32::NAN,
    ];
    let mut g = Rng(7);
    let base = [
        Vec3::new(-0.5, -0.5, 1.0),
        Vec3::new(1.0, 0.0, 0.0),
        Vec3::new(0.0, 1.0, 0.0),
    ];
    let us = [
        Vec2::new(0.3, 0.7),
        Vec2::ZERO,
        Vec2::ONE,
        Vec2::new(f32::NAN, 0.5),
        Vec2::new(f32::INFINITY, -1.0),
    ];
    for _ in 0..20_000 {
        let mut v = base.map(|b| b.to_array());
        for _ in 0..1 + g.next() % 3 {
            let (a, b) = ((g.next() % 3) as usize, (g.next() % 3) as usize);
            v[a][b] = specials[(g.next() % specials.len() as u64) as usize];
        }
        let [c, ex, ey] = v.map(Vec3::from_array);
        let rect = SphericalRectangle::new(c, ex, ey);
        for u in us {
            let (p, pdf) = rect.sample(u);
            let ok = (p.is_finite() || !c.is_finite())
                && pdf >= 0.0
                && pdf.is_finite()
                && (pdf > 0.0 || p.to_array().map(f32::to_bits) == c.to_array().map(f32::to_bits))
                && (!u.is_nan() || pdf == 0.0);
            assert!(ok, "{:?} u={u:?}: p={p:?} pdf={pdf}", (c, ex, ey));
            let q = rect.pdf(p);
            assert!(
                q == pdf || pdf == 0.0,
                "{:?} u={u:?}: pdf {pdf} vs {q}",
                (c, ex, ey)
            );
            let _ = rect.inverse(p);
        }
        for w in [
            Vec3::Z,
            Vec3::NAN,
            Vec3::ZERO,
            Vec3::splat(f32::INFINITY),
            Vec3::splat(1e30),
        ] {
            let q = rect.pdf(w);
            assert!(
                q >= 0.0 && q.is_finite(),
                "{:?}: pdf({w:?}) = {q}",
                (c, ex, ey)
            );
        }
    }
}

/// Time per sample (scalar and x8) of the old map, the new map with its set-up (the free
/// functions pay it per sample), and the prepared type's sample alone: `--ignored --nocapture`.
#[test]
#[ignore = "prints timings"]
fn print_timings() {
    use mcsample::x8::{Vec2x8, Vec3x8};
    use std::hint::black_box;
    use std::time::Instant;
    let mut g = Rng(10);
    let rects: Vec<(Vec3, Vec3, Vec3)> = (0..4096)
        .map(|i| random_rectangle(&mut g, KINDS[i % 5]))
        .collect();
    let us: Vec<Vec2> = (0..4096).map(|_| Vec2::new(g.u01(), g.u01())).collect();
    let time = |name: &str, f: &dyn Fn() -> f32| {
        let mut best = f64::INFINITY;
        for _ in 0..15 {
            let t = Instant::now();
            black_box(f());
            best = best.min(t.elapsed().as_secs_f64());
        }
        println!("{name:<40} {:>8.1} ns/sample", best * 1e9 / 4096.0);
    };
    time("old map (set-up + map), scalar", &|| {
        rects
            .iter()
            .zip(&us)
            .map(|(r, &u)| old32(u, black_box(r.0), r.1, r.2).x)
            .sum()
    });
    time("urena_rectangle (set-up + map), scalar", &|| {
        rects
            .iter()
            .zip(&us)
            .map(|(r, &u)| new32(u, black_box(r.0), r.1, r.2).x)
            .sum()
    });
    time("spherical_rectangle, scalar", &|| {
        rects
            .iter()
            .zip(&us)
            .map(|(r, &u)| warp::spherical_rectangle(u, black_box(r.0), r.1, r.2).1)
            .sum()
    });
    time("SphericalRectangle::new, scalar", &|| {
        rects
            .iter()
            .map(|r| SphericalRectangle::new(black_box(r.0), r.1, r.2).solid_angle())
            .sum()
    });
    let prepared: Vec<SphericalRectangle<Vec3>> = rects
        .iter()
        .map(|r| SphericalRectangle::new(r.0, r.1, r.2))
        .collect();
    time("SphericalRectangle::sample, scalar", &|| {
        prepared
            .iter()
            .zip(&us)
            .map(|(r, &u)| black_box(r).sample(u).1)
            .sum()
    });
    let r8: Vec<(Vec3x8, Vec3x8, Vec3x8)> = rects
        .chunks(8)
        .map(|c| {
            let f = |k: usize| {
                Vec3x8::from(std::array::from_fn::<Vec3, 8, _>(|i| {
                    [c[i].0, c[i].1, c[i].2][k]
                }))
            };
            (f(0), f(1), f(2))
        })
        .collect();
    let u8: Vec<Vec2x8> = us
        .chunks(8)
        .map(|c| Vec2x8::from(<[Vec2; 8]>::try_from(c).unwrap()))
        .collect();
    time("old map (set-up + map), x8", &|| {
        r8.iter()
            .zip(&u8)
            .map(|(r, &u)| old_map(u, black_box(r.0), r.1, r.2).x.to_array()[0])
            .sum()
    });
    time("urena_rectangle (set-up + map), x8", &|| {
        r8.iter()
            .zip(&u8)
            .map(|(r, &u)| {
                warp::urena_rectangle(u, black_box(r.0), r.1, r.2)
                    .x
                    .to_array()[0]
            })
            .sum()
    });
    time("spherical_rectangle, x8", &|| {
        r8.iter()
            .zip(&u8)
            .map(|(r, &u)| {
                warp::spherical_rectangle(u, black_box(r.0), r.1, r.2)
                    .1
                    .to_array()[0]
            })
            .sum()
    });
    let p8: Vec<SphericalRectangle<Vec3x8>> = r8
        .iter()
        .map(|r| SphericalRectangle::new(r.0, r.1, r.2))
        .collect();
    time("SphericalRectangle::sample, x8", &|| {
        p8.iter()
            .zip(&u8)
            .map(|(r, &u)| black_box(r).sample(u).1.to_array()[0])
            .sum()
    });
}

/// The map depends only on ratios, and the set-up works at a power-of-two scale of its own: a
/// rectangle scaled by 2^k (k from −50 to 50, coordinates from 1e-17 to 1e19) gives the same
/// pdf and the same point scaled by 2^k, bit for bit. (Unscaled, squares and cubes of the
/// coordinates overflowed from about 1e9 and gave wrong directions with pdf > 0.)
#[test]
fn power_of_two_scaling_changes_nothing_but_the_scale() {
    let mut g = Rng(11);
    let mut n = 0;
    for i in 0..3000 {
        let (c, ex, ey) = random_rectangle(&mut g, KINDS[i % KINDS.len()]);
        let base = SphericalRectangle::new(c, ex, ey);
        if base.solid_angle() <= 0.0 {
            continue;
        }
        let u = Vec2::new(g.u01(), g.u01());
        let (p0, pdf0) = base.sample(u);
        for e in (-50..=50).step_by(10) {
            let k = 2f32.powi(e);
            let r = SphericalRectangle::new(c * k, ex * k, ey * k);
            let (p, pdf) = r.sample(u);
            assert!(
                pdf.to_bits() == pdf0.to_bits()
                    && p.to_array().map(f32::to_bits) == (p0 * k).to_array().map(f32::to_bits)
                    && r.by_area() == base.by_area()
                    && r.solid_angle() == base.solid_angle(),
                "2^{e}: {:?} u={u:?}: {p:?} {pdf} vs {:?} {pdf0}",
                (c, ex, ey),
                p0 * k
            );
            n += 1;
        }
    }
    assert!(n > 20_000, "{n}");
}
