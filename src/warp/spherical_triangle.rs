//! Uniform sampling of the solid angle of a triangle (Arvo 1995), with an exact area fallback
//! where spherical sampling is unstable.
//!
//! Vertices are given relative to the shading point, in any winding. The solid angle Ω comes from
//! Van Oosterom–Strackee on edge vectors, and the same Ω serves the sample and the pdf.

use crate::lane::{V2, V3};
use crate::math::Math;
use crate::point::{Point2, Point3};
use crate::warp::common::clamp_u;
use crate::warp::polygon::{area_pdf_solid_angle, inside_polygon, vos_solid_angle};
use crate::warp::triangle::{uniform_triangle, uniform_triangle_inverse};

/// Below this solid angle (sr) the triangle is sampled by area.
///
/// With the half-angle form of Arvo's map (see `arvo`), f32 spherical sampling stays within 1e-7
/// of its f64 instance down to 1e-8 sr (the report's stability table), so the threshold is set
/// by the f32 direction grid, not by the algorithm: below 1e-6 sr (0.06° across) a unit f32
/// vector resolves only 1e-4 of the light, and area sampling, whose pdf there is uniform in
/// solid angle to 1e-6, is exact and cheaper to reason about.
pub const SPHERICAL_TRIANGLE_MIN_SR: f32 = 1.0e-6;
/// Above this solid angle (sr), close to a hemisphere, the triangle is sampled by area too: the
/// spherical map's f32 error grows to 3e-6 at 5–6 sr and to 1.6e-5 beyond.
pub const SPHERICAL_TRIANGLE_MAX_SR: f32 = 6.0;

/// Everything the sampler, pdf and inverse need, computed once per triangle.
struct Setup<L: Math> {
    a: V3<L>,
    /// Unit vertex directions.
    ua: V3<L>,
    ub: V3<L>,
    uc: V3<L>,
    /// Plane normal (b−a)×(c−a), unnormalised.
    n: V3<L>,
    omega: L,
    /// α, the interior angle at A, and its sine.
    alpha: L,
    sin_alpha: L,
    /// 1 − cos and sin of the arc AB.
    one_minus_cos_c: L,
    sin_c: L,
    /// True where the triangle can be sampled at all.
    valid: L::Mask,
    /// True where it is sampled by area.
    by_area: L::Mask,
}

#[inline(always)]
fn setup<L: Math>(a: V3<L>, b: V3<L>, c: V3<L>) -> Setup<L> {
    let (la, lb, lc) = (a.length(), b.length(), c.length());
    let (ua, ub, uc) = (
        a.scale(L::c(1.0) / la),
        b.scale(L::c(1.0) / lb),
        c.scale(L::c(1.0) / lc),
    );
    let e1 = b - a;
    let e2 = c - a;
    let n = e1.cross(e2);
    // Scale-free triple product: a·(e1×e2)/(|a||b||c|), from edges so it keeps its precision.
    let triple = ua.dot(n) / (lb * lc);
    let omega = vos_solid_angle(triple, ua, ub, uc, L::c(1.0), L::c(1.0), L::c(1.0));

    // α from the normals of the planes through (A, B) and (A, C), as atan2(|n₁×n₂|, n₁·n₂),
    // which is accurate at every angle (acos is not, near 0 and π). The normals come from the raw
    // vertex and edge vectors: a × (b − a) keeps its relative precision for a small triangle,
    // where the cross product of two nearly equal unit vectors would not.
    let nab = a.cross(e1);
    let nac = a.cross(e2);
    let lab = nab.length();
    let nab = nab.scale(L::c(1.0) / lab);
    let nac = nac.scale(L::c(1.0) / nac.length());
    let cos_alpha = nab.dot(nac).clamp(L::c(-1.0), L::c(1.0));
    let sin_alpha = nab.cross(nac).length();
    let alpha = sin_alpha.atan2(cos_alpha);
    // The arc c from A to B, as its cosine and (from the same cross product) its sine.
    let dab = ua - ub;
    let one_minus_cos_c = L::c(0.5) * dab.dot(dab);
    let sin_c = lab / (la * lb);

    // Collinear vertices can leave a rounding-sized normal, and a shading point in the plane a
    // rounding-sized triple product (with FMA, say), while VOS still reports up to 2π. Neither is
    // a light: the plane must be tilted by more than 1e-6 rad both ways.
    let nn = n.length();
    let valid = nn.gt(L::c(1e-6) * e1.length() * e2.length())
        & ua.dot(n).abs().gt(L::c(1e-6) * nn)
        & omega.gt(L::c(0.0))
        & omega.is_finite()
        & alpha.is_finite()
        & n.dot(n).is_finite()
        & la.gt(L::c(0.0))
        & lb.gt(L::c(0.0))
        & lc.gt(L::c(0.0));
    let by_area = omega.lt(L::c(SPHERICAL_TRIANGLE_MIN_SR as f64))
        | omega.gt(L::c(SPHERICAL_TRIANGLE_MAX_SR as f64))
        | !alpha.is_finite()
        | sin_alpha.eq(L::c(0.0));
    Setup {
        a,
        ua,
        ub,
        uc,
        n,
        omega,
        alpha,
        sin_alpha,
        one_minus_cos_c,
        sin_c,
        valid,
        by_area,
    }
}

/// The component of `v` orthogonal to unit `u`, normalised.
#[inline(always)]
fn ortho<L: Math>(v: V3<L>, u: V3<L>) -> V3<L> {
    let w = v - u.scale(v.dot(u));
    w.scale(L::c(1.0) / w.length())
}

/// Arvo's map: u₀ picks the sub-triangle A B Ĉ of area u₀Ω, u₁ the point along the arc B Ĉ.
///
/// Arvo writes cos b′, the arc from A to Ĉ, as a ratio and takes sin b′ = √(1 − cos²b′), which
/// cancels when Ĉ is near A: a small u₀ then loses up to 3e-4 of direction in f32. Expanding the
/// ratio with φ = Â − α, h₁ = sin(Â/2), h₂ = sin(Â/2 − α) and k = 1 − cos c = sin²c/(1 + cos c):
///
/// - P = 1 − cos φ cos α = h₁² + h₂² and Q = sin α sin φ (k itself is taken as |A − B|²/2,
///   which does not cancel even when A and B are nearly opposite);
/// - D = 2h₁² − kQ and cos b′ = (kP − 2h₁²)/D;
/// - sin b′ = 2 sin c |h₁h₂|/|D|.
///
/// Every term is a product of sines, so nothing cancels for small triangles or small u₀.
#[inline(always)]
fn arvo<L: Math>(s: &Setup<L>, u: V2<L>) -> V3<L> {
    let half = u.x * s.omega * L::c(0.5);
    let (h1, c1) = half.sin_cos();
    let (h2, c2) = (half - s.alpha).sin_cos();
    let p = h1.mul_add(h1, h2 * h2);
    let q = s.sin_alpha * h1.mul_add(c2, c1 * h2);
    let k = s.one_minus_cos_c;
    let two_h1_sq = L::c(2.0) * h1 * h1;
    let d = (-k).mul_add(q, two_h1_sq);
    let cos_b = k.mul_add(p, -two_h1_sq) / d;
    let sin_b = L::c(2.0) * s.sin_c * (h1 * h2).abs() / d.abs();
    let cos_b = cos_b.clamp(L::c(-1.0), L::c(1.0));
    let c_hat = s.ua.scale(cos_b) + ortho(s.uc, s.ua).scale(sin_b);
    // 1 − Ĉ·B as |Ĉ − B|²/2, so that z keeps its precision when Ĉ is close to B.
    let d = c_hat - s.ub;
    let one_minus_z = u.y * (L::c(0.5) * d.dot(d));
    let z = L::c(1.0) - one_minus_z;
    let sin_z = (one_minus_z * (L::c(2.0) - one_minus_z))
        .max(L::c(0.0))
        .sqrt();
    // Each step is accurate to a few ulp, but their rounding leaves |w| off 1 by up to 1e-5 for
    // wide triangles: renormalise, which also pulls the point back onto the sphere's triangle.
    (s.ub.scale(z) + ortho(c_hat, s.ub).scale(sin_z)).normalize()
}

/// The point of the plane hit by unit direction `w`, as barycentrics (b₀, b₁, b₂), and whether
/// the hit lies in front of the origin.
#[inline(always)]
fn barycentrics<L: Math>(w: V3<L>, a: V3<L>, b: V3<L>, c: V3<L>, n: V3<L>) -> (V3<L>, L::Mask) {
    let wn = w.dot(n);
    let t = a.dot(n) / wn;
    let d = w.scale(t) - a;
    let nn = n.dot(n);
    let b1 = d.cross(c - a).dot(n) / nn;
    let b2 = (b - a).cross(d).dot(n) / nn;
    (V3::new(L::c(1.0) - b1 - b2, b1, b2), t.gt(L::c(0.0)))
}

/// Arvo's map alone, with no area fallback and no validity checks: for measuring where spherical
/// sampling breaks down (the report's stability table). Use [`spherical_triangle`] to sample.
#[inline]
pub fn arvo_triangle<P: Point2>(u: P, a: P::Vec3, b: P::Vec3, c: P::Vec3) -> P::Vec3 {
    let s = setup(a.to_lanes(), b.to_lanes(), c.to_lanes());
    Point3::from_lanes(arvo(&s, clamp_u(u.to_lanes())))
}

/// A direction towards triangle (a, b, c), vertices relative to the shading point in either
/// winding, and its pdf per steradian ([`spherical_triangle_pdf`] gives the same number).
///
/// Arvo's map (1995), uniform in solid angle with pdf 1/Ω, Ω by Van Oosterom–Strackee on edge
/// vectors. Below [`SPHERICAL_TRIANGLE_MIN_SR`] or above [`SPHERICAL_TRIANGLE_MAX_SR`] it
/// samples by area instead and returns the exact converted pdf.
///
/// u is clamped to [0, 1]². Degenerate triangles (coincident or collinear vertices, the shading
/// point within 1e-6 rad of the triangle's plane, non-finite input) give pdf 0 and direction +z.
/// NaN in u gives pdf 0.
#[inline]
pub fn spherical_triangle<P: Point2<Lane = L>, L: Math>(
    u: P,
    a: P::Vec3,
    b: P::Vec3,
    c: P::Vec3,
) -> (P::Vec3, L) {
    let u = clamp_u(u.to_lanes());
    let (a, b, c) = (a.to_lanes(), b.to_lanes(), c.to_lanes());
    let s = setup(a, b, c);
    let w_sph = arvo(&s, u);
    let bary = uniform_triangle(u);
    let p = a.scale(bary.x) + b.scale(bary.y) + c.scale(bary.z);
    let w_area = p.normalize();
    let w = V3::select(s.by_area, w_area, w_sph);
    let pdf = pdf_of(&s, w);
    let ok = s.valid & w.dot(w).is_finite();
    let w = V3::select(ok, w, V3::new(L::c(0.0), L::c(0.0), L::c(1.0)));
    (Point3::from_lanes(w), L::select(ok, pdf, L::c(0.0)))
}

/// The pdf of direction `w` given a set-up triangle, without the inside test: 1/Ω when sampled
/// spherically, the converted area pdf otherwise.
#[inline(always)]
fn pdf_of<L: Math>(s: &Setup<L>, w: V3<L>) -> L {
    let sph = L::c(1.0) / s.omega;
    let area = area_pdf_solid_angle(w, s.a, s.n, L::c(2.0));
    L::select(s.by_area, area, sph)
}

/// pdf per steradian that [`spherical_triangle`] returns unit direction `w`: the same formula,
/// hence the same number, as the sampler's; 0 outside the triangle, for degenerate triangles
/// and for NaN.
#[inline]
pub fn spherical_triangle_pdf<P: Point3<Lane = L>, L: Math>(w: P, a: P, b: P, c: P) -> L {
    let (w, a, b, c) = (w.to_lanes(), a.to_lanes(), b.to_lanes(), c.to_lanes());
    let s = setup(a, b, c);
    let inside = inside_polygon(w, [a, b, c], [b - a, c - b, a - c], a.dot(s.n));
    L::select(s.valid & inside, pdf_of(&s, w), L::c(0.0))
}

/// Inverse of [`spherical_triangle`]: the u that maps to unit direction `w`, clamped to [0, 1]².
///
/// Spherically: Ĉ is where the great circle through B and w meets the arc AC; u₁ is the fraction
/// of the arc B Ĉ covered, |w − B|²/|Ĉ − B|², and u₀ the area of A B Ĉ over Ω. By area: the
/// low-distortion triangle inverse of w's barycentrics. NaN gives NaN.
#[inline]
pub fn spherical_triangle_inverse<P: Point3<Lane = L>, L: Math>(w: P, a: P, b: P, c: P) -> P::Vec2 {
    let (w, a, b, c) = (w.to_lanes(), a.to_lanes(), b.to_lanes(), c.to_lanes());
    let s = setup(a, b, c);
    let (bary, _) = barycentrics(w, a, b, c, s.n);
    let u_area = uniform_triangle_inverse(bary);

    let plane_bw = s.ub.cross(w);
    let plane_ac = s.ua.cross(s.uc);
    let c_hat = plane_bw.cross(plane_ac);
    let c_hat = c_hat.scale(L::c(1.0) / c_hat.length());
    // The two planes meet in ±Ĉ: keep the one on the arc from A to C.
    let c_hat = c_hat.scale(L::c(1.0).copysign(c_hat.dot(s.ua + s.uc)));
    let dw = w - s.ub;
    let dc = c_hat - s.ub;
    let u1 = dw.dot(dw) / dc.dot(dc);
    let e1 = s.ub - s.ua;
    let e2 = c_hat - s.ua;
    let sub = vos_solid_angle(
        s.ua.dot(e1.cross(e2)),
        s.ua,
        s.ub,
        c_hat,
        L::c(1.0),
        L::c(1.0),
        L::c(1.0),
    );
    let u0 = sub / s.omega;
    // w = B leaves Ĉ undefined; any u₀ with u₁ = 0 maps there.
    let at_b = dw.dot(dw).eq(L::c(0.0));
    let u_sph = V2::new(
        L::select(at_b, L::c(0.0), u0),
        L::select(at_b, L::c(0.0), u1),
    );
    Point2::from_lanes(clamp_u(V2::select(s.by_area, u_area, u_sph)).nan_where(w.any_nan()))
}
