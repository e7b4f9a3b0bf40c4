//! What the spherical triangle and rectangle share: Van Oosterom–Strackee solid angles and the
//! area-to-solid-angle pdf of a planar light.

use crate::lane::V3;
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
/// light with normal `n` (unnormalised, |n| = area·`area_per_n`) and offset `h` = p·n for any
/// point p of it: d²/(|cos θ_l|·area) = h²/|w·n|³ · (1/area_per_n)… written as k·h²/|w·n|³.
///
/// A light seen edge-on (h = 0) or a direction parallel to it (w·n = 0) gives 0: the sample is
/// dropped rather than weighted by an infinite pdf.
#[inline(always)]
pub(crate) fn area_pdf_solid_angle<L: Math>(w: V3<L>, h: L, n: V3<L>, k: L) -> L {
    let c = w.dot(n).abs();
    let p = k * (h * h) / (c * c * c);
    let ok = h.abs().gt(L::ZERO) & c.gt(L::ZERO) & p.is_finite();
    L::select(ok, p, L::ZERO)
}

/// True where direction `w` lies inside the convex polygon with vertices `p` and edges
/// `e` (eᵢ = pᵢ₊₁ − pᵢ, given exactly where the caller has them) seen from the origin: on the
/// inner side of every edge's plane through the origin.
///
/// Each plane normal is pᵢ × eᵢ, from the edge vector, so it keeps its precision for a small or
/// distant polygon. Unlike intersecting w with the polygon's plane, this stays
/// well-conditioned when the polygon is seen at a grazing angle. `winding` (any value with the
/// sign of p₀·((p₁ − p₀) × (p₂ − p₀))) makes either winding work.
#[inline(always)]
pub(crate) fn inside_polygon<L: Math, const N: usize>(
    w: V3<L>,
    p: [V3<L>; N],
    e: [V3<L>; N],
    winding: L,
) -> L::Mask {
    let sign = L::ONE.copysign(winding);
    let side = |i: usize| (w.dot(p[i].cross(e[i])) * sign).ge(L::ZERO);
    let mut inside = side(0);
    let mut i = 1;
    while i < N {
        inside = inside & side(i);
        i += 1;
    }
    inside
}
