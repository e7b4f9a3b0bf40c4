//! The list of shapes, from which the light of any shape is made ([`Light`]), and the choice of
//! a light from a slice: uniform, or in proportion to power through a table in storage the
//! caller provides.

use glam::Vec3;

use super::emitter::{Emitter, PreparedEmitter};
use super::shape::{AreaPoint, AtPoint, LightSampling, PreparedShape, Shape, ShapeSample};
use super::{
    Disk, PreparedDisk, PreparedRectangle, PreparedSphere, PreparedTriangle, Rectangle, Sphere,
    Triangle,
};
use crate::lane::{Lane, V3};
use crate::math::Math;
use crate::point::Point3;
use crate::warp::ONE_MINUS_EPS;

/// The luminance of linear RGB (Rec. 709 weights 0.2126, 0.7152, 0.0722): the power of a light
/// and the weight of its selection.
#[inline]
pub fn luminance<V: Point3>(rgb: V) -> V::Lane {
    let c = rgb.to_lanes();
    type L<V> = <V as Point3>::Lane;
    L::<V>::c(0.2126).mul_add(c.x, L::<V>::c(0.7152).mul_add(c.y, L::<V>::c(0.0722) * c.z))
}

/// A light of any shape, so that a scene is a slice `&[Light]`: one [`Emitter`] over
/// [`AnyShape`]. Build one from a light of a given shape with `Light::from`.
pub type Light<V = Vec3> = Emitter<AnyShape<V>, V>;

/// A [`Light`] prepared at one shading point: [`Light::at`](Emitter::at).
pub type PreparedLight<V = Vec3> = PreparedEmitter<AnyPrepared<V>, V>;

/// The shapes a [`Light`] can have, each with its prepared form: one line per shape. The enums
/// [`AnyShape`] and [`AnyPrepared`], their dispatch, the conversion from each shape's light to a
/// [`Light`] and the splat to other widths all come from this list.
macro_rules! shapes {
    ($($name:ident($shape:ident, $prepared:ident)),* $(,)?) => {
        /// One of the shapes, as the shape of a [`Light`].
        #[derive(Clone, Copy, Debug)]
        pub enum AnyShape<V: Point3 = Vec3> {
            $(
                #[doc = concat!("A [`", stringify!($shape), "`].")]
                $name($shape<V>),
            )*
        }

        /// One of the prepared shapes: [`AnyShape`] prepared at a shading point.
        #[derive(Clone, Copy)]
        pub enum AnyPrepared<V: Point3 = Vec3> {
            $(
                #[doc = concat!("A [`", stringify!($prepared), "`].")]
                $name($prepared<V>),
            )*
        }

        impl<V: Point3<Lane = L>, L: Math> Shape<V> for AnyShape<V> {
            type Prepared = AnyPrepared<V>;
            type Half = AnyShape<V::Half>;
            // A shape of one kind in all its lanes: its halves are of that kind.
            #[inline(always)]
            fn halves(&self) -> (AnyShape<V::Half>, AnyShape<V::Half>) {
                match self {
                    $(Self::$name(s) => {
                        let (lo, hi) = s.halves();
                        (AnyShape::$name(lo), AnyShape::$name(hi))
                    })*
                }
            }
            // Out of line: inlined into a caller that stores the result, the variant is built
            // on the stack and then copied, enum and all, to where it is kept.
            #[inline(never)]
            fn at(&self, p: V, n: V, sampling: LightSampling) -> AnyPrepared<V> {
                match self { $(Self::$name(s) => AnyPrepared::$name(s.at(p, n, sampling)),)* }
            }
            #[inline(always)]
            fn with_at<W: AtPoint<V>>(
                &self,
                p: V,
                n: V,
                sampling: LightSampling,
                work: W,
            ) -> W::Output {
                match self { $(Self::$name(s) => s.with_at(p, n, sampling, work),)* }
            }
            #[inline]
            fn sample_area(&self, u: V::Vec2) -> AreaPoint<V> {
                match self { $(Self::$name(s) => s.sample_area(u),)* }
            }
            #[inline]
            fn area(&self) -> L {
                match self { $(Self::$name(s) => s.area(),)* }
            }
            #[inline]
            fn modes(&self) -> &'static [LightSampling] {
                match self { $(Self::$name(s) => s.modes(),)* }
            }
        }

        impl<V: Point3<Lane = L>, L: Math> PreparedShape<V> for AnyPrepared<V> {
            #[inline]
            fn sample(&self, u: V::Vec2) -> ShapeSample<V> {
                match self { $(Self::$name(s) => s.sample(u),)* }
            }
            #[inline]
            fn eval(&self, wi: V) -> (L, L) {
                match self { $(Self::$name(s) => s.eval(wi),)* }
            }
            #[inline]
            fn dist(&self, wi: V) -> L {
                match self { $(Self::$name(s) => s.dist(wi),)* }
            }
            #[inline]
            fn front(&self) -> L::Mask {
                match self { $(Self::$name(s) => s.front(),)* }
            }
        }

        impl<V: Point3<Lane = L>, L: Math> Light<V> {
            /// The light prepared at `p` ([`Emitter::at_sampling`]), written to `slot`: built in
            /// its variant, so that what is copied into the slot is the variant's size, not the
            /// enum's (a sphere's prepared packet is a seventh of a projected rectangle's).
            #[inline(never)]
            pub(crate) fn prepare_into<'s>(
                &self,
                slot: &'s mut Option<PreparedLight<V>>,
                p: V,
                n: V,
                sampling: LightSampling,
            ) -> &'s PreparedLight<V> {
                let le = self.le.to_lanes();
                match &self.shape {
                    $(AnyShape::$name(s) => slot.insert(PreparedEmitter {
                        shape: AnyPrepared::$name(s.at(p, n, sampling)),
                        le,
                    }),)*
                }
            }
        }

        impl PartialEq for AnyShape<Vec3> {
            fn eq(&self, other: &Self) -> bool {
                match (self, other) {
                    $((Self::$name(a), Self::$name(b)) => a == b,)*
                    #[allow(unreachable_patterns)]
                    _ => false,
                }
            }
        }

        $(
            impl<V: Point3> From<$shape<V>> for AnyShape<V> {
                #[inline]
                fn from(s: $shape<V>) -> Self {
                    AnyShape::$name(s)
                }
            }

            impl<V: Point3> From<Emitter<$shape<V>, V>> for Light<V> {
                #[inline]
                fn from(l: Emitter<$shape<V>, V>) -> Self {
                    Emitter { shape: AnyShape::$name(l.shape), le: l.le }
                }
            }
        )*

        impl AnyShape<Vec3> {
            /// The same shape in every lane of width `W` (exact: f32 to f64 is exact).
            #[inline]
            pub fn splat<W: Point3>(&self) -> AnyShape<W> {
                match self { $(Self::$name(s) => AnyShape::$name(s.splat()),)* }
            }
        }
    };
}

/// The one list of shapes: `with_shapes!(m)` calls macro `m` with it, so that everything that
/// enumerates the shapes (here and in the test layer) follows the list. A new shape is its file
/// and one line here.
macro_rules! with_shapes {
    ($m:ident) => {
        $m! {
            Sphere(Sphere, PreparedSphere),
            Disk(Disk, PreparedDisk),
            Triangle(Triangle, PreparedTriangle),
            Rectangle(Rectangle, PreparedRectangle),
        }
    };
}

#[cfg(feature = "std")]
pub(crate) use with_shapes;

with_shapes!(shapes);

impl Light<Vec3> {
    /// The same light in every lane of width `V`: `Light<Vec3x8>` for a packet whose lanes
    /// share it, `Light<DVec3>` for the f64 reference. Each field is converted exactly (f32 to
    /// f64 is exact), so lane i of the result equals this light bit for bit.
    #[inline]
    pub fn splat<V: Point3>(&self) -> Light<V> {
        Emitter {
            shape: self.shape.splat(),
            le: splat_vec(self.le),
        }
    }
}

/// `x` in every lane of width `V`, exactly.
#[inline(always)]
pub(crate) fn splat_vec<V: Point3>(x: Vec3) -> V {
    V::from_lanes(V3::new(splat_lane(x.x), splat_lane(x.y), splat_lane(x.z)))
}

/// `x` in every lane of `L`, exactly.
#[inline(always)]
pub(crate) fn splat_lane<L: Lane>(x: f32) -> L {
    L::c(f64::from(x))
}

/// The light chosen by one u: its index, the probability it had, and u rescaled to [0, 1) to
/// drive the light's own sampler.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightChoice {
    /// The index into the slice.
    pub index: usize,
    /// The probability of choosing it: multiply every pdf of that light by it.
    pub pmf: f32,
    /// u rescaled to [0, 1) within the light's interval.
    pub u: f32,
}

impl LightChoice {
    /// The choice among `count` lights with equal probability 1/count. u is clamped to
    /// [0, 1); NaN picks light 0. With no lights, the pmf is 0.
    #[inline]
    pub fn uniform(count: usize, u: f32) -> Self {
        let n = count as f32;
        let x = clamp_u(u) * n;
        // x < n always (u < 1 and the product rounds down to at most the largest float below n
        // for every count f32 represents), but the index is capped anyway.
        let index = (x as usize).min(count.saturating_sub(1));
        Self {
            index,
            pmf: if count == 0 { 0.0 } else { 1.0 / n },
            u: clamp_u(x - index as f32),
        }
    }
}

/// u clamped to [0, 1 − 2⁻²⁴]; NaN gives 0.
#[inline(always)]
fn clamp_u(u: f32) -> f32 {
    if u > 0.0 { u.min(ONE_MINUS_EPS) } else { 0.0 }
}

/// Selection in proportion to power: a cumulative table over a light slice, in storage the
/// caller provides (no allocation), with one entry per light.
///
/// Light i is chosen with pmf cdfᵢ − cdfᵢ₋₁ (cdf₋₁ = 0), both read from the table, so
/// [`select`](Self::select) and [`pmf`](Self::pmf) return the same number. A light of zero (or
/// negative, or NaN) power is never chosen. If no light has positive finite power, the table is
/// uniform.
#[derive(Clone, Copy, Debug)]
pub struct PowerTable<'a> {
    cdf: &'a [f32],
}

impl<'a> PowerTable<'a> {
    /// The table of `lights` in `storage`, whose first `lights.len()` entries it overwrites. If
    /// `storage` is shorter, only the lights it has room for can be chosen.
    pub fn new<V: Point3<Lane = f32>>(lights: &[Light<V>], storage: &'a mut [f32]) -> Self {
        let n = lights.len().min(storage.len());
        let (cdf, _) = storage.split_at_mut(n);
        // Accumulate in f64: with many lights an f32 running sum would drop small ones.
        let power = |l: &Light<V>| {
            let p = l.power() as f64;
            if p > 0.0 && p.is_finite() { p } else { 0.0 }
        };
        let total: f64 = lights.iter().take(n).map(power).sum();
        if total > 0.0 && total.is_finite() {
            let mut sum = 0.0f64;
            for (c, l) in cdf.iter_mut().zip(lights) {
                sum += power(l);
                *c = (sum / total) as f32;
            }
        } else {
            for (i, c) in cdf.iter_mut().enumerate() {
                *c = (i + 1) as f32 / n as f32;
            }
        }
        if let Some(last) = cdf.last_mut() {
            *last = 1.0;
        }
        Self { cdf }
    }

    /// The number of lights the table chooses among.
    pub fn len(&self) -> usize {
        self.cdf.len()
    }

    /// True when there is no light to choose.
    pub fn is_empty(&self) -> bool {
        self.cdf.is_empty()
    }

    /// The light for u: the first i with u < cdfᵢ, by binary search. u is clamped to [0, 1);
    /// NaN picks the first light of positive power. With no lights, index 0 and pmf 0.
    pub fn select(&self, u: f32) -> LightChoice {
        let u = clamp_u(u);
        // The first entry above u: zero-power lights (cdf[i] = cdf[i−1] ≤ u) are skipped.
        let index = self
            .cdf
            .partition_point(|&c| c <= u)
            .min(self.cdf.len().saturating_sub(1));
        let pmf = self.pmf(index);
        let lo = self.lower(index);
        LightChoice {
            index,
            pmf,
            u: if pmf > 0.0 {
                clamp_u((u - lo) / pmf)
            } else {
                0.0
            },
        }
    }

    /// The probability that [`select`](Self::select) chooses light `index`; 0 out of range.
    pub fn pmf(&self, index: usize) -> f32 {
        match self.cdf.get(index) {
            Some(&c) => c - self.lower(index),
            None => 0.0,
        }
    }

    fn lower(&self, index: usize) -> f32 {
        match index.checked_sub(1).and_then(|i| self.cdf.get(i)) {
            Some(&c) => c,
            None => 0.0,
        }
    }
}
