//! Uniform sampling of the solid angle of a rectangle (Ureña, Fajardo, King 2013), with an exact
//! area fallback where spherical sampling is not worth it.
//!
//! The rectangle is `corner + s·ex + t·ey`, s, t ∈ [0, 1], relative to the shading point, with
//! `ex` ⟂ `ey`; a parallelogram whose edges are further than 2e-6 from orthogonal (as the cosine
//! between them) is sampled by area, exactly. The algorithm works in the rectangle's frame: x̂
//! along ex, ŷ along ey, the plane at distance d from the shading point, the rectangle
//! [x0, x1] × [y0, y1] in it, and (0, 0) the foot of the perpendicular from the shading point.
//!
//! Every quantity of the map is a solid angle measured from where it is small, the frame and
//! the far edges are formed with f64 products where f32 would cancel, and the set-up first
//! scales the geometry by an exact power of two, so that the f32 map's direction error against
//! its f64 instance stays at most 5.7e-7 from 2π down to 1e-9 sr. The derivation is in
//! `docs/polygons.md` ("The rectangle without cancellation").

use core::marker::PhantomData;

use crate::lane::{Lane, Mask, V2, V3};
use crate::math::Math;
use crate::point::{Point2, Point3, by_halves, halved, split_fields};
use crate::warp::common::clamp_u;
use crate::warp::polygon::{cross_wide, dot_wide, plane_dot};
use crate::warp::polygon::{parallelogram_area_pdf, pow2_scale};

/// Below this solid angle (sr) the rectangle is sampled by area.
///
/// The map's f32 direction error against its f64 instance is at most 5.7e-7 from 2π down to 1e-9
/// sr, measured on 2.4e5 random rectangles of every kind (anywhere above the horizon, far and
/// small, grazing, straddling the foot of the perpendicular, larger than their distance, nearly
/// edge-on; `tests/all/warp/rectangle_accuracy.rs`, 80 u each), and at most 2.8e-7 on the report's stability
/// rows (a facing square and a tilted 2:1 rectangle from 1e-9 to 6.3 sr). So, as for the
/// triangle, the threshold is set
/// by the f32 direction grid, not by the algorithm: below 1e-6 sr (0.06° across) a unit f32 vector
/// resolves only 1e-4 of the light, and area sampling there is exact and cheaper, its pdf uniform
/// in solid angle to about the light's angular size (1e-3).
pub const SPHERICAL_RECTANGLE_MIN_SR: f32 = 1.0e-6;
/// Above this solid angle (sr) the rectangle would be sampled by area too: 2π, which no
/// rectangle reaches. The map keeps its accuracy (3.5e-7 measured in [6, 2π), for rectangles up
/// to 1e5 times larger than their distance), and area sampling of such a light, near and huge,
/// has a pdf that varies by orders of magnitude across it.
pub const SPHERICAL_RECTANGLE_MAX_SR: f32 = core::f32::consts::TAU;
/// The largest ratio of a rectangle's size (|ex| + |ey|) to its plane's distance from the
/// shading point that the rectangle's f32 set-up and inverse reach. The slab solid angles
/// multiply powers of the distance that leave f32's range beyond it: measured, the inverse gave
/// NaN for none of 2000 random samples at 2⁴⁰ and a third of them at 2⁴², but at a corner of a
/// light of 3.7 sr already at 1.7e9; and at 5e11 (with an aspect ratio of 3e11) the set-up
/// called a light degenerate from one corner and not from another (all found by the `spherical`
/// fuzz target). Beyond this limit, 1e7, the inverse of a spherically sampled rectangle is NaN,
/// and sampling may find the light degenerate (pdf 0).
pub const SPHERICAL_RECTANGLE_INVERSE_REACH: f32 = 1.0e7;

/// How far outside the rectangle, as the sine of the angle to an edge's plane, a direction still
/// counts as inside, in units of ε·(1 + R/r) (ε = 2⁻²³, R = |corner| + |ex| + |ey|, r a lower
/// bound on the distance to the rectangle: the larger of the plane's distance and the centre's
/// distance less half the diagonal). A sample is an f32 sum, off the exact rectangle by up to a
/// few ε·R, a few ε·R/r of angle from the shading point; the edge planes are formed in f64. For
/// a rectangle not much larger than its distance that is a few ulp of angle, at grazing angles
/// too. With 2, none of 2.4e6 samples of random rectangles of every kind (u on the square's
/// corners and edges included) falls outside, and a 1e-3-wide light's ∫pdf grows by 2e-3 at
/// most (with 8, by 8e-3).
const INSIDE_SLACK: f64 = 2.0 * f32::EPSILON as f64;

/// Everything the sampler, pdf and inverse need, computed once per rectangle.
#[derive(Clone, Copy)]
struct Setup<L: Math> {
    /// The corner as given, returned for a dropped sample.
    given_corner: V3<L>,
    /// The power of two the geometry is scaled by (see `pow2_scale`), and its inverse.
    scale: L,
    unscale: L,
    /// The scaled geometry, which everything below describes.
    corner: V3<L>,
    ex: V3<L>,
    ey: V3<L>,
    /// Unit axes of the rectangle's frame, and the cosine between them (0 but for rounding).
    xh: V3<L>,
    yh: V3<L>,
    cos_xy: L,
    /// The foot of the perpendicular from the shading point to the plane: the frame's origin.
    foot: V3<L>,
    x0: L,
    x1: L,
    /// y0, y1, |ey| and the distance d from the shading point to the plane (> 0 where valid).
    strip: Strip<L>,
    /// The lune's parts beyond the rectangle: L(x0) towards −x and R(x1) towards +x; and the
    /// column at x0.
    l0: L,
    r1: L,
    col0: Column<L>,
    /// Ψ = ψ₀ + ψ₁ = π − β, the angle the lune leaves out of a hemisphere.
    psi: L,
    /// sin and cos of ψ₀ = π/2 + β₀ and ψ₁ = π/2 − β₁, the angles of the edges y = y0 and
    /// y = y1 from the horizon beyond them: d/r and ∓y/r.
    sin_psi0: L,
    cos_psi0: L,
    sin_psi1: L,
    cos_psi1: L,
    /// The solid angle by Van Oosterom–Strackee.
    omega: L,
    /// Unit normals of the planes through the shading point and each edge, pointing inwards.
    planes: [V3<L>; 4],
    /// −INSIDE_SLACK·(1 + R/r): see [`INSIDE_SLACK`].
    slack: L,
    valid: L::Mask,
    by_area: L::Mask,
    /// True where the spherical inverse is out of f32's range: see
    /// [`SPHERICAL_RECTANGLE_INVERSE_REACH`].
    beyond_reach: L::Mask,
}

split_fields!(Setup<L: Math> by L {
    given_corner, scale, unscale, corner, ex, ey, xh, yh, cos_xy, foot, x0, x1, strip, l0, r1,
    col0, psi, sin_psi0, cos_psi0, sin_psi1, cos_psi1, omega, planes, slack, valid: mask,
    by_area: mask, beyond_reach: mask,
});

/// The strip y0 ≤ y ≤ y1 of the plane at distance d, in the rectangle's frame, and its lune:
/// what the solid angles below share. dy = y1 − y0 is the edge's length, not recomputed (which
/// would cancel for a far rectangle).
#[derive(Clone, Copy)]
struct Strip<L> {
    y0: L,
    y1: L,
    dy: L,
    d: L,
    /// 1/(r0·r1), r0 = √(d² + y0²) and r1 = √(d² + y1²) the distances to the lines of the
    /// edges y = y0, y = y1.
    inv_rr: L,
    /// β, the dihedral angle between the planes of those edges: the lune has area 2β, β on
    /// either side of the foot.
    beta: L,
    /// d²(d² + y0² + y1²)/((r0·r1 − y0·y1)·r0·r1): the factor of x² in the denominator of
    /// tan(g/2) where y0·y1 < 0 (see [`column`]), the same for every column.
    opposite: L,
}

split_fields!(Strip<L: Math> by L { y0, y1, dy, d, inv_rr, beta, opposite });

/// The column of the strip at x (see [`column`]).
#[derive(Clone, Copy)]
struct Column<L> {
    x: L,
    /// |G(x)|, the lune's part between the foot and x, and t = β − g, the part beyond.
    g: L,
    t: L,
    /// The distances to (x, y0), (x, y1) and (x, 0) in the plane.
    ra: L,
    rb: L,
    rho: L,
}

split_fields!(Column<L: Math> by L { x, g, t, ra, rb, rho });

/// (ra·rb + ya·yb, ra·rb − ya·yb) for ra = √(ρ² + ya²), rb = √(ρ² + yb²), without
/// cancellation: the sum where ya·yb ≥ 0 and the difference where ya·yb ≤ 0 directly, the other
/// as ρ²(ρ² + ya² + yb²) over the direct one (their product is ρ²(ρ² + ya² + yb²)). At most one
/// of the two needs that quotient, so one division serves both.
#[inline(always)]
fn rr_plus_minus_yy<L: Math>(ra: L, rb: L, ya: L, yb: L, rho2: L) -> (L, L) {
    let yy = ya * yb;
    let plus = ra.mul_add(rb, yy);
    let minus = ra.mul_add(rb, -yy);
    let neg = yy.lt(L::ZERO);
    let ratio = (rho2 / L::select(neg, minus, plus)) * ya.mul_add(ya, yb.mul_add(yb, rho2));
    (
        L::select(neg, ratio, plus),
        L::select(yy.gt(L::ZERO), ratio, minus),
    )
}

/// The column at x: its corners' distances, and the two parts into which the plane at x cuts half
/// the lune, g = |G(x)| the solid angle of [0, x] × [y0, y1] (between the foot and x) and t that of
/// the part beyond, g + t = β. Each is the spherical triangle's solid angle in half-angle form,
///
/// - tan(t/2) = d·dy / (ra·rb + y0·y1 + ρ² + |x|(ra + rb)) (Van Oosterom–Strackee on the
///   triangle with a vertex at ±x̂),
/// - tan(g/2) = |x|·d·K / (ρ²·r0·r1 + d²·ra·rb + x²·y0·y1), K = y1·ra − y0·rb (the difference
///   of the two corner triangles' angles atan(x·y/(d·r))),
///
/// with ρ² = x² + d², ra, rb the distances to the corners (x, y0), (x, y1), and every sum
/// rewritten so that its terms have one sign. The smaller of g and t comes from its own
/// arctangent, the larger as β less it, so both keep their relative precision.
#[inline(always)]
fn column<L: Math>(x: L, s: &Strip<L>) -> Column<L> {
    let (y0, y1, d) = (s.y0, s.y1, s.d);
    let ax = x.abs();
    let d2 = d * d;
    let rho2 = ax.mul_add(ax, d2);
    let ra = y0.mul_add(y0, rho2).sqrt();
    let rb = y1.mul_add(y1, rho2).sqrt();
    let num_t = d * s.dy;
    let (rr_plus, rr_minus) = rr_plus_minus_yy(ra, rb, y0, y1, rho2);
    let den_t = ax.mul_add(ra + rb, rr_plus + rho2);
    // K = dy·(ρ² + ra·rb − y0·y1)/(ra + rb); numerator and denominator of tan(g/2) divided by
    // r0·r1. Where y0·y1 < 0, ρ²·r0·r1 + x²·y0·y1 is rewritten as
    // d²·r0·r1 + x²·d²(d² + y0² + y1²)/(r0·r1 − y0·y1).
    let k = s.dy * ((rho2 + rr_minus) / (ra + rb));
    let yy = y0 * y1;
    let num_g = ax * d * (k * s.inv_rr);
    let x2 = ax * ax;
    let same = x2.mul_add(yy * s.inv_rr, rho2);
    let opposite = x2.mul_add(s.opposite, d2);
    let den_g = d2.mul_add(
        (ra * rb) * s.inv_rr,
        L::select(yy.ge(L::ZERO), same, opposite),
    );
    // tan(g/2) ≤ tan(t/2), cross-multiplied (the scaled geometry keeps the products in range).
    let g_smaller = (num_g * den_t).le(num_t * den_g);
    let v = L::TWO * L::select(g_smaller, num_g, num_t).atan2(L::select(g_smaller, den_g, den_t));
    let rest = s.beta - v;
    Column {
        x,
        g: L::select(g_smaller, v, rest),
        t: L::select(g_smaller, rest, v),
        ra,
        rb,
        rho: rho2.sqrt(),
    }
}

/// Van Oosterom–Strackee's terms for the triangle (a, b, c) with lengths la, lb, lc, scaled by
/// 1/(la·lb·lc): (D, T) with tan(Ω/2) = T/D, so that Ω/2 is the argument of D + iT.
#[inline(always)]
fn vos_terms<L: Math>(triple: L, a: V3<L>, b: V3<L>, c: V3<L>, la: L, lb: L, lc: L) -> (L, L) {
    let den = (la * lb).mul_add(
        lc,
        a.dot(b).mul_add(lc, a.dot(c).mul_add(lb, b.dot(c) * la)),
    );
    let k = L::ONE / (la * lb * lc);
    (den * k, triple.abs() * k)
}

/// (a + ib)(c + id): half solid angles add as the arguments of their terms multiply.
#[inline(always)]
fn cmul<L: Math>((a, b): (L, L), (c, d): (L, L)) -> (L, L) {
    (a.mul_add(c, -(b * d)), a.mul_add(d, b * c))
}

/// The terms (as [`vos_terms`]) of the rectangle [xa, xb] × [ya, yb] (width w, height h) at
/// distance d, given the distances to its corners: the product of its two triangles', whose
/// triple products are exactly d·w·h.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
fn rect_terms<L: Math>(
    (xa, xb, w): (L, L, L),
    (ya, yb, h): (L, L, L),
    d: L,
    [l00, l10, l11, l01]: [L; 4],
) -> (L, L) {
    let z = -d;
    let v00 = V3::new(xa, ya, z);
    let v10 = V3::new(xb, ya, z);
    let v11 = V3::new(xb, yb, z);
    let v01 = V3::new(xa, yb, z);
    let triple = d * w * h;
    cmul(
        vos_terms(triple, v00, v10, v11, l00, l10, l11),
        vos_terms(triple, v00, v11, v01, l00, l11, l01),
    )
}

/// Solid angle of the slab between columns a and b (a.x ≤ b.x, width w) over [y0, y1].
///
/// Across the foot (a.x ≤ 0 ≤ b.x) it is a.g + b.g. On one side of it, VOS, split at y = 0 where
/// the strip straddles the foot: then every pair of corners of a piece lies in one quadrant,
/// their dot products are positive, and VOS's denominator is at least the product of the
/// lengths, so it cannot cancel. Unsplit, VOS fails for a near, wide slab, whose corners
/// (x, y0) and (x, y1) are nearly opposite seen from the shading point: its triangles' triple
/// products and denominators both nearly vanish (3e-5 of Ω in f32 for a strip 0.02 from the
/// shading point). The four triangles' half-angles (each piece under π/4, the slab under π/2)
/// are summed as the argument of the product of their terms: one arctangent.
#[inline(always)]
fn slab<L: Math>(a: &Column<L>, b: &Column<L>, w: L, s: &Strip<L>) -> L {
    let across = a.x.le(L::ZERO) & b.x.ge(L::ZERO);
    let split = s.y0.lt(L::ZERO) & s.y1.gt(L::ZERO);
    // The pieces [y0, ys] and [ys, y1], the first empty where the strip does not straddle.
    let ys = L::select(split, L::ZERO, s.y0);
    let (h0, h1) = (
        L::select(split, -s.y0, L::ZERO),
        L::select(split, s.y1, s.dy),
    );
    let (a_s, b_s) = (L::select(split, a.rho, a.ra), L::select(split, b.rho, b.ra));
    let x = (a.x, b.x, w);
    let (re, im) = cmul(
        rect_terms(x, (s.y0, ys, h0), s.d, [a.ra, b.ra, b_s, a_s]),
        rect_terms(x, (ys, s.y1, h1), s.d, [a_s, b_s, b.rb, a.rb]),
    );
    L::select(across, a.g + b.g, L::TWO * im.atan2(re))
}

/// h(yb) − h(ya) for h(y) = y/r(y), r(y) = √(ρ² + y²) (the elevation sine), given ra = r(ya),
/// rb = r(yb), ρ and dy = yb − ya: where ya and yb have the same sign, as
/// (ρ/ra)(ρ/rb)·dy·(ya + yb)/(ya·rb + yb·ra), which does not cancel.
#[inline(always)]
fn h_diff<L: Math>(ya: L, yb: L, dy: L, ra: L, rb: L, rho: L) -> L {
    let direct = yb / rb - ya / ra;
    let ratio = ((rho / ra) * (rho / rb)) * (dy / ya.mul_add(rb, yb * ra)) * (ya + yb);
    L::select((ya * yb).gt(L::ZERO), ratio, direct)
}

/// a + b as an unevaluated sum hi + lo, exactly (Knuth's TwoSum; + and − only, so it is exact
/// in every lane whatever the build's FMA).
#[inline(always)]
fn two_sum<L: Math>(a: L, b: L) -> (L, L) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// (p + e)·e, accurately: p + e split exactly into hi + lo by components, then hi·e in f64,
/// rounded once (within an ulp of the result), plus lo·e, rounding-sized, in the lane.
#[inline(always)]
fn shifted_dot<L: Math>(p: V3<L>, e: V3<L>) -> L {
    let (x, xl) = two_sum(p.x, e.x);
    let (y, yl) = two_sum(p.y, e.y);
    let (z, zl) = two_sum(p.z, e.z);
    dot_wide([x, y, z], [e.x, e.y, e.z]) + V3::new(xl, yl, zl).dot(e)
}

#[inline(always)]
fn setup<L: Math>(corner: V3<L>, ex: V3<L>, ey: V3<L>) -> Setup<L> {
    // The geometry at a scale where its squares and cubes cannot overflow or underflow (the
    // samples are scaled back; directions, Ω and pdfs do not depend on the scale).
    let given_corner = corner;
    let amax = |v: V3<L>| v.x.abs().max(v.y.abs()).max(v.z.abs());
    let scale = pow2_scale(amax(corner).max(amax(ex)).max(amax(ey)));
    let (corner, ex, ey) = (corner.scale(scale), ex.scale(scale), ey.scale(scale));
    let exl = ex.length();
    let eyl = ey.length();
    let xh = ex.scale(L::ONE / exl);
    let yh = ey.scale(L::ONE / eyl);
    // The plane's normal and offset in f64 (products of f32 are exact there): in f32 the
    // offset h = v·(ex × ey) carries ε|v||ex||ey|, which for a rectangle seen at a grazing
    // angle is a large part of the distance d = |h|/|ex × ey| that shapes the map. In f64 it
    // carries about ε₆₄·|corner| of d: see `valid` below. (Not from the nearest corner: the other
    // corners are f32 sums, rounded by ε₃₂ of themselves, which is far worse for a light nearly
    // filling the hemisphere.)
    let c1 = corner + ex;
    let c2 = c1 + ey;
    let c3 = corner + ey;
    let nearest2 = [c1, c2, c3]
        .into_iter()
        .fold(corner.dot(corner), |m, c| c.dot(c).min(m));
    let a = |v: V3<L>| [v.x, v.y, v.z];
    let [nx, ny, nz] = cross_wide(a(ex), a(ey));
    let n = V3::new(nx, ny, nz);
    let h = plane_dot(a(corner), [L::ZERO; 3], a(ex), a(ey));
    let nn = n.dot(n);
    let d = h.abs() / nn.sqrt();
    // The foot of the perpendicular, the frame's origin: samples are formed from it, as
    // foot + x·x̂ + y·ŷ, which keeps their direction to a few ulp. corner + s·ex + t·ey would
    // carry the rounding of the corner's coordinates, ε|corner|, into a sample perhaps far
    // closer to the shading point than the corner (60ε of direction for a rectangle 30 times
    // larger than its distance).
    let foot = n.scale(h / nn);
    // The corner's coordinates: corner − foot = x0·x̂ + y0·ŷ, in the oblique frame should ex
    // and ey not be quite orthogonal (as f32 edges rarely are, to 1e-8), so that every sample
    // lies on the parallelogram given. Dot products in f64: they cancel for a far corner.
    let xc = dot_wide(a(corner), a(ex)) / exl;
    let yc = dot_wide(a(corner), a(ey)) / eyl;
    let cos_xy = dot_wide(a(ex), a(ey)) / (exl * eyl);
    let k = L::ONE / cos_xy.mul_add(-cos_xy, L::ONE);
    let x0 = cos_xy.mul_add(-yc, xc) * k;
    let y0 = cos_xy.mul_add(-xc, yc) * k;
    // The far edges from their own corners, not as x0 + |ex|: that would carry ε|x0|, which
    // for a far corner and a near edge is a large angle seen from the shading point.
    let xc1 = shifted_dot(corner, ex) / exl;
    let yc1 = shifted_dot(corner, ey) / eyl;
    let x1 = cos_xy.mul_add(-cos_xy.mul_add(exl, yc), xc1) * k;
    let y1 = cos_xy.mul_add(-cos_xy.mul_add(eyl, xc), yc1) * k;
    // β and Ψ = π − β from one arctangent: tan(β/2) = d·dy / (r0·r1 + y0·y1 + d²) and
    // tan(Ψ/2) is its reciprocal; the smaller angle is computed, the other is π less it.
    let d2 = d * d;
    let dist0 = y0.mul_add(y0, d2).sqrt();
    let dist1 = y1.mul_add(y1, d2).sqrt();
    let num = d * eyl;
    let den = rr_plus_minus_yy(dist0, dist1, y0, y1, d2).0 + d2;
    let beta_smaller = num.le(den);
    let v = L::TWO * L::select(beta_smaller, num, den).atan2(L::select(beta_smaller, den, num));
    let pi = L::c(core::f64::consts::PI);
    let (beta, psi) = (
        L::select(beta_smaller, v, pi - v),
        L::select(beta_smaller, pi - v, v),
    );
    let rr = dist0 * dist1;
    let inv_rr = L::ONE / rr;
    let strip = Strip {
        y0,
        y1,
        dy: eyl,
        d,
        inv_rr,
        beta,
        opposite: d2 * (y0.mul_add(y0, y1.mul_add(y1, d2)) / (rr - y0 * y1) * inv_rr),
    };
    // The lune's parts beyond the rectangle, L(x0) towards −x and R(x1) towards +x: the tail
    // beyond an edge on the side away from the foot, β plus the part from the foot otherwise.
    let col0 = column(x0, &strip);
    let col1 = column(x1, &strip);
    let l0 = L::select(x0.le(L::ZERO), col0.t, beta + col0.g);
    let r1 = L::select(x1.ge(L::ZERO), col1.t, beta + col1.g);
    let omega = slab(&col0, &col1, exl, &strip);

    let sign = L::ONE.copysign(h);
    // Each edge's plane, its normal p × e in f64: an f32 cross product would turn it by up to
    // ε·|p|/d (the edge is nearly radial when the light is seen at a grazing angle), and the
    // slack would have to grow with it.
    let plane = |p: V3<L>, e: V3<L>| {
        let [x, y, z] = cross_wide([p.x, p.y, p.z], [e.x, e.y, e.z]);
        let m = V3::new(x, y, z);
        m.scale(sign / m.length())
    };
    let planes = [
        plane(corner, ex),
        plane(c1, ey),
        plane(c2, -ex),
        plane(c3, -ey),
    ];
    // The samples are f32 sums corner + s·ex + t·ey, off the exact rectangle by a few ε·R,
    // which turns them by ε·R over their distance, at least the larger of d and the centre's
    // distance less half the diagonal.
    let reach = corner.length() + exl + eyl;
    let half = L::HALF * (exl + eyl);
    let near = d.max((corner + (ex + ey).scale(L::HALF)).length() - half);
    let slack = -(L::c(INSIDE_SLACK) * (L::ONE + reach / near));

    // d ≈ 0: the shading point lies in the rectangle's plane (to within rounding), where VOS may
    // still report up to 4π: d must exceed 1e-6 of the distance to the nearest corner, the
    // same whichever corner describes the rectangle, and 1e-14 of the corner's distance, well
    // above the f64 rounding of h (from a far corner, a shading point on the light's own corner
    // got d = 1e-15·|corner| and a solid angle of π; found by the `spherical` fuzz target).
    let valid = d.gt(L::c(1e-6) * nearest2.sqrt())
        & d.gt(L::c(1e-14) * corner.length())
        & omega.gt(L::ZERO)
        & omega.is_finite()
        & exl.gt(L::ZERO)
        & eyl.gt(L::ZERO)
        & (x0 + x1 + y0 + y1 + d).is_finite()
        & n.dot(n).is_finite();
    let map_ok = (l0 + r1 + dist0 + dist1 + psi).is_finite() & l0.ge(L::ZERO) & r1.ge(L::ZERO);
    // Ureña's map needs a rectangle: where the edges are not orthogonal, Ω (and with it the pdf)
    // is off by about 1.5·|cos| (measured against the parallelogram's exact Ω: 1.5e-4 at 1e-4,
    // 2e-6 at 1e-6). Edges further than 2e-6 from orthogonal are sampled by area, whose pdf and
    // inside test hold for any parallelogram; f32 rounding leaves orthogonal edges about 1e-7
    // off, well inside, while a threshold of 1e-4 would let through strips whose Ω from one
    // corner is 7.5e-5 off.
    let skewed = cos_xy.abs().gt(L::c(2e-6));
    let by_area = omega.lt(L::c(SPHERICAL_RECTANGLE_MIN_SR as f64))
        | omega.gt(L::c(SPHERICAL_RECTANGLE_MAX_SR as f64))
        | !map_ok
        | skewed;
    let beyond_reach =
        !by_area & (exl + eyl).gt(L::c(SPHERICAL_RECTANGLE_INVERSE_REACH as f64) * d);
    Setup {
        given_corner,
        scale,
        unscale: L::ONE / scale,
        corner,
        ex,
        ey,
        xh,
        yh,
        cos_xy,
        foot,
        x0,
        x1,
        strip,
        l0,
        r1,
        col0,
        psi,
        sin_psi0: d / dist0,
        cos_psi0: -y0 / dist0,
        sin_psi1: d / dist1,
        cos_psi1: y1 / dist1,
        omega,
        planes,
        slack,
        valid,
        by_area,
        beyond_reach,
    }
}

/// The map: u₀ picks x where the slab [x0, x] has solid angle u₀Ω, u₁ the height y uniformly in
/// the elevation sine within the column at x (see the module's documentation). Returns local
/// (x, y), clamped to the rectangle.
#[inline(always)]
fn urena<L: Math>(s: &Setup<L>, u: V2<L>) -> (L, L) {
    // x: the lune's parts on either side, and the tangent form.
    let hl = u.x.mul_add(s.omega, s.l0) * L::HALF;
    let hr = (L::ONE - u.x).mul_add(s.omega, s.r1) * L::HALF;
    // L/2 + R/2 = β = π − Ψ: where the lune is nearly a hemisphere (both edges near the
    // horizon), L/2 or R/2 comes close to π, and its sine, small there, would keep only the
    // absolute precision of the angle. Take the sine and cosine of π − L/2 = Ψ + R/2 instead
    // (and likewise for R), whichever of the two is the smaller angle.
    let hl_c = s.psi + hr;
    let hr_c = s.psi + hl;
    let flip_l = hl_c.lt(hl);
    let flip_r = hr_c.lt(hr);
    let (sl, cl) = L::select(flip_l, hl_c, hl).sin_cos();
    let (sr, cr) = L::select(flip_r, hr_c, hr).sin_cos();
    let (cl, cr) = (L::select(flip_l, -cl, cl), L::select(flip_r, -cr, cr));
    let sin_t = sl.mul_add(cr, -(cl * sr));
    // sin(ψ₁ + R/2) = sin(ψ₀ + L/2) and sin(ψ₁ + L/2) = sin(ψ₀ + R/2) (the arguments of each
    // pair sum to π), each from the pair's argument that is at most π/2 (its cosine, which may
    // cancel, only decides which): a sum of two non-negative products of sines and cosines of
    // angles in [0, π/2]. The other argument would be near π where the sine is small, and
    // sin(a + b) there would lose its relative precision to cos a and cos b near 0.
    let (sp0, cp0, sp1, cp1) = (s.sin_psi0, s.cos_psi0, s.sin_psi1, s.cos_psi1);
    let sa = L::select(
        cp1.mul_add(cr, -(sp1 * sr)).ge(L::ZERO),
        sp1.mul_add(cr, cp1 * sr),
        sp0.mul_add(cl, cp0 * sl),
    );
    let sb = L::select(
        cp1.mul_add(cl, -(sp1 * sl)).ge(L::ZERO),
        sp1.mul_add(cl, cp1 * sl),
        sp0.mul_add(cr, cp0 * sr),
    );
    let den = L::TWO * ((sl * sr) * (sa * sb)).max(L::ZERO).sqrt();
    let x = (s.strip.d * sin_t / den).clamp(s.x0, s.x1);

    // y: the elevation sine h interpolated between the edges, 1 − h² from whichever of 1 ∓ h is
    // known without cancellation.
    let rho2 = x.mul_add(x, s.strip.d * s.strip.d);
    let rho = rho2.sqrt();
    let ra = s.strip.y0.mul_add(s.strip.y0, rho2).sqrt();
    let rb = s.strip.y1.mul_add(s.strip.y1, rho2).sqrt();
    let h0 = s.strip.y0 / ra;
    let dh = h_diff(s.strip.y0, s.strip.y1, s.strip.dy, ra, rb, rho);
    // 1 − h1 and 1 + h0, as ρ²/(r(r ± y)) on the side where 1 ∓ h would cancel.
    let g1 = L::select(
        s.strip.y1.gt(L::ZERO),
        (rho / rb) * (rho / (rb + s.strip.y1)),
        L::ONE - s.strip.y1 / rb,
    );
    let g0 = L::select(
        s.strip.y0.lt(L::ZERO),
        (rho / ra) * (rho / (ra - s.strip.y0)),
        L::ONE + h0,
    );
    let hv = u.y.mul_add(dh, h0);
    let g = L::select(
        hv.gt(L::ZERO),
        (L::ONE - u.y).mul_add(dh, g1),
        u.y.mul_add(dh, g0),
    );
    let y = (hv * rho / (g * (L::TWO - g)).max(L::ZERO).sqrt()).clamp(s.strip.y0, s.strip.y1);
    (x, y)
}

/// The point of the map at u, as corner + s·ex + t·ey where the corner is not much farther
/// than the point (as usual), so that u on the square's corners gives the rectangle's corners
/// exactly; otherwise as foot + x·x̂ + y·ŷ, whose rounding stays a few ulp of the point's own
/// length wherever it is (see `setup`).
#[inline(always)]
fn map_point<L: Math>(s: &Setup<L>, u: V2<L>) -> V3<L> {
    let (x, y) = urena(s, u);
    let from_foot = s.foot + s.xh.scale(x) + s.yh.scale(y);
    let fx = (x - s.x0) / (s.x1 - s.x0);
    let fy = (y - s.strip.y0) / (s.strip.y1 - s.strip.y0);
    let from_corner = s.corner + s.ex.scale(fx) + s.ey.scale(fy);
    let near = s
        .corner
        .length_squared()
        .le(L::c(4.0) * from_foot.length_squared());
    V3::select(near, from_corner, from_foot)
}

/// A rectangle set up for sampling at one shading point: [`spherical_rectangle`],
/// [`spherical_rectangle_pdf`] and [`spherical_rectangle_inverse`] with the set-up (frame, solid
/// angle, the lune's parts, edge planes) paid once, for a caller that takes several samples or
/// evaluates several pdfs at one point. The free functions are this type, built and used once.
///
/// `P` is the width: `SphericalRectangle<Vec3>`, `SphericalRectangle<Vec3x8>` (eight
/// rectangles, lane by lane) or `SphericalRectangle<DVec3>`.
///
/// ```
/// use glam::{Vec2, Vec3};
/// use mcsample::warp::SphericalRectangle;
///
/// let rect = SphericalRectangle::new(
///     Vec3::new(-1.0, -0.5, 2.0),
///     Vec3::new(2.0, 0.0, 0.0),
///     Vec3::new(0.0, 1.0, 0.0),
/// );
/// let (p, pdf) = rect.sample(Vec2::new(0.3, 0.8));
/// assert!(pdf > 0.0 && rect.pdf(p) == pdf);
/// assert!((1.0 / pdf - rect.solid_angle()).abs() < 1e-6);
/// assert!(!rect.by_area());
/// let u = rect.inverse(p);
/// assert!((u - Vec2::new(0.3, 0.8)).length() < 1e-5);
/// ```
#[derive(Clone, Copy)]
pub struct SphericalRectangle<P: Point3> {
    s: Setup<P::Lane>,
    width: PhantomData<P>,
}

impl<P: Point3> core::fmt::Debug for SphericalRectangle<P> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("SphericalRectangle")
            .field("solid_angle", &self.s.omega)
            .finish_non_exhaustive()
    }
}

impl<P: Point3<Lane = L>, L: Math> SphericalRectangle<P> {
    /// The rectangle corner + s·ex + t·ey, s, t ∈ [0, 1], relative to the shading point, with
    /// ex ⟂ ey (a parallelogram whose edges are further than 2e-6 from orthogonal is sampled
    /// by area).
    // Always inlined, as the triangle's (see there): 1.93× → 1.86× the textbook rectangle for
    // the scalar free function in SSE2, 1.96× → 1.67× in AVX2. Not on bare metal, where flash
    // is what counts.
    #[cfg_attr(target_os = "none", inline)]
    #[cfg_attr(not(target_os = "none"), inline(always))]
    pub fn new(corner: P, ex: P, ey: P) -> Self {
        Self {
            // In halves at sixteen lanes without AVX-512 (`point::Split`).
            s: by_halves(
                (corner.to_lanes(), ex.to_lanes(), ey.to_lanes()),
                #[inline(always)]
                |(corner, ex, ey)| setup(corner, ex, ey),
            ),
            width: PhantomData,
        }
    }

    /// The solid angle Ω (Van Oosterom–Strackee), or 0 where the rectangle is degenerate or
    /// seen edge-on.
    #[inline]
    pub fn solid_angle(&self) -> L {
        L::select(self.s.valid, self.s.omega, L::ZERO)
    }

    /// True (lane by lane) where the rectangle is sampled by area rather than spherically:
    /// below [`SPHERICAL_RECTANGLE_MIN_SR`] or above [`SPHERICAL_RECTANGLE_MAX_SR`].
    #[inline]
    pub fn by_area(&self) -> <L as Lane>::Mask {
        self.s.by_area
    }

    /// The same parallelogram sampled by area in every lane, with the area pdf converted to
    /// solid angle (the scene's [`LightSampling::Area`](crate::scene::LightSampling::Area)).
    #[inline]
    pub fn by_area_only(self) -> Self {
        let all = L::ZERO.le(L::ZERO);
        Self {
            s: Setup {
                by_area: all,
                beyond_reach: !all,
                ..self.s
            },
            width: PhantomData,
        }
    }

    /// The unit directions of the corners where the square's corners (0, 0), (1, 0), (0, 1),
    /// (1, 1) land, by either map: corner, corner + ex, corner + ey, corner + ex + ey.
    #[inline(always)]
    pub(crate) fn square_corners(&self) -> [V3<L>; 4] {
        let s = &self.s;
        let c1 = s.corner + s.ex;
        [s.corner, c1, s.corner + s.ey, c1 + s.ey].map(|p| p.normalize())
    }

    /// True where the spherical inverse is NaN: the rectangle is larger than
    /// [`SPHERICAL_RECTANGLE_INVERSE_REACH`] times its distance.
    #[inline(always)]
    pub(crate) fn beyond_reach(&self) -> L::Mask {
        self.s.beyond_reach
    }

    /// The point of the rectangle's plane in direction `w` (any positive multiple of a point):
    /// w·|f|²/(w·f), f the foot of the perpendicular, at the given scale.
    #[inline(always)]
    pub(crate) fn on_plane(&self, w: V3<L>) -> V3<L> {
        let f = self.s.foot;
        w.scale(f.dot(f) / w.dot(f) * self.s.unscale)
    }

    /// See [`spherical_rectangle`].
    // Always inlined as well (unlike the triangle's sample, which was slower so): 8 % off the
    // free function in SSE2, the same in AVX2. Not on bare metal, as the set-up.
    #[cfg_attr(target_os = "none", inline)]
    #[cfg_attr(not(target_os = "none"), inline(always))]
    pub fn sample(&self, u: P::Vec2) -> (P, L) {
        let s = &self.s;
        let u = clamp_u(u.to_lanes());
        let p_sph = map_point(s, u);
        let p_area = s.corner + s.ex.scale(u.x) + s.ey.scale(u.y);
        // Scaling back is exact: p_area is corner + s·ex + t·ey as given, bit for bit.
        let p = V3::select(s.by_area, p_area, p_sph).scale(s.unscale);
        // The pdf is the pdf function's, at the very point returned: equal by construction.
        let pdf = self.pdf_lanes(p);
        let p = V3::select(pdf.gt(L::ZERO), p, s.given_corner);
        (P::from_lanes(p), pdf)
    }

    /// See [`spherical_rectangle_pdf`].
    #[inline]
    pub fn pdf(&self, w: P) -> L {
        self.pdf_lanes(w.to_lanes())
    }

    #[inline(always)]
    fn pdf_lanes(&self, w: V3<L>) -> L {
        let s = &self.s;
        let len2 = w.dot(w);
        let unit = w.normalize();
        let mut inside = len2.gt(L::ZERO) & len2.is_finite();
        for m in s.planes {
            inside = inside & unit.dot(m).ge(s.slack);
        }
        // The area pdf of `w` as given, only where some lane samples by area: the branch follows
        // the rectangle, not the point. The scaled geometry gives the same pdf (H²/|n|³ is
        // scale-free).
        let area = if s.by_area.any() {
            parallelogram_area_pdf(w, s.corner, s.ex, s.ey)
        } else {
            L::ZERO
        };
        let pdf = L::select(s.by_area, area, L::ONE / s.omega);
        L::select(s.valid & inside, pdf, L::ZERO)
    }

    /// See [`spherical_rectangle_inverse`].
    #[inline]
    pub fn inverse(&self, p: P) -> P::Vec2 {
        let s = &self.s;
        let p = p.to_lanes().scale(s.scale);
        let d = p - s.corner;
        // By area: (s, t) of p − corner = s·ex + t·ey from the 2 × 2 Gram system, which holds for
        // any parallelogram (the skewed ones are sampled by area); projecting on each edge
        // alone would leak one coordinate into the other.
        let (xx, xy, yy) = (s.ex.dot(s.ex), s.ex.dot(s.ey), s.ey.dot(s.ey));
        let (dx, dy) = (d.dot(s.ex), d.dot(s.ey));
        let det = xx.mul_add(yy, -(xy * xy));
        let st = V2::new(
            dx.mul_add(yy, -(dy * xy)) / det,
            dy.mul_add(xx, -(dx * xy)) / det,
        );
        // A sliver whose Gram system is singular in f32 (0/0, or ∞ − ∞ from edges 10²² times
        // apart) has no (s, t): it inverts to 0, as documented; NaN in p still gives NaN below.
        let zero_nan = |v: L| L::select(v.is_nan(), L::ZERO, v);
        let st = V2::new(zero_nan(st.x), zero_nan(st.y));
        // The oblique coordinates of p − foot, as in `setup`.
        let f = p - s.foot;
        let (xc, yc) = (f.dot(s.xh), f.dot(s.yh));
        let k = L::ONE / s.cos_xy.mul_add(-s.cos_xy, L::ONE);
        let x = s.cos_xy.mul_add(-yc, xc) * k;
        let y = s.cos_xy.mul_add(-xc, yc) * k;
        // u₀: the slab [x0, x] over the whole, signed so that a point just outside clamps to 0.
        let colx = column(x, &s.strip);
        let before = x.lt(s.x0);
        let pick = |p: L, q: L| (L::select(before, p, q), L::select(before, q, p));
        let (x_lo, x_hi) = pick(colx.x, s.col0.x);
        let (g_lo, g_hi) = pick(colx.g, s.col0.g);
        let (ra_lo, ra_hi) = pick(colx.ra, s.col0.ra);
        let (rb_lo, rb_hi) = pick(colx.rb, s.col0.rb);
        let (rho_lo, rho_hi) = pick(colx.rho, s.col0.rho);
        let lo = Column {
            x: x_lo,
            g: g_lo,
            t: L::ZERO,
            ra: ra_lo,
            rb: rb_lo,
            rho: rho_lo,
        };
        let hi = Column {
            x: x_hi,
            g: g_hi,
            t: L::ZERO,
            ra: ra_hi,
            rb: rb_hi,
            rho: rho_hi,
        };
        let part = slab(&lo, &hi, x_hi - x_lo, &s.strip);
        let u0 = L::select(before, -part, part) / s.omega;
        // u₁: the fraction of the elevation sine's span, both differences without cancellation.
        let rho2 = x.mul_add(x, s.strip.d * s.strip.d);
        let rho = rho2.sqrt();
        let ra = s.strip.y0.mul_add(s.strip.y0, rho2).sqrt();
        let rb = s.strip.y1.mul_add(s.strip.y1, rho2).sqrt();
        let ry = y.mul_add(y, rho2).sqrt();
        let u1 = h_diff(s.strip.y0, y, y - s.strip.y0, ra, ry, rho)
            / h_diff(s.strip.y0, s.strip.y1, s.strip.dy, ra, rb, rho);
        let u = clamp_u(V2::select(s.by_area, st, V2::new(u0, u1)));
        Point2::from_lanes(u.nan_where(p.any_nan() | s.beyond_reach))
    }
}

/// Ureña's map alone (in its cancellation-free form), with no area fallback and no validity
/// checks, as a point: for measuring where spherical sampling breaks down (the report's
/// stability table). Use [`spherical_rectangle`] to sample.
#[inline]
pub fn urena_rectangle<P: Point2>(u: P, corner: P::Vec3, ex: P::Vec3, ey: P::Vec3) -> P::Vec3 {
    let s = setup(corner.to_lanes(), ex.to_lanes(), ey.to_lanes());
    Point3::from_lanes(map_point(&s, clamp_u(u.to_lanes())).scale(s.unscale))
}

/// A point on the rectangle corner + s·ex + t·ey (relative to the shading point; ex ⟂ ey) and its
/// pdf per steradian ([`spherical_rectangle_pdf`] gives the same number, bit for bit, at the
/// returned point). [`SphericalRectangle`] is the same with the set-up paid once.
///
/// Ureña et al.'s map (2013) in a form without cancellation (see the module's documentation),
/// uniform in solid angle with pdf 1/Ω, Ω by Van Oosterom–Strackee. Below
/// [`SPHERICAL_RECTANGLE_MIN_SR`] or above [`SPHERICAL_RECTANGLE_MAX_SR`], and for a
/// parallelogram whose edges are further than 2e-6 from orthogonal, it samples by area and
/// returns the exact converted pdf.
///
/// u is clamped to [0, 1]². Seen edge-on (the shading point closer to the plane than 1e-6 of its
/// distance to the nearest corner), or degenerate, the pdf is 0 and the point is `corner`. NaN in
/// u gives pdf 0 and `corner`.
#[inline]
pub fn spherical_rectangle<P: Point2<Lane = L>, L: Math>(
    u: P,
    corner: P::Vec3,
    ex: P::Vec3,
    ey: P::Vec3,
) -> (P::Vec3, L) {
    halved!(sample SphericalRectangle::new(corner, ex, ey) at u)
}

/// pdf per steradian that [`spherical_rectangle`] returns a point in direction `w` (any positive
/// multiple: it is normalised here as the sampler normalises its point, so the returned point
/// itself gets the sampler's pdf bit for bit): 1/Ω, or the converted area pdf where it samples by
/// area; 0 when `w` misses the rectangle, for a degenerate one, for NaN, and where |w|² is 0 or
/// overflows. "Misses" is beyond a slack of 2ε·(1 + R/r) as the sine of the angle to an edge's
/// plane (ε = 2⁻²³, R = |corner| + |ex| + |ey|, r a lower bound on the distance to the rectangle:
/// a few ulp of angle unless the rectangle is much larger than its distance), which covers the
/// f32 rounding of the sample point.
#[inline]
pub fn spherical_rectangle_pdf<P: Point3<Lane = L>, L: Math>(w: P, corner: P, ex: P, ey: P) -> L {
    halved!(pdf SphericalRectangle::new(corner, ex, ey) at w)
}

/// Inverse of [`spherical_rectangle`]: the u that maps to point `p` of the rectangle, in
/// [0, 1]².
///
/// Spherically: u₀ is the solid angle of the slab [x0, x] over the whole, u₁ the fraction of the
/// elevation sine h between the slab's bottom and top edges. By area: p's (s, t) (0 for a sliver
/// whose 2 × 2 system is singular in f32). NaN gives NaN,
/// and so does a spherically sampled rectangle larger than [`SPHERICAL_RECTANGLE_INVERSE_REACH`]
/// times its distance from the shading point.
#[inline]
pub fn spherical_rectangle_inverse<P: Point3<Lane = L>, L: Math>(
    p: P,
    corner: P,
    ex: P,
    ey: P,
) -> P::Vec2 {
    halved!(inverse SphericalRectangle::new(corner, ex, ey) at p)
}
