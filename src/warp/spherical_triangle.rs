//! Uniform sampling of the solid angle of a triangle (Arvo 1995), with an exact area fallback
//! where spherical sampling is unstable.
//!
//! Vertices are given relative to the shading point, in any winding. The solid angle Ω comes from
//! Van Oosterom–Strackee on edge vectors, and the same Ω serves the sample and the pdf.

use core::marker::PhantomData;

use crate::lane::{Mask, V2, V3};
use crate::math::Math;
use crate::point::{Point2, Point3, by_halves, halved, split_fields};
use crate::warp::common::clamp_u;
use crate::warp::polygon::{
    EdgePlanes, needs_pow2_scale, pow2_scale, triangle_area_pdf, vos_solid_angle,
};
use crate::warp::polygon::{plane_dot, triangle_terms, wide_cross};

/// Below this solid angle (sr) the triangle is sampled by area.
///
/// With the half-angle form of Arvo's map (see `arvo`), f32 spherical sampling stays within 1e-7
/// of its f64 instance down to 1e-8 sr (the report's stability table), so the threshold is set
/// by the f32 direction grid, not by the algorithm: below 1e-6 sr (0.06° across) a unit f32
/// vector resolves only 1e-4 of the light, and area sampling, whose pdf there is uniform in
/// solid angle to 1e-6, is exact and cheaper to reason about.
pub const SPHERICAL_TRIANGLE_MIN_SR: f32 = 1.0e-6;
/// Above this solid angle (sr), close to a hemisphere, the triangle is sampled by area too: the
/// spherical map's f32 direction error against its f64 instance is within 1e-6 up to 5.3 sr,
/// 2.3e-6 at 5.9 sr and 1.1e-5 at 6.2 sr (the report's stability table: three vertices ever
/// closer to the horizon).
pub const SPHERICAL_TRIANGLE_MAX_SR: f32 = 6.0;

/// Everything the sampler, pdf and inverse need, computed once per triangle.
#[derive(Clone, Copy)]
struct Setup<L: Math> {
    /// The vertices as given, times `scale`'s power of two.
    a: V3<L>,
    b: V3<L>,
    c: V3<L>,
    /// The planes through the origin and each edge, for the inside test.
    edges: EdgePlanes<L, 3>,
    /// The plane's offset v·n, the same for every vertex v.
    h: L,
    /// Unit vertex directions.
    ua: V3<L>,
    ub: V3<L>,
    uc: V3<L>,
    /// Plane normal (b−a)×(c−a), unnormalised.
    n: V3<L>,
    /// The inverse of the power of two the vertices are scaled by.
    unscale: L,
    omega: L,
    /// From each end P ∈ {A, C} of the arc AC: the tangent T̂ towards the other end, and with c the
    /// arc PB and φ the angle at P, sin c and (1 − cos c)·(sin φ, cos φ).
    t_a: V3<L>,
    t_c: V3<L>,
    sin_ab: L,
    sin_cb: L,
    vs_a: L,
    vc_a: L,
    vs_c: L,
    vc_c: L,
    /// True where the triangle can be sampled at all.
    valid: L::Mask,
    /// True where it is sampled by area.
    by_area: L::Mask,
}

split_fields!(Setup<L: Math> by L {
    a, b, c, edges, h, ua, ub, uc, n, unscale, omega, t_a, t_c, sin_ab, sin_cb, vs_a, vc_a, vs_c,
    vc_c, valid: mask, by_area: mask,
});

#[inline(always)]
fn setup<L: Math>(a: V3<L>, b: V3<L>, c: V3<L>) -> Setup<L> {
    // The vertices at a scale where the products of three lengths cannot overflow or underflow,
    // by an exact power of two: directions, Ω and pdfs depend only on ratios, so they come out
    // bit for bit as at the given scale, but a triangle 1e-14 across keeps its solid angle.
    let amax = |v: V3<L>| v.x.abs().max(v.y.abs()).max(v.z.abs());
    let (ma, mb, mc) = (amax(a), amax(b), amax(c));
    // Only where some lane needs a power of two other than 1 (then everything below is as if
    // each scaling were done, bit for bit): the branch follows the triangle, not the sample.
    let (scale, (a, b, c), (pa, pb, pc)) =
        if (needs_pow2_scale(ma) | needs_pow2_scale(mb) | needs_pow2_scale(mc)).any() {
            let scale = pow2_scale(ma.max(mb).max(mc));
            let (a, b, c) = (a.scale(scale), b.scale(scale), c.scale(scale));
            // The spherical quantities (unit vertices, arcs, the angle at A) depend on each
            // vertex's direction alone, so each vertex gets its own power of two for them: cross
            // products of two vertices and their squares then stay in range however much nearer
            // one vertex is than the others (a vertex 2⁻⁴⁵ as far as the others underflowed them
            // in f32; found by the fuzz target). The plane, its offset and area sampling keep the
            // vertices as scaled above.
            let own = |v: V3<L>| v.scale(pow2_scale(amax(v)));
            (scale, (a, b, c), (own(a), own(b), own(c)))
        } else {
            (L::ONE, (a, b, c), (a, b, c))
        };
    let (pla, plb, plc) = (pa.length(), pb.length(), pc.length());
    let (ua, ub, uc) = (
        pa.scale(L::ONE / pla),
        pb.scale(L::ONE / plb),
        pc.scale(L::ONE / plc),
    );
    // Arvo's map sweeps Ĉ along the arc AC and then samples the arc from B to Ĉ, whose great
    // circle is ill-conditioned when B and Ĉ are nearly opposite (its f32 error is ε over the
    // sine of the arc: 9e-5 for a straddling triangle). Where an arc exceeds 154° (cosine below
    // −0.9), relabel (keeping the winding) so that it is AC and B the vertex opposite it, which
    // keeps B away from every Ĉ. The arcs of a triangle sum to less than 2π, so at most one
    // arc is that long, and the choice is the same in every width but within an ulp of −0.9.
    let long = |p: V3<L>, q: V3<L>| p.dot(q).lt(L::c(-0.9));
    let ab_longest = long(ua, ub);
    let bc_longest = long(ub, uc) & !ab_longest;
    // Only the spherical quantities are relabelled; the plane, Ω and area sampling keep the
    // order given. Only where some lane has a long arc: the branch follows the triangle, not
    // the sample.
    let ((pa, pb, pc), (ua, ub, uc), (pla, plb, plc)) = if (ab_longest | bc_longest).any() {
        let rot =
            |x: V3<L>, y: V3<L>, z: V3<L>| V3::select(ab_longest, y, V3::select(bc_longest, z, x));
        let rotl = |x: L, y: L, z: L| L::select(ab_longest, y, L::select(bc_longest, z, x));
        (
            (rot(pa, pb, pc), rot(pb, pc, pa), rot(pc, pa, pb)),
            (rot(ua, ub, uc), rot(ub, uc, ua), rot(uc, ua, ub)),
            (
                rotl(pla, plb, plc),
                rotl(plb, plc, pla),
                rotl(plc, pla, plb),
            ),
        )
    } else {
        ((pa, pb, pc), (ua, ub, uc), (pla, plb, plc))
    };
    let e1 = b - a;
    let e2 = c - a;
    // The plane, its offset and the solid angle in f64: in f32 they lose what the tilt loses
    // (4e-3 of Ω at 1e-5 rad from edge-on) and what nearly opposite vertices lose (2e-5).
    let ([nx, ny, nz], h, triple, den) =
        triangle_terms([a.x, a.y, a.z], [b.x, b.y, b.z], [c.x, c.y, c.z]);
    let n = V3::new(nx, ny, nz);
    let omega = L::TWO * triple.abs().atan2(den);

    // The edge planes through the origin, from f64 normals: an f32 cross product of nearly
    // parallel or nearly opposite vectors keeps few digits of its direction.
    let (nab, nbc, nca) = (wide_cross(pa, pb), wide_cross(pb, pc), wide_cross(pc, pa));
    let (lab, lbc, lca) = (nab.length(), nbc.length(), nca.length());
    let (mab, mbc, mca) = (
        nab.scale(L::ONE / lab),
        nbc.scale(L::ONE / lbc),
        nca.scale(L::ONE / lca),
    );
    // The frames of Arvo's map (see `arvo`), every term from the f64 normals and the VOS
    // numerator rather than from differences of f32 unit vectors, which lose ε over the arc:
    // sin c from |P × B|, 1 − cos c from it (`versine`), sin φ as det(Â, B̂, Ĉ) / (sin c sin AC),
    // cos φ as the dot product of the normals of the two arcs at P.
    let height = triple.abs() / (lca / (pla * plc));
    let frame = |cos_pb: L, sin_pb: L, cos_phi: L| {
        let vers = versine(sin_pb, cos_pb);
        (height * (vers / sin_pb), vers * cos_phi)
    };
    let (t_a, t_c) = (ua.cross(mca), mca.cross(uc));
    let (sin_ab, sin_cb) = (lab / (pla * plb), lbc / (plb * plc));
    let (vs_a, vc_a) = frame(ub.dot(ua), sin_ab, -mab.dot(mca));
    let (vs_c, vc_c) = frame(ub.dot(uc), sin_cb, -mbc.dot(mca));

    // Collinear vertices can leave a rounding-sized normal, and a shading point in the plane a
    // rounding-sized triple product (with FMA, say), while VOS still reports up to 2π. Neither is
    // a light: the triangle's height over its longest edge, and the distance to the plane over
    // the distance to the nearest vertex, must both exceed 1e-6. The second compares h with its
    // rounding, which `triangle_terms` keeps to ε|v|·|n| with v that nearest vertex. Both are
    // measured without a favoured vertex, so that the verdict does not depend on the vertices'
    // order (measured from A, a point just below a vertex of a huge triangle was a light in one
    // order and edge-on in another, and a sliver collinear in one and not in another: found by
    // the `spherical` fuzz target).
    let nn = n.length();
    // The root of the least square: the least root, bit for bit (the root is monotonic).
    let near = a.dot(a).min(b.dot(b)).min(c.dot(c)).sqrt();
    let e3 = c - b;
    let longest = e1.dot(e1).max(e2.dot(e2)).max(e3.dot(e3));
    let valid = nn.gt(L::c(1e-6) * longest)
        & (h / near).abs().gt(L::c(1e-6) * nn)
        & omega.gt(L::ZERO)
        & omega.is_finite()
        & n.dot(n).is_finite()
        & pla.gt(L::ZERO)
        & plb.gt(L::ZERO)
        & plc.gt(L::ZERO);
    let by_area = omega.lt(L::c(SPHERICAL_TRIANGLE_MIN_SR as f64))
        | omega.gt(L::c(SPHERICAL_TRIANGLE_MAX_SR as f64));
    Setup {
        a,
        b,
        c,
        // The edge planes a × b, b × c, c × a (rotating the labels keeps the winding).
        edges: EdgePlanes::new([mab, mbc, mca], h, omega),
        h,
        ua,
        ub,
        uc,
        n,
        unscale: L::ONE / scale,
        omega,
        t_a,
        t_c,
        sin_ab,
        sin_cb,
        vs_a,
        vc_a,
        vs_c,
        vc_c,
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

/// Arvo's map: u₀ picks the point Ĉ of the arc AC for which the sub-triangle A B Ĉ has area
/// E = u₀Ω, u₁ the point along the arc B Ĉ.
///
/// Ĉ in closed form, after Peters (2021, §5), who finds it by a reflection: in an orthonormal
/// frame (P, T̂, N̂) at an end P of the arc, with T̂ its tangent towards the other end, Van
/// Oosterom–Strackee's tan(E/2) for the triangle P B Ĉ is linear in the bisector H = P + Ĉ, so
/// H's angle from P solves tan = y/x with x = (1 − cos c) sin(φ − E/2) and y = sin c sin(E/2),
/// c the arc PB and φ the angle at P; Ĉ is at twice that angle, (x² − y², 2xy) / (x² + y²) in
/// (P, T̂). x is expanded as (1 − cos c)(sin φ cos(E/2) − cos φ sin(E/2)), and φ − E/2 stays at
/// least φ/2 for E ≤ Ω/2 (every angle exceeds half the excess), so the difference loses at most a
/// bit or two: P is A with E = u₀Ω for u₀ ≤ ½, and C with the area (1 − u₀)Ω of C B Ĉ above. No
/// arc or angle is formed, so nothing cancels near 0 or π.
#[inline(always)]
fn arvo<L: Math>(s: &Setup<L>, u: V2<L>) -> V3<L> {
    let from_a = u.x.le(L::HALF);
    let e = L::select(from_a, u.x, L::ONE - u.x) * (s.omega * L::HALF);
    let (sin_e, cos_e) = e.sin_cos();
    let x = L::select(from_a, s.vs_a, s.vs_c) * cos_e - L::select(from_a, s.vc_a, s.vc_c) * sin_e;
    let y = L::select(from_a, s.sin_ab, s.sin_cb) * sin_e;
    let r = L::ONE / x.mul_add(x, y * y);
    let (cos_pc, sin_pc) = ((x - y) * (x + y) * r, L::TWO * x * y * r);
    let c_hat = V3::select(from_a, s.ua, s.uc).scale(cos_pc)
        + V3::select(from_a, s.t_a, s.t_c).scale(sin_pc);
    // 1 − Ĉ·B as |Ĉ − B|²/2, so that z keeps its precision when Ĉ is close to B, and 1 + z as
    // (1 − u₁)(1 − Ĉ·B) + |Ĉ + B|²/2, a sum of non-negative terms, so that sin z = √((1−z)(1+z))
    // keeps it when Ĉ is nearly opposite B (2 − (1 − z) would cancel there: 5e-6 of direction
    // for a 5 sr triangle at u = (1, 1)).
    let (dm, dp) = (c_hat - s.ub, c_hat + s.ub);
    let full = L::HALF * dm.dot(dm);
    let one_minus_z = u.y * full;
    let one_plus_z = (L::ONE - u.y).mul_add(full, L::HALF * dp.dot(dp));
    let z = L::ONE - one_minus_z;
    let sin_z = (one_minus_z * one_plus_z).max(L::ZERO).sqrt();
    // Each step is accurate to a few ulp, but their rounding leaves |w| off 1 by up to 1e-5 for
    // wide triangles: renormalise, which also pulls the point back onto the sphere's triangle.
    (s.ub.scale(z) + ortho(c_hat, s.ub).scale(sin_z)).normalize()
}

/// The point of the plane hit by unit direction `w`, as barycentrics (b₀, b₁, b₂), and whether
/// the hit lies in front of the origin. The distance h / (w·n) takes both terms from the f64
/// forms: in f32, w·n cancels for a triangle seen nearly edge-on, and a·n for a far plane, and
/// the inverse was NaN for a light of 2.6e-10 sr (found by the `spherical` fuzz target).
#[inline(always)]
fn barycentrics<L: Math>(w: V3<L>, s: &Setup<L>) -> (V3<L>, L::Mask) {
    let (a, b, c, n) = (s.a, s.b, s.c, s.n);
    let wn = plane_dot(
        [w.x, w.y, w.z],
        [a.x, a.y, a.z],
        [b.x, b.y, b.z],
        [c.x, c.y, c.z],
    );
    let t = s.h / wn;
    let d = w.scale(t) - a;
    let nn = n.dot(n);
    let b1 = d.cross(c - a).dot(n) / nn;
    let b2 = (b - a).cross(d).dot(n) / nn;
    (V3::new(L::ONE - b1 - b2, b1, b2), t.gt(L::ZERO))
}

/// Barycentrics (of A, B, C) of the planar limit of Arvo's map, uniform by area: u₀ places C′ on
/// the edge from A to C by area (linearly, in a plane), u₁ the point on the segment from B to C′
/// (at √u₁ of it). It has Arvo's corners, so that the area fallback maps u to nearly the same
/// direction as the spherical map would (their difference is of the order of Ω), and the
/// bilinear warp's corner weights and a fan's shared diagonals stay where the spherical map
/// puts them.
#[inline(always)]
fn planar_arvo<L: Math>(u: V2<L>) -> V3<L> {
    let t = u.y.sqrt();
    V3::new(t * (L::ONE - u.x), L::ONE - t, t * u.x)
}

/// The inverse of [`planar_arvo`]: u₀ = b_C / (b_A + b_C), u₁ = (b_A + b_C)², and u₀ = 0 at B
/// itself, where every u₀ maps.
#[inline(always)]
fn planar_arvo_inverse<L: Math>(b: V3<L>) -> V2<L> {
    let t = b.x + b.z;
    let u0 = L::select(t.gt(L::ZERO), b.z / t, L::ZERO);
    V2::new(u0, t * t)
}

/// Arvo's map alone, with no area fallback and no validity checks: for measuring where spherical
/// sampling breaks down (the report's stability table). Use [`spherical_triangle`] to sample.
#[inline]
pub fn arvo_triangle<P: Point2>(u: P, a: P::Vec3, b: P::Vec3, c: P::Vec3) -> P::Vec3 {
    let s = setup(a.to_lanes(), b.to_lanes(), c.to_lanes());
    Point3::from_lanes(arvo(&s, clamp_u(u.to_lanes())))
}

/// A triangle set up for sampling at one shading point: [`spherical_triangle`],
/// [`spherical_triangle_pdf`] and [`spherical_triangle_inverse`] with the set-up (solid angle,
/// arcs, edge planes) paid once, for a caller that takes several samples or evaluates several
/// pdfs at one point. The free functions are this type, built and used once.
///
/// `P` is the width: `SphericalTriangle<Vec3>`, `SphericalTriangle<Vec3x8>` (eight triangles,
/// lane by lane) or `SphericalTriangle<DVec3>`.
///
/// Ω, and whether the triangle is degenerate, do not depend on the order or winding of the
/// vertices (within the accuracy above) while their distances from the shading point are
/// within a factor 2²⁶ of each other. Beyond that the set-up's f64 differences of vertices are
/// rounded, and for a shading point within that rounding of an edge Ω may depend on the order.
///
/// ```
/// use glam::{Vec2, Vec3};
/// use mcsample::warp::SphericalTriangle;
///
/// let tri = SphericalTriangle::new(Vec3::new(-1.0, -1.0, 2.0), Vec3::new(1.0, -1.0, 2.0), Vec3::Z);
/// let (w, pdf) = tri.sample(Vec2::new(0.3, 0.8));
/// assert!(pdf > 0.0 && tri.pdf(w) == pdf);
/// assert!((1.0 / pdf - tri.solid_angle()).abs() < 1e-6);
/// ```
#[derive(Clone, Copy)]
pub struct SphericalTriangle<P: Point3> {
    s: Setup<P::Lane>,
    width: PhantomData<P>,
}

impl<P: Point3<Lane = L>, L: Math> SphericalTriangle<P> {
    /// The triangle with vertices `a`, `b`, `c` relative to the shading point, in either winding.
    // Always inlined: a caller that samples once (the free functions, a light per shading point)
    // then computes only the set-up its sample, pdf or inverse reads, and keeps it in registers
    // rather than returning the whole set-up through memory. The sample stays a call: inlined
    // too, the scalar free function measured 5 % slower. On bare
    // metal, where flash is what counts, the set-up stays one copy: inlined into each free
    // function it added 44 KB to a Cortex-M4F firmware that links them all.
    #[cfg_attr(target_os = "none", inline)]
    #[cfg_attr(not(target_os = "none"), inline(always))]
    pub fn new(a: P, b: P, c: P) -> Self {
        Self {
            // In halves at sixteen lanes without AVX-512 (`point::Split`).
            s: by_halves(
                (a.to_lanes(), b.to_lanes(), c.to_lanes()),
                #[inline(always)]
                |(a, b, c)| setup(a, b, c),
            ),
            width: PhantomData,
        }
    }

    /// The solid angle Ω (Van Oosterom–Strackee, the plane offset in f64), or 0 where the
    /// triangle is degenerate.
    #[inline]
    pub fn solid_angle(&self) -> L {
        L::select(self.s.valid, self.s.omega, L::ZERO)
    }

    /// True (lane by lane) where the triangle is sampled by area rather than spherically.
    #[inline]
    pub fn by_area(&self) -> L::Mask {
        self.s.by_area
    }

    /// The same triangle sampled by area in every lane, with the area pdf converted to solid
    /// angle: what renderers do without a spherical sampler (the scene's
    /// [`LightSampling::Area`](crate::scene::LightSampling::Area)).
    #[inline]
    pub fn by_area_only(self) -> Self {
        self.by_area_where(L::ZERO.le(L::ZERO))
    }

    /// The same triangle, sampled by area also where `m` (lane by lane).
    #[inline]
    pub(crate) fn by_area_where(self, m: L::Mask) -> Self {
        Self {
            s: Setup {
                by_area: self.s.by_area | m,
                ..self.s
            },
            width: PhantomData,
        }
    }

    /// The plane as (h, n): n a positive multiple of (b − a) × (c − a), and h its offset,
    /// scaled so that the distance along unit direction w to the plane is h / (w·n) and h has
    /// the sign of v·n for any vertex v.
    #[inline]
    pub fn plane(&self) -> (L, P) {
        (self.s.h * self.s.unscale, P::from_lanes(self.s.n))
    }

    /// The unit directions where the square's corners (0, 0), (1, 0), (0, 1), (1, 1) land under
    /// Arvo's map: B, B, A, C as relabelled (see `setup`). Not where the triangle is sampled by
    /// area, whose map places them otherwise.
    #[inline(always)]
    pub(crate) fn square_corners(&self) -> [V3<L>; 4] {
        let s = &self.s;
        [s.ub, s.ub, s.ua, s.uc]
    }

    /// See [`spherical_triangle`].
    #[inline]
    pub fn sample(&self, u: P::Vec2) -> (P, L) {
        let s = &self.s;
        let u = clamp_u(u.to_lanes());
        // Each path only where some lane takes it: the choice is the triangle's, so the branch
        // is predictable, and a spherically sampled triangle pays nothing for the fallback.
        let zero = V3::all(L::ZERO);
        let w_sph = if (!s.by_area).any() { arvo(s, u) } else { zero };
        let w_area = if s.by_area.any() {
            let bary = planar_arvo(u);
            let p = s.a.scale(bary.x) + s.b.scale(bary.y) + s.c.scale(bary.z);
            // Normalised at its own scale: a point near a vertex 2⁻⁷⁰ as far as the others has
            // squares below f32's normal range, and its direction came out 4e-5 short of unit.
            let amax = p.x.abs().max(p.y.abs()).max(p.z.abs());
            p.scale(pow2_scale(amax)).normalize()
        } else {
            zero
        };
        let w = V3::select(s.by_area, w_area, w_sph);
        // The pdf function's, inside test included, so that the two agree by construction: an
        // area sample of a triangle whose vertices are 10²⁶ apart in distance can round outside
        // its edge planes, and so can a spherical sample on an arc between nearly antipodal
        // vertices, whose great circle f32 places only roughly (both found by the `spherical`
        // fuzz target, which checks pdf(w) against this bit for bit).
        let inside = s.edges.contains(w);
        let pdf = self.pdf_lanes(w, inside & !w.any_nan());
        let w = V3::select(pdf.gt(L::ZERO), w, V3::new(L::ZERO, L::ZERO, L::ONE));
        (P::from_lanes(w), pdf)
    }

    /// See [`spherical_triangle_pdf`].
    #[inline]
    pub fn pdf(&self, w: P) -> L {
        let w = w.to_lanes();
        self.pdf_lanes(w, self.s.edges.contains(w))
    }

    /// 1/Ω, or the area pdf, where `inside` and the triangle is valid.
    #[inline(always)]
    fn pdf_lanes(&self, w: V3<L>, inside: L::Mask) -> L {
        let s = &self.s;
        let sph = L::ONE / s.omega;
        let area = if s.by_area.any() {
            triangle_area_pdf(w, s.h, [s.a, s.b, s.c])
        } else {
            L::ZERO
        };
        let pdf = L::select(s.by_area, area, sph);
        L::select(s.valid & inside, pdf, L::ZERO)
    }

    /// See [`spherical_triangle_inverse`].
    #[inline]
    pub fn inverse(&self, w: P) -> P::Vec2 {
        let s = &self.s;
        let w = w.to_lanes();
        let (bary, _) = barycentrics(w, s);
        let u_area = planar_arvo_inverse(bary);

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
        // w along B leaves Ĉ undefined; any u₀ with u₁ = 0 maps there. "Along" is where Ĉ could
        // not be normalised, not w = B: the map's own direction for B can differ from B/|B| by an
        // ulp, and in a sliver the planes through B, w and A, C can be parallel to f32's
        // precision; either way Ĉ was 0/0 (both found by the `spherical` fuzz target).
        let at_b = !c_hat.dot(c_hat).is_finite();
        let u_sph = V2::new(L::select(at_b, L::ZERO, u0), L::select(at_b, L::ZERO, u1));
        let u = clamp_u(V2::select(s.by_area, u_area, u_sph));
        Point2::from_lanes(u.nan_where(w.any_nan()))
    }
}

/// A direction towards triangle (a, b, c), vertices relative to the shading point in either
/// winding, and its pdf per steradian ([`spherical_triangle_pdf`] gives the same number, bit for
/// bit, at the returned direction). [`SphericalTriangle`] is the same with the set-up paid once.
///
/// Arvo's map (1995), uniform in solid angle with pdf 1/Ω, Ω by Van Oosterom–Strackee with the
/// plane offset in f64. Below [`SPHERICAL_TRIANGLE_MIN_SR`] or above
/// [`SPHERICAL_TRIANGLE_MAX_SR`] it samples by area instead, by the planar limit of Arvo's map
/// (u₀ sweeps from edge BA to edge BC, u₁ from B outwards, as on the sphere), and returns the
/// exact converted pdf.
///
/// u is clamped to [0, 1]². Degenerate triangles (coincident or collinear vertices, the shading
/// point closer to the triangle's plane than 1e-6 of its distance to the nearest vertex,
/// non-finite input) give pdf 0 and direction +z, and so does NaN in u.
#[inline]
pub fn spherical_triangle<P: Point2<Lane = L>, L: Math>(
    u: P,
    a: P::Vec3,
    b: P::Vec3,
    c: P::Vec3,
) -> (P::Vec3, L) {
    halved!(sample SphericalTriangle::new(a, b, c) at u)
}

/// pdf per steradian that [`spherical_triangle`] returns unit direction `w`: 1/Ω, or the
/// converted area pdf where it samples by area; 0 outside the triangle, for degenerate triangles
/// and for NaN. "Outside" is beyond a slack of 4.8e-7 + 7.6e-6·√Ω rad, which covers the f32
/// rounding of the map, so that every sample keeps its pdf.
#[inline]
pub fn spherical_triangle_pdf<P: Point3<Lane = L>, L: Math>(w: P, a: P, b: P, c: P) -> L {
    halved!(pdf SphericalTriangle::new(a, b, c) at w)
}

/// Inverse of [`spherical_triangle`]: the u that maps to unit direction `w`, clamped to [0, 1]².
///
/// Spherically: Ĉ is where the great circle through B and w meets the arc AC; u₁ is the fraction
/// of the arc B Ĉ covered, |w − B|²/|Ĉ − B|², and u₀ the area of A B Ĉ over Ω. By area: the
/// low-distortion triangle inverse of w's barycentrics. NaN gives NaN.
#[inline]
pub fn spherical_triangle_inverse<P: Point3<Lane = L>, L: Math>(w: P, a: P, b: P, c: P) -> P::Vec2 {
    halved!(inverse SphericalTriangle::new(a, b, c) at w)
}
