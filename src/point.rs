//! The width of a call, picked by the type of its argument.
//!
//! Every warp, frame and pdf is one public generic function over [`Point2`] or [`Point3`], as
//! Mitsuba's `warp.h` is one template for scalar and packet values. The argument's type decides
//! the width and the result's types follow:
//!
//! | width | [`Point2`] | [`Point3`] | lane (scalars: pdfs, parameters) |
//! |---|---|---|---|
//! | one f32 sample | [`glam::Vec2`] | [`glam::Vec3`] | `f32` |
//! | eight f32 samples | [`Vec2x8`](crate::x8::Vec2x8) | [`Vec3x8`](crate::x8::Vec3x8) | [`F32x8`](crate::x8::F32x8) |
//! | sixteen f32 samples | [`Vec2x16`](crate::x16::Vec2x16) | [`Vec3x16`](crate::x16::Vec3x16) | [`F32x16`](crate::x16::F32x16) |
//! | the f64 reference | [`glam::DVec2`] | [`glam::DVec3`] | `f64` |
//!
//! The crate's own generic vectors [`V2`] and [`V3`] implement the traits too (for any lane with
//! [`Math`]), so code generic over a lane calls the same functions.
//!
//! ```
//! use glam::{DVec2, Vec2};
//! use mcsample::warp;
//! use mcsample::x8::Vec2x8;
//!
//! let u = Vec2::new(0.3, 0.7);
//! let one = warp::cosine_hemisphere(u); // glam::Vec3
//! let eight = warp::cosine_hemisphere(Vec2x8::splat(u)); // Vec3x8
//! let reference = warp::cosine_hemisphere(DVec2::new(0.3, 0.7)); // glam::DVec3, via libm
//! assert_eq!(eight.lane(5), one);
//! assert!((reference - one.as_dvec3()).length() < 2e-7);
//! ```

use glam::{DVec2, DVec3, Vec2, Vec3};

use crate::lane::{V2, V3};
use crate::math::Math;

/// A 2D point of one width: [`glam::Vec2`], [`Vec2x8`](crate::x8::Vec2x8),
/// [`Vec2x16`](crate::x16::Vec2x16), [`glam::DVec2`], or the generic [`V2<L>`](V2).
pub trait Point2: Copy {
    /// The lane of the width: `f32`, [`F32x8`](crate::x8::F32x8), [`F32x16`](crate::x16::F32x16)
    /// or `f64`.
    type Lane: Math;
    /// The 3D point of the same width.
    type Vec3: Point3<Lane = Self::Lane, Vec2 = Self>;
    /// The components as lanes.
    fn to_lanes(self) -> V2<Self::Lane>;
    /// The point with components `v`.
    fn from_lanes(v: V2<Self::Lane>) -> Self;
}

/// A 3D point or direction of one width: [`glam::Vec3`], [`Vec3x8`](crate::x8::Vec3x8),
/// [`Vec3x16`](crate::x16::Vec3x16), [`glam::DVec3`], or the generic [`V3<L>`](V3).
pub trait Point3: Copy {
    /// The lane of the width: `f32`, [`F32x8`](crate::x8::F32x8), [`F32x16`](crate::x16::F32x16)
    /// or `f64`.
    type Lane: Math;
    /// The 2D point of the same width.
    type Vec2: Point2<Lane = Self::Lane, Vec3 = Self>;
    /// The point of the width a long algorithm runs at ([`Split`]): [`V3`] of
    /// [`Math::Half`] for the packets, `Self` for glam's types.
    type Half: Point3<Lane = <Self::Lane as Math>::Half>;
    /// The components as lanes.
    fn to_lanes(self) -> V3<Self::Lane>;
    /// The point with components `v`.
    fn from_lanes(v: V3<Self::Lane>) -> Self;
}

/// Point `v` as its two halves ([`Split`]).
#[inline(always)]
pub(crate) fn halves3<V: Point3>(v: V) -> (V::Half, V::Half) {
    let (lo, hi) = v.to_lanes().halves();
    (V::Half::from_lanes(lo), V::Half::from_lanes(hi))
}

/// The point whose halves are `lo` and `hi` ([`Split`]).
#[inline(always)]
pub(crate) fn join3<V: Point3>(lo: V::Half, hi: V::Half) -> V {
    V::from_lanes(V3::join(lo.to_lanes(), hi.to_lanes()))
}

/// Point `u` as its two halves, of the half width's 2D type.
#[inline(always)]
pub(crate) fn halves2<V: Point3>(
    u: V::Vec2,
) -> (<V::Half as Point3>::Vec2, <V::Half as Point3>::Vec2) {
    let (lo, hi) = u.to_lanes().halves();
    (Point2::from_lanes(lo), Point2::from_lanes(hi))
}

/// One width's pair of public types, converted through the glam conversions of [`V2`]/[`V3`].
macro_rules! width {
    ($v2:ty, $v3:ty, $lane:ty) => {
        impl Point2 for $v2 {
            type Lane = $lane;
            type Vec3 = $v3;
            #[inline(always)]
            fn to_lanes(self) -> V2<$lane> {
                self.into()
            }
            #[inline(always)]
            fn from_lanes(v: V2<$lane>) -> Self {
                v.into()
            }
        }
        impl Point3 for $v3 {
            type Lane = $lane;
            type Vec2 = $v2;
            type Half = $v3;
            #[inline(always)]
            fn to_lanes(self) -> V3<$lane> {
                self.into()
            }
            #[inline(always)]
            fn from_lanes(v: V3<$lane>) -> Self {
                v.into()
            }
        }
    };
}

width!(Vec2, Vec3, f32);
width!(DVec2, DVec3, f64);

impl<L: Math> Point2 for V2<L> {
    type Lane = L;
    type Vec3 = V3<L>;
    #[inline(always)]
    fn to_lanes(self) -> V2<L> {
        self
    }
    #[inline(always)]
    fn from_lanes(v: V2<L>) -> Self {
        v
    }
}

impl<L: Math> Point3 for V3<L> {
    type Lane = L;
    type Vec2 = V2<L>;
    type Half = V3<L::Half>;
    #[inline(always)]
    fn to_lanes(self) -> V3<L> {
        self
    }
    #[inline(always)]
    fn from_lanes(v: V3<L>) -> Self {
        v
    }
}

/// A value of one width as two values of half its width, where the build runs the width as two
/// halves, or as itself: the lanes ([`Math::Half`]), [`V2`], [`V3`], arrays and tuples of them,
/// and the crate's structs of them.
///
/// Without AVX-512, `wide` runs each [`F32x16`](crate::x16::F32x16) operation as two eight-wide
/// ones, so a long algorithm at width 16 holds every intermediate in twice the registers of width
/// 8 and spills: run whole at width 16, the spherical triangle takes 1.4× the time per sample of
/// its eight-wide form, the bilinear rectangle 1.8×. The long algorithms (the free functions of the spherical,
/// bilinear and projected polygons, the projected cap and the spherical ellipse; a light's
/// queries at a point; the Phong BSDF) therefore run a sixteen-wide call as two eight-wide
/// calls there, through `by_halves`. Lane *i* is the scalar computation on lane *i*'s inputs
/// either way.
pub trait Split: Copy {
    /// The type of a half: `Self` where the width runs whole.
    type Half: Copy;
    /// True where the width runs as two halves.
    const SPLIT: bool;
    /// The two halves, lanes 0..w/2 and w/2..w; where the width runs whole, `self` twice.
    fn halves(self) -> (Self::Half, Self::Half);
}

/// A [`Split`] value that can be put together again from its halves: what a split call returns.
/// (An argument need only split: a light of one kind in all its lanes has no join of two kinds.)
pub trait Join: Split {
    /// The value whose halves are `lo` and `hi`; where the width runs whole, `lo`.
    fn join(lo: Self::Half, hi: Self::Half) -> Self;
}

/// `f(x)`, or, where `x`'s width runs as two halves, `f` of each half, joined. The long
/// algorithms' public entries call it once, at the top; the short warps gain nothing from it.
/// The spherical triangle's and rectangle's constructors (their set-ups) call it too, and so do
/// the f64 plane and area terms of the polygons, wherever they run: their few arguments cost
/// nothing to split. A prepared form's queries do not: a set-up read through `&self` is copied
/// into its halves at every query, kilobytes a sample, which costs more than the spills it
/// saves (split so, the projected cap's sample takes 3.3× the time at sixteen lanes and 5× at
/// eight).
///
/// Callers mark `f` `#[inline(always)]`, and `f` calls a whole-width body, never the public
/// entry itself. A closure left to LLVM, with one call from the x8 path and two from the x16
/// one, may stay out of line, and the x8 spherical triangle then builds its set-up in one place
/// and copies it to another (two more `memcpy` a sample, 8 % more instructions, 12 % more
/// time); a public entry calling itself in the dead branch of its x8 instance doubles Phong's
/// x8 time.
#[inline(always)]
pub(crate) fn by_halves<I: Split, O: Join>(x: I, f: impl Fn(I::Half) -> O::Half) -> O {
    let (lo, hi) = x.halves();
    let lo = f(lo);
    // Where the width runs whole, `hi` is `lo` again, and the second call is never made.
    let hi = if I::SPLIT { f(hi) } else { lo };
    O::join(lo, hi)
}

/// The body of a long sampler's free function: its prepared type built and queried on each half
/// ([`by_halves`]). `halved!(sample Type::new(a, b) at u)` returns the sample and its pdf as the
/// call's width; `pdf … at w` the pdf; `inverse … at w` the u. The arguments are points of the
/// call's width, or lanes where marked `r: lane`. The closure is always inlined (see
/// [`by_halves`]).
macro_rules! halved {
    (@lanes $g:ident) => { $g.to_lanes() };
    (@lanes $g:ident lane) => { $g };
    (@run $t:ident::$new:ident($($g:ident $(: $k:ident)?),*), $q:ident, $x:ident) => {
        $crate::point::by_halves(
            ($x.to_lanes(), $($crate::point::halved!(@lanes $g $($k)?)),*),
            #[inline(always)]
            |($x, $($g),*)| $t::$new($($g),*).$q($x),
        )
    };
    (sample $t:ident::$new:ident $args:tt at $x:ident) => {{
        let (w, pdf) = $crate::point::halved!(@run $t::$new $args, sample, $x);
        ($crate::point::Point3::from_lanes(w), pdf)
    }};
    (pdf $t:ident::$new:ident $args:tt at $x:ident) => {
        $crate::point::halved!(@run $t::$new $args, pdf, $x)
    };
    (inverse $t:ident::$new:ident $args:tt at $x:ident) => {
        $crate::point::Point2::from_lanes($crate::point::halved!(@run $t::$new $args, inverse, $x))
    };
}
pub(crate) use halved;

/// [`Split`] and [`Join`] for a struct of values of one width, field by field:
/// `split_fields!(Phong<V: Point3> by V::Lane { kd: point, ks: point, n })`. The struct is
/// generic over its point (`V: Point3`) or lane (`L: Math`) and any number of `const` lengths;
/// `by` names its lane. A field marked `point` is a `V`, `points` an array of them and `mask`
/// the lane's mask; the others are [`Join`] themselves. Fields may be named
/// `0`, `1`, … (a tuple struct). Each half takes its own `halves` of every field: they are
/// register moves, and LLVM keeps one of each pair.
macro_rules! split_fields {
    (@halves $l:ty, $x:expr) => { $crate::point::Split::halves($x) };
    (@halves $l:ty, $x:expr, point) => { $crate::point::halves3($x) };
    (@halves $l:ty, $x:expr, points) => {{
        let h = $x.map($crate::point::halves3);
        (h.map(|h| h.0), h.map(|h| h.1))
    }};
    (@halves $l:ty, $x:expr, mask) => { <$l as $crate::math::Math>::mask_halves($x) };
    (@join $l:ty, $lo:expr, $hi:expr) => { $crate::point::Join::join($lo, $hi) };
    (@join $l:ty, $lo:expr, $hi:expr, point) => { $crate::point::join3($lo, $hi) };
    (@join $l:ty, $lo:expr, $hi:expr, points) => {{
        let (lo, hi) = ($lo, $hi);
        // By index, below the length, as arrays join.
        #[allow(clippy::indexing_slicing)]
        core::array::from_fn(|i| $crate::point::join3(lo[i], hi[i]))
    }};
    (@join $l:ty, $lo:expr, $hi:expr, mask) => { <$l as $crate::math::Math>::mask_join($lo, $hi) };
    (
        $t:ident<$p:ident: $bound:ident $(, const $c:ident)*> by $l:ty
        { $($f:tt $(: $k:ident)?),* $(,)? }
    ) => {
        impl<$p: $bound $(, const $c: usize)*> $crate::point::Split for $t<$p $(, $c)*> {
            type Half = $t<$p::Half $(, $c)*>;
            const SPLIT: bool = <$l as $crate::math::Math>::SPLIT;
            #[inline(always)]
            fn halves(self) -> (Self::Half, Self::Half) {
                (
                    $t { $($f: $crate::point::split_fields!(@halves $l, self.$f $(, $k)?).0),* },
                    $t { $($f: $crate::point::split_fields!(@halves $l, self.$f $(, $k)?).1),* },
                )
            }
        }
        impl<$p: $bound $(, const $c: usize)*> $crate::point::Join for $t<$p $(, $c)*> {
            #[inline(always)]
            fn join(lo: Self::Half, hi: Self::Half) -> Self {
                $t { $($f: $crate::point::split_fields!(@join $l, lo.$f, hi.$f $(, $k)?)),* }
            }
        }
    };
}
pub(crate) use split_fields;

impl<L: Math> Split for L {
    type Half = L::Half;
    const SPLIT: bool = L::SPLIT;
    #[inline(always)]
    fn halves(self) -> (L::Half, L::Half) {
        Math::halves(self)
    }
}

impl<L: Math> Join for L {
    #[inline(always)]
    fn join(lo: L::Half, hi: L::Half) -> L {
        Math::join(lo, hi)
    }
}

impl<L: Math> Split for V2<L> {
    type Half = V2<L::Half>;
    const SPLIT: bool = L::SPLIT;
    #[inline(always)]
    fn halves(self) -> (Self::Half, Self::Half) {
        let ((x0, x1), (y0, y1)) = (self.x.halves(), self.y.halves());
        (V2::new(x0, y0), V2::new(x1, y1))
    }
}

impl<L: Math> Join for V2<L> {
    #[inline(always)]
    fn join(lo: Self::Half, hi: Self::Half) -> Self {
        V2::new(L::join(lo.x, hi.x), L::join(lo.y, hi.y))
    }
}

impl<L: Math> Split for V3<L> {
    type Half = V3<L::Half>;
    const SPLIT: bool = L::SPLIT;
    #[inline(always)]
    fn halves(self) -> (Self::Half, Self::Half) {
        let ((x0, x1), (y0, y1), (z0, z1)) = (self.x.halves(), self.y.halves(), self.z.halves());
        (V3::new(x0, y0, z0), V3::new(x1, y1, z1))
    }
}

impl<L: Math> Join for V3<L> {
    #[inline(always)]
    fn join(lo: Self::Half, hi: Self::Half) -> Self {
        V3::new(
            L::join(lo.x, hi.x),
            L::join(lo.y, hi.y),
            L::join(lo.z, hi.z),
        )
    }
}

impl<T: Split, const N: usize> Split for [T; N] {
    type Half = [T::Half; N];
    const SPLIT: bool = T::SPLIT;
    #[inline(always)]
    fn halves(self) -> (Self::Half, Self::Half) {
        (self.map(|t| t.halves().0), self.map(|t| t.halves().1))
    }
}

impl<T: Join, const N: usize> Join for [T; N] {
    #[inline(always)]
    fn join(lo: Self::Half, hi: Self::Half) -> Self {
        // By index (below N, so it cannot panic): at a whole width `hi` is then unread and
        // dropped. Through an iterator or a counter it survives (2 % more instructions in the
        // spherical triangle's set-up).
        #[allow(clippy::indexing_slicing)]
        core::array::from_fn(|i| T::join(lo[i], hi[i]))
    }
}

/// Tuples split element by element: a function's arguments, or its results, as one value.
macro_rules! tuples {
    ($(($($t:ident $i:tt),+))*) => {$(
        impl<$($t: Split),+> Split for ($($t,)+) {
            type Half = ($($t::Half,)+);
            const SPLIT: bool = $($t::SPLIT)|+;
            #[inline(always)]
            fn halves(self) -> (Self::Half, Self::Half) {
                let parts = ($(self.$i.halves(),)+);
                (($(parts.$i.0,)+), ($(parts.$i.1,)+))
            }
        }
        impl<$($t: Join),+> Join for ($($t,)+) {
            #[inline(always)]
            fn join(lo: Self::Half, hi: Self::Half) -> Self {
                ($($t::join(lo.$i, hi.$i),)+)
            }
        }
    )*};
}

tuples! {
    (A 0, B 1)
    (A 0, B 1, C 2)
    (A 0, B 1, C 2, D 3)
    (A 0, B 1, C 2, D 3, E 4)
}
