//! The main job: speed against error for every warp and every sequence generator.
//!
//! `cargo run --release --example report` prints, per warp, the scalar and x8 time per sample on
//! in-cache points (medians of repeated runs, the two forms interleaved so that their ratio comes
//! from one run), the scalar time over the plain glam+std version's (`plain.rs`), the speedup, the worst error against the f64 instance of the same generic code,
//! the worst pdf error, and the χ² p-value of 10⁶ samples. Then, per sequence generator, scalar
//! and x8 ns per value, the L2-star discrepancy at N = 1024 and the RMSE slopes on the Gaussian
//! and the disk indicator (see `sequences.rs`). `-- --quick` is a shorter run for CI;
//! `-- --json PATH` also writes the numbers as JSON, and `-- --markdown PATH` the printed tables
//! as Markdown (`table.rs` builds each table once for both; REPORT.md is a full run's).

mod direct;
mod estimators;
mod markdown;
mod plain;
mod plots;
mod sequences;
mod table;

use std::fmt::Write as _;
use std::hint::black_box;
use std::time::Instant;

use glam::{DVec2, DVec3, Vec2, Vec3};
use mcsample::lane::{V2, V3};
use mcsample::scene::{AnyShape, Light, LightSampling, PreparedLight, Shape, Sphere};
use mcsample::verify::registry::{self, Sampler};
use mcsample::warp::{
    self, SolidAngleRectangle, SolidAngleTriangle, SphericalRectangle, SphericalTriangle,
};
use mcsample::x8::{Vec2x8, Vec3x8};
use mcsample::x16::{Vec2x16, Vec3x16};
use rand_core::Rng;
use rand_pcg::Pcg32;

/// In-cache working set for timings, in points.
const POINTS: usize = 4096;

struct Config {
    quick: bool,
    json: Option<String>,
    plots: Option<String>,
    markdown: Option<String>,
}

struct Row {
    name: String,
    scalar_ns: f64,
    /// Our scalar loop's time over the plain glam+std version's, in the same run.
    scalar_vs_plain: Option<f64>,
    x8_ns: f64,
    /// The sixteen-wide loop, ns per sample, and its throughput over the eight-wide loop's,
    /// timed as their own interleaved pair.
    x16_ns: f64,
    x16_vs_x8: f64,
    max_abs_err: f64,
    worst_u: Vec2,
    /// The plain version's worst error against the same f64 instance, where it computes the same
    /// map (the spherical polygons: Arvo's and Ureña's).
    plain_max_abs_err: Option<f64>,
    max_pdf_rel_err: f64,
    chi2_p: f64,
}

/// A light of the registry prepared at a shading point in one light-sampling mode: its first
/// sample at a new point (set-up included) and each further sample of the prepared light, scalar
/// ns, timed as one interleaved pair.
pub struct PreparedRow {
    name: String,
    mode: &'static str,
    first_ns: f64,
    further_ns: f64,
    /// further_ns over the same light's further sample by solid angle, timed as a pair of its
    /// own.
    further_vs_solid_angle: f64,
}

fn uniform_points(n: usize, seed: u64) -> Vec<Vec2> {
    let mut rng = Pcg32::new(seed, 0xda3e_39cb_94b9_5bdb);
    let mut f = move || (rng.next_u32() >> 8) as f32 * (1.0 / 16_777_216.0);
    (0..n).map(|_| Vec2::new(f(), f())).collect()
}

/// Points for the error sweep: random, plus a stratified grid, plus the square's edges and the
/// lines where the maps change branch.
fn error_points(quick: bool) -> Vec<Vec2> {
    let mut v = uniform_points(if quick { 1 << 16 } else { 1 << 20 }, 5);
    let m = if quick { 128 } else { 512 };
    for i in 0..m {
        for j in 0..m {
            v.push(Vec2::new(
                (i as f32 + 0.5) / m as f32,
                (j as f32 + 0.5) / m as f32,
            ));
        }
    }
    let edges = [0.0, 1e-7, 0.5, 0.25, 0.75, warp::ONE_MINUS_EPS];
    for &a in &edges {
        for k in 0..=256 {
            let b = (k as f32 / 256.0).min(warp::ONE_MINUS_EPS);
            v.push(Vec2::new(a, b));
            v.push(Vec2::new(b, a));
        }
    }
    v
}

/// Median ns per element of `a_in` of two loops over the same points (in two layouts: single
/// points, or packets), interleaved run by run so that their ratio comes from one stretch of the
/// machine's load.
fn time_pair<A, B, OA: Default + Clone, OB: Default + Clone>(
    cfg: &Config,
    a_in: &[A],
    b_in: &[B],
    fa: &dyn Fn(&[A], &mut [OA]),
    fb: &dyn Fn(&[B], &mut [OB]),
) -> (f64, f64) {
    let points = a_in.len();
    let mut out_a = vec![OA::default(); a_in.len()];
    let mut out_b = vec![OB::default(); b_in.len()];
    let runs = if cfg.quick { 9 } else { 41 };
    let target = if cfg.quick { 2e-4 } else { 2e-3 }; // seconds per run
    let mut reps = 1usize;
    loop {
        let t = Instant::now();
        for _ in 0..reps {
            fa(black_box(a_in), &mut out_a);
        }
        if t.elapsed().as_secs_f64() > target / 4.0 {
            break;
        }
        reps *= 2;
    }
    let (mut ta, mut tb) = (Vec::with_capacity(runs), Vec::with_capacity(runs));
    for _ in 0..runs {
        let t = Instant::now();
        for _ in 0..reps {
            fa(black_box(a_in), &mut out_a);
        }
        ta.push(t.elapsed().as_secs_f64());
        black_box(&out_a);
        let t = Instant::now();
        for _ in 0..reps {
            fb(black_box(b_in), &mut out_b);
        }
        tb.push(t.elapsed().as_secs_f64());
        black_box(&out_b);
    }
    let med = |v: &mut Vec<f64>| {
        v.sort_by(f64::total_cmp);
        v[v.len() / 2] * 1e9 / (reps * points) as f64
    };
    (med(&mut ta), med(&mut tb))
}

fn d2(u: DVec2) -> V2<f64> {
    u.into()
}
fn d3(v: Vec3) -> V3<f64> {
    v.as_dvec3().into()
}

/// A sampler's accuracy: its worst error against its f64 instance over the error points (and
/// the u where it occurs), its worst pdf error, and its χ² p-value.
struct Accuracy {
    max_abs_err: f64,
    worst_u: Vec2,
    plain_max_abs_err: Option<f64>,
    max_pdf_rel_err: f64,
    chi2_p: f64,
}

fn accuracy(cfg: &Config, s: Sampler, err_pts: &[Vec2]) -> Accuracy {
    let mut max_abs_err = 0.0f64;
    let mut worst_u = Vec2::ZERO;
    let mut max_pdf_rel_err = 0.0f64;
    for &u in err_pts.iter().filter(|&&u| !s.parameter_sensitive(u)) {
        let a = s.sample(u).0;
        let b = s.sample(u.as_dvec2()).0;
        let e = (a.as_dvec3() - b).abs().max_element();
        if worse(e, max_abs_err) {
            max_abs_err = e;
            worst_u = u;
        }
        let ps = s.pdf(a) as f64;
        let pr = s.pdf(a.as_dvec3());
        // A point on the support's boundary may be inside in one precision and outside in the
        // other: that is a rounding of the support, not a pdf error, so only points inside in
        // both count.
        if pr > 0.0 && ps > 0.0 {
            let rel = ((ps - pr) / pr).abs();
            if worse(rel, max_pdf_rel_err) {
                max_pdf_rel_err = rel;
            }
        }
    }
    // The textbook polygons map u as ours do where ours sample spherically, so their error is
    // measured against the same f64 instance there; the other plain versions may parametrise
    // differently.
    let same_map = match s {
        Sampler::SphericalTriangle(SolidAngleTriangle { v: [a, b, c] }) => {
            !SphericalTriangle::new(a, b, c).by_area()
        }
        Sampler::SphericalRectangle(SolidAngleRectangle { v: [c, ex, ey] }) => {
            !SphericalRectangle::new(c, ex, ey).by_area()
        }
        _ => false,
    };
    let plain_max_abs_err = plain::loop_for(s).filter(|_| same_map).map(|plain| {
        let us: Vec<Vec2> = err_pts
            .iter()
            .copied()
            .filter(|&u| !s.parameter_sensitive(u))
            .collect();
        let mut out = vec![Vec3::ZERO; us.len()];
        plain(&us, &mut out);
        us.iter().zip(&out).fold(0.0f64, |worst, (u, p)| {
            let e = (p.as_dvec3() - s.sample(u.as_dvec2()).0)
                .abs()
                .max_element();
            // A NaN stays: the textbook's NaN outputs are part of what it costs.
            if !worst.is_nan() && worse(e, worst) {
                e
            } else {
                worst
            }
        })
    });
    let n = if cfg.quick { 200_000 } else { 1_000_000 };
    let us = uniform_points(n, 7);
    Accuracy {
        max_abs_err,
        worst_u,
        plain_max_abs_err,
        max_pdf_rel_err,
        chi2_p: s.chi_square(n, |i| us[i]).p_value,
    }
}

/// `f` of every item, on every core: for the work that is not timed.
fn on_all_cores<T: Sync, R: Send>(items: &[T], f: impl Fn(&T) -> R + Sync) -> Vec<R> {
    use std::sync::Mutex;
    use std::sync::atomic::{AtomicUsize, Ordering};
    let next = AtomicUsize::new(0);
    let out: Mutex<Vec<Option<R>>> = Mutex::new(items.iter().map(|_| None).collect());
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    std::thread::scope(|scope| {
        for _ in 0..threads {
            scope.spawn(|| {
                loop {
                    let i = next.fetch_add(1, Ordering::Relaxed);
                    let Some(item) = items.get(i) else { break };
                    let r = f(item);
                    out.lock().unwrap()[i] = Some(r);
                }
            });
        }
    });
    out.into_inner()
        .unwrap()
        .into_iter()
        .map(|r| r.expect("every item is done"))
        .collect()
}

/// One row of the warp table: a sampler of the registry (the same samplers, at the same
/// parameters, as the tests), timed over the batch with the warp inlined into the loop, with its
/// accuracy.
fn measure(
    cfg: &Config,
    s: Sampler,
    pts: &[Vec2],
    (packets, packets16): (&[Vec2x8], &[Vec2x16]),
    acc: Accuracy,
) -> Row {
    let ours = |us: &[Vec2], out: &mut [Vec3]| s.sample_all(us, out);
    let x8 = |us: &[Vec2x8], out: &mut [Vec3x8]| s.sample_all(us, out);
    let (scalar_ns, x8_ns) = time_pair(cfg, pts, packets, &ours, &x8);
    let (x8_again, x16_ns) = time_pair(
        cfg,
        packets,
        packets16,
        &x8,
        &|us: &[Vec2x16], out: &mut [Vec3x16]| s.sample_all(us, out),
    );
    // The ratio to the plain version comes from its own interleaved pair.
    let scalar_vs_plain = plain::loop_for(s).map(|plain| {
        let (a, b) = time_pair(cfg, pts, pts, &ours, &*plain);
        a / b
    });
    Row {
        name: s.name(),
        scalar_ns,
        scalar_vs_plain,
        x8_ns,
        // This pair's times are per packet of eight: both loops cover the same samples.
        x16_ns: x16_ns / 8.0,
        x16_vs_x8: x8_again / x16_ns,
        max_abs_err: acc.max_abs_err,
        worst_u: acc.worst_u,
        plain_max_abs_err: acc.plain_max_abs_err,
        max_pdf_rel_err: acc.max_pdf_rel_err,
        chi2_p: acc.chi2_p,
    }
}

/// What a timed loop keeps of a light sample: its direction scaled by its pdf, so that the pdf's
/// computation cannot be left out of the time.
#[inline(always)]
fn sampled(s: mcsample::scene::LightSample<Vec3>) -> Vec3 {
    s.wi * s.pdf
}

/// The receiver's normals a light is prepared for: the registry's tilted normal, and for a
/// sphere seen from outside two more, named, that put its cap across the horizon (the centre on
/// it) and mostly below (the centre half the cap's angular radius σ below it), the cases whose
/// projected sample solves the lune.
fn receivers(shape: &AnyShape) -> Vec<(&'static str, Vec3)> {
    let mut normals = vec![("", mcsample::registry::TILTED)];
    if let AnyShape::Sphere(Sphere { center, radius }) = *shape {
        let c = center.as_dvec3();
        let sin = f64::from(radius) / c.length();
        if sin < 1.0 {
            let (axis, across) = (c.normalize(), c.any_orthonormal_vector());
            let tilt = |beta: f64| (axis * beta.cos() + across * beta.sin()).as_vec3();
            let half_pi = std::f64::consts::FRAC_PI_2;
            normals.push((" across", tilt(half_pi)));
            normals.push((" below", tilt(half_pi + 0.5 * sin.asin())));
        }
    }
    normals
}

/// The timed loop of a prepared light's further samples.
fn further_samples(light: &PreparedLight) -> impl Fn(&[Vec2], &mut [Vec3]) + '_ {
    move |us, out| {
        for (o, &u) in out.iter_mut().zip(us) {
            *o = sampled(light.sample(u));
        }
    }
}

/// Every light of the registry prepared at the origin for a receiver with normal
/// [`TILTED`](mcsample::registry::TILTED) (and the spheres for the normals of [`receivers`]), in
/// every light-sampling mode its shape offers.
fn prepared(cfg: &Config, samplers: &[Sampler], pts: &[Vec2]) -> Vec<PreparedRow> {
    let p = Vec3::ZERO;
    let mut rows = Vec::new();
    for s in samplers {
        let Some(light) = s.scene_light() else {
            continue;
        };
        for (suffix, n) in receivers(&light.shape) {
            rows.extend(prepared_at(cfg, s, &light, p, n, suffix, pts));
        }
    }
    rows
}

/// One light's rows for the receiver at p with normal n, in every mode its shape offers.
fn prepared_at(
    cfg: &Config,
    s: &Sampler,
    light: &Light,
    p: Vec3,
    n: Vec3,
    suffix: &str,
    pts: &[Vec2],
) -> Vec<PreparedRow> {
    let plain = light.at_sampling(p, n, LightSampling::SolidAngle);
    let mut rows = Vec::new();
    for &mode in light.shape.modes() {
        let prepared = light.at_sampling(p, n, mode);
        let (first, further) = time_pair(
            cfg,
            pts,
            pts,
            &|us: &[Vec2], out: &mut [Vec3]| {
                for (o, &u) in out.iter_mut().zip(us) {
                    *o = sampled(light.at_sampling(black_box(p), n, mode).sample(u));
                }
            },
            &further_samples(&prepared),
        );
        // Against solid angle in a pair of its own: one mode's time over another's from separate
        // runs moved by ±20 % on this shared machine where code identical in both did not.
        let vs_plain = if mode == LightSampling::SolidAngle {
            1.0
        } else {
            let (a, b) = time_pair(
                cfg,
                pts,
                pts,
                &further_samples(&plain),
                &further_samples(&prepared),
            );
            b / a
        };
        rows.push(PreparedRow {
            name: format!("{}{suffix}", s.name()),
            mode: mode.name(),
            first_ns: first,
            further_ns: further,
            further_vs_solid_angle: vs_plain,
        });
    }
    rows
}

/// Where spherical sampling breaks down: f32 Arvo and Ureña maps (no fallback) against their f64
/// instances, for lights from 1e-8 sr to nearly a hemisphere. The error is the worst direction
/// error over the light's angular size √Ω: a sample displaced by that fraction of the light.
fn stability(quick: bool) -> Vec<(String, f64, f64, f64)> {
    let pts = uniform_points(if quick { 1024 } else { 16384 }, 21);
    let mut rows = Vec::new();
    let sizes = [
        1e-4f32, 3e-4, 1e-3, 3e-3, 1e-2, 3e-2, 0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0,
    ];
    for &s in &sizes {
        let tri: Vec<Vec3> = (0..3)
            .map(|k| {
                let t = std::f32::consts::TAU * k as f32 / 3.0 + 0.3;
                Vec3::new(s * t.cos(), s * t.sin(), 1.0)
            })
            .collect();
        let (a, b, c) = (tri[0], tri[1], tri[2]);
        // Ω from the f64 set-up: 1/pdf would be the area pdf outside the spherical range.
        let omega = warp::SphericalTriangle::new(d3(a), d3(b), d3(c)).solid_angle();
        let mut worst = 0.0f64;
        for &u in &pts {
            let w32 = warp::arvo_triangle(u, a, b, c);
            let w64 = warp::arvo_triangle(d2(u.as_dvec2()), d3(a), d3(b), d3(c));
            let e = (w32.as_dvec3() - DVec3::from(w64)).length();
            worst = if worse(e, worst) { e } else { worst };
        }
        rows.push((
            format!("triangle s={s}"),
            omega,
            worst,
            worst / omega.sqrt(),
        ));

        // The rectangle: the facing square, and a 2:1 rectangle of the same area tilted 60°
        // from facing, seen 40° off its normal. Ω from the f64 set-up (exact VOS, whatever the
        // sampling mode).
        let tilted = {
            let (a, b) = (s * std::f32::consts::SQRT_2, s / std::f32::consts::SQRT_2);
            let (c60, s60) = (0.5f32, 0.75f32.sqrt());
            let ex = Vec3::new(a, 0.0, 0.0);
            let ey = Vec3::new(0.0, b * c60, b * s60);
            let centre = Vec3::new(0.64, 0.2, 0.74).normalize();
            (centre - ex * 0.5 - ey * 0.5, ex, ey)
        };
        let square = (
            Vec3::new(-s / 2.0, -s / 2.0, 1.0),
            Vec3::new(s, 0.0, 0.0),
            Vec3::new(0.0, s, 0.0),
        );
        for (label, (corner, ex, ey)) in [("rectangle", square), ("tilted rect", tilted)] {
            let omega = warp::SphericalRectangle::new(d3(corner), d3(ex), d3(ey)).solid_angle();
            let mut worst = 0.0f64;
            for &u in &pts {
                let p32 = warp::urena_rectangle(u, corner, ex, ey);
                let p64 = DVec3::from(warp::urena_rectangle(
                    d2(u.as_dvec2()),
                    d3(corner),
                    d3(ex),
                    d3(ey),
                ));
                let e = (p32.as_dvec3().normalize() - p64.normalize()).length();
                worst = if worse(e, worst) { e } else { worst };
            }
            rows.push((format!("{label} s={s}"), omega, worst, worst / omega.sqrt()));
        }
    }
    rows
}

fn cpu_name() -> String {
    std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .map(|l| l.split(':').nth(1).unwrap_or("").trim().to_string())
        })
        .unwrap_or_else(|| std::env::consts::ARCH.to_string())
}

fn target_features() -> Vec<&'static str> {
    let mut f = Vec::new();
    macro_rules! feat {
        ($($name:tt),*) => {$( if cfg!(target_feature = $name) { f.push($name); } )*};
    }
    feat!("sse2", "sse4.1", "avx", "avx2", "fma", "avx512f", "neon");
    f
}

/// Large arrays: x8 cosine_hemisphere against a copy kernel that moves the same bytes.
fn streaming(cfg: &Config) -> (f64, f64) {
    let n = if cfg.quick { 1 << 20 } else { 1 << 24 };
    let pts = uniform_points(n, 9);
    let packets: Vec<Vec2x8> = pts
        .chunks_exact(8)
        .map(|c| Vec2x8::from(<[Vec2; 8]>::try_from(c).unwrap()))
        .collect();
    drop(pts);
    let mut out8 = vec![Vec3x8::splat(Vec3::ZERO); packets.len()];
    let runs = if cfg.quick { 3 } else { 11 };
    let (mut tc, mut tw) = (Vec::new(), Vec::new());
    for _ in 0..runs {
        let t = Instant::now();
        for (o, u) in out8.iter_mut().zip(black_box(&packets)) {
            *o = Vec3x8::new(u.x, u.y, u.x);
        }
        black_box(&out8);
        tc.push(t.elapsed().as_secs_f64());
        let t = Instant::now();
        for (o, &u) in out8.iter_mut().zip(black_box(&packets)) {
            *o = warp::cosine_hemisphere(u);
        }
        black_box(&out8);
        tw.push(t.elapsed().as_secs_f64());
    }
    tc.sort_by(f64::total_cmp);
    tw.sort_by(f64::total_cmp);
    (tc[runs / 2] * 1e9 / n as f64, tw[runs / 2] * 1e9 / n as f64)
}

fn main() {
    let mut cfg = Config {
        quick: false,
        json: None,
        plots: None,
        markdown: None,
    };
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        match a.as_str() {
            "--quick" => cfg.quick = true,
            "--json" => cfg.json = args.next(),
            "--plots" => cfg.plots = args.next(),
            "--markdown" => cfg.markdown = args.next(),
            other => {
                eprintln!(
                    "unknown argument {other}; use --quick, --json PATH, --markdown PATH, --plots DIR"
                );
                std::process::exit(2);
            }
        }
    }
    let md_head = cfg.markdown.as_ref().map(|_| markdown::head());
    let cpu = cpu_name();
    let feats = target_features();
    println!(
        "mcsample {} report{}",
        env!("CARGO_PKG_VERSION"),
        if cfg.quick { " (quick)" } else { "" }
    );
    println!("  CPU: {cpu}");
    println!("  target features: {}", feats.join(", "));

    let pts = uniform_points(POINTS, 1);
    let packets: Vec<Vec2x8> = pts
        .chunks_exact(8)
        .map(|c| Vec2x8::from(<[Vec2; 8]>::try_from(c).unwrap()))
        .collect();
    let packets16: Vec<Vec2x16> = pts
        .chunks_exact(16)
        .map(|c| Vec2x16::from(<[Vec2; 16]>::try_from(c).unwrap()))
        .collect();
    let err_pts = error_points(cfg.quick);

    // Each table is printed as soon as it is measured, and kept for --markdown.
    let mut tables = Vec::new();
    let mut show = |t: table::Table| {
        print!("{}", t.text());
        tables.push(t);
    };
    // The accuracy of every sampler on all the cores first; then the timings, one at a time.
    let samplers: Vec<Sampler> = registry::registry().into_iter().collect();
    let accuracies = on_all_cores(&samplers, |&s| accuracy(&cfg, s, &err_pts));
    let rows: Vec<Row> = samplers
        .iter()
        .zip(accuracies)
        .map(|(&s, acc)| measure(&cfg, s, &pts, (&packets, &packets16), acc))
        .collect();
    show(table::warps(&cfg, &rows));
    let prepared_rows = prepared(&cfg, &samplers, &pts);
    show(table::prepared(&prepared_rows));
    let stab = stability(cfg.quick);
    show(table::stability(&stab));
    let seqs = sequences::sequences(cfg.quick);
    show(table::sequences(&cfg, &seqs));
    let est = estimators::variances(&cfg);
    show(table::estimators(&est));
    let weights = estimators::weight_times(&cfg);
    show(table::weights(&weights));
    let direct_rows = direct::direct(&cfg);
    show(table::direct(&direct_rows));
    let (copy_ns, cos_ns) = streaming(&cfg);
    show(table::streaming(&cfg, copy_ns, cos_ns));

    if let (Some(path), Some(head)) = (&cfg.markdown, &md_head) {
        markdown::write(path, head, &tables).expect("cannot write the Markdown report");
        println!("wrote {path}");
    }
    if let Some(path) = &cfg.json {
        let mut s = String::new();
        let esc = |x: &str| x.replace('\\', "\\\\").replace('"', "\\\"");
        let num = |x: f64| {
            if x.is_finite() {
                format!("{x:e}")
            } else {
                "null".into()
            }
        };
        write!(
            s,
            "{{\"build\": {{\"version\": \"{}\", \"target_features\": [{}], \"cpu\": \"{}\"}}, ",
            env!("CARGO_PKG_VERSION"),
            feats
                .iter()
                .map(|f| format!("\"{f}\""))
                .collect::<Vec<_>>()
                .join(", "),
            esc(&cpu)
        )
        .unwrap();
        write!(
            s,
            "\"streaming\": {{\"copy_ns\": {}, \"cosine_hemisphere_x8_ns\": {}}}, ",
            num(copy_ns),
            num(cos_ns)
        )
        .unwrap();
        // Each table is an array of flat objects, written the same way.
        let array = |key: &str, items: Vec<String>| format!("\"{key}\": [{}]", items.join(", "));
        let arrays = [
            array(
                "warps",
                rows.iter()
                    .map(|r| format!(
                        "{{\"name\": \"{}\", \"scalar_ns\": {}, \"scalar_vs_plain\": {}, \"x8_ns\": {}, \"x16_ns\": {}, \"x16_vs_x8\": {}, \"speedup\": {}, \"max_abs_err\": {}, \"plain_max_abs_err\": {}, \"max_pdf_rel_err\": {}, \"chi2_p\": {}}}",
                        esc(&r.name),
                        num(r.scalar_ns),
                        num(r.scalar_vs_plain.unwrap_or(f64::NAN)),
                        num(r.x8_ns),
                        num(r.x16_ns),
                        num(r.x16_vs_x8),
                        num(r.scalar_ns / r.x8_ns),
                        num(r.max_abs_err),
                        num(r.plain_max_abs_err.unwrap_or(f64::NAN)),
                        num(r.max_pdf_rel_err),
                        num(r.chi2_p)
                    ))
                    .collect(),
            ),
            array(
                "prepared",
                prepared_rows
                    .iter()
                    .map(|r| format!(
                        "{{\"name\": \"{}\", \"light_sampling\": \"{}\", \"first_ns\": {}, \"further_ns\": {}, \"further_vs_solid_angle\": {}}}",
                        esc(&r.name),
                        r.mode,
                        num(r.first_ns),
                        num(r.further_ns),
                        num(r.further_vs_solid_angle)
                    ))
                    .collect(),
            ),
            array(
                "stability",
                stab.iter()
                    .map(|(name, omega, err, rel)| format!(
                        "{{\"light\": \"{}\", \"omega\": {}, \"max_dir_err\": {}, \"err_over_sqrt_omega\": {}}}",
                        esc(name),
                        num(*omega),
                        num(*err),
                        num(*rel)
                    ))
                    .collect(),
            ),
            array(
                "sequences",
                seqs.iter()
                    .map(|r| format!(
                        "{{\"name\": \"{}\", \"scalar_ns\": {}, \"scalar_call_ns\": {}, \"x8_ns\": {}, \"x16_ns\": {}, \"l2_star_1024\": {}, \"slope_gaussian\": {}, \"slope_disk\": {}}}",
                        esc(r.name),
                        num(r.scalar_ns),
                        num(r.scalar_call_ns),
                        num(r.x8_ns),
                        num(r.x16_ns),
                        num(r.l2_star_1024),
                        num(r.slope_gaussian),
                        num(r.slope_disk)
                    ))
                    .collect(),
            ),
            array(
                "estimators",
                est.iter()
                    .map(|r| format!(
                        "{{\"integrand\": \"{}\", \"estimator\": \"{}\", \"variance\": {}, \"vs_best_single\": {}}}",
                        esc(r.integrand),
                        esc(r.estimator),
                        num(r.variance),
                        num(r.vs_best_single)
                    ))
                    .collect(),
            ),
            array(
                "direct",
                direct_rows
                    .iter()
                    .map(|r| format!(
                        "{{\"scene\": \"{}\", \"strategy\": \"{}\", \"light_sampling\": \"{}\", \"reference\": {}, \"mean\": {}, \"stderr\": {}, \"bias_sigma\": {}, \"rel_rmse\": {}, \"ns_per_estimate\": {}, \"scalar_ns_per_estimate\": {}, \"x16_vs_x8\": {}, \"visibility_calls\": {}, \"efficiency\": {}, \"efficiency_vs_best_single\": {}, \"efficiency_vs_solid_angle\": {}, \"estimates\": {}, \"samples_per_estimate\": {}}}",
                        esc(&r.scene),
                        r.strategy,
                        r.light_sampling,
                        num(r.reference),
                        num(r.run.mean),
                        num(r.run.stderr),
                        num(r.bias_sigma().unwrap_or(f64::NAN)),
                        num(r.run.rel_rmse),
                        num(r.ns),
                        num(r.scalar_ns),
                        num(r.x16_vs_x8),
                        num(r.run.shadow_rays),
                        num(r.efficiency),
                        num(r.vs_best_single),
                        num(r.vs_solid_angle),
                        r.run.estimates,
                        2 * direct::N
                    ))
                    .collect(),
            ),
            array(
                "mis_weights",
                weights
                    .iter()
                    .map(|w| format!(
                        "{{\"name\": \"{}\", \"scalar_ns\": {}, \"x8_ns\": {}, \"x16_ns\": {}, \"x16_vs_x8\": {}}}",
                        w.name,
                        num(w.scalar_ns),
                        num(w.x8_ns),
                        num(w.x16_ns),
                        num(w.x16_vs_x8)
                    ))
                    .collect(),
            ),
        ];
        s.push_str(&arrays.join(", "));
        s.push_str("}\n");
        std::fs::write(path, s).expect("cannot write the JSON report");
        println!("wrote {path}");
    }

    if let Some(dir) = &cfg.plots {
        let curves = sequences::rmse_curves(cfg.quick);
        plots::write(dir, &cfg, &rows, &curves).expect("cannot write the plots");
        println!("wrote the SVG plots into {dir}");
    }
}

/// True when `e` is a new worst error; NaN always is, so it cannot hide.
fn worse<T: PartialOrd>(e: T, current: T) -> bool {
    e.partial_cmp(&current) != Some(std::cmp::Ordering::Less)
        && e.partial_cmp(&current) != Some(std::cmp::Ordering::Equal)
}
