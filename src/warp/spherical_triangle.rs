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
    /// The plane's offset v·n, the same for every vertex v.
    h: L,
    /// Unit vertex directions.
    ua: V3<L>,
    ub: V3<L>,
    uc: V3<L>,
    /// Plane normal (b−a)×(c−a), unnormalised.
    n: V3<L>,
    omega: L,
    /// π − α for an obtuse α, the interior angle at A, else δ = α − Ω/2 (positive in every
    /// spherical triangle): the accurate term of sin(α − E/2).
    angle0: L,
    obtuse: L::Mask,
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
        a.scale(L::ONE / la),
        b.scale(L::ONE / lb),
        c.scale(L::ONE / lc),
    );
    let e1 = b - a;
    let e2 = c - a;
    let e3 = c - b;
    // The plane normal n = (b−a)×(c−a) = (c−b)×(a−b) = (a−c)×(b−c) and its offset h = v·n, from
    // whichever vertex v conditions them best. Rounding in the cross product of the two edges at
    // v costs about ε|v||e||e′| in h; up to a factor common to all three vertices that is |v|
    // over the opposite edge. Basing at a alone loses 3e-3 of Ω for a light with one far vertex
    // and two near ones, whose edges from a are long and nearly parallel.
    let (ra, rb, rc) = (la / e3.length(), lb / e2.length(), lc / e1.length());
    let at_b = rb.lt(ra) & rb.le(rc);
    let at_c = rc.lt(ra) & rc.lt(rb);
    let p = V3::select(at_c, e2, e1);
    let q = V3::select(at_b | at_c, e3, e2);
    let n = p.cross(q);
    let h = V3::select(at_b, b, V3::select(at_c, c, a)).dot(n);
    // Scale-free triple product a·(b×c)/(|a||b||c|).
    let triple = h / (la * lb * lc);
    let omega = vos_solid_angle(triple, ua, ub, uc, L::ONE, L::ONE, L::ONE);

    // The arcs c = AB and b = AC and the angle α at A come from the normals a×b and a×c of the
    // planes through A. a × b = a × (b − a): the shorter of b and b − a leaves the smaller
    // rounding error, so a small triangle keeps its relative precision (b − a is short) and so
    // does a far vertex beside near ones (b is).
    let nab = a.cross(V3::select(e1.length_squared().lt(lb * lb), e1, b));
    let nac = a.cross(V3::select(e2.length_squared().lt(lc * lc), e2, c));
    let (lab, lac) = (nab.length(), nac.length());
    let (sin_c, cos_c) = (lab / (la * lb), ua.dot(ub));
    let (sin_b, cos_b) = (lac / (la * lc), ua.dot(uc));
    // α as atan2(sin, cos), accurate at every angle (acos is not, near 0 and π). sin α from
    // |(a×b)×(a×c)| = |a||a·(b×c)| = |a||h|, the well-conditioned offset, rather than from the
    // cross product of two nearly parallel normals, which loses α's relative precision when α is
    // small.
    let inv = L::ONE / (lab * lac);
    let cos_alpha = (nab.dot(nac) * inv).clamp(L::c(-1.0), L::ONE);
    let sin_alpha = (la * h.abs() * inv).min(L::ONE);
    let one_minus_cos_c = versine(sin_c, cos_c);
    // δ = α − Ω/2 from the half-angle excess formula at E = Ω (see `arvo`):
    // tan δ = sin α / (cos α + tan(b/2) tan(c/2)), multiplied through by sin b sin c. For an
    // obtuse α the map wants π − α instead, which f32 cannot recover from α near π.
    let sbc = sin_b * sin_c;
    let obtuse = cos_alpha.lt(L::ZERO);
    let delta =
        (sin_alpha * sbc).atan2(cos_alpha.mul_add(sbc, versine(sin_b, cos_b) * one_minus_cos_c));
    let angle0 = L::select(obtuse, sin_alpha.atan2(-cos_alpha), delta);

    // Collinear vertices can leave a rounding-sized normal, and a shading point in the plane a
    // rounding-sized triple product (with FMA, say), while VOS still reports up to 2π. Neither is
    // a light: the plane must be tilted by more than 1e-6 rad both ways.
    let nn = n.length();
    let valid = nn.gt(L::c(1e-6) * e1.length() * e2.length())
        & (h / la).abs().gt(L::c(1e-6) * nn)
        & omega.gt(L::ZERO)
        & omega.is_finite()
        & delta.is_finite()
        & n.dot(n).is_finite()
        & la.gt(L::ZERO)
        & lb.gt(L::ZERO)
        & lc.gt(L::ZERO);
    let by_area = omega.lt(L::c(SPHERICAL_TRIANGLE_MIN_SR as f64))
        | omega.gt(L::c(SPHERICAL_TRIANGLE_MAX_SR as f64))
        | !delta.is_finite()
        | sin_alpha.eq(L::ZERO);
    Setup {
        h,
        ua,
        ub,
        uc,
        n,
        omega,
        angle0,
        obtuse,
        one_minus_cos_c,
        sin_c,
        valid,
        by_area,
    }
}

/// 1 − cos θ of an angle given by its sine and cosine, without the cancellation near θ = 0:
/// sin²θ / (1 + cos θ) where cos θ ≥ 0.
#[inline(always)]
fn versine<L: Math>(sin: L, cos: L) -> L {
    L::select(cos.ge(L::ZERO), sin * sin / (L::ONE + cos), L::ONE - cos)
}

/// The component of `v` orthogonal to unit `u`, normalised.
#[inline(always)]
fn ortho<L: Math>(v: V3<L>, u: V3<L>) -> V3<L> {
    let w = v - u.scale(v.dot(u));
    w.scale(L::ONE / w.length())
}

/// Arvo's map: u₀ picks the sub-triangle A B Ĉ of area E = u₀Ω, u₁ the point along the arc B Ĉ.
///
/// Arvo solves for cos b′, the arc from A to Ĉ, as a ratio and takes sin b′ = √(1 − cos²b′); both
/// the ratio and the root cancel (a small u₀, or b′ near 90°, loses up to 3e-4 of direction in
/// f32). The half-angle form of the spherical excess of the triangle with sides c, b′ and angle α
/// between them, tan(E/2) = τt sin α / (1 + τt cos α) with τ = tan(c/2), t = tan(b′/2), solves
/// to t = sin(E/2) / (τ sin(α − E/2)). With τ = (1 − cos c)/sin c, b′/2 is the angle of
/// (x, y) = ((1 − cos c) sin(α − E/2), sin c sin(E/2)): two products of sines, each accurate, and
/// cos b′, sin b′ follow from x and y without a root.
#[inline(always)]
fn arvo<L: Math>(s: &Setup<L>, u: V2<L>) -> V3<L> {
    let half = u.x * s.omega * L::HALF;
    let (h1, _) = half.sin_cos();
    // sin(α − E/2) as a sum of two non-negative angles, never a difference, which would cancel
    // as E nears Ω with α close to Ω/2, or for α near π: sin(δ + (1 − u₀)Ω/2) for an acute α,
    // sin(π − α + E/2) for an obtuse one.
    let rest = L::select(s.obtuse, half, (L::ONE - u.x) * (s.omega * L::HALF));
    let (h2, _) = (s.angle0 + rest).sin_cos();
    let x = s.one_minus_cos_c * h2.max(L::ZERO);
    let y = s.sin_c * h1;
    let r = L::ONE / x.mul_add(x, y * y);
    let cos_b = ((x - y) * (x + y) * r).clamp(L::c(-1.0), L::ONE);
    let sin_b = L::TWO * x * y * r;
    let c_hat = s.ua.scale(cos_b) + ortho(s.uc, s.ua).scale(sin_b);
    // 1 − Ĉ·B as |Ĉ − B|²/2, so that z keeps its precision when Ĉ is close to B.
    let d = c_hat - s.ub;
    let one_minus_z = u.y * (L::HALF * d.dot(d));
    let z = L::ONE - one_minus_z;
    let sin_z = (one_minus_z * (L::TWO - one_minus_z)).max(L::ZERO).sqrt();
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
    (V3::new(L::ONE - b1 - b2, b1, b2), t.gt(L::ZERO))
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
    let w = V3::select(ok, w, V3::new(L::ZERO, L::ZERO, L::ONE));
    (Point3::from_lanes(w), L::select(ok, pdf, L::ZERO))
}

/// The pdf of direction `w` given a set-up triangle, without the inside test: 1/Ω when sampled
/// spherically, the converted area pdf otherwise.
#[inline(always)]
fn pdf_of<L: Math>(s: &Setup<L>, w: V3<L>) -> L {
    let sph = L::ONE / s.omega;
    let area = area_pdf_solid_angle(w, s.h, s.n, L::TWO);
    L::select(s.by_area, area, sph)
}

/// pdf per steradian that [`spherical_triangle`] returns unit direction `w`: the same formula,
/// hence the same number, as the sampler's; 0 outside the triangle, for degenerate triangles
/// and for NaN.
#[inline]
pub fn spherical_triangle_pdf<P: Point3<Lane = L>, L: Math>(w: P, a: P, b: P, c: P) -> L {
    let (w, a, b, c) = (w.to_lanes(), a.to_lanes(), b.to_lanes(), c.to_lanes());
    let s = setup(a, b, c);
    let inside = inside_polygon(w, [a, b, c], [b - a, c - b, a - c], s.h);
    L::select(s.valid & inside, pdf_of(&s, w), L::ZERO)
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
    let c_hat = c_hat.scale(L::ONE / c_hat.length());
    // The two planes meet in ±Ĉ: keep the one on the arc from A to C.
    let c_hat = c_hat.scale(L::ONE.copysign(c_hat.dot(s.ua + s.uc)));
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
        L::ONE,
        L::ONE,
        L::ONE,
    );
    let u0 = sub / s.omega;
    // w = B leaves Ĉ undefined; any u₀ with u₁ = 0 maps there.
    let at_b = dw.dot(dw).eq(L::ZERO);
    let u_sph = V2::new(L::select(at_b, L::ZERO, u0), L::select(at_b, L::ZERO, u1));
    Point2::from_lanes(clamp_u(V2::select(s.by_area, u_area, u_sph)).nan_where(w.any_nan()))
}
