//! One light type for slices, and the choice of a light from a slice: uniform, or in proportion
//! to power through a table in storage the caller provides.

use glam::Vec3;

use crate::lane::{Lane, V3};
use crate::math::Math;
use crate::point::Point3;
use crate::scene::{
    AreaSample, DiskLight, LightSample, PreparedDisk, PreparedRectangle, PreparedSphere,
    PreparedTriangle, RectangleLight, SphereLight, TriangleLight,
};
use crate::warp::ONE_MINUS_EPS;

/// The luminance of linear RGB (Rec. 709 weights 0.2126, 0.7152, 0.0722): the power of a light
/// and the weight of its selection.
#[inline]
pub fn luminance<V: Point3>(rgb: V) -> V::Lane {
    let c = rgb.to_lanes();
    type L<V> = <V as Point3>::Lane;
    L::<V>::c(0.2126).mul_add(c.x, L::<V>::c(0.7152).mul_add(c.y, L::<V>::c(0.0722) * c.z))
}

/// Any of the four lights, so that a scene is a slice `&[Light]`. Each method dispatches to the
/// light's own.
#[derive(Clone, Copy, Debug)]
pub enum Light<V: Point3 = Vec3> {
    /// A [`SphereLight`].
    Sphere(SphereLight<V>),
    /// A [`DiskLight`].
    Disk(DiskLight<V>),
    /// A [`TriangleLight`].
    Triangle(TriangleLight<V>),
    /// A [`RectangleLight`].
    Rectangle(RectangleLight<V>),
}

/// A [`Light`] prepared at one shading point: [`Light::at`].
#[derive(Clone, Copy)]
pub enum PreparedLight<V: Point3 = Vec3> {
    /// A [`PreparedSphere`].
    Sphere(PreparedSphere<V>),
    /// A [`PreparedDisk`].
    Disk(PreparedDisk<V>),
    /// A [`PreparedTriangle`].
    Triangle(PreparedTriangle<V>),
    /// A [`PreparedRectangle`].
    Rectangle(PreparedRectangle<V>),
}

/// One body for every method: the same call on whichever light it is.
macro_rules! each {
    ($self:expr, $l:ident => $e:expr) => {
        match $self {
            Self::Sphere($l) => $e,
            Self::Disk($l) => $e,
            Self::Triangle($l) => $e,
            Self::Rectangle($l) => $e,
        }
    };
}

impl<V: Point3<Lane = L>, L: Math> Light<V> {
    /// The light prepared at shading point `p`.
    #[inline]
    pub fn at(&self, p: V) -> PreparedLight<V> {
        match self {
            Self::Sphere(l) => PreparedLight::Sphere(l.at(p)),
            Self::Disk(l) => PreparedLight::Disk(l.at(p)),
            Self::Triangle(l) => PreparedLight::Triangle(l.at(p)),
            Self::Rectangle(l) => PreparedLight::Rectangle(l.at(p)),
        }
    }

    /// A direction towards the light from `p`, its distance, Le and pdf per steradian.
    #[inline]
    pub fn sample(&self, p: V, u: V::Vec2) -> LightSample<V> {
        each!(self, l => l.sample(p, u))
    }

    /// The pdf per steradian of `sample` at `p` in unit direction `wi`.
    #[inline]
    pub fn pdf(&self, p: V, wi: V) -> L {
        each!(self, l => l.pdf(p, wi))
    }

    /// The distance from `p` along unit `wi` to the light, ∞ for a miss.
    #[inline]
    pub fn hit(&self, p: V, wi: V) -> L {
        each!(self, l => l.hit(p, wi))
    }

    /// A point on the light drawn uniformly by area, its normal, Le towards `p` and the pdf per
    /// unit area.
    #[inline]
    pub fn sample_area(&self, p: V, u: V::Vec2) -> AreaSample<V> {
        each!(self, l => l.sample_area(p, u))
    }

    /// The power the light emits: π·area·luminance(Le).
    #[inline]
    pub fn power(&self) -> L {
        each!(self, l => l.power())
    }
}

impl<V: Point3<Lane = L>, L: Math> PreparedLight<V> {
    /// A direction towards the light, its distance, Le and pdf per steradian.
    #[inline]
    pub fn sample(&self, u: V::Vec2) -> LightSample<V> {
        each!(self, l => l.sample(u))
    }

    /// The pdf per steradian of `sample` in unit direction `wi`.
    #[inline]
    pub fn pdf(&self, wi: V) -> L {
        each!(self, l => l.pdf(wi))
    }

    /// The distance along unit `wi` to the light, ∞ for a miss.
    #[inline]
    pub fn hit(&self, wi: V) -> L {
        each!(self, l => l.hit(wi))
    }

    /// `pdf` and `hit` at `wi` from one evaluation.
    #[inline]
    pub fn pdf_hit(&self, wi: V) -> (L, L) {
        each!(self, l => l.pdf_hit(wi))
    }

    /// The radiance arriving from every direction on the light (0 from behind it).
    #[inline]
    pub fn le(&self) -> V {
        each!(self, l => l.le())
    }
}

impl Light<Vec3> {
    /// The same light in every lane of width `V`: `Light<Vec3x8>` for a packet whose lanes
    /// share it, `Light<DVec3>` for the f64 reference. Each field is converted exactly (f32 to
    /// f64 is exact), so lane i of the result equals this light bit for bit.
    #[inline]
    pub fn splat<V: Point3>(&self) -> Light<V> {
        let s = |x: f32| V::Lane::c(f64::from(x));
        let v = |x: Vec3| V::from_lanes(V3::new(s(x.x), s(x.y), s(x.z)));
        match *self {
            Self::Sphere(l) => Light::Sphere(SphereLight::new(v(l.center), s(l.radius), v(l.le))),
            Self::Disk(l) => Light::Disk(DiskLight::new(
                v(l.center),
                v(l.normal),
                s(l.radius),
                v(l.le),
            )),
            Self::Triangle(l) => {
                Light::Triangle(TriangleLight::new(v(l.v[0]), v(l.v[1]), v(l.v[2]), v(l.le)))
            }
            Self::Rectangle(l) => {
                Light::Rectangle(RectangleLight::new(v(l.corner), v(l.ex), v(l.ey), v(l.le)))
            }
        }
    }
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

impl<V: Point3<Lane = L>, L: Math> LightSample<V> {
    /// The same sample with its pdf multiplied by a selection probability: what an estimator
    /// that chose the light at random must divide by.
    #[inline]
    pub fn chosen_with(self, pmf: L) -> Self {
        Self {
            pdf: self.pdf * pmf,
            ..self
        }
    }
}
