//! The report's tables, one builder per table. Each builds its cells once; stdout prints them as
//! aligned text and `--markdown` writes them as Markdown, so the two cannot disagree.

use crate::direct::{self, DirectRow};
use crate::estimators::{self, EstRow, WeightRow};
use crate::sequences::SeqRow;
use crate::{Config, POINTS, PreparedRow, Row};
use mcsample::verify::mis1d::{ESTIMATORS, INTEGRANDS};

pub struct Table {
    pub title: &'static str,
    /// What the columns mean and the run's parameters, one sentence or clause per line.
    pub note: String,
    pub head: Vec<String>,
    pub rows: Vec<Vec<String>>,
    /// How many leading columns hold names (left-aligned); the rest hold numbers.
    pub names: usize,
}

impl Table {
    fn new(title: &'static str, note: String, head: &[&str], names: usize) -> Self {
        let head = head.iter().map(|h| h.to_string()).collect();
        Table {
            title,
            note,
            head,
            rows: Vec::new(),
            names,
        }
    }

    /// Aligned columns under the title and the note, for stdout.
    pub fn text(&self) -> String {
        let width = |i: usize| {
            let cells = self.rows.iter().chain([&self.head]).map(|r| &r[i]);
            cells.map(|c| c.chars().count()).max().unwrap_or(0)
        };
        let widths: Vec<usize> = (0..self.head.len()).map(width).collect();
        let mut s = format!("\n{}:\n", self.title);
        for line in self.note.lines() {
            s += &format!("  {line}\n");
        }
        for cells in [&self.head].into_iter().chain(&self.rows) {
            let padded: Vec<String> = (cells.iter().zip(&widths).enumerate())
                .map(|(i, (c, &w))| {
                    if i < self.names {
                        format!("{c:<w$}")
                    } else {
                        format!("{c:>w$}")
                    }
                })
                .collect();
            s += padded.join("  ").trim_end();
            s.push('\n');
        }
        s
    }

    /// A section: the title as a heading, the note as a paragraph, then the table.
    pub fn markdown(&self) -> String {
        let line = |cells: &[String]| {
            let cells: Vec<String> = cells.iter().map(|c| c.replace('|', "\\|")).collect();
            format!("| {} |\n", cells.join(" | "))
        };
        let align: String = (0..self.head.len())
            .map(|i| if i < self.names { "---|" } else { "---:|" })
            .collect();
        let mut s = format!("## {}\n\n{}\n\n", self.title, self.note.trim_end());
        s += &line(&self.head);
        s += &format!("|{align}\n");
        for r in &self.rows {
            s += &line(r);
        }
        s
    }
}

/// `digits` significant digits, in positional notation from 0.01 to 10⁴ and in exponent notation
/// outside.
fn sig(x: f64, digits: i32) -> String {
    let e = x.abs().log10().floor() as i32;
    if x == 0.0 {
        "0".into()
    } else if !x.is_finite() || (-2..4).contains(&e) {
        let decimals = (digits - 1 - e.clamp(-2, 3)).max(0) as usize;
        format!("{x:.decimals$}")
    } else {
        format!("{x:.*e}", (digits - 1) as usize)
    }
}

fn ratio(a: f64, b: f64) -> String {
    format!("{:.1}×", a / b)
}

/// The χ² p-value below which one of `tests` tests fails at α = 0.01 overall (Šidák).
fn sidak(tests: usize) -> f64 {
    1.0 - 0.99f64.powf(1.0 / tests as f64)
}

pub fn warps(cfg: &Config, rows: &[Row]) -> Table {
    let tests = rows.iter().filter(|r| r.chi2_p.is_finite()).count();
    let (random, grid, chi2) = if cfg.quick {
        ("2¹⁶", 128, "2·10⁵")
    } else {
        ("2²⁰", 512, "10⁶")
    };
    let note = format!(
        "Every sampler of `verify::registry`: the warps, the lights seen from the origin (set-up \
         paid at every sample) and the BSDFs.\n\
         Times: ns per sample on {POINTS} in-cache points, medians of runs in which the scalar and \
         x8 loops alternate, so their ratio comes from one stretch of the machine's load; \
         x16 / x8: the sixteen-wide loop's throughput over the eight-wide loop's, from their own \
         alternating pair ({x16}).\n\
         vs plain: the scalar loop's time over that of the plain glam+std version of the same \
         formula (`examples/report/plain.rs`), timed as its own interleaved pair.\n\
         Errors: the worst over {random} random u, a {grid}² grid and the square's edges and \
         branch lines, against the f64 instance of the same generic code (`worst u` is where); \
         plain err: the plain version's, against the same f64 instance, where it computes the same \
         map (the spherical polygons); pdf errors where both instances are inside the support.\n\
         χ² p: Mitsuba's test on {chi2} samples; the Šidák level for α = 0.01 over these {tests} \
         tests is {:.1e}.",
        sidak(tests),
        x16 = if cfg!(target_feature = "avx512f") {
            "one AVX-512 register per sixteen lanes"
        } else {
            "emulated: this build has no AVX-512, so `wide` runs each sixteen-wide operation as two \
             eight-wide halves"
        }
    );
    let head = [
        "sampler",
        "scalar ns",
        "vs plain",
        "x8 ns",
        "speedup",
        "x16 ns",
        "x16 / x8",
        "max abs err",
        "plain err",
        "worst u",
        "pdf rel err",
        "χ² p",
    ];
    let mut t = Table::new("Warps, lights and BSDFs", note, &head, 1);
    for r in rows {
        t.rows.push(vec![
            r.name.clone(),
            format!("{:.2}", r.scalar_ns),
            r.scalar_vs_plain.map_or("–".into(), |v| format!("{v:.2}×")),
            format!("{:.2}", r.x8_ns),
            ratio(r.scalar_ns, r.x8_ns),
            format!("{:.2}", r.x16_ns),
            format!("{:.2}×", r.x16_vs_x8),
            format!("{:.2e}", r.max_abs_err),
            r.plain_max_abs_err
                .map_or("–".into(), |e| format!("{e:.2e}")),
            format!("({:.7}, {:.7})", r.worst_u.x, r.worst_u.y),
            format!("{:.2e}", r.max_pdf_rel_err),
            format!("{:.4}", r.chi2_p),
        ]);
    }
    t
}

pub fn prepared(rows: &[PreparedRow]) -> Table {
    let note = "Scalar ns of a light's first sample at a new shading point (set-up included) and \
                of each further sample of the light prepared there (`light.at_sampling(p, n, \
                mode)`, n the registry's tilted normal; the loop keeps direction × pdf, so the \
                pdf is timed too), timed as one interleaved pair; further / solid angle: a \
                further sample's time over the same light's by solid angle, timed as an \
                interleaved pair of its own. The triangle and the rectangle in every \
                light-sampling mode, the sphere by solid angle (its cone) and projected solid \
                angle (its cap), the disk by solid angle (its spherical ellipse) and by area. \
                The spheres seen from outside also for two more normals: `across` puts the \
                centre on the receiver's horizon, `below` half the cap's angular radius under \
                it; their projected samples solve the lune between the cap's ellipse and the \
                horizon by Newton's method."
        .to_string();
    let head = [
        "light",
        "lights",
        "first ns",
        "further ns",
        "first / further",
        "further / solid angle",
    ];
    let mut t = Table::new("Prepared lights", note, &head, 2);
    for r in rows {
        t.rows.push(vec![
            r.name.clone(),
            r.mode.to_string(),
            format!("{:.2}", r.first_ns),
            format!("{:.2}", r.further_ns),
            ratio(r.first_ns, r.further_ns),
            format!("{:.2}×", r.further_vs_solid_angle),
        ]);
    }
    t
}

pub fn stability(rows: &[(String, f64, f64, f64)]) -> Table {
    let note = "The f32 Arvo and Ureña maps without their area fallback, against their f64 \
                instances, for lights from 1e-8 sr to nearly a hemisphere: the worst direction \
                error over the light's angular size √Ω is a sample displaced by that fraction of \
                the light."
        .to_string();
    let head = ["light", "Ω (sr)", "max dir err", "err / √Ω"];
    let mut t = Table::new("Spherical sampling stability", note, &head, 1);
    for (name, omega, err, rel) in rows {
        t.rows.push(vec![
            name.clone(),
            sig(*omega, 3),
            format!("{err:.2e}"),
            format!("{rel:.2e}"),
        ]);
    }
    t
}

pub fn sequences(cfg: &Config, rows: &[SeqRow]) -> Table {
    let note = format!(
        "ns per f32 value: a plain loop of scalar calls over consecutive indices (LLVM may \
         vectorise it), scalar calls one at a time on opaque indices, x8 and x16 (all four \
         interleaved in one run).\n\
         L2*: the RMS L2-star discrepancy of the first 1024 points over 32 seeds (iid points: \
         {:.2e}).\n\
         Slopes: log RMSE against log N over N = 16…4096 and {} seeds, on the Gaussian \
         e^(−x²−y²) and on the disk indicator 1[x² + y² < 2/π].",
        ((0.25f64 - 1.0 / 9.0) / 1024.0).sqrt(),
        if cfg.quick { 16 } else { 64 }
    );
    let head = [
        "generator",
        "loop ns",
        "call ns",
        "x8 ns",
        "x8 / call",
        "x16 ns",
        "L2* 1024",
        "slope, Gaussian",
        "slope, disk",
    ];
    let mut t = Table::new("Sequences", note, &head, 1);
    for r in rows {
        t.rows.push(vec![
            r.name.to_string(),
            format!("{:.3}", r.scalar_ns),
            format!("{:.3}", r.scalar_call_ns),
            format!("{:.3}", r.x8_ns),
            ratio(r.scalar_call_ns, r.x8_ns),
            format!("{:.3}", r.x16_ns),
            format!("{:.2e}", r.l2_star_1024),
            format!("{:.3}", r.slope_gaussian),
            format!("{:.3}", r.slope_disk),
        ]);
    }
    t
}

pub fn estimators(rows: &[EstRow]) -> Table {
    let n = estimators::N;
    let note = format!(
        "Variance per estimate relative to the better single technique, at {n} + {n} samples \
         (`verify::mis1d`: techniques p₁ = 1 and p₂ = 0.2 + 1.6x on [0, 1]).\n\
         Alone, each technique takes {} samples; RIS takes that many candidates from p₁ per f \
         evaluation.",
        2 * n
    );
    let mut head = vec!["estimator"];
    head.extend(INTEGRANDS.iter().map(|i| i.name));
    let mut t = Table::new("Estimators", note, &head, 1);
    for (k, name) in ESTIMATORS.iter().enumerate() {
        let mut cells = vec![name.to_string()];
        let per_integrand = rows.iter().skip(k).step_by(ESTIMATORS.len());
        cells.extend(per_integrand.map(|r| sig(r.vs_best_single, 3)));
        t.rows.push(cells);
    }
    t
}

pub fn weights(rows: &[WeightRow]) -> Table {
    let note = "ns per weight, pdfs over twelve decades; x16 / x8: the sixteen-wide form's \
                throughput over the eight-wide form's, from their own interleaved pair."
        .to_string();
    let head = [
        "heuristic", "scalar ns", "x8 ns", "speedup", "x16 ns", "x16 / x8",
    ];
    let mut t = Table::new("MIS weights", note, &head, 1);
    for w in rows {
        t.rows.push(vec![
            w.name.to_string(),
            format!("{:.3}", w.scalar_ns),
            format!("{:.3}", w.x8_ns),
            ratio(w.scalar_ns, w.x8_ns),
            format!("{:.3}", w.x16_ns),
            format!("{:.2}×", w.x16_vs_x8),
        ]);
    }
    t
}

pub fn direct(rows: &[DirectRow]) -> Table {
    let n = direct::N;
    let note = format!(
        "Every strategy of `mcsample::direct` on every scene of `verify::direct`, N = {n} + {n} \
         samples per estimate, independent samples, unit visibility.\n\
         bias σ: the mean's bias in standard errors of the mean of {} estimates (– where every \
         estimate was equal, or the mean is the reference to the f32 rounding of 1e-6: \
         projected light sampling has no variance on a Lambertian receiver); rel RMSE: of one \
         estimate.\n\
         x8 ns: per estimate per lane; x16 / x8: the sixteen-wide path's throughput over the \
         eight-wide path's, medians of five alternating runs each (– for scenes with occluders); \
         rays: shadow rays per estimate; eff / best: efficiency \
         1/(MSE·time) over that of the best single strategy (uniform, light or BSDF sampling) \
         of the scene in any mode; eff / solid angle: over that of the same strategy with the \
         lights sampled by solid angle.\n\
         lights: how every strategy that samples a light samples it (`LightSampling`): solid \
         angle, the bilinear cosine warp, projected solid angle or area for the triangle and \
         rectangle lights, whose scenes are run in every mode; solid angle (the cone) or \
         projected solid angle (the cap) for the sphere lights; solid angle (the spherical \
         ellipse) or area for the disk.",
        rows.first().map_or(0, |r| r.run.estimates)
    );
    let head = [
        "scene",
        "strategy",
        "lights",
        "reference",
        "bias σ",
        "rel RMSE",
        "x8 ns",
        "scalar ns",
        "x16 / x8",
        "rays",
        "eff / best",
        "eff / solid angle",
    ];
    let mut t = Table::new("Direct lighting", note, &head, 2);
    for r in rows {
        t.rows.push(vec![
            r.scene.clone(),
            r.strategy.to_string(),
            r.light_sampling.to_string(),
            sig(r.reference, 6),
            r.bias_sigma().map_or("–".into(), |b| format!("{b:.2}")),
            sig(r.run.rel_rmse, 3),
            format!("{:.0}", r.ns),
            format!("{:.0}", r.scalar_ns),
            if r.x16_vs_x8.is_finite() {
                format!("{:.2}×", r.x16_vs_x8)
            } else {
                "–".into()
            },
            format!("{:.2}", r.run.shadow_rays),
            sig(r.vs_best_single, 3),
            sig(r.vs_solid_angle, 3),
        ]);
    }
    t
}

pub fn streaming(cfg: &Config, copy_ns: f64, cosine_ns: f64) -> Table {
    let note = "Large arrays: the x8 cosine hemisphere against a copy kernel that moves the same \
                bytes (2 floats in, 3 out), ns per point."
        .to_string();
    let head = ["points", "copy ns", "x8 cosine_hemisphere ns", "ratio"];
    let mut t = Table::new("Streaming", note, &head, 1);
    t.rows.push(vec![
        if cfg.quick { "2²⁰" } else { "2²⁴" }.to_string(),
        format!("{copy_ns:.3}"),
        format!("{cosine_ns:.3}"),
        format!("{:.2}", cosine_ns / copy_ns),
    ]);
    t
}
