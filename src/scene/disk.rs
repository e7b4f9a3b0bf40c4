//! The disk: uniform in solid angle over its spherical ellipse, or uniform by area through the
//! concentric map, converted to solid angle.

use core::f64::consts::PI;

use glam::Vec3;

use super::emitter::Emitter;
use super::select::{splat_lane, splat_vec};
use super::shape::{
    AreaPoint, AtPoint, LightSampling, PreparedShape, Shape, ShapeSample, on_shape,
};
use crate::frame::Frame;
use crate::lane::{Lane, Mask, V2, V3};
use crate::math::Math;
use crate::point::{Point2, Point3, Split, split_fields};
use crate::warp::dot_wide;
use crate::warp::{SphericalEllipse, concentric_disk};

/// A disk of radius `radius` about `center`, facing along `normal` (normalised on use); as a
/// light ([`DiskLight`](super::DiskLight)) it emits on that side.
///
/// Prepared with [`LightSampling::Area`] it samples a point uniformly by area through the
/// concentric map (Shirley and Chiu 1997) and converts to solid angle: pdf t²/(|cos θ_l|·πr²) =
/// h²/(|wi·n|³·πr²) per steradian, with h the shading point's distance to the disk's plane. wi·n
/// is formed in f64 for the f32 lanes, since it cancels for a disk seen edge-on and the pdf goes
/// with its cube. In every other mode it samples uniformly in the solid angle Ω of its spherical
/// ellipse ([`SphericalEllipse`]), pdf 1/Ω, where Ω is at least
/// [`ELLIPSE_MIN_SR`](crate::warp::ELLIPSE_MIN_SR) (below, by area, where the two agree).
///
/// `pdf` and `hit` call a direction on the disk when its hit point lies within r(1 + 4ε) of the
/// centre, widened by what a direction error of 2ε (ε the lane's epsilon) does to the hit point:
/// 2ε·t across the line of sight and 2ε·t/|cos θ_l| along it. The slack covers the rounding of a
/// sample's direction, so every sample keeps its pdf.
///
/// A shading point within 1e-6 rad of the disk's plane, a zero or non-finite radius or normal,
/// and NaN give pdf 0.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Disk<V: Point3 = Vec3> {
    /// The centre.
    pub center: V,
    /// The normal: the side the disk faces.
    pub normal: V,
    /// The radius.
    pub radius: V::Lane,
}

split_fields!(Disk<V: Point3> by V::Lane { center: point, normal: point, radius });

/// A disk light: a [`Disk`] emitting on the side of its normal.
pub type DiskLight<V = Vec3> = Emitter<Disk<V>, V>;

impl<V: Point3> DiskLight<V> {
    /// The disk of radius `radius` about `center`, facing along `normal`, emitting `le`.
    #[inline]
    pub fn new(center: V, normal: V, radius: V::Lane, le: V) -> Self {
        Emitter {
            shape: Disk {
                center,
                normal,
                radius,
            },
            le,
        }
    }
}

impl Disk<Vec3> {
    /// The same disk in every lane of width `W`, exactly.
    #[inline]
    pub fn splat<W: Point3>(&self) -> Disk<W> {
        Disk {
            center: splat_vec(self.center),
            normal: splat_vec(self.normal),
            radius: splat_lane(self.radius),
        }
    }
}

/// A [`Disk`] prepared at one shading point.
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
    valid: <V::Lane as Lane>::Mask,
    /// The spherical ellipse (every mode but [`LightSampling::Area`]), and the lanes it samples.
    ellipse: Option<SphericalEllipse<V3<V::Lane>>>,
    by_ellipse: <V::Lane as Lane>::Mask,
}

impl<V: Point3<Lane = L>, L: Math> Shape<V> for Disk<V> {
    type Prepared = PreparedDisk<V>;
    type Half = Disk<V::Half>;

    #[inline(always)]
    fn halves(&self) -> (Disk<V::Half>, Disk<V::Half>) {
        Split::halves(*self)
    }

    #[inline(always)]
    fn at(&self, p: V, _n: V, sampling: LightSampling) -> PreparedDisk<V> {
        self.prepare(p, sampling, true)
    }

    /// A pdf or a distance at one point needs the ellipse's Ω and the hit test, not its
    /// sampling table.
    #[inline(always)]
    fn with_at<W: AtPoint<V>>(&self, p: V, _n: V, sampling: LightSampling, work: W) -> W::Output {
        let samples = work.samples();
        work.run(&self.prepare(p, sampling, samples))
    }

    /// A point uniform on the disk (the concentric map), its normal and the area pdf 1/(πr²).
    #[inline]
    fn sample_area(&self, u: V::Vec2) -> AreaPoint<V> {
        let frame = Frame::from_normal(self.normal.to_lanes().normalize());
        let r = self.radius;
        let x = self.center.to_lanes() + offset(&frame, r, u.to_lanes());
        AreaPoint {
            p: V::from_lanes(x),
            n: V::from_lanes(frame.n),
            pdf: L::c(1.0 / PI) / (r * r),
        }
    }

    /// πr².
    #[inline]
    fn area(&self) -> L {
        let r = self.radius;
        L::c(PI) * r * r
    }

    #[inline]
    fn modes(&self) -> &'static [LightSampling] {
        &[LightSampling::SolidAngle, LightSampling::Area]
    }
}

impl<V: Point3<Lane = L>, L: Math> Disk<V> {
    /// The disk prepared at `p`; with `table` false, its ellipse without the sampling table
    /// (for a pdf or a distance alone, [`SphericalEllipse::for_pdf`]).
    #[inline(always)]
    fn prepare(&self, p: V, sampling: LightSampling, table: bool) -> PreparedDisk<V> {
        let d = self.center.to_lanes() - p.to_lanes();
        let n = self.normal.to_lanes().normalize();
        let r = self.radius;
        let h = d.dot(n);
        let area_pdf = L::c(1.0 / PI) / (r * r);
        let valid = r.gt(L::ZERO)
            & area_pdf.is_finite()
            & h.abs().gt(L::c(1e-6) * d.length())
            & h.is_finite();
        let ellipse = match sampling {
            LightSampling::Area => None,
            _ if table => Some(SphericalEllipse::new(d, n, r)),
            _ => Some(SphericalEllipse::for_pdf(d, n, r)),
        };
        let by_ellipse = match &ellipse {
            Some(e) => valid & !e.by_area(),
            None => L::ZERO.gt(L::ZERO),
        };
        PreparedDisk {
            d,
            frame: Frame::from_normal(n),
            r,
            h,
            area_pdf,
            valid,
            ellipse,
            by_ellipse,
        }
    }
}

impl<V: Point3<Lane = L>, L: Math> PreparedDisk<V> {
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
}

impl<V: Point3<Lane = L>, L: Math> PreparedShape<V> for PreparedDisk<V> {
    #[inline]
    fn sample(&self, u: V::Vec2) -> ShapeSample<V> {
        let mut wi = V3::default();
        if (!self.by_ellipse).any() {
            wi = (self.d + offset(&self.frame, self.r, u.to_lanes())).normalize_scaled();
        }
        // Where the ellipse drops the sample (NaN u), pdf 0 at +z; elsewhere the disk's own
        // hit test (in `eval`) decides, as for any direction.
        let mut dropped = L::ZERO.gt(L::ZERO);
        if let Some(e) = self.ellipse.as_ref().filter(|_| self.by_ellipse.any()) {
            let (w, nan) = e.direction(u.to_lanes());
            let w = V3::select(nan, V3::new(L::ZERO, L::ZERO, L::ONE), w);
            wi = V3::select(self.by_ellipse, w, wi);
            dropped = self.by_ellipse & nan;
        }
        let (pdf, dist) = self.eval(V::from_lanes(wi));
        let pdf = L::select(dropped, L::ZERO, pdf);
        ShapeSample {
            wi: V::from_lanes(wi),
            pdf,
            dist,
        }
    }

    /// 1/Ω (by the ellipse) or h²/(|wi·n|³·πr²) (by area) on the disk, with the distance to its
    /// plane.
    #[inline(always)]
    fn eval(&self, wi: V) -> (L, L) {
        let (wn, t, on) = self.ray(wi.to_lanes());
        let c = wn.abs();
        let pdf = self.area_pdf * (self.h * self.h) / (c * c * c);
        let pdf = match &self.ellipse {
            Some(e) => L::select(self.by_ellipse, L::ONE / e.solid_angle(), pdf),
            None => pdf,
        };
        on_shape(L::select(on, pdf, L::ZERO), t)
    }

    /// The shading point is in front of the disk.
    #[inline(always)]
    fn front(&self) -> L::Mask {
        self.h.lt(L::ZERO)
    }
}

/// The point of the disk of radius `r` in `frame`'s tangent plane for u, relative to the centre.
#[inline(always)]
fn offset<L: Math>(frame: &Frame<V3<L>>, r: L, u: V2<L>) -> V3<L> {
    let q: V2<L> = concentric_disk(u);
    (frame.t.scale(q.x) + frame.b.scale(q.y)).scale(r)
}
