//! The lights of the scene as one family of the registry: each light with Le = 1, sampled from
//! the origin, its sample the unit direction and its pdf per steradian.

use core::fmt;
use core::hint::black_box;

use glam::Vec3;

use crate::lane::{V2, V3};
use crate::math::Math;
use crate::point::Point3;
use crate::scene::{AnyShape, Disk, Emitter, Light, Rectangle, Sphere, Triangle};
use crate::warp::family::{is_unit, lanes3};
use crate::warp::{self, Family, polygon_size};

/// A light of the scene of any shape, with Le = 1, seen from the origin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSampler(pub AnyShape);

/// sin and cos of 0.4 rad, the square light's tilt about x.
const TILT: (f32, f32) = (0.389_418_33, 0.921_061);

/// A square light of side `s` one unit up, tilted about x by 0.4 rad.
const fn square(s: f32) -> LightSampler {
    LightSampler(AnyShape::Rectangle(Rectangle {
        corner: Vec3::new(-0.5 * s, -0.3 * s, 1.0),
        ex: Vec3::new(s, 0.0, 0.0),
        ey: Vec3::new(0.0, s * TILT.1, s * TILT.0),
    }))
}

/// A disk light one unit across at distance 2, facing the origin at a slant.
const fn disk(radius: f32) -> LightSampler {
    LightSampler(AnyShape::Disk(Disk {
        center: Vec3::new(0.4, 0.3, 2.0),
        normal: Vec3::new(0.2, -0.3, -1.0),
        radius,
    }))
}

/// A sphere light.
const fn sphere(center: Vec3, radius: f32) -> LightSampler {
    LightSampler(AnyShape::Sphere(Sphere { center, radius }))
}

/// The registry's test triangle of size `s` as a light.
const fn triangle(s: f32) -> LightSampler {
    LightSampler(AnyShape::Triangle(Triangle {
        v: super::triangle(s),
    }))
}

impl LightSampler {
    /// The registered lights: a sphere far, tiny (sin²θmax = 1e-4) and around the point, a disk
    /// large and small, a triangle large and sampled by area, a square large and small.
    pub const REGISTERED: [LightSampler; 9] = [
        sphere(Vec3::new(0.6, -0.3, 3.0), 1.0),
        sphere(Vec3::new(0.2, 0.1, 1.0), 1.02e-2),
        sphere(Vec3::new(0.3, -0.2, 0.25), 1.0),
        disk(1.0),
        disk(0.02),
        triangle(1.0),
        triangle(1e-3),
        square(1.0),
        square(0.05),
    ];

    /// The scene light, in the width of `V`.
    #[inline(always)]
    pub fn light<V: Point3<Lane = L>, L: Math>(&self) -> Light<V> {
        Emitter {
            shape: self.0.splat(),
            le: V::from_lanes(V3::all(L::ONE)),
        }
    }

    /// How a polygon light is sampled ([`polygon_size`]); "" for the sphere and the disk.
    pub fn size(&self) -> &'static str {
        let pdf = self.sampler::<f32>()(V2::new(0.5, 0.5)).1;
        match self.0 {
            AnyShape::Triangle(_) => polygon_size(pdf, warp::SPHERICAL_TRIANGLE_MIN_SR),
            AnyShape::Rectangle(_) => polygon_size(pdf, warp::SPHERICAL_RECTANGLE_MIN_SR),
            AnyShape::Sphere(_) | AnyShape::Disk(_) => "",
        }
    }
}

impl Family for LightSampler {
    fn name(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.0 {
            AnyShape::Sphere(Sphere { center, radius }) => {
                let sin = radius as f64 / center.as_dvec3().length();
                let s2 = sin * sin;
                if s2 >= 1.0 {
                    f.write_str("light_sphere inside")
                } else {
                    write!(f, "light_sphere sin2={s2:.0e}")
                }
            }
            AnyShape::Disk(Disk { radius, .. }) => write!(f, "light_disk r={radius}"),
            AnyShape::Triangle(_) => write!(f, "light_triangle {}", self.size()),
            AnyShape::Rectangle(_) => write!(f, "light_rectangle {}", self.size()),
        }
    }
    fn sampler<L: Math>(&self) -> impl Fn(V2<L>) -> (V3<L>, L) + Copy {
        let light = self.light::<V3<L>, L>();
        // The light passes through `black_box` so that a loop over a batch pays the light's
        // set-up at every sample, as a renderer does when each sample has its own shading point.
        #[inline(always)]
        move |u| {
            let s = black_box(light).sample(V3::all(L::ZERO), u);
            (s.wi, s.pdf)
        }
    }
    fn pdf<L: Math>(&self, x: V3<L>) -> L {
        self.light::<V3<L>, L>().pdf(V3::all(L::ZERO), x)
    }
    fn inverse<L: Math>(&self, _: V3<L>) -> Option<V2<L>> {
        None
    }
    fn in_domain(&self, x: Vec3) -> bool {
        // A light's direction is unit and on the light, as its f32 pdf says.
        is_unit(x) && self.pdf(lanes3::<f32>(x)) > 0.0
    }
}
