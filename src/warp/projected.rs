//! Polygons sampled by projected solid angle (Peters, "BRDF Importance Sampling for Polygonal
//! Lights", ACM TOG 40(4), 2021): directions towards a triangle or parallelogram distributed as
//! the receiver's cosine n·ω over the light, exactly, with pdf n·ω / P per steradian.
//!
//! In the shading frame (+z along n) the polygon is clipped to the upper hemisphere and projected
//! orthographically onto the unit disk, where projected solid angle is area (Nusselt). Each edge
//! becomes an arc of a centred ellipse; the arc from a to b of a great circle with unit normal m̂
//! sweeps the signed area ½·θ·m̂_z from the centre (θ its length), so that P = ½ Σ θᵢ·m̂ᵢ_z, which
//! is Lambert's formula for the irradiance of the polygon at radiance 1. With the edges' normals
//! pointing into the polygon, edges with m̂_z > 0 are "outer" (far from the centre), and those
//! with m̂_z < 0 "inner" (towards it).
//!
//! - **Central case** (the normal inside the polygon): every edge is outer, and the region is a
//!   fan of ellipse sectors, each the linear image of a circular sector. u₁·P picks the sector and
//!   the angle along its arc in closed form (area is linear in the arc's angle), and u₀ the
//!   squared radius: exact, with no solve.
//! - **Decentral case**: each azimuth between the polygon's two extreme directions meets one
//!   inner and one outer edge. The azimuth comes from the area F(d) swept up to direction d,
//!   F(d) = u₁·P. The set-up tabulates F (in f64) at the vertices; a sample picks the sector
//!   between two vertices adjacent in azimuth, where one outer and one inner arc bound the
//!   region, seeds a quadratic, and takes bracketed Newton steps on those two arcs' f32 sweeps
//!   (F′ = ½(r_o² − r_i²) per radian), then steps on F summed in f64, where the sweeps do not
//!   cancel, to √ε of the distance to the nearer tip; the squared radius is uniform between the
//!   two ellipses.
//!
//! Lifting the disk's point p to ω = (p, √(1 − |p|²)) gives the density n·ω / P per steradian.
//! P, a sum of terms of both signs in the decentral case, cancels for small or distant lights;
//! below [`PROJECTED_MIN_SR`] the light is sampled by solid angle instead (the spherical
//! samplers, with their own area fallback), and the pdf is theirs.

use core::fmt;

use glam::Vec3;

use crate::frame::Frame;
use crate::lane::{Lane, Lanes, Mask, V2, V3, Widen, zip_map};
use crate::math::Math;
use crate::point::{Point2, Point3, halved};
use crate::warp::common::{clamp_u, pick};
use crate::warp::family::{is_unit, lanes3};
use crate::warp::polygon::{EdgePlanes, cross3_in, dot3_in, narrow3, unit_wide, widen3};
use crate::warp::{Family, SphericalRectangle, SphericalTriangle};

/// The projected solid angle (irradiance at radiance 1, in units of sr) below which a polygon is
/// sampled by solid angle rather than by projected solid angle.
pub const PROJECTED_MIN_SR: f32 = 1e-4;

/// The largest ratio Σ|Sᵢ| / P of the sectors' areas Sᵢ = ½·θᵢ·m̂ᵢ_z to their sum P (1 in the
/// central case; in the decentral one about the light's distance from the normal over its
/// size, and more for a light seen at a grazing angle or straddling the horizon) for which a
/// polygon is sampled by projected solid angle. The azimuth solve runs on f32 sectors, which
/// cancel by this ratio, and ends with Newton steps on the sectors in f64; up to 1024 the solve
/// is measured to land within about an ulp of the output (99 % of samples within 1.1 ulp, the
/// worst 2.6e-5 in u₁, over 5 samples each of 2·10⁴ random triangles and as many
/// parallelograms).
/// Beyond, the light is sampled by solid angle: it is small or thin as seen from the receiver,
/// so the cosine varies little over it.
pub const PROJECTED_MAX_SPREAD: f32 = 1024.0;

/// The most Newton (or bisection) steps of the decentral case's azimuth solve on the f32
/// sweeps; it stops after a step below [`SOLVE_TOLERANCE`] of the sector, as a rule after one.
const SOLVE_STEPS: usize = 12;

/// The f32 steps stop after a step below this fraction of the sector (or of the distance to
/// the nearer tip of the region, where that is less). Newton's error is then about its square,
/// below the √ε (3.5e-4) at which one step on F in f64 finishes the solve: further f32 steps
/// would only repeat what that step does anyway.
const SOLVE_TOLERANCE: f64 = 1e-2;

/// The most Newton (or bisection) steps of the decentral solve on F summed in f64, which
/// starts where the f32 steps end.
const WIDE_STEPS: usize = 6;

/// One edge of the clipped polygon in the shading frame.
#[derive(Clone, Copy, Default)]
struct Edge<L> {
    /// Unit start and end.
    a: V3<L>,
    b: V3<L>,
    /// Their azimuths as unit 2D vectors, formed alike, so that an edge's end and the next
    /// edge's start, and the extreme azimuths, are the same bits: the azimuth tests against
    /// them are then exact (a cross product of equal vectors is 0).
    da: V2<L>,
    db: V2<L>,
    /// Unit normal of the edge's great circle, pointing into the polygon; 0 for a degenerate edge.
    m: V3<L>,
    /// ½·θ·m̂_z: the signed area the arc sweeps from the disk's centre.
    area: L,
    /// θ, the arc's length.
    theta: L,
}

/// The set-up of the projected-solid-angle map of a convex polygon of `N` vertices, clipped to
/// 2N slots (vertices repeated where clipping removed some: a repeated vertex makes an edge of
/// length 0, which sweeps nothing) of the `K` ≥ 2N it holds.
#[derive(Clone, Copy)]
struct Projected<L: Math, const N: usize, const K: usize> {
    frame: Frame<V3<L>>,
    /// The receiver's normal as given: the pdf's cosine is the caller's n·ω/|n|, to the
    /// rounding of the result, so that a renderer's own cosine over this pdf gives P.
    normal: V3<L>,
    e: [Edge<L>; K],
    /// How many of `e` (and `wide`) are edges: 2N, or N where no lane clipped a vertex.
    count: usize,
    /// P, the projected area.
    p: L,
    /// ½ Σ θ·m̂_z: P again, to the rounding of its cancelling terms; the scale of the azimuth
    /// solve, whose F ends there.
    sectors: L,
    /// The normal lies inside (or on the boundary of) the clipped polygon.
    central: L::Mask,
    /// Unit 2D directions of the least and greatest azimuth (decentral case).
    lo: V2<L>,
    hi: V2<L>,
    /// The vertices at those azimuths, where the region narrows to a point (local frame).
    tips: [V3<L>; 2],
    /// The angle from `lo` to `hi`.
    width: L,
    /// The slots whose first vertex is at `lo` and at `hi` (whole numbers).
    lo_slot: L,
    hi_slot: L,
    /// The decentral solve's table, one entry per slot in use.
    starts: [Start<L>; K],
    /// The inside test of the whole (unclipped) polygon.
    edges: EdgePlanes<L, N>,
    /// The edges in f64 (world space), P in f64 and the unit normal: the decentral solve's
    /// last step and the inverse sum the sectors there.
    wide: [WideEdge<L::Wide>; K],
    wide_p: L::Wide,
    wide_n: V3<L::Wide>,
    /// P ≥ [`PROJECTED_MIN_SR`], the sweeps cancelling by at most [`PROJECTED_MAX_SPREAD`],
    /// an azimuth range found (decentral case), and everything finite.
    valid: L::Mask,
    /// P = 0 for a valid normal: nothing above the horizon, nothing to sample.
    empty: L::Mask,
}

/// 2D cross product of the xy parts: exactly 0 for equal vectors (no fused multiply-add).
#[inline(always)]
fn cross2<L: Lane>(a: V2<L>, b: V2<L>) -> L {
    a.x * b.y - a.y * b.x
}

#[inline(always)]
fn xy<L: Lane>(v: V3<L>) -> V2<L> {
    V2::new(v.x, v.y)
}

/// The angle between two vectors of any length, by atan2 of |a × b| and a·b: accurate at every
/// angle, unlike acos.
#[inline(always)]
fn angle<L: Math>(a: V3<L>, b: V3<L>) -> L {
    a.cross(b).length().atan2(a.dot(b))
}

/// A positive multiple of the point of the great circle with normal m at azimuth d (a 2D
/// direction): (|m_z|·d, −sgn(m_z)·(m_xy·d)), which lies in the plane m·ω = 0.
#[inline(always)]
fn arc_point<L: Math>(m: V3<L>, d: V2<L>) -> V3<L> {
    let lambda = m.z.abs();
    let z = -(L::ONE.copysign(m.z) * m.x.mul_add(d.x, m.y * d.y));
    V3::new(lambda * d.x, lambda * d.y, z)
}

/// 1 − r² of the projected great circle with normal m along the unit 2D direction d, and r²:
/// ((m_xy·d)², m_z²) / (m_z² + (m_xy·d)²), neither formed as a difference.
#[inline(always)]
fn radii<L: Math>(m: V3<L>, d: V2<L>) -> (L, L) {
    let k = m.x.mul_add(d.x, m.y * d.y);
    let k2 = k * k;
    let z2 = m.z * m.z;
    let s = z2 + k2;
    (k2 / s, z2 / s)
}

impl<L: Math, const N: usize, const K: usize> Projected<L, N, K> {
    /// The polygon `v` (directions from the shading point, in world space, in f64, convex,
    /// either winding) as seen by a receiver with unit normal `n`.
    #[inline(always)]
    fn new(v: [V3<L::Wide>; N], n: V3<L>) -> Self {
        const {
            assert!(
                N >= 3 && K >= 2 * N,
                "2N slots for a polygon of N ≥ 3 vertices"
            )
        };
        let normal = n;
        // The geometry in the f64 lane (see `Wide`), the sampling in f32.
        let g = Wide::new(v, normal);
        // The unit normal from f64, where the squares of huge or tiny coordinates neither
        // overflow nor vanish: a frame from a normal an ulp off unit is that far from
        // orthonormal, and the pdf's round trip through it that far off.
        let n = narrow3::<L>(g.n);
        let frame = Frame::from_normal(n);
        let mut rev = g.v;
        rev.reverse();
        let g = Wide {
            v: zip_map(g.v, rev, |x, r| V3::select(g.flip, r, x)),
            ..g
        };
        let mut e = [Edge::default(); K];
        let mut sectors = L::ZERO;
        let mut spread = L::ZERO;
        let mut central = L::ZERO.le(L::ZERO);
        let heights = g.v.map(|p| dot3_in(p, g.n));
        let slots = clip::<L::Wide, N, K>(g.v, heights);
        // The slots clipping fills: 2N of the K (K may be larger, a polygon's fixed capacity).
        let used = 2 * N;
        let mut p = <L::Wide as Lane>::ZERO;
        let mut wide = [WideEdge::default(); K];
        for (((edge, we), a), b) in e
            .iter_mut()
            .zip(wide.iter_mut())
            .zip(slots.iter().take(used))
            .zip(slots.iter().take(used).cycle().skip(1))
        {
            let a = *a;
            let t = g.edge(a, *b);
            *we = t;
            p = p + t.area;
            let local = |x: V3<L::Wide>| frame.to_local(narrow3(x));
            // The normal's z is the accurate m̂·n, not the rotation's. A great circle within
            // 2⁻⁶⁰ of the normal is a radial segment: its ellipse's r² = m_z²/(m_z² + (m_xy·d)²)
            // would underflow to 0/0, and its sweep is below 1e-14 of the least P sampled.
            let mz = L::narrow(t.mz);
            let radial = mz.abs().lt(L::c(8.673_617_379_884_035e-19)); // 2⁻⁶⁰
            let mz = L::select(radial, L::ZERO, mz);
            let area = L::select(radial, L::ZERO, L::narrow(t.area));
            let theta = L::narrow(t.theta);
            let m = local(t.m);
            let m = V3::new(m.x, m.y, mz);
            central = central & m.z.ge(L::ZERO);
            sectors = sectors + area;
            spread = spread + area.abs();
            let (a, b) = (local(unit_wide(a)), local(unit_wide(*b)));
            *edge = Edge {
                a,
                b,
                da: unit2(xy(a)),
                db: unit2(xy(b)),
                m,
                area,
                theta,
            };
        }
        // With every vertex above the horizon in every lane, the slots are v₀ v₁ v₁ v₂ … and
        // every other edge has length 0: keep the N real ones, and loop over those alone.
        let unclipped = heights
            .iter()
            .fold(L::Wide::ZERO.le(L::Wide::ZERO), |all, h| {
                all & h.gt(L::Wide::ZERO)
            });
        let count = if unclipped.all() {
            let (real, real_wide) = (e, wide);
            for (x, r) in e.iter_mut().zip(real.iter().step_by(2)) {
                *x = *r;
            }
            for (x, r) in wide.iter_mut().zip(real_wide.iter().step_by(2)) {
                *x = *r;
            }
            N
        } else {
            used
        };
        let wide_p = p;
        let p = L::narrow(p);
        // The extreme azimuths: the slot every other slot lies counter-clockwise (clockwise)
        // of, within half a turn; and the vertices there.
        let (mut lo, mut hi) = (V2::default(), V2::default());
        let mut tips = [V3::default(); 2];
        let no = L::ZERO.gt(L::ZERO);
        let (mut found_lo, mut found_hi) = (no, no);
        let (mut lo_slot, mut hi_slot) = (L::ZERO, L::ZERO);
        for (slot, x) in e.iter().take(count).enumerate() {
            let (mut is_lo, mut is_hi) = (L::ZERO.le(L::ZERO), L::ZERO.le(L::ZERO));
            for y in e.iter().take(count) {
                let c = cross2(x.da, y.da);
                is_lo = is_lo & c.ge(L::ZERO);
                is_hi = is_hi & c.le(L::ZERO);
            }
            // The first extreme slot, where several tie (two vertices on one radial plane):
            // the N edges kept where no lane clipped start at v₀ … in the order the 2N slots
            // first meet them, so a lane of a packet with a clipped lane picks the same one.
            let (take_lo, take_hi) = (is_lo & !found_lo, is_hi & !found_hi);
            lo = V2::select(take_lo, x.da, lo);
            hi = V2::select(take_hi, x.da, hi);
            lo_slot = L::select(take_lo, L::c(slot as f64), lo_slot);
            hi_slot = L::select(take_hi, L::c(slot as f64), hi_slot);
            found_lo = found_lo | is_lo;
            found_hi = found_hi | is_hi;
            let [t_lo, t_hi] = tips;
            tips = [
                V3::select(take_lo, x.a, t_lo),
                V3::select(take_hi, x.a, t_hi),
            ];
        }
        // The azimuth solve sums the sectors in f32, whose errors, a few ε of each term's
        // size, reach the sampled u₁ magnified by their cancellation.
        let known = spread.le(sectors * L::c(PROJECTED_MAX_SPREAD as f64));
        // A normal within rounding of an edge's plane, outside it, leaves the extreme azimuths
        // nearly opposite, and rounding can make neither slot extreme: no azimuth range.
        let ranged = central | (found_lo & found_hi);
        let valid =
            p.ge(L::c(PROJECTED_MIN_SR as f64)) & known & ranged & p.is_finite() & n.z.is_finite();
        let empty = p.le(L::ZERO) & n.z.is_finite();
        let mut starts = [Start::default(); K];
        // Only the decentral case reads the table.
        let rows = if central.all() { 0 } else { count };
        // A slot that repeats the previous slot's vertex (clipping kept 2N) repeats its entry.
        let mut last: Option<(V2<L>, Start<L>)> = None;
        for (start, x) in starts.iter_mut().zip(&e).take(rows) {
            *start = match last {
                Some((d, s)) if (x.da.x.eq(d.x) & x.da.y.eq(d.y)).all() => s,
                _ => Start::new(&e, &wide, count, lo, x.da, &frame, g.n),
            };
            last = Some((x.da, *start));
        }
        // F at the vertices, made non-decreasing in azimuth: near a tip, where F grows as the
        // square of the angle, a vertex just past it can round below the tip's F = 0, and the
        // sector search, which orders the vertices by F, would skip it.
        let rising = starts.map(|s| {
            starts
                .iter()
                .take(rows)
                .fold(s.f, |f, t| L::select(t.psi.le(s.psi), f.max(t.f), f))
        });
        for (s, f) in starts.iter_mut().zip(rising) {
            s.f = f;
        }
        Self {
            frame,
            normal,
            e,
            count,
            p,
            sectors,
            central,
            lo,
            hi,
            tips,
            width: cross2(lo, hi).atan2(lo.dot(hi)),
            lo_slot,
            hi_slot,
            starts,
            // A sample is built in the shading frame and rotated back: two f32 rotations and a
            // normalisation, each a few ε, on top of the spherical maps' slack.
            edges: EdgePlanes::new(g.planes(), L::ONE, p).widened(L::c(8.0) * L::EPSILON),
            valid,
            empty,
            wide,
            wide_p,
            wide_n: g.n,
        }
    }

    /// The edges in use.
    #[inline(always)]
    fn edges(&self) -> impl Iterator<Item = &Edge<L>> {
        self.e.iter().take(self.count)
    }

    /// A local unit direction for u, in the projected polygon: u₁ the area swept in azimuth
    /// (a fraction of a turn in the central case, so periodic there, as a disk's azimuth), u₀
    /// the squared radius between the inner and outer edges.
    #[inline(always)]
    fn sample_local(&self, u: V2<L>) -> V3<L> {
        let target = u.y * self.sectors;
        let c = if self.central.any() {
            self.sample_central(target, u.x)
        } else {
            V3::default()
        };
        let d = if (!self.central).any() {
            self.sample_decentral(u.y, u.x)
        } else {
            V3::default()
        };
        V3::select(self.central, c, d)
    }

    /// The central case: the sector whose cumulative area brackets `target`, the angle along
    /// its arc from the area (½·t·m̂_z), and the radius from u₁.
    #[inline(always)]
    fn sample_central(&self, target: L, radius: L) -> V3<L> {
        let mut cum = L::ZERO;
        let mut pick = Edge::default();
        let mut before = L::ZERO;
        for e in self.edges() {
            let take = cum.le(target) & e.area.gt(L::ZERO);
            pick = select_edge(take, *e, pick);
            before = L::select(take, cum, before);
            cum = cum + e.area;
        }
        let t = ((target - before) * L::TWO / pick.m.z)
            .max(L::ZERO)
            .min(pick.theta);
        let (s, c) = t.sin_cos();
        // The arc's point at angle t from a, in the plane with normal m̂.
        let w = pick.a.scale(c) + pick.m.cross(pick.a).scale(s);
        // The point √u₁ of the way out along it; z² = 1 − u₁(1 − w_z²), as a sum of
        // non-negative terms.
        let r = radius.sqrt();
        let z2 = (L::ONE - radius) + radius * w.z * w.z;
        V3::new(w.x * r, w.y * r, z2.max(L::ZERO).sqrt())
    }

    /// F(d): the area of the projected polygon between its least azimuth and unit 2D direction
    /// d, and the plane normals of the outer and inner edges that direction meets.
    ///
    /// An edge counts whole where both ends are at or before d, and in part where one is at or
    /// before and the other after (one edge of each chain). The edges returned for the radii
    /// also take an edge that ends exactly at d, so that the greatest azimuth, where nothing
    /// lies after, still has its two (coincident) ellipses.
    #[inline(always)]
    fn swept(&self, d: V2<L>) -> (L, V3<L>, V3<L>) {
        let mut full = L::ZERO;
        let (mut outer, mut inner) = (V3::default(), V3::default());
        let (mut part_o, mut part_i) = (V3::default(), V3::default());
        let (mut low_o, mut low_i) = (V3::default(), V3::default());
        for e in self.edges() {
            let (ca, cb) = (cross2(e.da, d), cross2(e.db, d));
            let (a_le, b_le) = (ca.ge(L::ZERO), cb.ge(L::ZERO));
            let (a_ge, b_ge) = (ca.le(L::ZERO), cb.le(L::ZERO));
            full = full + L::select(a_le & b_le, e.area, L::ZERO);
            let spans = (a_le & !b_le) | (b_le & !a_le);
            let meets = (a_le & b_ge) | (b_le & a_ge);
            let low = V3::select(a_le, e.a, e.b);
            let (o, i) = (e.m.z.gt(L::ZERO), e.m.z.lt(L::ZERO));
            part_o = V3::select(spans & o, e.m, part_o);
            part_i = V3::select(spans & i, e.m, part_i);
            low_o = V3::select(spans & o, low, low_o);
            low_i = V3::select(spans & i, low, low_i);
            outer = V3::select(meets & o, e.m, outer);
            inner = V3::select(meets & i, e.m, inner);
        }
        let part = |m: V3<L>, low: V3<L>| L::HALF * m.z * angle(low, arc_point(m, d));
        (
            full + part(part_o, low_o) + part(part_i, low_i),
            outer,
            inner,
        )
    }

    /// F in f64 at the azimuth of local 2D direction d: as [`swept`](Self::swept), with the
    /// azimuth tests n·(v × h) on the world-space edges (h the world direction of d) and the
    /// two partial sectors' angles from IEEE operations. Its terms cancel as the f32 ones do,
    /// but by 2⁻⁵² of themselves.
    #[inline(always)]
    fn swept_wide(&self, d: V2<L>) -> <L as Widen>::Wide {
        type W<L> = <L as Widen>::Wide;
        let h = widen3(self.frame.to_world(V3::new(d.x, d.y, L::ZERO)));
        let n = self.wide_n;
        let q = cross3_in(n, h);
        let zero = W::<L>::ZERO;
        let mut full = zero;
        let (mut low_o, mut m_o, mut z_o) = (V3::default(), V3::default(), zero);
        let (mut low_i, mut m_i, mut z_i) = (V3::default(), V3::default(), zero);
        for e in self.wide.iter().take(self.count) {
            let a_le = dot3_in(n, cross3_in(e.a, h)).ge(zero);
            let b_le = dot3_in(n, cross3_in(e.b, h)).ge(zero);
            full = full + W::<L>::select(a_le & b_le, e.area, zero);
            let spans = (a_le & !b_le) | (b_le & !a_le);
            let low = V3::select(a_le, e.a, e.b);
            // Radial edges as the f32 sweep classes them (|m_z| < 2⁻⁶⁰: neither).
            let radial = W::<L>::c(8.673_617_379_884_035e-19);
            let (o, i) = (spans & e.mz.gt(radial), spans & e.mz.lt(-radial));
            low_o = V3::select(o, low, low_o);
            m_o = V3::select(o, e.m, m_o);
            z_o = W::<L>::select(o, e.mz, z_o);
            low_i = V3::select(i, low, low_i);
            m_i = V3::select(i, e.m, m_i);
            z_i = W::<L>::select(i, e.mz, z_i);
        }
        full + wide_part(low_o, m_o, z_o, h, q) + wide_part(low_i, m_i, z_i, h, q)
    }

    /// The local 2D direction at angle ψ from `lo` (exactly `lo` and `hi` at the ends, where
    /// the rotation by the whole width could round past the last vertex, where no edge lies).
    #[inline(always)]
    fn at_angle(&self, psi: L) -> V2<L> {
        let lo = self.lo;
        let (sin, cos) = psi.sin_cos();
        let d = V2::new(
            lo.x.mul_add(cos, -lo.y * sin),
            lo.y.mul_add(cos, lo.x * sin),
        );
        V2::select(
            psi.ge(self.width),
            self.hi,
            V2::select(psi.le(L::ZERO), lo, d),
        )
    }

    /// The decentral case: the azimuth where F = u₁·P, then the squared radius uniform between
    /// the inner and outer ellipses there.
    ///
    /// The sector (two vertices adjacent in azimuth) comes from the table of F at the vertices;
    /// within it one outer and one inner arc bound the region, so that F is F at the sector's
    /// start plus their two sweeps, ½·m̂_z·(angle along the arc). The seed is the root of the
    /// cubic with the sector's end values and end slopes ([`seed`]); Newton's steps on the f32
    /// sweeps follow, bracketed, until a step is below [`SOLVE_TOLERANCE`] of the sector or of
    /// the distance to the nearer tip. The two sweeps cancel, and an arc whose plane passes
    /// near the normal carries its f32 plane's tilt: their rounding reaches u₁, so the solve
    /// goes on with Newton's steps on F summed in f64, bracketed afresh, until a step is below
    /// √ε of the distance to the nearer tip.
    #[inline(always)]
    fn sample_decentral(&self, share: L, radius: L) -> V3<L> {
        let target = share * self.p;
        // The sector: from the vertex with the greatest F ≤ target to the vertex with the
        // least F above it (the greatest azimuth if none is); of vertices with equal F, the
        // first slot, which is the same vertex whether a packet keeps N edges or 2N slots.
        let (mut k0, mut k1) = (self.lo_slot, self.hi_slot);
        let (mut f0, mut f1) = (L::c(f64::NEG_INFINITY), L::c(f64::INFINITY));
        let (mut a0, mut a1) = (L::ZERO, self.width);
        for (i, s) in self.starts.iter().enumerate().take(self.count) {
            let slot = L::c(i as f64);
            // By F, then (where F ties, as it rounds near a tip) by azimuth.
            let start = s.f.le(target) & (s.f.gt(f0) | (s.f.eq(f0) & s.psi.gt(a0)));
            let end = s.f.gt(target) & (s.f.lt(f1) | (s.f.eq(f1) & s.psi.lt(a1)));
            k0 = L::select(start, slot, k0);
            f0 = L::select(start, s.f, f0);
            a0 = L::select(start, s.psi, a0);
            k1 = L::select(end, slot, k1);
            f1 = L::select(end, s.f, f1);
            a1 = L::select(end, s.psi, a1);
        }
        let (k0, k1) = (k0.widen(), k1.widen());
        let table = &self.starts;
        let (psi0, f0) = (pick(table, k0, |s| s.psi), pick(table, k0, |s| s.f));
        let (psi1, f1) = (pick(table, k1, |s| s.psi), pick(table, k1, |s| s.f));
        let (s0, s1) = (pick(table, k0, |s| s.after), pick(table, k1, |s| s.before));
        let (outer, inner) = (pick(table, k0, |s| s.outer), pick(table, k0, |s| s.inner));
        let (m_o, m_i) = (
            pick3(&self.e, outer, |e| e.m),
            pick3(&self.e, inner, |e| e.m),
        );
        let d0 = pick2(&self.e, k0, |e| e.da);
        let width = (psi1 - psi0).max(L::ZERO);
        let span = (f1 - f0).max(L::ZERO);
        let t = (target - f0).max(L::ZERO).min(span);
        // The sweeps from the sector's start, and F′ = ½(r_o² − r_i²).
        let (start_o, start_i) = (arc_point(m_o, d0), arc_point(m_i, d0));
        let sweep = |d: V2<L>| {
            L::HALF * m_o.z * angle(start_o, arc_point(m_o, d))
                + L::HALF * m_i.z * angle(start_i, arc_point(m_i, d))
        };
        let slope = |d: V2<L>| {
            let (_, ro) = radii(m_o, d);
            let (_, ri) = radii(m_i, d);
            L::HALF * (ro - ri)
        };
        // First on the two arcs' f32 sweeps, to about the square of SOLVE_TOLERANCE.
        let unsolved = width.le(L::ZERO) | span.le(L::ZERO);
        let x = newton(
            seed(t, span, width, s0, s1),
            width,
            unsolved,
            SOLVE_STEPS,
            |x| {
                let d = self.at_angle(psi0 + x);
                (sweep(d) - t, slope(d))
            },
            |x| {
                // Near a tip F grows as the square of the distance to it: the tolerance
                // follows that distance, as the f64 steps' does.
                let psi = psi0 + x;
                L::c(SOLVE_TOLERANCE) * width.min(psi).min(self.width - psi)
            },
            L::ZERO,
        );
        // Then on F summed in f64. The f32 sweeps are off by a few ε of the arcs' angles, and
        // by more where an arc's plane passes near the normal (its f32 plane, rotated into the
        // frame, tilts by ε over a small m̂_z), and they cancel: past the median ulp of u₁ in
        // most sectors, and by far near a tip, where F is a difference of two sweeps each
        // linear in the distance ψ from the tip while F grows as ψ². Where F bends as ψ², a
        // Newton step of δ leaves δ²/2ψ, so the tolerance is √ε of the distance to the nearer
        // tip (and of the sector elsewhere); as a rule one step meets it. At a tip itself F′ is 0
        // and no step is defined: there the solve ends once F is within a quarter ε of u₁·P or
        // within the f64 sum's own rounding, whose terms reach the spread times P.
        let residual_tol = (L::EPSILON * L::c(0.25))
            .max(L::c(4.0 * PROJECTED_MAX_SPREAD as f64 * f64::EPSILON))
            * self.p;
        let goal = share.widen() * self.wide_p;
        let full = pick(table, k0, |s| s.full);
        let (from_o, from_i) = (
            pick(table, k0, |s| s.outer_from_a),
            pick(table, k0, |s| s.inner_from_a),
        );
        let x = newton(
            x,
            width,
            unsolved,
            WIDE_STEPS,
            |x| {
                let d = self.at_angle(psi0 + x);
                let h = widen3(self.frame.to_world(V3::new(d.x, d.y, L::ZERO)));
                let q = cross3_in(self.wide_n, h);
                let f = full
                    + sweep_from(&self.wide, outer, from_o, h, q)
                    + sweep_from(&self.wide, inner, from_i, h, q);
                (L::narrow(f - goal), slope(d))
            },
            |x| {
                let psi = psi0 + x;
                L::EPSILON.sqrt() * width.min(psi).min(self.width - psi)
            },
            residual_tol,
        );
        let d = self.at_angle(psi0 + x);
        let (zo, ro) = radii(m_o, d);
        let (zi, ri) = radii(m_i, d);
        // (1 − u)·a + u·b, sums of non-negative terms: at u → 1 against the horizon (zo = 0)
        // z² is (1 − u)·zi to the rounding of each factor, where zi − u·zi would cancel.
        let r2 = (L::ONE - radius).mul_add(ri, radius * ro);
        let z2 = (L::ONE - radius).mul_add(zi, radius * zo);
        let r = r2.max(L::ZERO).sqrt();
        let w = V3::new(d.x * r, d.y * r, z2.max(L::ZERO).sqrt());
        // At the extreme azimuths the two ellipses meet at a vertex; an edge whose plane
        // passes near the normal places it only to ε over that plane's tilt, so take the
        // vertex itself.
        let at = |t: V2<L>| d.x.eq(t.x) & d.y.eq(t.y);
        let [t_lo, t_hi] = self.tips;
        V3::select(at(self.lo), t_lo, V3::select(at(self.hi), t_hi, w))
    }

    /// u for a local unit direction w (inverse of `sample_local`).
    #[inline(always)]
    fn inverse_local(&self, w: V3<L>) -> V2<L> {
        let d = unit2(xy(w));
        let rho2 = w.x.mul_add(w.x, w.y * w.y);
        // Central: the sector whose azimuth range holds d, ends included, the later one where
        // two share an end (the same share, by continuity; at the turn's end, 1 for 0). With
        // the normal on the boundary the sectors span less than a turn, and the last one's end
        // is u₁ = 1.
        let mut cum = L::ZERO;
        let mut area = L::ZERO;
        let mut radius_c = L::ZERO;
        for e in self.edges() {
            let here =
                cross2(e.da, d).ge(L::ZERO) & cross2(d, e.db).ge(L::ZERO) & e.area.gt(L::ZERO);
            let part = L::HALF * e.m.z * angle(e.a, arc_point(e.m, d));
            area = L::select(here, cum + part, area);
            let (_, r2) = radii(e.m, d);
            radius_c = L::select(here, rho2 / r2, radius_c);
            cum = cum + e.area;
        }
        // Decentral: the area swept up to d, and where the radius lies between the ellipses.
        let (_, o, i) = self.swept(d);
        let (zo, _) = radii(o, d);
        let (zi, _) = radii(i, d);
        // Where no edge pair meets d (a direction off the light), 0 rather than 0/0.
        let radius_d = (zi - w.z * w.z) / (zi - zo);
        let radius_d = L::select(radius_d.is_finite(), radius_d, L::ZERO);
        let f = L::narrow(self.swept_wide(d) / self.wide_p);
        let share = L::select(self.central, area / self.sectors, f);
        // The normal itself, in the central case: u₀ = 0 for every u₁ (take 0), where its
        // azimuth is 0/0.
        let axis = rho2.eq(L::ZERO) & self.central;
        let u = V2::new(L::select(self.central, radius_c, radius_d), share);
        V2::select(axis, V2::default(), u)
    }
}

/// The unit vector along a 2D vector (NaN for 0).
#[inline(always)]
fn unit2<L: Math>(v: V2<L>) -> V2<L> {
    let k = L::ONE / v.length_squared().sqrt();
    V2::new(v.x * k, v.y * k)
}

/// ½·m̂_z·(the angle from `low` along the great circle with unit normal m to its point at the
/// world azimuth h, q = n × h): one edge's sweep up to h, in f64. The arc's point is taken in
/// the vertical plane through n and h (normal q), on h's side.
#[inline(always)]
fn wide_part<T: Lane>(low: V3<T>, m: V3<T>, mz: T, h: V3<T>, q: V3<T>) -> T {
    let x = cross3_in(m, q);
    let x = x.scale(T::ONE.copysign(dot3_in(x, h)));
    // low and x lie in the plane with unit normal m, so low × x is along m: its length is its
    // component along m, with no root.
    let s = dot3_in(cross3_in(low, x), m).abs();
    T::HALF * mz * angle_in(s, dot3_in(low, x))
}

/// The f64 sweep up to world azimuth h (q = n × h) of the edge in slot k of `wide`, from its
/// start a where `from_a` is 1, else from its end b: [`wide_part`] of a table's edge.
#[inline(always)]
fn sweep_from<L: Math, const K: usize>(
    wide: &[WideEdge<L::Wide>; K],
    k: L::Wide,
    from_a: L,
    h: V3<L::Wide>,
    q: V3<L::Wide>,
) -> L::Wide {
    let low = V3::select(
        from_a.widen().gt(<L::Wide as Lane>::ZERO),
        pick3(wide, k, |e| e.a),
        pick3(wide, k, |e| e.b),
    );
    wide_part(low, pick3(wide, k, |e| e.m), pick(wide, k, |e| e.mz), h, q)
}

/// One vertex of the decentral case, where a sector of the solve starts: see
/// [`Projected::sample_decentral`].
#[derive(Clone, Copy, Default)]
struct Start<L: Math> {
    /// The vertex's angle from the least azimuth.
    psi: L,
    /// F there, rounded from f64.
    f: L,
    /// The f64 sum of the sweeps of the edges wholly at or before it.
    full: L::Wide,
    /// The slots of the outer and inner edges that span the azimuths just after it, and 1
    /// where that edge's start a is its earlier end, else 0 (see [`sweep_from`]).
    outer: L::Wide,
    inner: L::Wide,
    outer_from_a: L,
    inner_from_a: L,
    /// F′ = ½(r_o² − r_i²) there, on the edges just after it and on those just before (0
    /// where there are none).
    after: L,
    before: L,
}

impl<L: Math> Start<L> {
    /// The entry at the vertex with local 2D azimuth d (the same bits as its edges' `da`,
    /// `db`, so that the tests against them are exact).
    #[inline(always)]
    fn new<const K: usize>(
        e: &[Edge<L>; K],
        wide: &[WideEdge<L::Wide>; K],
        count: usize,
        lo: V2<L>,
        d: V2<L>,
        frame: &Frame<V3<L>>,
        n: V3<L::Wide>,
    ) -> Self {
        type W<L> = <L as Widen>::Wide;
        let to_wide = |m: L::Mask| L::select(m, L::ONE, L::ZERO).widen().gt(W::<L>::ZERO);
        let zero = W::<L>::ZERO;
        // F here is the edges wholly before d plus the sweeps, up to d itself, of the two
        // that end at or pass over it: the edge ending at the vertex counts to d's rounded
        // azimuth, not whole to the vertex, so that F and ψ describe the same direction
        // (against the horizon's arc, a rounded azimuth moves F by ε of the disk's area).
        let (mut full, mut before) = (zero, zero);
        // The loop keeps slot numbers only; the edges are read by index after it. `none` reads
        // as an edge of zeros.
        let none = L::c(1e9);
        let (mut after_o, mut after_i, mut before_o, mut before_i) = (none, none, none, none);
        let (mut after_a_o, mut after_a_i, mut before_a_o, mut before_a_i) =
            (L::ZERO, L::ZERO, L::ZERO, L::ZERO);
        for (slot, x) in e.iter().enumerate().take(count) {
            let (ca, cb) = (cross2(x.da, d), cross2(x.db, d));
            let (a_le, b_le) = (ca.ge(L::ZERO), cb.ge(L::ZERO));
            let (a_lt, b_lt) = (ca.gt(L::ZERO), cb.gt(L::ZERO));
            let area = wide.get(slot).map_or(zero, |w| w.area);
            full = full + W::<L>::select(to_wide(a_le & b_le), area, zero);
            before = before + W::<L>::select(to_wide(a_lt & b_lt), area, zero);
            let spans = (a_le & !b_le) | (b_le & !a_le);
            let ends = (a_lt & !b_lt) | (b_lt & !a_lt);
            let (o, i) = (x.m.z.gt(L::ZERO), x.m.z.lt(L::ZERO));
            let index = L::c(slot as f64);
            // Of an edge that spans d, the end at or before it; of one that ends there, the
            // end strictly before.
            let (after_a, before_a) = (
                L::select(a_le, L::ONE, L::ZERO),
                L::select(a_lt, L::ONE, L::ZERO),
            );
            after_o = L::select(spans & o, index, after_o);
            after_i = L::select(spans & i, index, after_i);
            after_a_o = L::select(spans & o, after_a, after_a_o);
            after_a_i = L::select(spans & i, after_a, after_a_i);
            before_o = L::select(ends & o, index, before_o);
            before_i = L::select(ends & i, index, before_i);
            before_a_o = L::select(ends & o, before_a, before_a_o);
            before_a_i = L::select(ends & i, before_a, before_a_i);
        }
        let h = widen3(frame.to_world(V3::new(d.x, d.y, L::ZERO)));
        let q = cross3_in(n, h);
        let sweep = |k: L, from_a: L| sweep_from(wide, k.widen(), from_a, h, q);
        let f = before + sweep(before_o, before_a_o) + sweep(before_i, before_a_i);
        let slope = |o: L, i: L| {
            let (_, ro) = radii(pick3(e, o.widen(), |x| x.m), d);
            let (_, ri) = radii(pick3(e, i.widen(), |x| x.m), d);
            let g = L::HALF * (ro - ri);
            L::select(g.is_finite(), g, L::ZERO)
        };
        let found = |k: L| L::select(k.lt(none), k, L::ZERO).widen();
        let s = Self {
            outer: found(after_o),
            inner: found(after_i),
            outer_from_a: after_a_o,
            inner_from_a: after_a_i,
            ..Self::default()
        };
        Self {
            psi: cross2(lo, d).atan2(lo.dot(d)).max(L::ZERO),
            f: L::narrow(f),
            full,
            after: slope(after_o, after_i),
            before: slope(before_o, before_i),
            ..s
        }
    }
}

#[inline(always)]
fn pick2<S, T: Lanes, K: Lanes<Scalar = f64>>(table: &[S], k: K, f: impl Fn(&S) -> V2<T>) -> V2<T> {
    V2::new(pick(table, k, |s| f(s).x), pick(table, k, |s| f(s).y))
}

#[inline(always)]
fn pick3<S, T: Lanes, K: Lanes<Scalar = f64>>(table: &[S], k: K, f: impl Fn(&S) -> V3<T>) -> V3<T> {
    V3::new(
        pick(table, k, |s| f(s).x),
        pick(table, k, |s| f(s).y),
        pick(table, k, |s| f(s).z),
    )
}

/// The root in [0, w] of the increasing function whose residual and slope at x `at` gives,
/// from x: Newton's steps where they stay inside the bracket the residuals' signs have
/// narrowed, else bisection, at most `steps` of them. A lane is done once a Newton step is
/// below `tol` at x, or the residual is within `residual_tol` of 0 (or it starts `done`); the
/// step is kept where it lies inside the bracket, onto whose end it may round. A lane that is
/// done stays where it is, so that the steps the other lanes of a packet still take repeat its
/// values bit for bit, as its scalar call stops.
#[inline(always)]
fn newton<L: Math>(
    mut x: L,
    w: L,
    mut done: L::Mask,
    steps: usize,
    at: impl Fn(L) -> (L, L),
    tol: impl Fn(L) -> L,
    residual_tol: L,
) -> L {
    let (mut a, mut b) = (L::ZERO, w);
    for _ in 0..steps {
        if done.all() {
            break;
        }
        let (r, slope) = at(x);
        let below = r.lt(L::ZERO);
        a = L::select(below, x, a);
        b = L::select(below, b, x);
        let step = x - r / slope;
        let converged = (step - x).abs().le(tol(x)) | r.abs().le(residual_tol);
        let inside = step.gt(a) & step.lt(b);
        let next = L::select(inside, step, L::select(converged, x, L::HALF * (a + b)));
        x = L::select(done, x, next);
        done = done | converged;
    }
    x
}

/// x ∈ [0, w] where the cubic through (0, 0) and (w, F) with slopes s₀ at 0 and s₁ at w (the
/// Hermite interpolant of the sector's F) reaches t: the seed of the decentral solve.
///
/// It starts from the quadratic through the ends with slope s₀ at 0 (with s₁ at w, measured
/// from w, where the first would not be monotone), which is exact for a corner of straight
/// sides (s₀ = 0), where F grows as x², and takes two Newton steps on the cubic, kept in
/// [0, w]; within 1/16 of the sector's ends it keeps the quadratic's root. The f32 steps then
/// take 2.0 evaluations per sample for the registry's decentral triangle, 1.2 for its square
/// and 1.2 over 2000 random decentral triangles.
#[inline(always)]
fn seed<L: Math>(t: L, span: L, w: L, s0: L, s1: L) -> L {
    let forward = (s0 * w).le(L::TWO * span);
    let (s, tq) = (L::select(forward, s0, s1), L::select(forward, t, span - t));
    // G(x) = s·x + c·x² with c = (F − s·w)/w²: x = 2t / (s + √(s² + 4ct)).
    let c4t = L::c(4.0) * (span - s * w) * tq / (w * w);
    let x = L::TWO * tq / (s + (s * s + c4t).max(L::ZERO).sqrt());
    let x = L::select(tq.le(L::ZERO), L::ZERO, x);
    let x = L::select(forward, x, w - x);
    let x = L::select(x.is_finite(), x.max(L::ZERO).min(w), L::HALF * w);
    // The cubic in y = x/w, F·(3y² − 2y³) + s₀w·(y³ − 2y² + y) + s₁w·(y³ − y²), less t, and
    // its slope.
    let (a, b) = (s0 * w, s1 * w);
    let model = |y: L| {
        let y2 = y * y;
        let g = span * (L::c(3.0) * y2 - L::TWO * y2 * y)
            + a * (y2 * y - L::TWO * y2 + y)
            + b * (y2 * y - y2);
        let dg = span * (L::c(6.0) * (y - y2))
            + a * (L::c(3.0) * y2 - L::c(4.0) * y + L::ONE)
            + b * (L::c(3.0) * y2 - L::TWO * y);
        (g - t, dg)
    };
    let y0 = x / w;
    let mut y = y0;
    for _ in 0..2 {
        let (r, dg) = model(y);
        let next = y - r / dg;
        y = L::select(next.is_finite(), next.max(L::ZERO).min(L::ONE), y);
    }
    // Near a tip the quadratic is the better model (exact for a corner), and the cubic's slope
    // there is 0 to its rounding: keep the quadratic's root within 1/16 of either end, and the
    // cubic's elsewhere only where it fits the model better.
    let inner = y0.gt(L::c(0.0625)) & y0.lt(L::c(0.9375));
    let better = inner & model(y).0.abs().lt(model(y0).0.abs());
    L::select(better & y.is_finite(), y * w, x)
}

#[inline(always)]
fn select_edge<L: Math>(m: L::Mask, a: Edge<L>, b: Edge<L>) -> Edge<L> {
    Edge {
        a: V3::select(m, a.a, b.a),
        b: V3::select(m, a.b, b.b),
        da: V2::select(m, a.da, b.da),
        db: V2::select(m, a.db, b.db),
        m: V3::select(m, a.m, b.m),
        area: L::select(m, a.area, b.area),
        theta: L::select(m, a.theta, b.theta),
    }
}

/// Element i of a vertex array (0 past its end, which callers never reach).
#[inline(always)]
fn vertex<L: Lane, const N: usize>(v: &[V3<L>; N], i: usize) -> V3<L> {
    v.get(i).copied().unwrap_or_default()
}

/// The convex polygon `w` clipped to the half-space of heights `h` ≥ 0, as the first 2N of K
/// slots (the rest stay zero): for
/// each edge, where it crosses the boundary (or the previous slot again) and its end (or the
/// previous slot again), by Sutherland–Hodgman. Two passes, so that the first slots repeat the last point
/// emitted rather than a point outside. Nothing above the horizon leaves every slot at w₀, a
/// polygon of area 0.
///
/// A crossing is h_s·e − h_e·s (up to sign), not normalised: plain products and differences,
/// so that the f64 lanes of every width run the same operations.
#[inline(always)]
fn clip<T: Lane, const N: usize, const K: usize>(w: [V3<T>; N], h: [T; N]) -> [V3<T>; K] {
    let mut last = vertex(&w, 0);
    let mut slots = [V3::default(); K];
    let starts = w.iter().zip(h);
    let ends = starts.clone().cycle().skip(1);
    for pass in 0..2 {
        let mut out = slots.iter_mut();
        for ((s, hs), (e, he)) in starts.clone().zip(ends.clone()) {
            let (s_in, e_in) = (hs.ge(T::ZERO), he.ge(T::ZERO));
            let x = (e.scale(hs) - s.scale(he)).scale(T::ONE.copysign(hs - he));
            // A vertex on the horizon is its own crossing: h_s·e − h_e·s with h_s = 0 is only a
            // rounded copy of s, and the edge from s to it an arc of rounding noise whose plane
            // points anywhere.
            let x = V3::select(hs.eq(T::ZERO), *s, V3::select(he.eq(T::ZERO), *e, x));
            last = V3::select((s_in & !e_in) | (e_in & !s_in), x, last);
            let enter = last;
            last = V3::select(e_in, *e, last);
            if pass == 1 {
                if let Some(o) = out.next() {
                    *o = enter;
                }
                if let Some(o) = out.next() {
                    *o = last;
                }
            }
        }
    }
    slots
}

/// The polygon and the normal in the f64 lane of the width: the edges' planes, arcs and
/// sector areas computed there from the f32 inputs (whose products are exact) and rounded once.
///
/// In f32 the sector areas ½·θ·m̂_z carry errors of a few ε of their size, more for a short
/// edge, whose plane two nearby rounded unit vectors place only to ε over its length; and they
/// cancel: in the decentral case by the polygon's distance from the normal over its size (P
/// was 2e-4 off for random triangles of 1e-4 sr), and near the horizon, where the projected
/// region is a thin band along the rim. In f64, P = Σ of them is within 1e-6 until they cancel
/// by 10⁹. Only plain IEEE operations, no fused multiply-add, which the f64 lanes do not share.
#[derive(Clone, Copy)]
struct Wide<L: Math, const N: usize> {
    v: [V3<L::Wide>; N],
    /// The unit normal.
    n: V3<L::Wide>,
    /// v₀·(v₁ × v₂) < 0: the winding with outward edge normals.
    flip: <L::Wide as Lane>::Mask,
}

/// One edge in f64: its ends (directions of any length), its unit plane normal (0 for a
/// degenerate edge), m̂·n, θ, and ½·θ·m̂·n.
#[derive(Clone, Copy, Default)]
struct WideEdge<T> {
    a: V3<T>,
    b: V3<T>,
    m: V3<T>,
    mz: T,
    theta: T,
    area: T,
}

impl<L: Math, const N: usize> Wide<L, N> {
    #[inline(always)]
    fn new(v: [V3<L::Wide>; N], n: V3<L>) -> Self {
        let n = widen3(n);
        let n = n.scale(<L::Wide as Lane>::ONE / dot3_in(n, n).sqrt());
        // The winding from the whole fan, Σ v₀·(vᵢ × vᵢ₊₁): its first triangle alone is 0 for a
        // polygon whose first three vertices are collinear (a pentagon with a vertex on a side).
        let v0 = vertex(&v, 0);
        let det = v
            .iter()
            .zip(v.iter().skip(1))
            .skip(1)
            .fold(<L::Wide as Lane>::ZERO, |d, (a, b)| {
                d + dot3_in(v0, cross3_in(*a, *b))
            });
        Self {
            v,
            n,
            flip: det.lt(<L::Wide as Lane>::ZERO),
        }
    }

    /// The edge from a to b (directions of any length).
    #[inline(always)]
    fn edge(&self, a: V3<L::Wide>, b: V3<L::Wide>) -> WideEdge<L::Wide> {
        type W<L> = <L as Widen>::Wide;
        let m = cross3_in(a, b);
        let len2 = dot3_in(m, m);
        let len = len2.sqrt();
        // An edge shorter than the rounding of its ends' cross product (16 f64 ε of |a||b|) has
        // no plane: it sweeps nothing.
        let noise = W::<L>::c(256.0) * W::<L>::EPSILON * W::<L>::EPSILON;
        let some = len2.gt(noise * dot3_in(a, a) * dot3_in(b, b));
        let m = V3::select(some, m.scale(W::<L>::ONE / len), V3::default());
        let theta = angle_in(len, dot3_in(a, b));
        let mz = dot3_in(m, self.n);
        WideEdge {
            a,
            b,
            m,
            mz,
            theta,
            area: W::<L>::HALF * theta * mz,
        }
    }

    /// The unit normals of the polygon's own edge planes, rounded once.
    #[inline(always)]
    fn planes(&self) -> [V3<L>; N] {
        let mut out = [V3::default(); N];
        for ((o, a), b) in out
            .iter_mut()
            .zip(self.v)
            .zip(self.v.iter().cycle().skip(1))
        {
            *o = narrow3(unit_wide(cross3_in(a, *b)));
        }
        out
    }
}

/// atan(k/4) for k = 0, …, 4, rounded to f64.
const ATAN_QUARTERS: [f64; 5] = [
    0.0,
    0.244_978_663_126_864_14,
    0.463_647_609_000_806_1,
    0.643_501_108_793_284_4,
    core::f64::consts::FRAC_PI_4,
];

/// The angle θ ∈ [0, π] with sine and cosine proportional to s ≥ 0 and c, from IEEE
/// operations alone (the f64 lanes have no atan2). With a ≤ b the smaller and larger of s and
/// |c|, atan(a/b) ∈ [0, π/4] is atan(k/4) + atan(z) for the quarter k/4 nearest a/b, where
/// z = (a − (k/4)·b)/(b + (k/4)·a) lies within ±1/8 (one division, and no root), and atan(z)
/// is its Taylor series to z¹⁹, whose remainder is below 2⁻⁶³·z. Then π/2 less that where
/// s > |c|, and π less the result where c < 0. Within a few f64 ulp; 0 for s = c = 0.
#[inline(always)]
fn angle_in<T: Lane>(s: T, c: T) -> T {
    let ac = c.abs();
    let swap = s.gt(ac);
    let (a, b) = (T::select(swap, ac, s), T::select(swap, s, ac));
    // k = how many of the midpoints 1/8, 3/8, 5/8, 7/8 a/b reaches.
    let (mut q, mut base) = (T::ZERO, T::ZERO);
    for (k, &atan) in ATAN_QUARTERS.iter().enumerate().skip(1) {
        let past = a.ge(T::c((2 * k - 1) as f64 / 8.0) * b);
        q = T::select(past, T::c(k as f64 / 4.0), q);
        base = T::select(past, T::c(atan), base);
    }
    let z = (a - q * b) / (b + q * a);
    let z2 = z * z;
    let mut sum = T::ZERO;
    for k in (0..10).rev() {
        let sign = if k % 2 == 0 { 1.0 } else { -1.0 };
        sum = sum * z2 + T::c(sign / (2 * k + 1) as f64);
    }
    let low = base + z * sum;
    let theta = T::select(swap, T::c(core::f64::consts::FRAC_PI_2) - low, low);
    let theta = T::select(c.lt(T::ZERO), T::c(core::f64::consts::PI) - theta, theta);
    T::select(b.gt(T::ZERO), theta, T::ZERO)
}

/// The solid-angle sampler a projected polygon falls back to, as a map to directions.
trait SolidAngle<P: Point3>: Copy {
    fn sample(&self, u: P::Vec2) -> (P, P::Lane);
    fn pdf(&self, w: P) -> P::Lane;
    fn inverse(&self, w: P) -> P::Vec2;
}

impl<P: Point3> SolidAngle<P> for SphericalTriangle<P> {
    #[inline(always)]
    fn sample(&self, u: P::Vec2) -> (P, P::Lane) {
        SphericalTriangle::sample(self, u)
    }
    #[inline(always)]
    fn pdf(&self, w: P) -> P::Lane {
        SphericalTriangle::pdf(self, w)
    }
    #[inline(always)]
    fn inverse(&self, w: P) -> P::Vec2 {
        SphericalTriangle::inverse(self, w)
    }
}

/// The rectangle's points as their directions, with the pdf at the direction (the rounding of
/// the normalisation can move it across the inside test, or the area pdf's last bit); its
/// inverse takes the point of the light along a direction.
impl<P: Point3> SolidAngle<P> for SphericalRectangle<P> {
    #[inline(always)]
    fn sample(&self, u: P::Vec2) -> (P, P::Lane) {
        let (p, kept) = SphericalRectangle::sample(self, u);
        // From a scale where the square cannot underflow: a light 1e-21 away is a light.
        let w = P::from_lanes(p.to_lanes().normalize_scaled());
        let pdf = SphericalRectangle::pdf(self, w);
        (
            w,
            P::Lane::select(kept.gt(P::Lane::ZERO), pdf, P::Lane::ZERO),
        )
    }
    #[inline(always)]
    fn pdf(&self, w: P) -> P::Lane {
        SphericalRectangle::pdf(self, w)
    }
    #[inline(always)]
    fn inverse(&self, w: P) -> P::Vec2 {
        SphericalRectangle::inverse(self, P::from_lanes(self.on_plane(w.to_lanes())))
    }
}

/// A convex polygon of N vertices sampled by solid angle: the fan of spherical triangles
/// (v₀, vᵢ, vᵢ₊₁), one chosen in proportion to its weight (u₀ rescaled within its share, so that
/// u₀ sweeps the fan from edge v₀v₁ to edge v₀v_{N−1}), then sampled by [`SphericalTriangle`]
/// with v₀ its apex. The weight is its solid angle Ωᵢ, and the pdf 1/Ω in the first triangle
/// that holds the direction: the density of solid-angle sampling. Where any triangle of the fan
/// samples by area (below [`SPHERICAL_TRIANGLE_MIN_SR`](crate::warp::SPHERICAL_TRIANGLE_MIN_SR),
/// or above the maximum) every one does, weighted by its area Aᵢ, with pdf (Aᵢ/A)·pdfᵢ: for
/// coplanar vertices, the area density of the whole polygon. Mixing the two would make the
/// density jump at the diagonals, by the relative size of the triangle's angular extent. (f32
/// vertices that are not exactly coplanar give each triangle its own plane, and the density
/// jumps by their tilt, of the order of ε·|v| over the polygon's size.)
#[derive(Clone, Copy)]
struct Fan<P: Point3, const N: usize> {
    /// The N − 2 triangles of the fan (the rest repeat the first, with no share).
    tris: [SphericalTriangle<P>; N],
    /// The weights (Ωᵢ or Aᵢ), and the sum of those before i.
    weight: [P::Lane; N],
    before: [P::Lane; N],
    /// The weights' sum.
    total: P::Lane,
    /// Where the fan samples by area.
    by_area: <P::Lane as Lane>::Mask,
    /// Where every vertex is finite: elsewhere the polygon is degenerate and has pdf 0, as a
    /// triangle with such a vertex has, though its other triangles are not.
    finite: <P::Lane as Lane>::Mask,
}

impl<P: Point3<Lane = L>, L: Math, const N: usize> Fan<P, N> {
    #[inline(always)]
    fn new(v: [P; N]) -> Self {
        // Every index is below N (≥ 3, asserted where a fan is built); the fallback is never read.
        let at = |k: usize| v.get(k).copied().unwrap_or(P::from_lanes(V3::default()));
        // v₀ as Arvo's B, the apex u₁ starts from: u₀ sweeps each triangle from the diagonal
        // v₀vᵢ₊₁ to v₀vᵢ₊₂, so that it runs on across the fan without a jump.
        let first = SphericalTriangle::new(at(1), at(0), at(2));
        let tris: [SphericalTriangle<P>; N] = core::array::from_fn(|i| {
            if i == 0 || i + 2 >= N {
                first
            } else {
                SphericalTriangle::new(at(i + 1), at(0), at(i + 2))
            }
        });
        let by_area = tris
            .iter()
            .take(N - 2)
            .fold(L::ZERO.gt(L::ZERO), |m, t| m | t.by_area());
        let tris = tris.map(|t| t.by_area_where(by_area));
        // Areas in f64, where differences of nearby f32 vertices are exact, as shares of their
        // sum (an area of coordinates near f32's range overflows f32); none for a triangle with
        // a vertex that is not finite.
        let zero = <L::Wide as Lane>::ZERO;
        let origin = widen3(at(0).to_lanes());
        let areas: [L::Wide; N] = core::array::from_fn(|i| {
            if by_area.any() && i + 2 < N {
                let e1 = widen3(at(i + 1).to_lanes()) - origin;
                let e2 = widen3(at(i + 2).to_lanes()) - origin;
                let area = cross3_in(e1, e2).length();
                <L::Wide as Lane>::select(area.is_finite(), area, zero)
            } else {
                zero
            }
        });
        let sum = areas.iter().fold(zero, |s, a| s + *a);
        let mut weight = [L::ZERO; N];
        let mut before = [L::ZERO; N];
        let mut total = L::ZERO;
        for (((w, b), t), area) in weight
            .iter_mut()
            .zip(&mut before)
            .zip(&tris)
            .zip(areas)
            .take(N - 2)
        {
            // A degenerate triangle (solid angle 0) has no share either way.
            let valid = t.solid_angle().gt(L::ZERO);
            let area = L::select(valid, L::narrow(area / sum), L::ZERO);
            *w = L::select(by_area, area, t.solid_angle());
            *b = total;
            total = total + *w;
        }
        let finite = v.iter().fold(L::ZERO.le(L::ZERO), |m, x| {
            let x = x.to_lanes();
            m & x.x.is_finite() & x.y.is_finite() & x.z.is_finite()
        });
        Self {
            tris,
            weight,
            before,
            total,
            by_area,
            finite,
        }
    }

    /// The fan's triangles, with their index, weight and the weight before them.
    #[inline(always)]
    fn triangles(&self) -> impl Iterator<Item = (L, &SphericalTriangle<P>, L, L)> {
        self.tris
            .iter()
            .zip(self.weight)
            .zip(self.before)
            .enumerate()
            .take(N - 2)
            .map(|(i, ((t, o), b))| (L::c(i as f64), t, o, b))
    }

    /// Of the triangles holding w, the first: its index (−1 for none), the pdf there, its
    /// weight and the weight before it.
    #[inline(always)]
    fn holding(&self, w: P) -> (L, L, L, L) {
        let (mut k, mut pdf, mut weight, mut before) = (L::c(-1.0), L::ZERO, L::ZERO, L::ZERO);
        for (i, t, o, b) in self.triangles() {
            let p = t.pdf(w);
            let here = p.gt(L::ZERO) & k.lt(L::ZERO);
            k = L::select(here, i, k);
            pdf = L::select(here, p, pdf);
            weight = L::select(here, o, weight);
            before = L::select(here, b, before);
        }
        (k, pdf, weight, before)
    }
}

impl<P: Point3<Lane = L>, L: Math, const N: usize> SolidAngle<P> for Fan<P, N> {
    #[inline(always)]
    fn sample(&self, u: P::Vec2) -> (P, L) {
        let u = clamp_u(u.to_lanes());
        let t = u.x * self.total;
        // The last triangle with a share that starts at or below t (the first if none does).
        let (mut k, mut before, mut share) = (L::ZERO, L::ZERO, L::ZERO);
        for (i, _, o, b) in self.triangles() {
            let take = (b.le(t) & o.gt(L::ZERO)) | i.eq(L::ZERO);
            k = L::select(take, i, k);
            before = L::select(take, b, before);
            share = L::select(take, o, share);
        }
        // u₀ within the triangle's share (NaN stays NaN, and drops the sample there).
        let x = ((t - before) / share).max(L::ZERO).min(L::ONE);
        let x = L::select(u.x.is_nan(), u.x, x);
        let v = P::Vec2::from_lanes(V2::new(x, u.y));
        let (mut w, mut kept) = (V3::default(), L::ZERO.gt(L::ZERO));
        for (i, tri, _, _) in self.triangles() {
            let chosen = k.eq(i);
            if chosen.any() {
                let (wi, pi) = tri.sample(v);
                w = V3::select(chosen, wi.to_lanes(), w);
                kept = kept | (chosen & pi.gt(L::ZERO));
            }
        }
        // The pdf function's own path, so that the two agree bit for bit; a sample its triangle
        // dropped stays dropped.
        let pdf = L::select(kept, self.pdf(P::from_lanes(w)), L::ZERO);
        let w = V3::select(pdf.gt(L::ZERO), w, V3::new(L::ZERO, L::ZERO, L::ONE));
        (P::from_lanes(w), pdf)
    }

    #[inline(always)]
    fn pdf(&self, w: P) -> L {
        let (k, p, weight, _) = self.holding(w);
        let pdf = L::select(self.by_area, p * weight / self.total, L::ONE / self.total);
        L::select(k.ge(L::ZERO) & self.finite, pdf, L::ZERO)
    }

    #[inline(always)]
    fn inverse(&self, w: P) -> P::Vec2 {
        let (k, _, weight, before) = self.holding(w);
        // Outside every triangle, the first one's inverse.
        let outside = k.lt(L::ZERO);
        let k = k.max(L::ZERO);
        let first = self.weight.first().copied().unwrap_or(L::ZERO);
        let (weight, before) = (
            L::select(outside, first, weight),
            L::select(outside, L::ZERO, before),
        );
        let mut u = V2::default();
        for (i, tri, _, _) in self.triangles() {
            let here = k.eq(i);
            if here.any() {
                u = V2::select(here, tri.inverse(w).to_lanes(), u);
            }
        }
        let x = u.x.mul_add(weight, before) / self.total;
        // Clamped, NaN kept.
        P::Vec2::from_lanes(V2::new(x.clamp(L::ZERO, L::ONE), u.y))
    }
}

/// A fallback built only where some lane takes it: without one, every direction has pdf 0 and
/// maps to (0, 0), which no caller reads (the projected map serves every lane).
impl<P: Point3, B: SolidAngle<P>> SolidAngle<P> for Option<B> {
    #[inline(always)]
    fn sample(&self, u: P::Vec2) -> (P, P::Lane) {
        match self {
            Some(b) => b.sample(u),
            None => (
                P::from_lanes(V3::new(P::Lane::ZERO, P::Lane::ZERO, P::Lane::ONE)),
                P::Lane::ZERO,
            ),
        }
    }
    #[inline(always)]
    fn pdf(&self, w: P) -> P::Lane {
        self.as_ref().map_or(P::Lane::ZERO, |b| b.pdf(w))
    }
    #[inline(always)]
    fn inverse(&self, w: P) -> P::Vec2 {
        self.as_ref()
            .map_or(P::Vec2::from_lanes(V2::default()), |b| b.inverse(w))
    }
}

/// A convex polygon of N vertices sampled by projected solid angle, with the spherical sampler
/// `B` where it falls back: the body of [`ProjectedTriangle`] and [`ProjectedRectangle`].
#[derive(Clone, Copy)]
struct Sampler<P: Point3, B, const N: usize, const K: usize> {
    core: Projected<P::Lane, N, K>,
    base: B,
}

impl<P: Point3<Lane = L>, L: Math, B: SolidAngle<P>, const N: usize, const K: usize>
    Sampler<P, B, N, K>
{
    #[inline(always)]
    fn sample(&self, u: P::Vec2) -> (P, L) {
        let u = u.to_lanes();
        let c = &self.core;
        let (mut w, mut pdf) = (V3::default(), L::ZERO);
        if c.valid.any() {
            let local = c.sample_local(clamp_u(u));
            w = c.frame.to_world(local).normalize();
            // The pdf function's own path, so that the two agree bit for bit.
            pdf = c.pdf(w);
        }
        if (!c.valid).any() {
            let (wb, pb) = self.base.sample(P::Vec2::from_lanes(u));
            w = V3::select(c.valid, w, wb.to_lanes());
            pdf = L::select(c.valid, pdf, pb);
        }
        let pdf = L::select(u.any_nan() | c.empty, L::ZERO, pdf);
        let w = V3::select(pdf.gt(L::ZERO), w, V3::new(L::ZERO, L::ZERO, L::ONE));
        (P::from_lanes(w), pdf)
    }

    #[inline(always)]
    fn pdf(&self, w: P) -> L {
        let c = &self.core;
        let own = if c.valid.any() {
            c.pdf(w.to_lanes())
        } else {
            L::ZERO
        };
        let base = if (!c.valid).any() {
            self.base.pdf(w)
        } else {
            L::ZERO
        };
        L::select(c.valid, own, L::select(c.empty, L::ZERO, base))
    }

    #[inline(always)]
    fn inverse(&self, w: P) -> P::Vec2 {
        let c = &self.core;
        let w = w.to_lanes();
        let own = if c.valid.any() {
            c.inverse(w)
        } else {
            V2::default()
        };
        let base = if (!c.valid).any() {
            self.base.inverse(P::from_lanes(w)).to_lanes()
        } else {
            V2::default()
        };
        P::Vec2::from_lanes(V2::select(c.valid, own, base))
    }
}

/// The methods every projected polygon shares, documented once.
macro_rules! projected_methods {
    ($sample:ident, $pdf:ident, $inverse:ident) => {
        /// P, the projected solid angle of the part of the polygon above the receiver's
        /// horizon: its irradiance at radiance 1 (0 for a polygon wholly below it, NaN for
        /// vertices that are not finite).
        #[inline]
        pub fn projected_area(&self) -> L {
            self.0.core.p
        }

        /// True (lane by lane) where the polygon is sampled by solid angle instead: P below
        /// [`PROJECTED_MIN_SR`] (0 too: a polygon wholly below the horizon, whose samples are
        /// then dropped), sweeps cancelling by more than
        /// [`PROJECTED_MAX_SPREAD`], a normal within rounding of an edge's plane that leaves
        /// no azimuth range, vertices or a normal that are not finite.
        #[inline]
        pub fn by_solid_angle(&self) -> L::Mask {
            !self.0.core.valid
        }

        /// True (lane by lane) where the receiver's normal lies inside the clipped polygon
        /// (Peters' central case, sampled in closed form).
        #[inline]
        pub fn central(&self) -> L::Mask {
            self.0.core.central
        }

        #[doc = concat!("See [`", stringify!($sample), "`].")]
        #[inline]
        pub fn sample(&self, u: P::Vec2) -> (P, L) {
            self.0.sample(u)
        }

        #[doc = concat!("See [`", stringify!($pdf), "`].")]
        #[inline]
        pub fn pdf(&self, w: P) -> L {
            self.0.pdf(w)
        }

        #[doc = concat!("See [`", stringify!($inverse), "`].")]
        #[inline]
        pub fn inverse(&self, w: P) -> P::Vec2 {
            self.0.inverse(w)
        }
    };
}

/// A triangle sampled by projected solid angle for a receiver with unit normal `n`: see
/// [`projected_triangle`]. The set-up (clipping, P, the frame) is paid once.
#[derive(Clone, Copy)]
pub struct ProjectedTriangle<P: Point3>(Sampler<P, SphericalTriangle<P>, 3, 6>);

impl<P: Point3<Lane = L>, L: Math> ProjectedTriangle<P> {
    /// The triangle with vertices `a`, `b`, `c` relative to the shading point, in either
    /// winding, seen by a receiver with unit normal `n`.
    #[inline]
    pub fn new(a: P, b: P, c: P, n: P) -> Self {
        let v = [a, b, c].map(|x| widen3(x.to_lanes()));
        Self(Sampler {
            core: Projected::new(v, n.to_lanes()),
            base: SphericalTriangle::new(a, b, c),
        })
    }

    /// The spherical triangle it falls back to.
    #[inline]
    pub fn spherical(&self) -> &SphericalTriangle<P> {
        &self.0.base
    }

    projected_methods!(
        projected_triangle,
        projected_triangle_pdf,
        projected_triangle_inverse
    );
}

/// A parallelogram sampled by projected solid angle for a receiver with unit normal `n`: see
/// [`projected_rectangle`]. The set-up (clipping, P, the frame) is paid once.
#[derive(Clone, Copy)]
pub struct ProjectedRectangle<P: Point3>(Sampler<P, SphericalRectangle<P>, 4, 8>);

impl<P: Point3<Lane = L>, L: Math> ProjectedRectangle<P> {
    /// The parallelogram corner + s·ex + t·ey, s, t ∈ [0, 1], relative to the shading point,
    /// seen by a receiver with unit normal `n`. Its corners are summed in f64 (exactly where
    /// the coordinates of corner, ex and ey are within 2²⁹ of each other).
    #[inline]
    pub fn new(corner: P, ex: P, ey: P, n: P) -> Self {
        let [c, x, y] = [corner, ex, ey].map(|p| widen3(p.to_lanes()));
        Self(Sampler {
            core: Projected::new([c, c + x, c + x + y, c + y], n.to_lanes()),
            base: SphericalRectangle::new(corner, ex, ey),
        })
    }

    /// The spherical rectangle it falls back to.
    #[inline]
    pub fn spherical(&self) -> &SphericalRectangle<P> {
        &self.0.base
    }

    projected_methods!(
        projected_rectangle,
        projected_rectangle_pdf,
        projected_rectangle_inverse
    );
}

impl<L: Math, const N: usize, const K: usize> Projected<L, N, K> {
    /// n·ω / P where unit direction w (world) is inside the polygon and above the horizon.
    #[inline(always)]
    fn pdf(&self, w: V3<L>) -> L {
        // The cosine in f64, rounded once: within an ε of itself, where the frame's f32
        // rotation leaves an ε of 1, which near the horizon is far more. Any positive multiple
        // of a direction is read as the direction (|w| in f64: f32 squares of huge or tiny
        // coordinates would overflow or vanish).
        let (w, n) = (widen3(w), widen3(self.normal));
        let cos = L::narrow(dot3_in(w, n) / (dot3_in(n, n) * dot3_in(w, w)).sqrt());
        let unit = narrow3::<L>(unit_wide(w));
        let inside = self.edges.contains(unit) & cos.gt(L::ZERO) & self.valid;
        L::select(inside, cos / self.p, L::ZERO)
    }

    /// u of a direction (any positive multiple), clamped to the square; NaN gives NaN.
    #[inline(always)]
    fn inverse(&self, w: V3<L>) -> V2<L> {
        let local = self.frame.to_local(w.normalize_scaled());
        let u = clamp_u(self.inverse_local(local));
        u.nan_where(w.any_nan())
    }
}

/// A direction towards triangle (a, b, c) (vertices relative to the shading point, in either
/// winding), distributed as the cosine n·ω of a receiver with unit normal `n` over the part of
/// the triangle above its horizon, and its pdf per steradian n·ω / P (P the projected solid
/// angle, [`ProjectedTriangle::projected_area`]). [`projected_triangle_pdf`] gives the same
/// number, bit for bit, at the returned direction.
///
/// Peters' map (2021): exact in the central case, a solve ending in a step on f64 sums in the
/// decentral one. Where [`ProjectedTriangle::by_solid_angle`] (below [`PROJECTED_MIN_SR`], a
/// normal that is not finite, …) it is [`spherical_triangle`](crate::warp::spherical_triangle)
/// instead, with that pdf.
///
/// u is clamped to [0, 1]². A triangle wholly below the horizon (P = 0) gives pdf 0 and
/// direction +z for every u; degenerate geometry and NaN in u give the same.
#[inline]
pub fn projected_triangle<P: Point2<Lane = L>, L: Math>(
    u: P,
    a: P::Vec3,
    b: P::Vec3,
    c: P::Vec3,
    n: P::Vec3,
) -> (P::Vec3, L) {
    halved!(sample ProjectedTriangle::new(a, b, c, n) at u)
}

/// pdf per steradian that [`projected_triangle`] returns direction `w` (any positive multiple):
/// n·ω / P inside the triangle and above the horizon, else 0 (also for NaN, and everywhere for
/// a triangle wholly below the horizon); the spherical triangle's pdf where the triangle is
/// sampled by solid angle.
#[inline]
pub fn projected_triangle_pdf<P: Point3<Lane = L>, L: Math>(w: P, a: P, b: P, c: P, n: P) -> L {
    halved!(pdf ProjectedTriangle::new(a, b, c, n) at w)
}

/// Inverse of [`projected_triangle`]: the u that maps to direction `w`, clamped to the square.
/// NaN gives NaN.
#[inline]
pub fn projected_triangle_inverse<P: Point3<Lane = L>, L: Math>(
    w: P,
    a: P,
    b: P,
    c: P,
    n: P,
) -> P::Vec2 {
    halved!(inverse ProjectedTriangle::new(a, b, c, n) at w)
}

/// The registry's [`projected_triangle`] towards vertices `v` for the receiver's normal `n`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProjectedSolidAngleTriangle {
    /// The vertices.
    pub v: [Vec3; 3],
    /// The receiver's unit normal.
    pub n: Vec3,
}

/// The registry's name for a projected polygon's case: "central" (the normal inside the
/// polygon), "large" or "small" (decentral, P above or below 0.05), each with " horizon" where
/// some vertex lies below the receiver's horizon; "solid" where it falls back to solid angle.
fn case(by_solid_angle: bool, central: bool, p: f32, vertices: &[Vec3], n: Vec3) -> &'static str {
    let across = vertices.iter().any(|x| n.dot(*x) < 0.0);
    match (by_solid_angle, central, across) {
        (true, _, _) => "solid",
        (false, true, false) => "central",
        (false, true, true) => "central horizon",
        (false, false, false) if p > 0.05 => "large",
        (false, false, true) if p > 0.05 => "large horizon",
        (false, false, false) => "small",
        (false, false, true) => "small horizon",
    }
}

/// Near the decentral case's tips (u₁ within 1e-2 of 0 or 1) the region is a wedge whose swept
/// area grows as the square of the azimuth, so the azimuth inherits the square root of the
/// rounding of the area and of the edges' f32 planes: measured up to 6e-6 rad within 3e-3 of a
/// tip of the registry's small triangle, 1.2e-6 beyond 1e-2. Error measurements skip those u.
fn near_a_tip(case: &str, u: glam::Vec2) -> bool {
    !case.starts_with("central") && (u.y < 1e-2 || u.y > 1.0 - 1e-2)
}

impl ProjectedSolidAngleTriangle {
    /// Which case it is: "central", "large", "small", with " horizon", or "solid" (see the
    /// registry's rows).
    pub fn case(&self) -> &'static str {
        let [a, b, c] = self.v;
        let t = ProjectedTriangle::new(a, b, c, self.n);
        let p = t.projected_area();
        case(t.by_solid_angle(), t.central(), p, &self.v, self.n)
    }
}

impl Family for ProjectedSolidAngleTriangle {
    fn name(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "projected_triangle {}", self.case())
    }
    fn sampler<L: Math>(&self) -> impl Fn(V2<L>) -> (V3<L>, L) + Copy {
        let (v, n) = (self.v.map(lanes3::<L>), lanes3::<L>(self.n));
        // Through `black_box`, as the spherical triangle's: the set-up is paid at every sample.
        #[inline(always)]
        move |u| {
            let ([a, b, c], n) = core::hint::black_box((v, n));
            projected_triangle(u, a, b, c, n)
        }
    }
    fn pdf<L: Math>(&self, x: V3<L>) -> L {
        let [a, b, c] = self.v.map(lanes3::<L>);
        projected_triangle_pdf(x, a, b, c, lanes3(self.n))
    }
    fn inverse<L: Math>(&self, x: V3<L>) -> Option<V2<L>> {
        let [a, b, c] = self.v.map(lanes3::<L>);
        Some(projected_triangle_inverse(x, a, b, c, lanes3(self.n)))
    }
    fn in_domain(&self, x: Vec3) -> bool {
        is_unit(x)
    }
    fn parameter_sensitive(&self, u: glam::Vec2) -> bool {
        near_a_tip(self.case(), u)
    }
}

/// A direction towards the parallelogram corner + s·ex + t·ey, s, t ∈ [0, 1] (relative to the
/// shading point), distributed as the cosine n·ω of a receiver with unit normal `n` over the
/// part of it above the horizon, and its pdf per steradian n·ω / P: the map of
/// [`projected_triangle`] for four vertices, with the same cases, accuracy and bad input.
/// Where [`ProjectedRectangle::by_solid_angle`] it is the direction of
/// [`spherical_rectangle`](crate::warp::spherical_rectangle)'s point, with that pdf.
///
/// It returns a direction, not a point of the light (unlike the spherical rectangle): the map
/// is one of directions, and a caller who needs the point meets the plane along it.
#[inline]
pub fn projected_rectangle<P: Point2<Lane = L>, L: Math>(
    u: P,
    corner: P::Vec3,
    ex: P::Vec3,
    ey: P::Vec3,
    n: P::Vec3,
) -> (P::Vec3, L) {
    halved!(sample ProjectedRectangle::new(corner, ex, ey, n) at u)
}

/// pdf per steradian that [`projected_rectangle`] returns direction `w` (any positive
/// multiple): n·ω / P inside the parallelogram and above the horizon, else 0 (also for NaN);
/// the spherical rectangle's pdf where it is sampled by solid angle.
#[inline]
pub fn projected_rectangle_pdf<P: Point3<Lane = L>, L: Math>(
    w: P,
    corner: P,
    ex: P,
    ey: P,
    n: P,
) -> L {
    halved!(pdf ProjectedRectangle::new(corner, ex, ey, n) at w)
}

/// Inverse of [`projected_rectangle`]: the u that maps to direction `w`, clamped to the
/// square. NaN gives NaN, as does a rectangle sampled by solid angle beyond
/// [`SPHERICAL_RECTANGLE_INVERSE_REACH`](crate::warp::SPHERICAL_RECTANGLE_INVERSE_REACH).
#[inline]
pub fn projected_rectangle_inverse<P: Point3<Lane = L>, L: Math>(
    w: P,
    corner: P,
    ex: P,
    ey: P,
    n: P,
) -> P::Vec2 {
    halved!(inverse ProjectedRectangle::new(corner, ex, ey, n) at w)
}

/// The registry's [`projected_rectangle`] towards corner + s·ex + t·ey (`v` is corner, ex, ey)
/// for the receiver's normal `n`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProjectedSolidAngleRectangle {
    /// Corner, ex, ey.
    pub v: [Vec3; 3],
    /// The receiver's unit normal.
    pub n: Vec3,
}

impl ProjectedSolidAngleRectangle {
    /// Which case it is, as the triangle's.
    pub fn case(&self) -> &'static str {
        let [c, ex, ey] = self.v;
        let r = ProjectedRectangle::new(c, ex, ey, self.n);
        let corners = [c, c + ex, c + ex + ey, c + ey];
        let p = r.projected_area();
        case(r.by_solid_angle(), r.central(), p, &corners, self.n)
    }
}

impl Family for ProjectedSolidAngleRectangle {
    fn name(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "projected_rectangle {}", self.case())
    }
    fn sampler<L: Math>(&self) -> impl Fn(V2<L>) -> (V3<L>, L) + Copy {
        let (v, n) = (self.v.map(lanes3::<L>), lanes3::<L>(self.n));
        #[inline(always)]
        move |u| {
            let ([c, ex, ey], n) = core::hint::black_box((v, n));
            projected_rectangle(u, c, ex, ey, n)
        }
    }
    fn pdf<L: Math>(&self, x: V3<L>) -> L {
        let [c, ex, ey] = self.v.map(lanes3::<L>);
        projected_rectangle_pdf(x, c, ex, ey, lanes3(self.n))
    }
    fn inverse<L: Math>(&self, x: V3<L>) -> Option<V2<L>> {
        let [c, ex, ey] = self.v.map(lanes3::<L>);
        Some(projected_rectangle_inverse(x, c, ex, ey, lanes3(self.n)))
    }
    fn in_domain(&self, x: Vec3) -> bool {
        is_unit(x)
    }
    fn parameter_sensitive(&self, u: glam::Vec2) -> bool {
        near_a_tip(self.case(), u)
    }
}

/// The most vertices of a [`ProjectedPolygon`].
pub const PROJECTED_POLYGON_MAX_VERTICES: usize = 8;

/// A convex polygon of N vertices (3 ≤ N ≤ [`PROJECTED_POLYGON_MAX_VERTICES`]) sampled by
/// projected solid angle for a receiver with unit normal `n`: see [`projected_polygon`]. The
/// set-up (clipping, P, the frame, and the fan it falls back to where some lane does) is paid once.
///
/// Its clipped edges fill 2N of sixteen slots whatever N is (stable Rust cannot write 2N in a
/// type); the loops run over the 2N (over N where nothing is clipped).
#[derive(Clone, Copy)]
pub struct ProjectedPolygon<P: Point3, const N: usize>(
    Sampler<P, Option<Fan<P, N>>, N, { 2 * PROJECTED_POLYGON_MAX_VERTICES }>,
);

impl<P: Point3<Lane = L>, L: Math, const N: usize> ProjectedPolygon<P, N> {
    /// The convex polygon with vertices `v` in order (either winding), relative to the shading
    /// point, seen by a receiver with unit normal `n`. Its directions are what is sampled: the
    /// spherical polygon with great-circle edges between consecutive vertices, which is the
    /// planar polygon's when the vertices are coplanar.
    #[inline]
    pub fn new(v: [P; N], n: P) -> Self {
        const {
            assert!(
                N >= 3 && N <= PROJECTED_POLYGON_MAX_VERTICES,
                "a projected polygon has 3 to 8 vertices"
            )
        };
        let core = Projected::new(v.map(|x| widen3(x.to_lanes())), n.to_lanes());
        // Its N − 2 spherical set-ups cost as much as the projected one: only where needed.
        let base = (!core.valid).any().then(|| Fan::new(v));
        Self(Sampler { core, base })
    }

    projected_methods!(
        projected_polygon,
        projected_polygon_pdf,
        projected_polygon_inverse
    );
}

/// A direction towards the convex polygon with vertices `v` (relative to the shading point, in
/// order, either winding; 3 to [`PROJECTED_POLYGON_MAX_VERTICES`] of them), distributed as the
/// cosine n·ω of a receiver with unit normal `n` over the part of it above the horizon, and its
/// pdf per steradian n·ω / P: the map of [`projected_triangle`] for N vertices, with the same
/// cases, accuracy and bad input. Where [`ProjectedPolygon::by_solid_angle`] it samples by solid
/// angle instead: the fan of spherical triangles (v₀, vᵢ, vᵢ₊₁), one chosen in proportion to its
/// solid angle Ωᵢ, then [`spherical_triangle`](crate::warp::spherical_triangle) in it, with pdf
/// 1/Ω (Ω the polygon's solid angle; (Ωᵢ/Ω)·pdfᵢ in a triangle that samples by area).
///
/// A polygon that is not convex as seen from the shading point is outside the contract: its
/// samples follow no stated density.
#[inline]
pub fn projected_polygon<P: Point2<Lane = L>, L: Math, const N: usize>(
    u: P,
    v: [P::Vec3; N],
    n: P::Vec3,
) -> (P::Vec3, L) {
    let v = v.map(Point3::to_lanes);
    halved!(sample ProjectedPolygon::new(v: lane, n) at u)
}

/// pdf per steradian that [`projected_polygon`] returns direction `w` (any positive multiple):
/// n·ω / P inside the polygon and above the horizon, else 0 (also for NaN); the fan's where the
/// polygon is sampled by solid angle.
#[inline]
pub fn projected_polygon_pdf<P: Point3<Lane = L>, L: Math, const N: usize>(
    w: P,
    v: [P; N],
    n: P,
) -> L {
    let v = v.map(Point3::to_lanes);
    halved!(pdf ProjectedPolygon::new(v: lane, n) at w)
}

/// Inverse of [`projected_polygon`]: the u that maps to direction `w`, clamped to the square.
/// NaN gives NaN.
#[inline]
pub fn projected_polygon_inverse<P: Point3<Lane = L>, L: Math, const N: usize>(
    w: P,
    v: [P; N],
    n: P,
) -> P::Vec2 {
    let v = v.map(Point3::to_lanes);
    halved!(inverse ProjectedPolygon::new(v: lane, n) at w)
}

/// The hexagon c + cos(kπ/3)·ex + sin(kπ/3)·ey, k = 0 … 5, of the registry's
/// [`ProjectedSolidAngleHexagon`]: convex for any ex and ey that are not parallel.
pub fn hexagon([c, ex, ey]: [Vec3; 3]) -> [Vec3; 6] {
    const H: f32 = 0.866_025_4; // sin(π/3)
    [
        c + ex,
        c + ex * 0.5 + ey * H,
        c - ex * 0.5 + ey * H,
        c - ex,
        c - ex * 0.5 - ey * H,
        c + ex * 0.5 - ey * H,
    ]
}

/// The registry's [`projected_polygon`] towards the [`hexagon`] of `v` = [c, ex, ey] for the
/// receiver's normal `n`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProjectedSolidAngleHexagon {
    /// The centre and the two half-axes.
    pub v: [Vec3; 3],
    /// The receiver's unit normal.
    pub n: Vec3,
}

impl ProjectedSolidAngleHexagon {
    /// Which case it is: "central", "large", "small", with " horizon", or "solid" (as the
    /// projected triangle's).
    pub fn case(&self) -> &'static str {
        let v = hexagon(self.v);
        let t = ProjectedPolygon::new(v, self.n);
        case(
            t.by_solid_angle(),
            t.central(),
            t.projected_area(),
            &v,
            self.n,
        )
    }
}

impl Family for ProjectedSolidAngleHexagon {
    fn name(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "projected_polygon hexagon {}", self.case())
    }
    fn sampler<L: Math>(&self) -> impl Fn(V2<L>) -> (V3<L>, L) + Copy {
        let (v, n) = (hexagon(self.v).map(lanes3::<L>), lanes3::<L>(self.n));
        // Through `black_box`, as the spherical triangle's: the set-up is paid at every sample.
        #[inline(always)]
        move |u| {
            let (v, n) = core::hint::black_box((v, n));
            projected_polygon(u, v, n)
        }
    }
    fn pdf<L: Math>(&self, x: V3<L>) -> L {
        projected_polygon_pdf(x, hexagon(self.v).map(lanes3::<L>), lanes3(self.n))
    }
    fn inverse<L: Math>(&self, x: V3<L>) -> Option<V2<L>> {
        let v = hexagon(self.v).map(lanes3::<L>);
        Some(projected_polygon_inverse(x, v, lanes3(self.n)))
    }
    fn in_domain(&self, x: Vec3) -> bool {
        is_unit(x)
    }
    fn parameter_sensitive(&self, u: glam::Vec2) -> bool {
        near_a_tip(self.case(), u)
    }
}

#[cfg(test)]
mod tests {
    use super::angle_in;

    /// angle_in against libm's atan2 (within 1 ulp): at most 2 f64 ulp of θ over a spread of
    /// magnitudes, both signs of c, and the quarter boundaries of its reduction exactly.
    #[test]
    fn angle_in_is_atan2_to_two_ulp() {
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let mut worst = 0.0f64;
        let mut check = |s: f64, c: f64| {
            let (got, want) = (angle_in(s, c), libm::atan2(s, c));
            let ulp = libm::nextafter(want, f64::INFINITY) - want;
            let err = (got - want).abs() / ulp;
            assert!(
                err <= 2.0,
                "angle_in({s}, {c}) = {got}, atan2 {want}: {err} ulp"
            );
            worst = worst.max(err);
        };
        for _ in 0..200_000 {
            let scale = libm::exp2(next() * 40.0 - 20.0);
            let (s, c) = (
                next() * scale,
                (next() - 0.5) * libm::exp2(next() * 40.0 - 20.0),
            );
            check(s, c);
        }
        for k in 1..5 {
            let t = (2 * k - 1) as f64 / 8.0;
            for c in [1.0, -1.0, 3.0e-5, -7.0e9] {
                check(t * libm::fabs(c), c);
                check(libm::fabs(c), c * t);
            }
        }
        assert_eq!(angle_in(0.0, 0.0), 0.0);
        assert_eq!(angle_in(0.0, 1.0), 0.0);
        assert_eq!(angle_in(0.0, -1.0), core::f64::consts::PI);
        assert_eq!(angle_in(1.0, 0.0), core::f64::consts::FRAC_PI_2);
        assert!(worst > 0.0);
    }
}
