//! The lights of the scene as one family of the registry: each light with Le = 1, sampled from
//! the origin, its sample the unit direction and its pdf per steradian.

use core::fmt;
use core::hint::black_box;

use glam::Vec3;

use crate::lane::{V2, V3};
use crate::math::Math;
use crate::point::Point3;
use crate::scene::{DiskLight, Light, RectangleLight, SphereLight, TriangleLight};
use crate::warp::family::{is_unit, lane, lanes3};
use crate::warp::{self, Family, polygon_size};

/// A light of the scene, with Le = 1, seen from the origin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LightSampler {
    /// [`SphereLight`].
    Sphere {
        /// The centre.
        center: Vec3,
        /// The radius.
        radius: f32,
    },
    /// [`DiskLight`].
    Disk {
        /// The centre.
        center: Vec3,
        /// The normal.
        normal: Vec3,
        /// The radius.
        radius: f32,
    },
    /// [`TriangleLight`].
    Triangle {
        /// The vertices.
        v: [Vec3; 3],
    },
    /// [`RectangleLight`].
    Rectangle {
        /// Corner, ex, ey (orthogonal).
        v: [Vec3; 3],
    },
}

/// sin and cos of 0.4 rad, the square light's tilt about x.
const TILT: (f32, f32) = (0.389_418_33, 0.921_061);

/// A square light of side `s` one unit up, tilted about x by 0.4 rad: corner and orthogonal edges.
const fn square_light(s: f32) -> [Vec3; 3] {
    [
        Vec3::new(-0.5 * s, -0.3 * s, 1.0),
        Vec3::new(s, 0.0, 0.0),
        Vec3::new(0.0, s * TILT.1, s * TILT.0),
    ]
}

/// A disk light one unit across at distance 2, facing the origin at a slant.
const fn disk(radius: f32) -> LightSampler {
    LightSampler::Disk {
        center: Vec3::new(0.4, 0.3, 2.0),
        normal: Vec3::new(0.2, -0.3, -1.0),
        radius,
    }
}

impl LightSampler {
    /// The registered lights: a sphere far, tiny (sin²θmax = 1e-4) and around the point, a disk
    /// large and small, a triangle large and sampled by area, a square large and small.
    pub const REGISTERED: [LightSampler; 9] = [
        LightSampler::Sphere {
            center: Vec3::new(0.6, -0.3, 3.0),
            radius: 1.0,
        },
        LightSampler::Sphere {
            center: Vec3::new(0.2, 0.1, 1.0),
            radius: 1.02e-2,
        },
        LightSampler::Sphere {
            center: Vec3::new(0.3, -0.2, 0.25),
            radius: 1.0,
        },
        disk(1.0),
        disk(0.02),
        LightSampler::Triangle {
            v: super::triangle(1.0),
        },
        LightSampler::Triangle {
            v: super::triangle(1e-3),
        },
        LightSampler::Rectangle {
            v: square_light(1.0),
        },
        LightSampler::Rectangle {
            v: square_light(0.05),
        },
    ];

    /// The scene light, in the width of `V`.
    #[inline(always)]
    pub fn light<V: Point3<Lane = L>, L: Math>(&self) -> Light<V> {
        let v = |p: Vec3| V::from_lanes(lanes3(p));
        let one = V::from_lanes(V3::all(L::ONE));
        match *self {
            LightSampler::Sphere { center, radius } => {
                Light::from(SphereLight::new(v(center), lane(radius), one))
            }
            LightSampler::Disk {
                center,
                normal,
                radius,
            } => Light::from(DiskLight::new(v(center), v(normal), lane(radius), one)),
            LightSampler::Triangle { v: [a, b, c] } => {
                Light::from(TriangleLight::new(v(a), v(b), v(c), one))
            }
            LightSampler::Rectangle { v: [c, ex, ey] } => {
                Light::from(RectangleLight::new(v(c), v(ex), v(ey), one))
            }
        }
    }

    /// How a polygon light is sampled ([`polygon_size`]); "" for the sphere and the disk.
    pub fn size(&self) -> &'static str {
        let pdf = self.sampler::<f32>()(V2::new(0.5, 0.5)).1;
        match self {
            LightSampler::Triangle { .. } => polygon_size(pdf, warp::SPHERICAL_TRIANGLE_MIN_SR),
            LightSampler::Rectangle { .. } => polygon_size(pdf, warp::SPHERICAL_RECTANGLE_MIN_SR),
            LightSampler::Sphere { .. } | LightSampler::Disk { .. } => "",
        }
    }
}

impl Family for LightSampler {
    fn name(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            LightSampler::Sphere { center, radius } => {
                let sin = radius as f64 / center.as_dvec3().length();
                let s2 = sin * sin;
                if s2 >= 1.0 {
                    f.write_str("light_sphere inside")
                } else {
                    write!(f, "light_sphere sin2={s2:.0e}")
                }
            }
            LightSampler::Disk { radius, .. } => write!(f, "light_disk r={radius}"),
            LightSampler::Triangle { .. } => write!(f, "light_triangle {}", self.size()),
            LightSampler::Rectangle { .. } => write!(f, "light_rectangle {}", self.size()),
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
