//! `--plots DIR`: the report's figures as SVG, drawn with plotters.
//!
//! - `sequences_rmse.svg`: RMSE against N, log-log, for every sequence generator (the Gaussian
//!   integrand of the slopes column);
//! - `direct_<cell>.svg`: relative RMSE against ns per estimate for the direct-lighting
//!   strategies in two cells of the lecture's grid, one where light sampling wins and one where
//!   BSDF sampling does, at N = 2…128 samples per estimate;
//! - `warps_speed_error.svg`: x8 ns per sample against the worst error against the f64 instance,
//!   for every warp and light of the registry;
//! - `polygons_speed_error.svg`: the same for the spherical polygons, scalar and x8, beside their
//!   textbook versions (scalar ns from the `vs plain` pair, error against the same f64 instance).

use std::path::Path;
use std::time::Instant;

use mcsample::direct::{Config as DirectConfig, Strategy};
use mcsample::seq::Generator;
use mcsample::verify::direct::{grid_scenes, run};
use plotters::coord::Shift;
use plotters::prelude::*;

use crate::{Config, Row};

type Series = (String, Vec<(f64, f64)>);

/// The range of a set of positive values, widened by a factor of 1.5 each way for a log axis.
fn log_range(values: impl Iterator<Item = f64>) -> std::ops::Range<f64> {
    let (lo, hi) = values
        .filter(|v| v.is_finite() && *v > 0.0)
        .fold((f64::INFINITY, 0.0f64), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if lo.is_finite() {
        lo / 1.5..hi * 1.5
    } else {
        1e-3..1.0
    }
}

type LogLog = Cartesian2d<LogCoord<f64>, LogCoord<f64>>;

/// A white log-log chart with its caption, axes and grid drawn.
fn log_chart<'a, 'b>(
    root: &'a DrawingArea<SVGBackend<'b>, Shift>,
    title: &str,
    (xs, x_desc): (std::ops::Range<f64>, &str),
    (ys, y_desc): (std::ops::Range<f64>, &str),
) -> Result<ChartContext<'a, SVGBackend<'b>, LogLog>, Box<dyn std::error::Error>> {
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(root)
        .caption(title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(44)
        .y_label_area_size(70)
        .build_cartesian_2d(xs.log_scale(), ys.log_scale())?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc(y_desc)
        .draw()?;
    Ok(chart)
}

/// A log-log chart of lines with markers and a legend.
fn lines(
    path: &Path,
    title: &str,
    x_desc: &str,
    y_desc: &str,
    series: &[Series],
) -> Result<(), Box<dyn std::error::Error>> {
    let root = SVGBackend::new(path, (800, 560)).into_drawing_area();
    let xs = log_range(series.iter().flat_map(|s| s.1.iter().map(|p| p.0)));
    let ys = log_range(series.iter().flat_map(|s| s.1.iter().map(|p| p.1)));
    let mut chart = log_chart(&root, title, (xs, x_desc), (ys, y_desc))?;
    for (i, (name, points)) in series.iter().enumerate() {
        let color = Palette99::pick(i).to_rgba();
        let points: Vec<_> = points
            .iter()
            .copied()
            .filter(|p| p.0 > 0.0 && p.1 > 0.0)
            .collect();
        chart
            .draw_series(LineSeries::new(points.clone(), color.stroke_width(2)))?
            .label(name.as_str())
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
            });
        chart.draw_series(points.iter().map(|&p| Circle::new(p, 3, color.filled())))?;
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    root.present()?;

    Ok(())
}

/// Relative RMSE against ns per estimate for the direct strategies in one grid cell.
fn direct_curves(cell: &str, quick: bool) -> Vec<Series> {
    let scene = grid_scenes()
        .into_iter()
        .find(|s| s.name == cell)
        .expect("a grid cell");
    let estimates = if quick { 256 } else { 1024 };
    let strategies = [
        Strategy::LightSolidAngle,
        Strategy::Bsdf,
        Strategy::MisBalance,
        Strategy::MisPower,
        Strategy::OneSampleMis,
        Strategy::OptimalMis,
        Strategy::Ris,
    ];
    strategies
        .iter()
        .map(|&s| {
            let points = (1..=7)
                .map(|k| {
                    let half = 1u32 << (k - 1);
                    let config = DirectConfig::new(half, half);
                    // Warm the caches and the branch predictors, so that the first point is not
                    // charged for them.
                    run(&scene, s, config, 8, (Generator::Independent, 76));
                    let t = Instant::now();
                    let r = run(&scene, s, config, estimates, (Generator::Independent, 77));
                    let ns = t.elapsed().as_secs_f64() * 1e9 / r.estimates as f64;
                    (ns, r.rel_rmse)
                })
                .collect();
            (s.name().to_string(), points)
        })
        .collect()
}

/// Writes every figure into `dir`.
pub fn write(
    dir: &str,
    cfg: &Config,
    rows: &[Row],
    seq_curves: &[(&'static str, Vec<(f64, f64)>)],
) -> Result<(), Box<dyn std::error::Error>> {
    let dir = Path::new(dir);
    std::fs::create_dir_all(dir)?;
    let series: Vec<Series> = seq_curves
        .iter()
        .map(|(n, c)| (n.to_string(), c.clone()))
        .collect();
    lines(
        &dir.join("sequences_rmse.svg"),
        "Sequences: RMSE of ∫ Gaussian against N",
        "N",
        "RMSE",
        &series,
    )?;
    for cell in ["grid_n100_r0.05", "grid_n1000_r0.2"] {
        let series = direct_curves(cell, cfg.quick);
        let title = format!("Direct lighting, {cell}: error against time (N = 2…128)");
        lines(
            &dir.join(format!("direct_{cell}.svg")),
            &title,
            "ns per estimate (x8, per lane)",
            "relative RMSE",
            &series,
        )?;
    }
    // Warps and lights: one point each, labelled. Exact results (error 0) sit on the floor.
    let floor = 1e-9;
    let path = dir.join("warps_speed_error.svg");
    let root = SVGBackend::new(&path, (900, 640)).into_drawing_area();
    let xs = log_range(rows.iter().map(|r| r.x8_ns));
    let ys = log_range(rows.iter().map(|r| r.max_abs_err.max(floor)));
    let mut chart = log_chart(
        &root,
        "Warps and lights: x8 time against worst error vs f64",
        (xs, "x8 ns per sample"),
        (ys, "max abs error (1e-9 = exact)"),
    )?;
    chart.draw_series(rows.iter().map(|r| {
        let p = (r.x8_ns, r.max_abs_err.max(floor));
        EmptyElement::at(p)
            + Circle::new((0, 0), 3, BLUE.filled())
            + Text::new(r.name.clone(), (5, -10), ("sans-serif", 10))
    }))?;
    root.present()?;

    // The polygons beside their textbook versions: what the robust set-up's time buys.
    let mut points: Vec<(String, f64, f64, RGBColor)> = Vec::new();
    for r in rows {
        if let (Some(vs), Some(plain_err)) = (r.scalar_vs_plain, r.plain_max_abs_err) {
            let err = r.max_abs_err.max(floor);
            points.push((format!("{} scalar", r.name), r.scalar_ns, err, BLUE));
            points.push((format!("{} x8", r.name), r.x8_ns, err, BLUE));
            let textbook = (r.scalar_ns / vs, plain_err.max(floor));
            points.push((format!("{} textbook", r.name), textbook.0, textbook.1, RED));
        }
    }
    if !points.is_empty() {
        let path = dir.join("polygons_speed_error.svg");
        let root = SVGBackend::new(&path, (900, 640)).into_drawing_area();
        let xs = log_range(points.iter().map(|p| p.1));
        let ys = log_range(points.iter().map(|p| p.2));
        let mut chart = log_chart(
            &root,
            "Spherical polygons: ns per sample against worst error vs f64 (red: textbook)",
            (xs, "ns per sample (scalar, or x8 per lane)"),
            (ys, "max abs error (1e-9 = exact)"),
        )?;
        chart.draw_series(points.iter().map(|(name, x, y, colour)| {
            EmptyElement::at((*x, *y))
                + Circle::new((0, 0), 3, colour.filled())
                + Text::new(name.clone(), (5, -10), ("sans-serif", 10))
        }))?;
        root.present()?;
    }
    Ok(())
}
