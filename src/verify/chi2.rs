//! Pearson's χ² goodness-of-fit test of a sampler against its pdf, in Mitsuba 3's form.
//!
//! See the [module documentation](super) for the method and an example.

use core::f64::consts::PI;
use core::fmt;
use core::marker::PhantomData;

use glam::{DVec2, DVec3};
use std::format;
use std::string::String;
use std::vec;
use std::vec::Vec;

use super::gamma::chi2_sf;

/// A sampling domain and its equal-area parameterisation by the unit box [0, 1]².
///
/// The test bins samples in the box and integrates the pdf over the box, so the map
/// [`from_unit`](Domain::from_unit) must be *equal-area*: a region of box area A must have measure
/// `A · MEASURE` in the domain. Then a pdf in the domain's own measure (per unit area, per
/// steradian) integrates over a cell with the constant Jacobian `MEASURE` and no other factor.
///
/// The crate provides [`Square`], [`Disk`] and [`Sphere`]. You may implement the trait for your
/// own domain (a hemisphere, a triangle in barycentrics, …) under the same rule.
pub trait Domain {
    /// The point handed to the pdf; samples are converted to it with `Into`.
    type Point: Copy + fmt::Debug;
    /// Name used in reports.
    const NAME: &'static str;
    /// Default histogram resolution (cells along the first and the second box coordinate).
    const DEFAULT_RES: (usize, usize);
    /// Measure of the whole domain (area, or solid angle in steradians).
    const MEASURE: f64;
    /// Box coordinates in [0, 1]² of a point, or `None` if the point is NaN, infinite or farther
    /// outside the domain than `tolerance` (points within the tolerance are clamped into it).
    fn to_unit(p: Self::Point, tolerance: f64) -> Option<DVec2>;
    /// The point at box coordinates `st` ∈ [0, 1]².
    fn from_unit(st: DVec2) -> Self::Point;
}

/// The unit square [0, 1)²: box coordinates are the point itself. Measure 1.
#[derive(Clone, Copy, Debug, Default)]
pub struct Square;

/// The unit disk, binned in (φ, r²): s = (φ + π)/2π, t = r² = x² + y².
///
/// Because dA = ½ d(r²) dφ, this box is equal-area (measure π), so every cell is an annular
/// sector of area π/(nx·ny), no cell is cut by the rim of the disk, and a uniform sampler expects
/// the same count in every cell. (Binning the bounding square [−1, 1]² instead would put the
/// pdf's jump at the rim through ~400 cells, where the trapezoid rule is biased.)
#[derive(Clone, Copy, Debug, Default)]
pub struct Disk;

/// The unit sphere of directions, binned in (φ, cos θ): s = (φ + π)/2π, t = (z + 1)/2.
///
/// By Archimedes' hat-box theorem this box is equal-area (measure 4π), so a pdf per steradian
/// integrates with no Jacobian. Directions are normalised before binning; one whose length is off
/// by more than the tolerance is counted as outside the domain. The +z pole is the top row (t = 1).
#[derive(Clone, Copy, Debug, Default)]
pub struct Sphere;

#[inline]
fn unit_phi(y: f64, x: f64) -> f64 {
    ((libm::atan2(y, x) + PI) / (2.0 * PI)).clamp(0.0, 1.0)
}

impl Domain for Square {
    type Point = DVec2;
    const NAME: &'static str = "square";
    const DEFAULT_RES: (usize, usize) = (101, 101);
    const MEASURE: f64 = 1.0;

    fn to_unit(p: DVec2, tolerance: f64) -> Option<DVec2> {
        let inside = |v: f64| v.is_finite() && v >= -tolerance && v <= 1.0 + tolerance;
        (inside(p.x) && inside(p.y)).then(|| p.clamp(DVec2::ZERO, DVec2::ONE))
    }

    fn from_unit(st: DVec2) -> DVec2 {
        st
    }
}

impl Domain for Disk {
    type Point = DVec2;
    const NAME: &'static str = "disk";
    const DEFAULT_RES: (usize, usize) = (101, 101);
    const MEASURE: f64 = PI;

    fn to_unit(p: DVec2, tolerance: f64) -> Option<DVec2> {
        let r2 = p.x * p.x + p.y * p.y;
        (r2.is_finite() && r2 <= 1.0 + tolerance)
            .then(|| DVec2::new(unit_phi(p.y, p.x), r2.min(1.0)))
    }

    fn from_unit(st: DVec2) -> DVec2 {
        let r = libm::sqrt(st.y);
        let phi = 2.0 * PI * st.x - PI;
        DVec2::new(r * libm::cos(phi), r * libm::sin(phi))
    }
}

impl Domain for Sphere {
    type Point = DVec3;
    const NAME: &'static str = "sphere";
    const DEFAULT_RES: (usize, usize) = (50, 101);
    const MEASURE: f64 = 4.0 * PI;

    fn to_unit(w: DVec3, tolerance: f64) -> Option<DVec2> {
        let len = libm::sqrt(w.x * w.x + w.y * w.y + w.z * w.z);
        if !(len.is_finite() && (len - 1.0).abs() <= tolerance) {
            return None;
        }
        let z = (w.z / len).clamp(-1.0, 1.0);
        Some(DVec2::new(
            unit_phi(w.y, w.x),
            (0.5 * (z + 1.0)).clamp(0.0, 1.0),
        ))
    }

    fn from_unit(st: DVec2) -> DVec3 {
        let z = 2.0 * st.y - 1.0;
        // 1 − z² = (1 − z)(1 + z) keeps its digits near the poles.
        let sin_theta = libm::sqrt(((1.0 - z) * (1.0 + z)).max(0.0));
        let phi = 2.0 * PI * st.x - PI;
        DVec3::new(sin_theta * libm::cos(phi), sin_theta * libm::sin(phi), z)
    }
}

/// Configuration of a χ² goodness-of-fit test on domain `D`; [`run`](ChiSquare::run) performs it.
///
/// Defaults: the domain's resolution (101 × 101 for [`Square`] and [`Disk`], 50 × 101 for
/// [`Sphere`]), 10⁶ samples, `ires` = 6 integration nodes per cell side, pooling below an expected
/// count of 5, and a domain tolerance of 1e-4.
#[derive(Clone, Copy, Debug)]
pub struct ChiSquare<D: Domain> {
    res: (usize, usize),
    samples: usize,
    ires: usize,
    min_expected: f64,
    tolerance: f64,
    domain: PhantomData<D>,
}

impl<D: Domain> Default for ChiSquare<D> {
    fn default() -> Self {
        Self::new()
    }
}

impl ChiSquare<Square> {
    /// A test on the unit square with the default settings.
    pub fn square() -> Self {
        Self::new()
    }
}

impl ChiSquare<Disk> {
    /// A test on the unit disk with the default settings.
    pub fn disk() -> Self {
        Self::new()
    }
}

impl ChiSquare<Sphere> {
    /// A test on the sphere of directions with the default settings.
    pub fn sphere() -> Self {
        Self::new()
    }
}

impl<D: Domain> ChiSquare<D> {
    /// A test on domain `D` with the default settings.
    pub fn new() -> Self {
        Self {
            res: D::DEFAULT_RES,
            samples: 1_000_000,
            ires: 6,
            min_expected: 5.0,
            tolerance: 1e-4,
            domain: PhantomData,
        }
    }

    /// Histogram resolution: `nx` cells along the first box coordinate (x for the square, φ for the
    /// disk and the sphere) and `ny` along the second (y, r², cos θ). Panics if either is 0.
    pub fn res(mut self, nx: usize, ny: usize) -> Self {
        assert!(
            nx > 0 && ny > 0,
            "ChiSquare::res: resolution must be positive"
        );
        self.res = (nx, ny);
        self
    }

    /// Number of samples drawn: the sampling closure is called with indices `0..n`.
    pub fn samples(mut self, n: usize) -> Self {
        self.samples = n;
        self
    }

    /// Integration nodes per cell side, counting both edges (so `ires − 1` trapezoid intervals per
    /// side; nodes on shared edges are evaluated once). Panics if `ires < 2`.
    ///
    /// Raise it when a sharp edge of the pdf's support cuts through cells (cones, spherical
    /// triangles): the trapezoid rule's error there shrinks like 1/(ires − 1). Keep it even when
    /// an edge runs through the middle of a row of cells, as the equator does with an odd number of
    /// cos θ cells: then no node lies on the edge and the symmetric rule integrates the step
    /// exactly.
    pub fn ires(mut self, ires: usize) -> Self {
        assert!(
            ires >= 2,
            "ChiSquare::ires: need at least the two cell edges"
        );
        self.ires = ires;
        self
    }

    /// Cells expecting fewer than this many samples are pooled (default 5).
    pub fn min_expected(mut self, min_expected: f64) -> Self {
        self.min_expected = min_expected;
        self
    }

    /// How far outside the domain a sample may fall, to absorb f32 rounding, before it counts as
    /// invalid (default 1e-4: in each coordinate for the square, in r² for the disk, in the length
    /// of the direction for the sphere).
    pub fn tolerance(mut self, tolerance: f64) -> Self {
        self.tolerance = tolerance;
        self
    }

    /// The expected count of every cell for `self.samples` samples of `pdf` (the integration half
    /// of [`run`](ChiSquare::run), useful on its own to check ∫ pdf = 1).
    pub fn expected<F>(&self, mut pdf: F) -> ExpectedCounts
    where
        F: FnMut(D::Point) -> f64,
    {
        let (nx, ny) = self.res;
        let m = self.ires - 1;
        let (gx, gy) = (nx * m + 1, ny * m + 1);
        let (dx, dy) = ((nx * m) as f64, (ny * m) as f64);

        // The pdf on the shared node grid.
        let mut bad = 0;
        let mut first_bad = None;
        let mut nodes = Vec::with_capacity(gx * gy);
        for j in 0..gy {
            for i in 0..gx {
                let p = D::from_unit(DVec2::new(i as f64 / dx, j as f64 / dy));
                let v = pdf(p);
                if v.is_finite() && v >= 0.0 {
                    nodes.push(v);
                } else {
                    bad += 1;
                    if first_bad.is_none() {
                        first_bad = Some(format!("pdf({p:?}) = {v}"));
                    }
                    nodes.push(0.0);
                }
            }
        }

        // Tensor trapezoid rule per cell: weights ½, 1, …, 1, ½ on each side.
        let weight = |k: usize| if k == 0 || k == m { 0.5 } else { 1.0 };
        let cell_measure = D::MEASURE / (dx * dy); // measure of one node-grid square
        let scale = self.samples as f64 * cell_measure;
        let mut expected = vec![0.0; nx * ny];
        let mut total = 0.0;
        for iy in 0..ny {
            for ix in 0..nx {
                let mut sum = 0.0;
                for b in 0..=m {
                    let row = &nodes[(iy * m + b) * gx + ix * m..][..=m];
                    let mut row_sum = 0.0;
                    for (a, v) in row.iter().enumerate() {
                        row_sum += weight(a) * v;
                    }
                    sum += weight(b) * row_sum;
                }
                total += sum;
                expected[iy * nx + ix] = sum * scale;
            }
        }
        ExpectedCounts {
            integral: total * cell_measure,
            counts: expected,
            invalid_nodes: bad,
            first_invalid: first_bad,
        }
    }

    /// Draw `self.samples` samples and test them against `pdf`.
    ///
    /// `sample(i)` returns the `i`-th sample (pass the index to a deterministic sequence, or ignore
    /// it and draw from a generator); anything that converts into the domain's point type will do
    /// (`glam::Vec2`/`DVec2` for the square and disk, `Vec3`/`DVec3` for the sphere). `pdf` is the
    /// density the samples claim to follow, in the domain's measure, as a function of an f64 point.
    ///
    /// The result's p-value is forced to 0, and [`passes`](ChiSquareResult::passes) to `false`,
    /// when any sample is NaN or outside the domain, when samples fall in cells whose expected
    /// count is 0, when the pdf is NaN, infinite or negative at an integration node, or when fewer
    /// than two contributions remain after pooling.
    pub fn run<P, S, F>(&self, mut sample: S, pdf: F) -> ChiSquareResult
    where
        S: FnMut(usize) -> P,
        P: Into<D::Point>,
        F: FnMut(D::Point) -> f64,
    {
        let (nx, ny) = self.res;

        // Observed counts.
        let mut observed = vec![0u64; nx * ny];
        let mut invalid_samples = 0;
        let mut first_invalid = None;
        for i in 0..self.samples {
            let p: D::Point = sample(i).into();
            match D::to_unit(p, self.tolerance) {
                Some(st) => {
                    let ix = ((st.x * nx as f64) as usize).min(nx - 1);
                    let iy = ((st.y * ny as f64) as usize).min(ny - 1);
                    observed[iy * nx + ix] += 1;
                }
                None => {
                    invalid_samples += 1;
                    if first_invalid.is_none() {
                        first_invalid = Some((i, format!("{p:?}")));
                    }
                }
            }
        }

        // Expected counts.
        let ExpectedCounts {
            counts: expected,
            integral: pdf_integral,
            invalid_nodes: invalid_pdf_nodes,
            first_invalid: first_invalid_pdf,
        } = self.expected(pdf);

        // Pearson's statistic over the cells sorted by expected count, pooling small cells.
        let mut order: Vec<usize> = (0..nx * ny).collect();
        order.sort_by(|&a, &b| expected[a].total_cmp(&expected[b]));
        let mut statistic = 0.0;
        let mut contributions = 0usize;
        let mut pooled_cells = 0usize;
        let mut pooled_groups = 0usize;
        let mut samples_in_zero_cells = 0u64;
        let (mut pool_obs, mut pool_exp) = (0.0, 0.0);
        let term = |o: f64, e: f64| (o - e) * (o - e) / e;
        for &c in &order {
            let (o, e) = (observed[c] as f64, expected[c]);
            if e == 0.0 {
                samples_in_zero_cells += observed[c];
                continue;
            }
            if e < self.min_expected {
                pool_obs += o;
                pool_exp += e;
                pooled_cells += 1;
                if pool_exp > self.min_expected {
                    statistic += term(pool_obs, pool_exp);
                    contributions += 1;
                    pooled_groups += 1;
                    (pool_obs, pool_exp) = (0.0, 0.0);
                }
            } else if pool_exp > 0.0 {
                // The small cells left over join the first large one, rather than being dropped.
                statistic += term(o + pool_obs, e + pool_exp);
                contributions += 1;
                pooled_groups += 1;
                (pool_obs, pool_exp) = (0.0, 0.0);
            } else {
                statistic += term(o, e);
                contributions += 1;
            }
        }
        if pool_exp > 0.0 {
            statistic += term(pool_obs, pool_exp);
            contributions += 1;
            pooled_groups += 1;
        }
        let dof = contributions.saturating_sub(1);

        let mut result = ChiSquareResult {
            domain: D::NAME,
            res: self.res,
            ires: self.ires,
            samples: self.samples,
            statistic,
            dof,
            p_value: 0.0,
            invalid_samples,
            first_invalid,
            samples_in_zero_cells,
            invalid_pdf_nodes,
            first_invalid_pdf,
            pdf_integral,
            pooled_cells,
            pooled_groups,
            observed,
            expected,
        };
        if !result.has_defects() {
            result.p_value = chi2_sf(statistic, dof as f64);
        }
        result
    }
}

/// Expected counts from [`ChiSquare::expected`].
#[derive(Clone, Debug)]
pub struct ExpectedCounts {
    /// Expected count per cell, row-major (cell (ix, iy) at `iy * nx + ix`).
    pub counts: Vec<f64>,
    /// ∫ pdf over the domain by the same rule (independent of the sample count).
    pub integral: f64,
    /// Integration nodes where the pdf was NaN, infinite or negative; they contribute 0.
    pub invalid_nodes: usize,
    /// The first such node and value, formatted.
    pub first_invalid: Option<String>,
}

/// The outcome of [`ChiSquare::run`]. Its `Display` prints a one-line summary and any defects.
#[derive(Clone, Debug)]
pub struct ChiSquareResult {
    /// [`Domain::NAME`].
    pub domain: &'static str,
    /// Histogram resolution (nx, ny).
    pub res: (usize, usize),
    /// Integration nodes per cell side.
    pub ires: usize,
    /// Samples drawn.
    pub samples: usize,
    /// Pearson's χ² statistic after pooling.
    pub statistic: f64,
    /// Degrees of freedom: contributions to the statistic − 1.
    pub dof: usize,
    /// P(χ²_dof ≥ statistic); 0 when the result has defects (see [`ChiSquare::run`]).
    pub p_value: f64,
    /// Samples that were NaN, infinite or outside the domain (beyond the tolerance).
    pub invalid_samples: usize,
    /// Index and value (Debug) of the first invalid sample.
    pub first_invalid: Option<(usize, String)>,
    /// Samples in cells where the integrated pdf is exactly 0.
    pub samples_in_zero_cells: u64,
    /// Integration nodes where the pdf was NaN, infinite or negative.
    pub invalid_pdf_nodes: usize,
    /// The first such node and value, formatted.
    pub first_invalid_pdf: Option<String>,
    /// ∫ pdf over the domain by the same trapezoid rule (Σ expected / samples). Should be 1 up to
    /// quadrature error; a pdf that integrates to 1.05 fails the test itself at 10⁶ samples. It is
    /// a diagnostic: [`passes`](ChiSquareResult::passes) does not look at it.
    pub pdf_integral: f64,
    /// Cells that expected fewer than the pooling threshold.
    pub pooled_cells: usize,
    /// Contributions those cells were pooled into.
    pub pooled_groups: usize,
    /// Observed counts per cell, row-major (cell (ix, iy) at `iy * nx + ix`).
    pub observed: Vec<u64>,
    /// Expected counts per cell, same layout.
    pub expected: Vec<f64>,
}

impl ChiSquareResult {
    /// True when the result has a defect that fails the test regardless of the statistic.
    pub fn has_defects(&self) -> bool {
        self.invalid_samples > 0
            || self.samples_in_zero_cells > 0
            || self.invalid_pdf_nodes > 0
            || self.dof == 0
            || !self.statistic.is_finite()
    }

    /// Whether the test accepts the sampler at significance `threshold` (for example
    /// [`sidak_alpha`](super::sidak_alpha)`(0.01, k)`): no defects and p ≥ threshold.
    pub fn passes(&self, threshold: f64) -> bool {
        !self.has_defects() && self.p_value >= threshold
    }
}

impl fmt::Display for ChiSquareResult {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "chi-square on the {} ({}x{} cells, ires {}, {} samples): statistic {:.2}, dof {}, \
             p = {:.6e}; pdf integral {:.6}; {} small cells pooled into {} groups",
            self.domain,
            self.res.0,
            self.res.1,
            self.ires,
            self.samples,
            self.statistic,
            self.dof,
            self.p_value,
            self.pdf_integral,
            self.pooled_cells,
            self.pooled_groups,
        )?;
        if self.invalid_samples > 0 {
            write!(
                f,
                "; FAIL: {} samples NaN or outside the domain",
                self.invalid_samples
            )?;
            if let Some((i, p)) = &self.first_invalid {
                write!(f, " (first: sample {i} = {p})")?;
            }
        }
        if self.samples_in_zero_cells > 0 {
            write!(
                f,
                "; FAIL: {} samples in cells where the pdf integrates to 0",
                self.samples_in_zero_cells
            )?;
        }
        if self.invalid_pdf_nodes > 0 {
            write!(
                f,
                "; FAIL: pdf NaN, infinite or negative at {} nodes",
                self.invalid_pdf_nodes
            )?;
            if let Some(s) = &self.first_invalid_pdf {
                write!(f, " (first: {s})")?;
            }
        }
        if self.dof == 0 {
            write!(f, "; FAIL: fewer than two contributions after pooling")?;
        }
        if !self.statistic.is_finite() {
            write!(f, "; FAIL: statistic not finite")?;
        }
        Ok(())
    }
}
