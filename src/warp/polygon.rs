//! What the spherical triangle and rectangle share: Van Oosterom–Strackee solid angles and the
//! area-to-solid-angle pdf of a planar light.

use crate::lane::{Mask, V3};
use crate::math::Math;

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

/// pdf per steradian of direction `w` (unit) when points are drawn uniformly by area on a planar
/// light with normal `n` (unnormalised) and offset `h` = p·n for any point p of it:
/// d²/(|cos θ_l|·area) = k·h²/|w·n|³ with k = |n|/area.
#[inline(always)]
pub(crate) fn area_pdf_solid_angle<L: Math>(w: V3<L>, h: L, n: V3<L>, k: L) -> L {
    // In f64 for the f32 lanes: a direction nearly in the light's plane makes w·n cancel.
    area_pdf_from_cos(L::dot_wide([w.x, w.y, w.z], [n.x, n.y, n.z]), h, k)
}

/// [`area_pdf_solid_angle`] from w·n, computed by the caller as accurately as it can: the pdf
/// goes with its cube.
///
/// A light seen edge-on (h = 0) or a direction parallel to it (w·n = 0) gives 0: the sample is
/// dropped rather than weighted by an infinite pdf.
#[inline(always)]
pub(crate) fn area_pdf_from_cos<L: Math>(wn: L, h: L, k: L) -> L {
    let c = wn.abs();
    let p = k * (h * h) / (c * c * c);
    let ok = h.abs().gt(L::ZERO) & c.gt(L::ZERO) & p.is_finite();
    L::select(ok, p, L::ZERO)
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
