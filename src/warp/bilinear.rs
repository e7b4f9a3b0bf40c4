//! The bilinear warp of the square (Hart, Pharr, Müller, Lopes, McGuire, Wyman: "Practical
//! Product Sampling by Fitting and Composing Warps", EGSR 2020), and the spherical polygons
//! composed with it so that their samples follow the receiver's cosine: [`bilinear_triangle`],
//! [`bilinear_rectangle`].
//!
//! The spherical maps send the square's corners to the polygon's corners, so a density on the
//! square that is bilinear in the cosines max(0.01, n·ω) at those corners, warped through the
//! uniform spherical map, approximates the cosine factor of a Lambertian receiver with normal n.
//! The pdf per steradian is the spherical map's times the bilinear density at u′, where u′ is
//! the spherical map's inverse of the direction.

use core::fmt;

use glam::Vec3;

use crate::lane::{Lane, Mask, V2, V3};
use crate::math::Math;
use crate::point::{Point2, Point3, by_halves, halved};
use crate::warp::common::{clamp_u, clamp01};
use crate::warp::family::{is_unit, lanes3};
use crate::warp::polygon::pow2_scale;
use crate::warp::solid_angle::{on_parallelogram, polygon_size};
use crate::warp::{
    Family, SPHERICAL_RECTANGLE_MIN_SR, SPHERICAL_TRIANGLE_MIN_SR, SphericalRectangle,
    SphericalTriangle,
};

/// The smallest corner weight: a corner below the receiver's horizon (or nearly so) keeps 1 % of
/// a facing corner's density, so that no part of the light gets density 0 (as in Hart et al.).
pub const BILINEAR_MIN_WEIGHT: f32 = 0.01;

/// (1 − t)a + t·b for t ∈ [0, 1] and a, b ≥ 0: a sum of non-negative terms, exact at both ends
/// (a + t(b − a) cancels to 0 at t = 1 when b is below an ulp of a), and exactly a where a = b,
/// so that equal weights leave every map below exact.
#[inline(always)]
fn lerp<L: Math>(t: L, a: L, b: L) -> L {
    L::select(a.eq(b), a, (L::ONE - t).mul_add(a, t * b))
}

/// [0, 1] → [0, 1] with density 2((1 − x)a + x·b)/(a + b), for weights a, b > 0 whose squares
/// are normal f32 numbers (as [`bilinear`] makes them; a = 0 at u = 0 would be 0·∞): the
/// root of the quadratic CDF, x = u(a + b) / (a + √(a² + u(b² − a²))), whose denominator is a
/// sum of non-negative terms, so that nothing divides by a − b or cancels as a → b. With a = b
/// the factor (a + b)/(a + √a²) is exactly 1, and x = u bit for bit.
///
/// u is clamped to [0, 1]; NaN gives NaN (not canonicalised: [`bilinear`] does that once).
#[inline(always)]
pub fn linear<L: Math>(u: L, a: L, b: L) -> L {
    let u = clamp01(u);
    let a2 = a * a;
    let root = u.mul_add(b.mul_add(b, -a2), a2).sqrt();
    // NaN goes in the second operand of min, which returns it.
    L::ONE.min(u * ((a + b) / (a + root)))
}

/// pdf of [`linear`]: 2((1 − x)a + x·b)/(a + b) on [0, 1], else 0 (also for NaN).
#[inline(always)]
pub fn linear_pdf<L: Math>(x: L, a: L, b: L) -> L {
    let inside = x.ge(L::ZERO) & x.le(L::ONE);
    L::select(inside, L::TWO * lerp(x, a, b) / (a + b), L::ZERO)
}

/// Inverse of [`linear`]: u = x(2a + x(b − a))/(a + b), the CDF, a product of non-negative
/// terms (exactly x where a = b). x is clamped to [0, 1]; NaN gives NaN (not canonicalised).
#[inline(always)]
pub fn linear_inverse<L: Math>(x: L, a: L, b: L) -> L {
    let x = clamp01(x);
    x * (x.mul_add(b - a, a + a) / (a + b))
}

/// The square → the square with density 4·bilerp(x, y) / Σw, bilinear in the corner weights
/// `w` = [w₀₀, w₁₀, w₀₁, w₁₁] (w_xy the weight at corner (x, y)): x from its linear marginal
/// with ends (w₀₀ + w₀₁, w₁₀ + w₁₁), then y from the linear conditional at that x. (x first:
/// the spherical maps start their longest chain from u₀, which is then ready one square root
/// and one division earlier, while y is formed beside it.) Equal weights give the identity,
/// bit for bit.
///
/// The weights are positive and finite, at any scale: only their ratios matter, and they are
/// first scaled by a power of two (exactly) so that their squares stay in range; a weight below
/// 2⁻⁴⁰ of the largest counts as 2⁻⁴⁰ of it. Otherwise (a weight ≤ 0, NaN or ∞) they count as
/// equal, the identity with pdf 1, in all three functions.
///
/// u is clamped to [0, 1]²; NaN gives the canonical NaN in that coordinate, and NaN in u₁ in
/// both.
#[inline(always)]
pub fn bilinear<P: Point2<Lane = L>, L: Math>(u: P, w: [L; 4]) -> P {
    P::from_lanes(bilinear_lanes(u.to_lanes(), admissible(w)).canon())
}

/// The weights at a scale whose squares cannot overflow or underflow (the largest in [2⁻¹⁶,
/// 2¹⁶], by an exact power of two, which leaves every result bit for bit as it was), none below
/// 2⁻⁴⁰ of the largest (whose square would underflow, and [`linear`] divide 0 by 0 at u = 0), or
/// all 1 where any is not positive and finite.
#[inline(always)]
fn admissible<L: Math>(w: [L; 4]) -> [L; 4] {
    let m = w[0].max(w[1]).max(w[2]).max(w[3]);
    let ok = w[0].gt(L::ZERO) & w[1].gt(L::ZERO) & w[2].gt(L::ZERO) & w[3].gt(L::ZERO);
    let ok = ok & m.is_finite();
    let s = pow2_scale(m);
    let least = m * s * L::c(9.094947017729282e-13);
    w.map(|x| L::select(ok, (x * s).max(least), L::ONE))
}

#[inline(always)]
fn bilinear_lanes<L: Math>(u: V2<L>, w: [L; 4]) -> V2<L> {
    Warp::new(w).sample(u)
}

/// The bilinear warp for weights already [`admissible`], with its marginal's constants formed
/// once: what a light prepared at a shading point keeps.
#[derive(Clone, Copy)]
struct Warp<L> {
    w: [L; 4],
    /// The marginal's ends a = w₀₀ + w₀₁ and b = w₁₀ + w₁₁, a + b, a² and b² − a² (the root of
    /// [`linear`]), and Σw.
    a: L,
    b: L,
    ab: L,
    a2: L,
    d2: L,
    sum: L,
}

impl<L: Math> Warp<L> {
    #[inline(always)]
    fn new(w: [L; 4]) -> Self {
        let [w00, w10, w01, w11] = w;
        let (a, b) = (w00 + w01, w10 + w11);
        Self {
            w,
            a,
            b,
            ab: a + b,
            a2: a * a,
            d2: b.mul_add(b, -(a * a)),
            sum: (w00 + w10) + (w01 + w11),
        }
    }

    /// [`linear`] for the marginal, then for the conditional.
    #[inline(always)]
    fn sample(&self, u: V2<L>) -> V2<L> {
        self.sample_density(u).0
    }

    /// [`sample`](Self::sample) and the density there, which is [`pdf`](Self::pdf)'s at the
    /// returned point bit for bit: the conditional's ends at x, drawn for y, serve it too.
    #[inline(always)]
    fn sample_density(&self, u: V2<L>) -> (V2<L>, L) {
        let [w00, w10, w01, w11] = self.w;
        let ux = clamp01(u.x);
        let root = ux.mul_add(self.d2, self.a2).sqrt();
        let x = L::ONE.min(ux * (self.ab / (self.a + root)));
        let (c0, c1) = (lerp(x, w00, w10), lerp(x, w01, w11));
        let y = linear(u.y, c0, c1);
        (V2::new(x, y), self.density(lerp(y, c0, c1)))
    }

    /// 4·bilerp(x, y)/Σw in the square, else 0 (also for NaN): the conditional's ends at x,
    /// then y between them.
    #[inline(always)]
    fn pdf(&self, p: V2<L>) -> L {
        let [w00, w10, w01, w11] = self.w;
        let inside = p.x.ge(L::ZERO) & p.x.le(L::ONE) & p.y.ge(L::ZERO) & p.y.le(L::ONE);
        let density = lerp(p.y, lerp(p.x, w00, w10), lerp(p.x, w01, w11));
        L::select(inside, self.density(density), L::ZERO)
    }

    /// 4·bilerp/Σw, with Σw = 4w exactly for equal weights w, so that their density is exactly 1.
    #[inline(always)]
    fn density(&self, bilerp: L) -> L {
        L::c(4.0) * bilerp / self.sum
    }

    /// Each coordinate through [`linear_inverse`], x first.
    #[inline(always)]
    fn inverse(&self, p: V2<L>) -> V2<L> {
        let [w00, w10, w01, w11] = self.w;
        let p = clamp_u(p);
        let y = linear_inverse(p.y, lerp(p.x, w00, w10), lerp(p.x, w01, w11));
        V2::new(linear_inverse(p.x, self.a, self.b), y)
    }
}

/// pdf of [`bilinear`] per unit area: 4·bilerp(x, y) / Σw on [0, 1]², else 0 (also for NaN).
/// Exactly 1 everywhere in the square for equal weights (and for inadmissible ones, as
/// [`bilinear`] takes them). Positive in the square: the weights' floor at 2⁻⁴⁰ of the largest
/// keeps the density above 2⁻⁴⁰.
#[inline(always)]
pub fn bilinear_pdf<P: Point2<Lane = L>, L: Math>(p: P, w: [L; 4]) -> L {
    bilinear_pdf_lanes(p.to_lanes(), admissible(w))
}

#[inline(always)]
fn bilinear_pdf_lanes<L: Math>(p: V2<L>, w: [L; 4]) -> L {
    Warp::new(w).pdf(p)
}

/// Inverse of [`bilinear`]: each coordinate through [`linear_inverse`], x first. p is clamped
/// to [0, 1]²; NaN gives the canonical NaN, as in [`bilinear`].
#[inline(always)]
pub fn bilinear_inverse<P: Point2<Lane = L>, L: Math>(p: P, w: [L; 4]) -> P {
    P::from_lanes(bilinear_inverse_lanes(p.to_lanes(), admissible(w)).canon())
}

#[inline(always)]
fn bilinear_inverse_lanes<L: Math>(p: V2<L>, w: [L; 4]) -> V2<L> {
    Warp::new(w).inverse(p)
}

/// The corner weights max(0.01, n·ω̂) for the unit directions `corners` where the square's
/// corners land and the receiver's normal `n` (unit: a longer one scales the cosines against the
/// floor), made admissible. Equal weights (the plain spherical map) where `uniform`; NaN in n
/// gives 0.01 at every corner, and a non-finite weight equal weights (1), also the plain map.
#[inline(always)]
fn cosine_weights<L: Math>(corners: [V3<L>; 4], n: V3<L>, uniform: L::Mask) -> [L; 4] {
    let floor = L::c(BILINEAR_MIN_WEIGHT as f64);
    admissible(corners.map(|d| {
        let c = n.dot(d);
        L::select(c.gt(floor) & !uniform, c, floor)
    }))
}

/// True where the four weights are equal. There the bilinear warp is the identity and its
/// density exactly 1, so the spherical map alone gives the same bits, and a packet whose lanes
/// are all so skips the warp and the pdf's inverse (the branch follows the light and the
/// receiver, not the sample).
#[inline(always)]
fn all_equal<L: Math>(w: [L; 4]) -> L::Mask {
    w[0].eq(w[1]) & w[0].eq(w[2]) & w[0].eq(w[3])
}

/// The sample of a spherical map `base` at the bilinear warp of u, with the composed pdf: the
/// base pdf times the bilinear density at the u′ it was given, kept only where the base kept the
/// sample (its pdf > 0).
#[inline(always)]
fn sample_through<L: Math>(
    u: V2<L>,
    w: &Warp<L>,
    base: impl FnOnce(V2<L>) -> (V3<L>, L),
) -> (V3<L>, L) {
    let (v, d) = w.sample_density(clamp_u(u));
    let (x, p) = base(v);
    (x, compose(p, d))
}

/// The base pdf `p` times the bilinear density `d`, or 0 where `p` is 0 (`d` may be NaN
/// there). Where `p` is positive the result is too: the density is at least 4·min w/Σw in the
/// square, and where the inverse failed (a NaN u′, so NaN `d`) it counts as 1, so that the pdf
/// is positive exactly where the spherical one is.
#[inline(always)]
fn compose<L: Math>(p: L, d: L) -> L {
    L::select(
        p.gt(L::ZERO),
        p * L::select(d.gt(L::ZERO), d, L::ONE),
        L::ZERO,
    )
}

/// A triangle set up for cosine-weighted sampling at one shading point: [`SphericalTriangle`]
/// behind the bilinear warp, with weights max(0.01, n·ω̂) at the directions of the square's
/// corners under Arvo's map (B, B, A, C: u₁ = 0 is the apex B for any u₀, and u₁ = 1 the arc
/// from A to C). [`bilinear_triangle`], [`bilinear_triangle_pdf`] and
/// [`bilinear_triangle_inverse`] are this type, built and used once.
///
/// Where the triangle is sampled by area (below [`SPHERICAL_TRIANGLE_MIN_SR`] or above
/// [`SPHERICAL_TRIANGLE_MAX_SR`](crate::warp::SPHERICAL_TRIANGLE_MAX_SR)), whose map has other
/// corners, the weights are equal and it is sampled exactly as by [`SphericalTriangle`]; so it is
/// for the zero normal.
///
/// ```
/// use glam::{Vec2, Vec3};
/// use mcsample::warp::{BilinearTriangle, SphericalTriangle};
///
/// let (a, b, c) = (Vec3::new(-1.0, -1.0, 2.0), Vec3::new(1.0, -1.0, 2.0), Vec3::new(0.0, 1.0, 1.0));
/// let n = Vec3::new(0.6, 0.0, 0.8);
/// let tri = BilinearTriangle::new(a, b, c, n);
/// let (w, pdf) = tri.sample(Vec2::new(0.3, 0.8));
/// assert!(pdf > 0.0 && ((tri.pdf(w) - pdf) / pdf).abs() < 1e-4);
/// // No normal: the plain solid-angle sampler, bit for bit.
/// let plain = SphericalTriangle::new(a, b, c).sample(Vec2::new(0.3, 0.8));
/// assert_eq!(BilinearTriangle::new(a, b, c, Vec3::ZERO).sample(Vec2::new(0.3, 0.8)), plain);
/// ```
#[derive(Clone, Copy)]
pub struct BilinearTriangle<P: Point3> {
    base: SphericalTriangle<P>,
    w: Warp<P::Lane>,
    /// True where the weights are equal: the plain map, whose pdf needs no inverse.
    plain: <P::Lane as Lane>::Mask,
}

impl<P: Point3<Lane = L>, L: Math> BilinearTriangle<P> {
    /// The triangle with vertices `a`, `b`, `c` relative to the shading point, in either winding,
    /// weighted for the receiver's unit normal `n` (zero for none).
    #[inline(always)]
    pub fn new(a: P, b: P, c: P, n: P) -> Self {
        let base = SphericalTriangle::new(a, b, c);
        let w = cosine_weights(base.square_corners(), n.to_lanes(), base.by_area());
        Self {
            base,
            w: Warp::new(w),
            plain: all_equal(w),
        }
    }

    /// The spherical triangle behind the warp.
    #[inline]
    pub fn spherical(&self) -> &SphericalTriangle<P> {
        &self.base
    }

    /// The corner weights [w₀₀, w₁₀, w₀₁, w₁₁] of the bilinear warp.
    #[inline]
    pub fn weights(&self) -> [L; 4] {
        self.w.w
    }

    /// True in the lanes whose weights differ: there the warp is not the identity, and the pdf
    /// [`sample`](Self::sample) returns (the density at the u′ it drew) and [`pdf`](Self::pdf)'s
    /// (at the spherical inverse of the direction) agree to the inverse's round trip, not bit
    /// for bit.
    #[inline]
    pub fn weighted(&self) -> <L as Lane>::Mask {
        !self.plain
    }

    /// See [`bilinear_triangle`].
    #[inline]
    pub fn sample(&self, u: P::Vec2) -> (P, L) {
        if self.plain.all() {
            return self.base.sample(u);
        }
        let (w, pdf) = sample_through(u.to_lanes(), &self.w, |v| {
            let (w, p) = self.base.sample(P::Vec2::from_lanes(v));
            (w.to_lanes(), p)
        });
        (P::from_lanes(w), pdf)
    }

    /// See [`bilinear_triangle_pdf`].
    #[inline]
    pub fn pdf(&self, w: P) -> L {
        if self.plain.all() {
            return self.base.pdf(w);
        }
        let v = self.base.inverse(w).to_lanes();
        compose(self.base.pdf(w), self.w.pdf(v))
    }

    /// See [`bilinear_triangle_inverse`].
    #[inline]
    pub fn inverse(&self, w: P) -> P::Vec2 {
        P::Vec2::from_lanes(self.w.inverse(self.base.inverse(w).to_lanes()))
    }
}

/// A direction towards triangle (a, b, c) (vertices relative to the shading point, either
/// winding), distributed approximately as the cosine n·ω of a receiver with unit normal `n`
/// over the triangle's solid angle, and its pdf per steradian: Arvo's map (see
/// [`spherical_triangle`](crate::warp::spherical_triangle)) at [`bilinear`]`(u, w)` with corner
/// weights max(0.01, n·ω̂) (see [`BilinearTriangle`]). The pdf is 1/Ω times the bilinear density
/// at that u′; [`bilinear_triangle_pdf`] takes u′ from the spherical inverse of the direction
/// instead, and agrees within the inverse's round trip (measured: see the crate's tests).
///
/// u is clamped to [0, 1]². Bad input as for the spherical triangle: degenerate triangles and
/// NaN in u give pdf 0 and direction +z. The zero normal, and a non-finite one, give the plain
/// spherical sampler.
#[inline]
pub fn bilinear_triangle<P: Point2<Lane = L>, L: Math>(
    u: P,
    a: P::Vec3,
    b: P::Vec3,
    c: P::Vec3,
    n: P::Vec3,
) -> (P::Vec3, L) {
    halved!(sample BilinearTriangle::new(a, b, c, n) at u)
}

/// pdf per steradian that [`bilinear_triangle`] returns unit direction `w`: the spherical
/// triangle's pdf times the bilinear density at its inverse of `w`; 0 where the spherical pdf is
/// 0 (outside, degenerate, NaN).
#[inline]
pub fn bilinear_triangle_pdf<P: Point3<Lane = L>, L: Math>(w: P, a: P, b: P, c: P, n: P) -> L {
    halved!(pdf BilinearTriangle::new(a, b, c, n) at w)
}

/// Inverse of [`bilinear_triangle`]: [`bilinear_inverse`] of the spherical triangle's inverse.
/// NaN gives NaN.
#[inline]
pub fn bilinear_triangle_inverse<P: Point3<Lane = L>, L: Math>(
    w: P,
    a: P,
    b: P,
    c: P,
    n: P,
) -> P::Vec2 {
    halved!(inverse BilinearTriangle::new(a, b, c, n) at w)
}

/// A rectangle set up for cosine-weighted sampling at one shading point: [`SphericalRectangle`]
/// behind the bilinear warp, with weights max(0.01, n·ω̂) at its corners (u = (0, 0) is
/// `corner`, (1, 0) corner + ex, (0, 1) corner + ey). Where it is sampled by area (tiny, or a
/// skewed parallelogram), whose density in solid angle the corner cosines do not follow, and
/// where it is larger than
/// [`SPHERICAL_RECTANGLE_INVERSE_REACH`](crate::warp::SPHERICAL_RECTANGLE_INVERSE_REACH) times
/// its distance, whose spherical inverse is NaN, the weights are equal: the plain sampler. [`bilinear_rectangle`], [`bilinear_rectangle_pdf`]
/// and [`bilinear_rectangle_inverse`] are this type, built and used once.
#[derive(Clone, Copy)]
pub struct BilinearRectangle<P: Point3> {
    base: SphericalRectangle<P>,
    w: Warp<P::Lane>,
    /// True where the weights are equal, as for the triangle.
    plain: <P::Lane as Lane>::Mask,
}

impl<P: Point3<Lane = L>, L: Math> BilinearRectangle<P> {
    /// The rectangle corner + s·ex + t·ey relative to the shading point (ex ⟂ ey), weighted for
    /// the receiver's unit normal `n` (zero for none).
    #[inline(always)]
    pub fn new(corner: P, ex: P, ey: P, n: P) -> Self {
        let base = SphericalRectangle::new(corner, ex, ey);
        // Sampled by area, the density in solid angle carries d²/cos θ_l, which corner cosines
        // alone do not follow (a skewed parallelogram's error grew 1.3×); beyond the inverse's
        // reach the pdf could not find u′. Equal weights in both: the plain sampler.
        let plain = base.by_area() | base.beyond_reach();
        let w = cosine_weights(base.square_corners(), n.to_lanes(), plain);
        Self {
            base,
            w: Warp::new(w),
            plain: all_equal(w),
        }
    }

    /// The spherical rectangle behind the warp.
    #[inline]
    pub fn spherical(&self) -> &SphericalRectangle<P> {
        &self.base
    }

    /// The corner weights [w₀₀, w₁₀, w₀₁, w₁₁] of the bilinear warp.
    #[inline]
    pub fn weights(&self) -> [L; 4] {
        self.w.w
    }

    /// True in the lanes whose weights differ: there the warp is not the identity, and the pdf
    /// [`sample`](Self::sample) returns (the density at the u′ it drew) and [`pdf`](Self::pdf)'s
    /// (at the spherical inverse of the direction) agree to the inverse's round trip, not bit
    /// for bit.
    #[inline]
    pub fn weighted(&self) -> <L as Lane>::Mask {
        !self.plain
    }

    /// See [`bilinear_rectangle`].
    #[inline]
    pub fn sample(&self, u: P::Vec2) -> (P, L) {
        if self.plain.all() {
            return self.base.sample(u);
        }
        let (p, pdf) = sample_through(u.to_lanes(), &self.w, |v| {
            let (p, pdf) = self.base.sample(P::Vec2::from_lanes(v));
            (p.to_lanes(), pdf)
        });
        (P::from_lanes(p), pdf)
    }

    /// See [`bilinear_rectangle_pdf`].
    #[inline]
    pub fn pdf(&self, p: P) -> L {
        if self.plain.all() {
            return self.base.pdf(p);
        }
        // The inverse reads a point of the light; the pdf accepts any positive multiple.
        let on_plane = P::from_lanes(self.base.on_plane(p.to_lanes()));
        let v = self.base.inverse(on_plane).to_lanes();
        compose(self.base.pdf(p), self.w.pdf(v))
    }

    /// See [`bilinear_rectangle_inverse`].
    #[inline]
    pub fn inverse(&self, p: P) -> P::Vec2 {
        P::Vec2::from_lanes(self.w.inverse(self.base.inverse(p).to_lanes()))
    }
}

/// A point on the rectangle corner + s·ex + t·ey (relative to the shading point; ex ⟂ ey),
/// distributed approximately as the cosine n·ω of a receiver with unit normal `n` over the
/// rectangle's solid angle, and its pdf per steradian: Ureña et al.'s map (see
/// [`spherical_rectangle`](crate::warp::spherical_rectangle)) at [`bilinear`]`(u, w)` with
/// weights max(0.01, n·ω̂) at the corners. The pdf is the spherical map's times the bilinear
/// density at that u′; [`bilinear_rectangle_pdf`] takes u′ from the inverse of the point and
/// agrees within its round trip.
///
/// u is clamped to [0, 1]². Bad input as for the spherical rectangle: degenerate or edge-on
/// rectangles and NaN in u give pdf 0 and the point `corner`. The zero normal, and a non-finite
/// one, give the plain spherical sampler.
#[inline]
pub fn bilinear_rectangle<P: Point2<Lane = L>, L: Math>(
    u: P,
    corner: P::Vec3,
    ex: P::Vec3,
    ey: P::Vec3,
    n: P::Vec3,
) -> (P::Vec3, L) {
    halved!(sample BilinearRectangle::new(corner, ex, ey, n) at u)
}

/// pdf per steradian that [`bilinear_rectangle`] returns a point in direction `p` (any positive
/// multiple of the point): the spherical rectangle's pdf times the bilinear density at its
/// inverse of the point of the light in that direction; 0 where the spherical pdf is 0.
///
/// It is a function of the direction: a point is taken as its direction, and met again on the
/// plane, so for a light seen at a grazing angle (plane distance d, the point at |p|) its u′
/// moves by about ε·|p|/d of the light's size, and the pdf by that times the density's slope.
#[inline]
pub fn bilinear_rectangle_pdf<P: Point3<Lane = L>, L: Math>(
    p: P,
    corner: P,
    ex: P,
    ey: P,
    n: P,
) -> L {
    halved!(pdf BilinearRectangle::new(corner, ex, ey, n) at p)
}

/// Inverse of [`bilinear_rectangle`]: [`bilinear_inverse`] of the spherical rectangle's inverse.
/// NaN gives NaN, as does a rectangle beyond
/// [`SPHERICAL_RECTANGLE_INVERSE_REACH`](crate::warp::SPHERICAL_RECTANGLE_INVERSE_REACH).
#[inline]
pub fn bilinear_rectangle_inverse<P: Point3<Lane = L>, L: Math>(
    p: P,
    corner: P,
    ex: P,
    ey: P,
    n: P,
) -> P::Vec2 {
    halved!(inverse BilinearRectangle::new(corner, ex, ey, n) at p)
}

/// The registry's [`bilinear_triangle`] towards vertices `v` for the receiver's normal `n`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CosineTriangle {
    /// The vertices.
    pub v: [Vec3; 3],
    /// The receiver's unit normal.
    pub n: Vec3,
}

impl Family for CosineTriangle {
    fn name(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let [a, b, c] = self.v;
        let base = SphericalTriangle::new(a, b, c);
        let pdf = base.sample(glam::Vec2::splat(0.5)).1;
        write!(
            f,
            "bilinear_triangle {}",
            polygon_size(pdf, SPHERICAL_TRIANGLE_MIN_SR)
        )?;
        horizon(f, [a, b, c].map(|v| v.normalize()), self.n)
    }
    fn sampler<L: Math>(&self) -> impl Fn(V2<L>) -> (V3<L>, L) + Copy {
        let (v, n) = (self.v.map(lanes3::<L>), lanes3::<L>(self.n));
        // Through `black_box`, as the spherical triangle's: the set-up is paid at every sample.
        // The pdf is the pdf function's at the sample, the registry's contract, where the
        // sample is kept (a dropped sample's stand-in direction may lie on the light).
        #[inline(always)]
        move |u| {
            by_halves(
                (u, core::hint::black_box((v, n))),
                #[inline(always)]
                |(u, ([a, b, c], n))| {
                    let t = BilinearTriangle::new(a, b, c, n);
                    let (w, kept) = t.sample(u);
                    (w, Lane::select(kept.gt(Lane::ZERO), t.pdf(w), Lane::ZERO))
                },
            )
        }
    }
    fn pdf<L: Math>(&self, x: V3<L>) -> L {
        let [a, b, c] = self.v.map(lanes3::<L>);
        bilinear_triangle_pdf(x, a, b, c, lanes3(self.n))
    }
    fn inverse<L: Math>(&self, x: V3<L>) -> Option<V2<L>> {
        let [a, b, c] = self.v.map(lanes3::<L>);
        Some(bilinear_triangle_inverse(x, a, b, c, lanes3(self.n)))
    }
    fn in_domain(&self, x: Vec3) -> bool {
        is_unit(x)
    }
}

/// The registry's [`bilinear_rectangle`] towards corner + s·ex + t·ey (`v` is corner, ex, ey)
/// for the receiver's normal `n`. Its sample is the point on the light.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CosineRectangle {
    /// Corner, ex, ey.
    pub v: [Vec3; 3],
    /// The receiver's unit normal.
    pub n: Vec3,
}

impl Family for CosineRectangle {
    fn name(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let [c, ex, ey] = self.v;
        let base = SphericalRectangle::new(c, ex, ey);
        let pdf = base.sample(glam::Vec2::splat(0.5)).1;
        write!(
            f,
            "bilinear_rectangle {}",
            polygon_size(pdf, SPHERICAL_RECTANGLE_MIN_SR)
        )?;
        horizon(
            f,
            [c, c + ex, c + ey, c + ex + ey].map(|v| v.normalize()),
            self.n,
        )
    }
    fn sampler<L: Math>(&self) -> impl Fn(V2<L>) -> (V3<L>, L) + Copy {
        let (v, n) = (self.v.map(lanes3::<L>), lanes3::<L>(self.n));
        #[inline(always)]
        move |u| {
            by_halves(
                (u, core::hint::black_box((v, n))),
                #[inline(always)]
                |(u, ([c, ex, ey], n))| {
                    let r = BilinearRectangle::new(c, ex, ey, n);
                    let (p, kept) = r.sample(u);
                    (p, Lane::select(kept.gt(Lane::ZERO), r.pdf(p), Lane::ZERO))
                },
            )
        }
    }
    fn pdf<L: Math>(&self, x: V3<L>) -> L {
        let [c, ex, ey] = self.v.map(lanes3::<L>);
        bilinear_rectangle_pdf(x, c, ex, ey, lanes3(self.n))
    }
    fn inverse<L: Math>(&self, x: V3<L>) -> Option<V2<L>> {
        let [c, ex, ey] = self.v.map(lanes3::<L>);
        Some(bilinear_rectangle_inverse(x, c, ex, ey, lanes3(self.n)))
    }
    fn in_domain(&self, x: Vec3) -> bool {
        on_parallelogram(x, self.v)
    }
}

/// The name's last word where some corner of the light is at or below the weight's floor (the
/// receiver's horizon, nearly): " horizon".
fn horizon<const N: usize>(f: &mut fmt::Formatter<'_>, dirs: [Vec3; N], n: Vec3) -> fmt::Result {
    if dirs.iter().any(|d| n.dot(*d) <= BILINEAR_MIN_WEIGHT) {
        f.write_str(" horizon")?;
    }
    Ok(())
}
