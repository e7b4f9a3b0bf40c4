//! What the spherical triangle and rectangle, and the planar lights, share: Van
//! Oosterom–Strackee solid angles, the area-to-solid-angle pdf of a planar light, and the
//! geometric terms that cancel in f32, computed in the f64 lane of the same width.
//!
//! Each f64 term takes f32 inputs, whose products are exact in f64, runs a fixed sequence of
//! IEEE operations with no FMA, and rounds once to the lane: every lane of a packet performs the
//! same operations as the scalar form, so both f32 widths agree bit for bit, and the f64 instance
//! runs the same arithmetic as its reference.

use crate::lane::{Lane, Mask, V3, Widen};
use crate::math::Math;
use crate::point::{by_halves, split_fields};

/// The terms of Van Oosterom–Strackee's solid angle of triangle (a, b, c) seen from the origin,
/// computed in f64: `(n, h, t, d)` with
/// - n = (b − a) × (c − a), the plane's normal, unnormalised;
/// - h = a·n, the plane offset (six times the signed volume of the tetrahedron with the origin);
/// - t = h / (|a||b||c|) and d = 1 + â·b̂ + â·ĉ + b̂·ĉ, so that Ω = 2·atan2(|t|, d).
///
/// In f32, h carries an error of ε|a||b − a||c − a|, which relative to h is ε over the sine of
/// the tilt (4e-3 of Ω for a triangle seen 1e-5 rad from edge-on), and d cancels for a wide
/// triangle with nearly opposite vertices (2e-5 of Ω). In f64 each result is within an ulp or
/// two of its exact value for the given vertices.
#[inline(always)]
pub(crate) fn triangle_terms<L: Math>(a: [L; 3], b: [L; 3], c: [L; 3]) -> ([L; 3], L, L, L) {
    let w = |v: [L; 3]| v.map(L::widen);
    let (n, h, t, d) = triangle_terms_in(w(a), w(b), w(c));
    (n.map(L::narrow), L::narrow(h), L::narrow(t), L::narrow(d))
}

/// a × b in f64, rounded once to the lane: each component within about an ulp of the true one,
/// however nearly parallel a and b are (an f32 cross product of directions 1e-6 apart keeps only
/// one digit of its direction).
#[inline(always)]
pub(crate) fn cross_wide<L: Math>(a: [L; 3], b: [L; 3]) -> [L; 3] {
    cross_in(a.map(L::widen), b.map(L::widen)).map(L::narrow)
}

/// [`cross_wide`] on vectors.
#[inline(always)]
pub(crate) fn wide_cross<L: Math>(p: V3<L>, q: V3<L>) -> V3<L> {
    let [x, y, z] = cross_wide([p.x, p.y, p.z], [q.x, q.y, q.z]);
    V3::new(x, y, z)
}

/// a·b in f64, rounded once: accurate where the f32 dot product cancels (a direction nearly in a
/// light's plane against the plane's normal).
#[inline(always)]
pub(crate) fn dot_wide<L: Math>(a: [L; 3], b: [L; 3]) -> L {
    L::narrow(dot_in(a.map(L::widen), b.map(L::widen)))
}

/// w·((b − a) × (c − a)) in f64, rounded once: the cosine (times twice the area) between a
/// direction and the plane of triangle (a, b, c), accurate when w lies nearly in the plane, where
/// rounding the normal to f32 first would cost ε over that cosine.
#[inline(always)]
pub(crate) fn plane_dot<L: Math>(w: [L; 3], a: [L; 3], b: [L; 3], c: [L; 3]) -> L {
    // Sixteen lanes without AVX-512 as two calls of eight (`point::Split`): twelve f64 values
    // of sixteen lanes fill every register of the f64 arithmetic many times over, and spill.
    by_halves(
        (w, a, b, c),
        #[inline(always)]
        |(w, a, b, c)| {
            let x = |v: [L::Half; 3]| v.map(Widen::widen);
            let n = cross_in(sub_in(x(b), x(a)), sub_in(x(c), x(a)));
            Widen::narrow(dot_in(x(w), n))
        },
    )
}

#[inline(always)]
fn sub_in<T: Lane>(p: [T; 3], q: [T; 3]) -> [T; 3] {
    [p[0] - q[0], p[1] - q[1], p[2] - q[2]]
}

#[inline(always)]
fn dot_in<T: Lane>(p: [T; 3], q: [T; 3]) -> T {
    p[0] * q[0] + p[1] * q[1] + p[2] * q[2]
}

/// a × b, in a fixed order with no FMA.
#[inline(always)]
fn cross_in<T: Lane>(a: [T; 3], b: [T; 3]) -> [T; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// [`triangle_terms`] in one arithmetic.
#[inline(always)]
fn triangle_terms_in<T: Lane>(a: [T; 3], b: [T; 3], c: [T; 3]) -> ([T; 3], T, T, T) {
    // n and h = v·n from the vertex v nearest the shading point, as the base of both edges:
    // rounding n costs h |v|·err(n), and err(n) grows with the edges' lengths, so from a vertex
    // far beyond the others h would lose up to 1.2e-5 of itself even in f64 for a light seen
    // nearly edge-on, and Ω would depend on the vertices' order. A cyclic relabelling keeps n's
    // orientation.
    let (qa, qb, qc) = (dot_in(a, a), dot_in(b, b), dot_in(c, c));
    let select_lt = |a: T, b: T, x: T, y: T| T::select(a.lt(b), x, y);
    let pick = |m: (T, T), p: [T; 3], q: [T; 3]| {
        let s = |x: T, y: T| select_lt(m.0, m.1, x, y);
        [s(p[0], q[0]), s(p[1], q[1]), s(p[2], q[2])]
    };
    // (a, b, c), or (b, c, a) where b is nearer than a, then (c, a, b) where c is nearer still.
    let b_nearer = (qb, qa);
    let (v0, v1, v2) = (
        pick(b_nearer, b, a),
        pick(b_nearer, c, b),
        pick(b_nearer, a, c),
    );
    let c_nearest = (qc, select_lt(qb, qa, qb, qa));
    let (v0, v1, v2) = (
        pick(c_nearest, c, v0),
        pick(c_nearest, a, v1),
        pick(c_nearest, b, v2),
    );
    let n = cross_in(sub_in(v1, v0), sub_in(v2, v0));
    let h = dot_in(v0, n);
    let (la, lb, lc) = (qa.sqrt(), qb.sqrt(), qc.sqrt());
    let d = la * lb * lc + dot_in(a, b) * lc + dot_in(a, c) * lb + dot_in(b, c) * la;
    let s = la * lb * lc;
    (n, h, h / s, d / s)
}

/// Solid angle of the triangle with vertices `a`, `b`, `c` seen from the origin, by
/// Van Oosterom–Strackee: tan(Ω/2) = |a·(b×c)| / (|a||b||c| + (a·b)|c| + (a·c)|b| + (b·c)|a|).
///
/// The caller supplies the triple product, computed from edge vectors where it can
/// (a·((b−a)×(c−a)) keeps its relative precision for a tiny, distant triangle where a·(b×c)
/// cancels), and the three lengths. Result in [0, 2π].
#[inline(always)]
pub(crate) fn vos_solid_angle<L: Math>(
    triple: L,
    a: V3<L>,
    b: V3<L>,
    c: V3<L>,
    la: L,
    lb: L,
    lc: L,
) -> L {
    let den = (la * lb).mul_add(
        lc,
        a.dot(b).mul_add(lc, a.dot(c).mul_add(lb, b.dot(c) * la)),
    );
    L::TWO * triple.abs().atan2(den)
}

/// pdf per steradian of direction `w` (of any nonzero length) when points are drawn uniformly
/// by area on the parallelogram `corner + s·ex + t·ey`: see [`area_pdf_in`].
#[inline(always)]
pub(crate) fn parallelogram_area_pdf<L: Math>(w: V3<L>, corner: V3<L>, ex: V3<L>, ey: V3<L>) -> L {
    // In halves, as `plane_dot`.
    by_halves(
        (w, corner, ex, ey),
        #[inline(always)]
        |(w, corner, ex, ey)| {
            let x = |v: V3<L::Half>| [v.x, v.y, v.z].map(Widen::widen);
            let n = cross_in(x(ex), x(ey));
            area_pdf_in(x(w), dot_in(x(corner), n), n, L::Half::ONE)
        },
    )
}

/// pdf per steradian of direction `w` (of any nonzero length) when points are drawn uniformly
/// by area on the triangle (a, b, c) with plane offset `h` from [`triangle_terms`] (formed from
/// the vertex nearest the shading point, where a·n from a far vertex can cancel to nothing): see
/// [`area_pdf_in`].
#[inline(always)]
pub(crate) fn triangle_area_pdf<L: Math>(w: V3<L>, h: L, v: [V3<L>; 3]) -> L {
    // In halves, as `plane_dot`.
    by_halves(
        (w, h, v),
        #[inline(always)]
        |(w, h, [a, b, c])| {
            let x = |v: V3<L::Half>| [v.x, v.y, v.z].map(Widen::widen);
            let n = cross_in(sub_in(x(b), x(a)), sub_in(x(c), x(a)));
            area_pdf_in(x(w), h.widen(), n, L::Half::TWO)
        },
    )
}

/// The area pdf in solid angle of direction `w` for a planar light with normal n (unnormalised),
/// offset H = p·n for its points p and area |n|/k: t²/(|cos θ_l|·area) = k·H²·|w|³/|w·n|³.
///
/// Everything in the f64 lane, from f32 inputs, and rounded once, so the pdf is within half an
/// ulp of the exact density of the direction as given, at grazing angles too (1.5 ulp where H
/// comes rounded to f32). Normalising `w` or
/// rounding n to f32 first puts an error of ε on w·n, which is ε/c of a cosine c: 3ε/c on the
/// pdf, 1e-4 at c = 2e-3. A light seen edge-on (H = 0), a direction parallel to it (w·n = 0) and
/// a pdf beyond the lane's range give 0: the sample is dropped rather than weighted by an
/// infinite pdf.
#[inline(always)]
fn area_pdf_in<L: Math>(w: [L::Wide; 3], h: L::Wide, n: [L::Wide; 3], k: L) -> L {
    let (wn, len) = (dot_in(w, n), dot_in(w, w).sqrt());
    // (H|w|/w·n)² · |w|/|w·n|: the distance along w, squared, over the cosine.
    let t = h * len / wn;
    let p = k * L::narrow(t * t * len / wn.abs());
    let zero = <L::Wide as Lane>::ZERO;
    let ok = L::narrow_mask(h.abs().gt(zero) & wn.abs().gt(zero));
    L::select(ok & p.is_finite(), p, L::ZERO)
}

/// How far outside a polygon's silhouette, in radians, a direction still counts as inside:
/// (4 + 64√Ω)·ε, with ε the lane's epsilon: 4.8e-7 + 7.6e-6·√Ω in f32.
///
/// A sample built on an edge (u on the boundary of the square) lands a few ulp on either side of
/// the edge's plane, and the spherical maps' own f32 error, at most 6.6e-6 for the widest
/// triangles (measured against their f64 instances), can carry it further, in proportion to the
/// light's angular size; without the slack the pdf function would call a returned sample "off
/// the light" and give it 0 (1 sample in 400 for wide random triangles, measured).
#[inline(always)]
pub(crate) fn inside_slack<L: Math>(omega: L) -> L {
    L::EPSILON * L::c(64.0).mul_add(omega.max(L::ZERO).sqrt(), L::c(4.0))
}

/// The planes through the origin and the edges of a convex polygon, as unit normals pointing
/// inwards: the inside test of the pdf functions, set up once per polygon.
#[derive(Clone, Copy)]
pub(crate) struct EdgePlanes<L: Math, const N: usize> {
    m: [V3<L>; N],
    /// −[`inside_slack`].
    slack: L,
}

split_fields!(EdgePlanes<L: Math, const N> by L { m, slack });

impl<L: Math, const N: usize> EdgePlanes<L, N> {
    /// The planes through the origin and the polygon's edges, from their unit normals along
    /// pᵢ × pᵢ₊₁ (formed by the caller as accurately as it can: in f64 for the f32 lanes, so that
    /// the plane of a short or distant edge keeps its direction to an ulp). `winding` has the
    /// sign of p₀·((p₁ − p₀) × (p₂ − p₀)), so either winding works. A zero normal (a degenerate
    /// edge) gives a NaN plane, which contains nothing.
    #[inline(always)]
    pub(crate) fn new(units: [V3<L>; N], winding: L, omega: L) -> Self {
        let sign = L::ONE.copysign(winding);
        Self {
            m: units.map(|m| m.scale(sign)),
            slack: -inside_slack(omega),
        }
    }

    /// The same planes with `extra` radians more slack: for a sampler whose samples pass
    /// through more rounding than the spherical maps' (a rotation to a local frame and back).
    #[inline(always)]
    pub(crate) fn widened(self, extra: L) -> Self {
        Self {
            m: self.m,
            slack: self.slack - extra,
        }
    }

    /// True where unit direction `w` lies inside the polygon, or within [`inside_slack`] of it.
    /// Unlike intersecting w with the polygon's plane, this stays well-conditioned when the
    /// polygon is seen at a grazing angle. NaN gives false.
    #[inline(always)]
    pub(crate) fn contains(&self, w: V3<L>) -> L::Mask {
        let slack = self.slack;
        let mut inside = L::ZERO.le(L::ZERO);
        for m in &self.m {
            inside = inside & w.dot(*m).ge(slack);
        }
        inside
    }
}

/// True where [`pow2_scale`] is not 1: m outside [2⁻¹⁶, 2¹⁶] (NaN is not).
#[inline(always)]
pub(crate) fn needs_pow2_scale<L: Math>(m: L) -> L::Mask {
    m.gt(L::c(65536.0)) | m.lt(L::c(1.52587890625e-5))
}

/// A power of two that brings a magnitude m into [2⁻¹⁶, 2¹⁶] (for m from 2⁻¹¹² to 2¹¹²; 1 for
/// NaN): multiplying by it is exact, so a problem that depends only on ratios (directions, solid
/// angles) is solved bit for bit as it would be at m's own scale, but with squares and cubes far
/// from overflow and underflow.
#[inline(always)]
pub(crate) fn pow2_scale<L: Math>(m: L) -> L {
    // Geometry at a renderer's scale needs no scaling: skip the ladder where no lane does (a
    // branch that follows the scene, not the sample).
    if !needs_pow2_scale(m).any() {
        return L::ONE;
    }
    let mut scale = L::ONE;
    let mut m = m;
    // 2^±64, 2^±32, 2^±16 (core has no powi without std).
    for (big, small) in [
        (1.8446744073709552e19, 5.421010862427522e-20),
        (4294967296.0, 2.3283064365386963e-10),
        (65536.0, 1.52587890625e-5),
    ] {
        let (big, small) = (L::c(big), L::c(small));
        let down = m.gt(big);
        let up = m.lt(small);
        let k = L::select(down, small, L::select(up, big, L::ONE));
        scale = scale * k;
        m = m * k;
    }
    scale
}

/// A vector in the f64 lane of the same width, exactly.
#[inline(always)]
pub(crate) fn widen3<L: Math>(p: V3<L>) -> V3<L::Wide> {
    V3::new(p.x.widen(), p.y.widen(), p.z.widen())
}

/// A vector rounded to the lane.
#[inline(always)]
pub(crate) fn narrow3<L: Math>(p: V3<L::Wide>) -> V3<L> {
    V3::new(L::narrow(p.x), L::narrow(p.y), L::narrow(p.z))
}

/// p/|p| in f64 with plain operations.
#[inline(always)]
pub(crate) fn unit_wide<T: Lane>(p: V3<T>) -> V3<T> {
    p.scale(T::ONE / dot3_in(p, p).sqrt())
}

/// a·b with plain products (no fused multiply-add, which the f64 lanes do not share).
#[inline(always)]
pub(crate) fn dot3_in<T: Lane>(a: V3<T>, b: V3<T>) -> T {
    a.x * b.x + a.y * b.y + a.z * b.z
}

/// a × b with plain products.
#[inline(always)]
pub(crate) fn cross3_in<T: Lane>(a: V3<T>, b: V3<T>) -> V3<T> {
    V3::new(
        a.y * b.z - a.z * b.y,
        a.z * b.x - a.x * b.z,
        a.x * b.y - a.y * b.x,
    )
}
