//! Measures of point-set quality in the unit square: L2-star discrepancy, the elementary
//! interval ((0, m, 2)-net) property, and the RMSE convergence slope on the two test integrands
//! of REFERENCES §5. Allocation-free and usable without `std`.

use glam::Vec2;

/// The L2-star discrepancy T of a 2D point set, by Warnock's formula, in f64:
///
/// T² = 3⁻² − (2⁻¹/N)·Σᵢ (1 − xᵢ²)(1 − yᵢ²) + (1/N²)·ΣᵢΣⱼ (1 − max(xᵢ, xⱼ))(1 − max(yᵢ, yⱼ)).
///
/// T is the root mean square, over anchored boxes [0, a) × [0, b), of the difference between the
/// fraction of points in the box and its area. For N iid uniform points E\[T²\] = (2⁻² − 3⁻²)/N.
///
/// O(N²) time, O(1) space. Returns 0 for an empty set; a T² that rounding makes slightly
/// negative is clamped to 0 before the square root. Points are not checked to lie in [0, 1]².
pub fn l2_star_discrepancy(points: &[Vec2]) -> f64 {
    let n = points.len();
    if n == 0 {
        return 0.0;
    }
    let nf = n as f64;
    let mut single = 0.0;
    let mut pairs = 0.0;
    for (i, p) in points.iter().enumerate() {
        let (xi, yi) = (p.x as f64, p.y as f64);
        single += (1.0 - xi * xi) * (1.0 - yi * yi);
        // Diagonal term once, off-diagonal terms twice (the double sum is symmetric).
        pairs += (1.0 - xi) * (1.0 - yi);
        let mut off = 0.0;
        for q in points.iter().skip(i + 1) {
            let (xj, yj) = (q.x as f64, q.y as f64);
            off += (1.0 - xi.max(xj)) * (1.0 - yi.max(yj));
        }
        pairs += 2.0 * off;
    }
    let t2 = 1.0 / 9.0 - single / (2.0 * nf) + pairs / (nf * nf);
    libm::sqrt(t2.max(0.0))
}

/// The largest m that [`net_violation`] and [`is_elementary_net`] accept: 2¹² = 4096 points,
/// whose cells fit a 4096-bit bitset on the stack (512 bytes).
pub const MAX_NET_M: u32 = 12;

/// Why a point set is not a (0, m, 2)-net in base 2.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NetViolation {
    /// `m` exceeds [`MAX_NET_M`].
    MTooLarge,
    /// The set does not have 2^m points.
    WrongCount,
    /// Point `index` is NaN or outside [0, 1)².
    OutOfRange {
        /// The point's index.
        index: usize,
    },
    /// Point `index` falls in the elementary interval
    /// [cx/2^x_bits, (cx+1)/2^x_bits) × [cy/2^y_bits, (cy+1)/2^y_bits), which already holds an
    /// earlier point (x_bits + y_bits = m).
    Collision {
        /// log₂ of the number of columns.
        x_bits: u32,
        /// log₂ of the number of rows.
        y_bits: u32,
        /// The column.
        cx: u32,
        /// The row.
        cy: u32,
        /// The index of the second point found in the interval.
        index: usize,
    },
}

/// The first violation of the elementary-interval property, or `None` if `points` is a
/// (0, m, 2)-net in base 2: N = 2^m points, and for every split x_bits + y_bits = m, every
/// interval of 2^x_bits × 2^y_bits (volume 2⁻ᵐ) holds exactly one point.
///
/// Works for m ≤ [`MAX_NET_M`] = 12, without allocating: per split, a 4096-bit bitset on the stack
/// marks occupied cells; with 2^m points in 2^m cells, no collision means exactly one per cell.
/// Cells are found exactly: ⌊x·2^a⌋ of an f32 in [0, 1) is computed in f64 without rounding.
/// Splits are checked with x_bits = 0, 1, …, m, points in order.
pub fn net_violation(points: &[Vec2], m: u32) -> Option<NetViolation> {
    if m > MAX_NET_M {
        return Some(NetViolation::MTooLarge);
    }
    if points.len() != 1usize << m {
        return Some(NetViolation::WrongCount);
    }
    let in_unit = |v: f32| (0.0..1.0).contains(&v);
    if let Some(index) = points.iter().position(|p| !(in_unit(p.x) && in_unit(p.y))) {
        return Some(NetViolation::OutOfRange { index });
    }
    for x_bits in 0..=m {
        let y_bits = m - x_bits;
        let mut seen = [0u64; 1 << (MAX_NET_M - 6)];
        for (index, p) in points.iter().enumerate() {
            let cx = (p.x as f64 * (1u64 << x_bits) as f64) as u32;
            let cy = (p.y as f64 * (1u64 << y_bits) as f64) as u32;
            let cell = ((cx << y_bits) | cy) as usize;
            let (word, bit) = (cell >> 6, 1u64 << (cell & 63));
            // cell < 2^MAX_NET_M (checked above), so the word exists.
            let Some(seen) = seen.get_mut(word) else {
                return Some(NetViolation::OutOfRange { index });
            };
            if *seen & bit != 0 {
                return Some(NetViolation::Collision {
                    x_bits,
                    y_bits,
                    cx,
                    cy,
                    index,
                });
            }
            *seen |= bit;
        }
    }
    None
}

/// True if `points` is a (0, m, 2)-net in base 2: see [`net_violation`], which also says why not.
/// False when m > [`MAX_NET_M`].
pub fn is_elementary_net(points: &[Vec2], m: u32) -> bool {
    net_violation(points, m).is_none()
}

/// e^{−x²−y²}: the smooth test integrand of REFERENCES §5, whose integral over the unit square is
/// [`GAUSSIAN_INTEGRAL`].
pub fn gaussian(p: Vec2) -> f64 {
    let (x, y) = (p.x as f64, p.y as f64);
    libm::exp(-x * x - y * y)
}

/// ∫∫ e^{−x²−y²} over [0, 1]² = (√π/2 · erf 1)².
pub const GAUSSIAN_INTEGRAL: f64 = 0.557_746_285_351_034;

/// 1[x² + y² < 2/π]: the discontinuous test integrand of REFERENCES §5, a quarter disk whose
/// area is [`DISK_INTEGRAL`].
pub fn disk_indicator(p: Vec2) -> f64 {
    let (x, y) = (p.x as f64, p.y as f64);
    if x * x + y * y < core::f64::consts::FRAC_2_PI {
        1.0
    } else {
        0.0
    }
}

/// ∫∫ 1[x² + y² < 2/π] over [0, 1]² = ½.
pub const DISK_INTEGRAL: f64 = 0.5;

/// The RMSE over seeds 0..`seeds` of the N-point estimate of ∫ f against `exact`, where
/// `points(i, n, seed)` is point i of the family's set of size n: one point of the curve whose
/// slope [`rmse_slope`] fits. Allocation-free; the cost is seeds · N evaluations.
pub fn rmse(
    points: impl Fn(u32, u32, u32) -> Vec2,
    f: impl Fn(Vec2) -> f64,
    exact: f64,
    n: u32,
    seeds: u32,
) -> f64 {
    let mut mse = 0.0;
    for seed in 0..seeds {
        let mut sum = 0.0;
        for i in 0..n {
            sum += f(points(i, n, seed));
        }
        let error = sum / n as f64 - exact;
        mse += error * error;
    }
    libm::sqrt(mse / seeds as f64)
}

/// The convergence rate of a 2D point-set family on an integrand: the least-squares slope of
/// log RMSE against log N, for N = 2ᵏ with k in `log2_n`.
///
/// `points(i, n, seed)` is point i of the family's set of size n for `seed` (the set is indices
/// 0..n); the RMSE at each N is over seeds 0..`seeds` of the N-point estimate of ∫ f against
/// `exact`. Plain Monte Carlo gives −0.5; REFERENCES §5 lists the rates of the others.
/// Allocation-free; the cost is seeds · Σ N evaluations. Returns NaN for fewer than two sizes.
pub fn rmse_slope(
    points: impl Fn(u32, u32, u32) -> Vec2,
    f: impl Fn(Vec2) -> f64,
    exact: f64,
    log2_n: core::ops::RangeInclusive<u32>,
    seeds: u32,
) -> f64 {
    // Running sums for the regression of y = ln RMSE on x = ln N.
    let (mut m, mut sx, mut sy, mut sxx, mut sxy) = (0.0, 0.0, 0.0, 0.0, 0.0);
    for k in log2_n {
        let n = 1u32 << k;
        let e = rmse(&points, &f, exact, n, seeds);
        let (x, y) = (libm::log(n as f64), libm::log(e));
        m += 1.0;
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    if m < 2.0 {
        return f64::NAN;
    }
    (m * sxy - sx * sy) / (m * sxx - sx * sx)
}
