//! The disk light: uniform by area through the concentric map, converted to solid angle.

use core::f64::consts::PI;

use glam::Vec3;

use crate::frame::Frame;
use crate::lane::{V2, V3};
use crate::math::Math;
use crate::point::{Point2, Point3};
use crate::scene::{AreaSample, LightSample, area_sample, le_towards, light_sample, on_light};
use crate::warp::concentric_disk;
use crate::warp::dot_wide;

/// A disk light of radius `radius` about `center`, facing along `normal` (normalised on use), and
/// emitting radiance `le` on that side.
///
/// It samples a point uniformly by area through the concentric map (Shirley and Chiu 1997) and
/// converts to solid angle: pdf t²/(|cos θ_l|·πr²) = h²/(|wi·n|³·πr²) per steradian, with h the
/// shading point's distance to the disk's plane. wi·n is formed in f64 for the f32 lanes, since
/// it cancels for a disk seen edge-on and the pdf goes with its cube.
///
/// `pdf` and `hit` call a direction on the disk when its hit point lies within r(1 + 4ε) of the
/// centre, widened by what a direction error of 2ε (ε the lane's epsilon) does to the hit point:
/// 2ε·t across the line of sight and 2ε·t/|cos θ_l| along it. The slack covers the rounding of a
/// sample's direction, so every sample keeps its pdf.
///
/// A shading point within 1e-6 rad of the disk's plane, a zero or non-finite radius or normal,
/// and NaN give pdf 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DiskLight<V: Point3 = Vec3> {
    /// The centre.
    pub center: V,
    /// The normal: the side the disk emits on.
    pub normal: V,
    /// The radius.
    pub radius: V::Lane,
    /// The emitted radiance (RGB).
    pub le: V,
}

/// A [`DiskLight`] prepared at one shading point: [`DiskLight::at`].
#[derive(Clone, Copy)]
pub struct PreparedDisk<V: Point3 = Vec3> {
    /// Centre minus shading point.
    d: V3<V::Lane>,
    frame: Frame<V3<V::Lane>>,
    r: V::Lane,
    /// The plane's offset d·n: negative where the shading point is on the emitting side.
    h: V::Lane,
    /// 1/(πr²), the area pdf.
    area_pdf: V::Lane,
    valid: <V::Lane as crate::lane::Lane>::Mask,
    le: V3<V::Lane>,
}

impl<V: Point3<Lane = L>, L: Math> DiskLight<V> {
    /// The disk of radius `radius` about `center`, facing along `normal`.
    #[inline]
    pub fn new(center: V, normal: V, radius: L, le: V) -> Self {
        Self {
            center,
            normal,
            radius,
            le,
        }
    }

    /// The light prepared at shading point `p`.
    #[inline]
    pub fn at(&self, p: V) -> PreparedDisk<V> {
        let d = self.center.to_lanes() - p.to_lanes();
        let n = self.normal.to_lanes().normalize();
        let r = self.radius;
        let h = d.dot(n);
        let area_pdf = L::c(1.0 / PI) / (r * r);
        let valid = r.gt(L::ZERO)
            & area_pdf.is_finite()
            & h.abs().gt(L::c(1e-6) * d.length())
            & h.is_finite();
        PreparedDisk {
            d,
            frame: Frame::from_normal(n),
            r,
            h,
            area_pdf,
            valid,
            le: self.le.to_lanes(),
        }
    }

    super::at_one_point!(PreparedDisk);

    /// A point uniform on the disk (the concentric map), its normal, Le towards `p` and the area
    /// pdf 1/(πr²).
    #[inline]
    pub fn sample_area(&self, p: V, u: V::Vec2) -> AreaSample<V> {
        let s = self.at(p);
        let x = self.center.to_lanes() + s.offset(u.to_lanes());
        area_sample(p.to_lanes(), x, s.frame.n, s.area_pdf, s.le)
    }

    /// The power the light emits, π·πr²·luminance(Le).
    #[inline]
    pub fn power(&self) -> L {
        let r = self.radius;
        L::c(PI * PI) * r * r * super::luminance(self.le.to_lanes())
    }
}

impl<V: Point3<Lane = L>, L: Math> PreparedDisk<V> {
    /// The point of the disk for u, relative to the centre.
    #[inline(always)]
    fn offset(&self, u: V2<L>) -> V3<L> {
        let q: V2<L> = concentric_disk(u);
        (self.frame.t.scale(q.x) + self.frame.b.scale(q.y)).scale(self.r)
    }

    /// A direction towards the light, its distance, Le and pdf per steradian (see
    /// [`DiskLight`]). u is clamped to [0, 1]²; NaN gives the dropped sample (pdf 0).
    #[inline]
    pub fn sample(&self, u: V::Vec2) -> LightSample<V> {
        let wi = (self.d + self.offset(u.to_lanes())).normalize_scaled();
        let (pdf, t) = self.eval(wi);
        light_sample(wi, t, self.le().to_lanes(), pdf)
    }

    super::from_eval!();

    /// The shading point is in front of the disk.
    #[inline(always)]
    fn front(&self) -> L::Mask {
        self.h.lt(L::ZERO)
    }

    /// wi·n (in f64 for the f32 lanes), the distance t along wi to the plane, and whether the
    /// ray meets the disk in front of the shading point.
    #[inline(always)]
    fn ray(&self, wi: V3<L>) -> (L, L, L::Mask) {
        let n = self.frame.n;
        let wn = dot_wide([wi.x, wi.y, wi.z], [n.x, n.y, n.z]);
        let t = self.h / wn;
        // The hit's offset from the centre is n × (wi × d) / (wi·n): the component of wi × d
        // across n, with no cancellation between the long vectors t·wi and d.
        let v = wi.cross(self.d);
        let across = v - n.scale(v.dot(n));
        let m = across.length();
        // On the disk: |offset| = m/|wi·n| ≤ r, with a slack for a direction error of 2ε: it
        // moves the hit by 2εt across the line of sight, and by 2εt/|wi·n| along its
        // projection onto the plane. So m ≤ r|wi·n|(1 + 4ε) + 2εt(|wi·n| + |ê·wp|), with ê the
        // offset's direction and wp the direction's part in the plane; multiplied through by m
        // so that the centre (m = 0) needs no division.
        let slack = L::TWO * L::EPSILON * t;
        let wp = wi - n.scale(wn);
        let a = (self.r * wn.abs()).mul_add(L::ONE + L::c(4.0) * L::EPSILON, slack * wn.abs());
        let on =
            t.gt(L::ZERO) & (m * m).le(a.mul_add(m, slack * across.dot(wp).abs())) & self.valid;
        (wn, t, on)
    }

    /// The pdf and the hit distance of unit `wi` together, from one test of whether it is on the
    /// light: pdf > 0 exactly where t < ∞.
    #[inline(always)]
    fn eval(&self, wi: V3<L>) -> (L, L) {
        let (wn, t, on) = self.ray(wi);
        let c = wn.abs();
        let pdf = self.area_pdf * (self.h * self.h) / (c * c * c);
        on_light(L::select(on, pdf, L::ZERO), t)
    }
}
