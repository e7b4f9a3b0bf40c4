//! Uniform sampling of the solid angle of a rectangle (Ureña, Fajardo, King 2013), with an exact
//! area fallback where spherical sampling is unstable.
//!
//! The rectangle is `corner + s·ex + t·ey`, s, t ∈ [0, 1], relative to the shading point; `ex`
//! and `ey` must be orthogonal. The algorithm works in the rectangle's frame (x̂ along ex, ŷ along
//! ey, ẑ towards the shading point's side flipped so that z₀ ≤ 0).

use crate::lane::{V2, V3};
use crate::math::Math;
use crate::point::{Point2, Point3};
use crate::warp::common::clamp_u;
use crate::warp::polygon::{area_pdf_solid_angle, inside_polygon, vos_solid_angle};

/// Below this solid angle (sr) the rectangle is sampled by area.
///
/// Ureña's map forms the solid angle as a sum of four angles near π/2 minus 2π, which cancels
/// for small rectangles: measured against its f64 instance, the f32 direction error is 2e-6 at
/// 0.01 sr, 2e-5 at 1e-3 sr and 4e-5 at 1e-4 sr (the report's stability table). At 0.02 sr and
/// below, a rectangle is under 8° across, and area sampling's pdf varies across it by under 2 %,
/// which costs almost no variance.
pub const SPHERICAL_RECTANGLE_MIN_SR: f32 = 0.02;
/// Above this solid angle (sr) the rectangle is sampled by area too: the spherical map's f32
/// error reaches 4e-6 at 5.9 sr and 6e-5 at 6.2 sr.
pub const SPHERICAL_RECTANGLE_MAX_SR: f32 = 6.0;

const TAU: f64 = core::f64::consts::TAU;

struct Setup<L: Math> {
    corner: V3<L>,
    ex: V3<L>,
    ey: V3<L>,
    /// Unit axes of the rectangle's frame.
    xh: V3<L>,
    yh: V3<L>,
    x0: L,
    y0: L,
    z0: L,
    x1: L,
    y1: L,
    /// Ureña's b₀, b₁ (z components of two edge-plane normals) and k = 2π − γ₂ − γ₃.
    b0: L,
    b1: L,
    k: L,
    /// Σγ − 2π: the solid angle as the sampler's own map sees it.
    s_map: L,
    /// The solid angle by Van Oosterom–Strackee, used for the pdf.
    omega: L,
    valid: L::Mask,
    by_area: L::Mask,
}

/// Solid angle of the local rectangle [x0, x1] × [y0, y1] at height z0, as two VOS triangles.
/// Their triple products are exactly z0·(x1−x0)·(y1−y0), so no cancellation enters.
#[inline(always)]
fn rect_solid_angle<L: Math>(x0: L, x1: L, y0: L, y1: L, z0: L) -> L {
    let v00 = V3::new(x0, y0, z0);
    let v10 = V3::new(x1, y0, z0);
    let v11 = V3::new(x1, y1, z0);
    let v01 = V3::new(x0, y1, z0);
    let (l00, l10, l11, l01) = (v00.length(), v10.length(), v11.length(), v01.length());
    let triple = z0 * (x1 - x0) * (y1 - y0);
    vos_solid_angle(triple, v00, v10, v11, l00, l10, l11)
        + vos_solid_angle(triple, v00, v11, v01, l00, l11, l01)
}

#[inline(always)]
fn setup<L: Math>(corner: V3<L>, ex: V3<L>, ey: V3<L>) -> Setup<L> {
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

    // Interior angles between consecutive edge planes, as atan2(|n_i × n_j|, −n_i·n_j) with the
    // common positive factors cancelled: accurate where acos(−n_i·n_j) is not.
    let az = z0.abs();
    let len = |x: L, y: L| x.mul_add(x, y.mul_add(y, z0 * z0)).sqrt();
    let g0 = (az * len(x1, y0)).atan2(y0 * x1);
    let g1 = (az * len(x1, y1)).atan2(-(x1 * y1));
    let g2 = (az * len(x0, y1)).atan2(x0 * y1);
    let g3 = (az * len(x0, y0)).atan2(-(x0 * y0));
    let b0 = -y0 / z0.mul_add(z0, y0 * y0).sqrt();
    let b1 = y1 / z0.mul_add(z0, y1 * y1).sqrt();
    let k = L::c(TAU) - g2 - g3;
    let s_map = g0 + g1 - k;
    let omega = rect_solid_angle(x0, x1, y0, y1, z0);

    // z0 ≈ 0: the shading point lies in the rectangle's plane (to within rounding), where VOS may
    // still report up to 4π.
    let valid = z0.lt(L::c(-1e-6) * corner.length())
        & omega.gt(L::ZERO)
        & omega.is_finite()
        & exl.gt(L::ZERO)
        & eyl.gt(L::ZERO)
        & (x0 + y0 + z0).is_finite();
    let by_area = omega.lt(L::c(SPHERICAL_RECTANGLE_MIN_SR as f64))
        | omega.gt(L::c(SPHERICAL_RECTANGLE_MAX_SR as f64))
        | !s_map.gt(L::ZERO);
    Setup {
        corner,
        ex,
        ey,
        xh,
        yh,
        x0,
        y0,
        z0,
        x1,
        y1,
        b0,
        b1,
        k,
        s_map,
        omega,
        valid,
        by_area,
    }
}

/// h = y/√(d² + y²): the sine of the elevation of (·, y) seen at distance d from the y-axis line.
#[inline(always)]
fn elevation<L: Math>(y: L, d: L) -> L {
    y / d.mul_add(d, y * y).sqrt()
}

/// Ureña's map: u₀ picks x by inverting the solid angle of the slab [x0, x], u₁ the height y
/// uniformly in the slab's solid angle. Returns local (x, y).
#[inline(always)]
fn urena<L: Math>(s: &Setup<L>, u: V2<L>) -> (L, L) {
    let au = u.x.mul_add(s.s_map, s.k);
    let (sa, ca) = au.sin_cos();
    let fu = ca.mul_add(s.b0, -s.b1) / sa;
    let cu = (L::ONE.copysign(fu) / fu.mul_add(fu, s.b0 * s.b0).sqrt()).clamp(L::c(-1.0), L::ONE);
    let sin_u = ((L::ONE - cu) * (L::ONE + cu)).max(L::ZERO).sqrt();
    let xu = (-(cu * s.z0) / sin_u).clamp(s.x0, s.x1);
    let d = xu.mul_add(xu, s.z0 * s.z0).sqrt();
    let h0 = elevation(s.y0, d);
    let h1 = elevation(s.y1, d);
    let hv = u.y.mul_add(h1 - h0, h0);
    let hv2 = hv * hv;
    // Written so that NaN takes the formula's branch and stays NaN.
    let yv = L::select(
        hv2.ge(L::c(1.0 - 1e-6)),
        s.y1,
        (hv * d) / (L::ONE - hv2).sqrt(),
    );
    (xu, yv.clamp(s.y0, s.y1))
}

#[inline(always)]
fn pdf_of<L: Math>(s: &Setup<L>, w: V3<L>) -> L {
    let n = s.ex.cross(s.ey);
    L::select(
        s.by_area,
        area_pdf_solid_angle(w, s.corner.dot(n), n, L::ONE),
        L::ONE / s.omega,
    )
}

/// Ureña's map alone, with no area fallback and no validity checks, as a point: for measuring
/// where spherical sampling breaks down. Use [`spherical_rectangle`] to sample.
#[inline]
pub fn urena_rectangle<P: Point2>(u: P, corner: P::Vec3, ex: P::Vec3, ey: P::Vec3) -> P::Vec3 {
    let corner = corner.to_lanes();
    let s = setup(corner, ex.to_lanes(), ey.to_lanes());
    let (xu, yv) = urena(&s, clamp_u(u.to_lanes()));
    Point3::from_lanes(corner + s.xh.scale(xu - s.x0) + s.yh.scale(yv - s.y0))
}

/// A point on the rectangle corner + s·ex + t·ey (relative to the shading point; ex ⟂ ey) and its
/// pdf per steradian ([`spherical_rectangle_pdf`] gives the same number).
///
/// Ureña et al.'s map (2013), uniform in solid angle with pdf 1/Ω, Ω by Van Oosterom–Strackee.
/// Below [`SPHERICAL_RECTANGLE_MIN_SR`] or above [`SPHERICAL_RECTANGLE_MAX_SR`] it samples by
/// area and returns the exact converted pdf.
///
/// u is clamped to [0, 1]². Seen edge-on (the shading point within 1e-6 rad of the plane), or
/// degenerate, the pdf is 0 and the point is `corner`. NaN in u gives pdf 0.
#[inline]
pub fn spherical_rectangle<P: Point2<Lane = L>, L: Math>(
    u: P,
    corner: P::Vec3,
    ex: P::Vec3,
    ey: P::Vec3,
) -> (P::Vec3, L) {
    let u = clamp_u(u.to_lanes());
    let (corner, ex, ey) = (corner.to_lanes(), ex.to_lanes(), ey.to_lanes());
    let s = setup(corner, ex, ey);
    let (xu, yv) = urena(&s, u);
    // Offsets from the corner keep the point on the plane even when the rectangle is far away.
    let fx = L::select(s.by_area, u.x, (xu - s.x0) / (s.x1 - s.x0));
    let fy = L::select(s.by_area, u.y, (yv - s.y0) / (s.y1 - s.y0));
    let p = corner + ex.scale(fx) + ey.scale(fy);
    let pdf = pdf_of(&s, p.normalize());
    let ok = s.valid & p.dot(p).is_finite();
    let p = V3::select(ok, p, corner);
    (Point3::from_lanes(p), L::select(ok, pdf, L::ZERO))
}

/// pdf per steradian that [`spherical_rectangle`] returns a point in unit direction `w`; 0 when
/// `w` misses the rectangle, for a degenerate one and for NaN.
#[inline]
pub fn spherical_rectangle_pdf<P: Point3<Lane = L>, L: Math>(w: P, corner: P, ex: P, ey: P) -> L {
    let (w, corner, ex, ey) = (
        w.to_lanes(),
        corner.to_lanes(),
        ex.to_lanes(),
        ey.to_lanes(),
    );
    let s = setup(corner, ex, ey);
    let quad = [corner, corner + ex, corner + ex + ey, corner + ey];
    let inside = inside_polygon(w, quad, [ex, ey, -ex, -ey], corner.dot(ex.cross(ey)));
    L::select(s.valid & inside, pdf_of(&s, w), L::ZERO)
}

/// Inverse of [`spherical_rectangle`]: the u that maps to point `p` of the rectangle, in
/// [0, 1]².
///
/// Spherically: u₀ is the solid angle of the slab [x0, x] over the whole, u₁ the fraction of the
/// elevation sine h between the slab's bottom and top edges. By area: p's (s, t). NaN gives NaN.
#[inline]
pub fn spherical_rectangle_inverse<P: Point3<Lane = L>, L: Math>(
    p: P,
    corner: P,
    ex: P,
    ey: P,
) -> P::Vec2 {
    let (p, corner, ex, ey) = (
        p.to_lanes(),
        corner.to_lanes(),
        ex.to_lanes(),
        ey.to_lanes(),
    );
    let s = setup(corner, ex, ey);
    let d = p - corner;
    let st = V2::new(d.dot(s.ex) / s.ex.dot(s.ex), d.dot(s.ey) / s.ey.dot(s.ey));
    let x = d.dot(s.xh) + s.x0;
    let y = d.dot(s.yh) + s.y0;
    let u0 = rect_solid_angle(s.x0, x, s.y0, s.y1, s.z0) / s.omega;
    let dist = x.mul_add(x, s.z0 * s.z0).sqrt();
    let h0 = elevation(s.y0, dist);
    let h1 = elevation(s.y1, dist);
    let u1 = (elevation(y, dist) - h0) / (h1 - h0);
    Point2::from_lanes(clamp_u(V2::select(s.by_area, st, V2::new(u0, u1))).nan_where(p.any_nan()))
}
