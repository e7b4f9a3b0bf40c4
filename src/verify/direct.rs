//! Scenes for the direct-lighting estimator, each with its reference value, and a runner that
//! measures a strategy on one: the registry that the tests, the report, the benches and the fuzz
//! target share.
//!
//! - [`analytic_scenes`]: a Lambertian point (albedo 1, so L = E/π) under a sphere above the
//!   horizon, a sphere partly below it, a rectangle and a disk on its axis, and lights that
//!   overlap in direction (one hiding another, or not; chosen uniformly or by power), with
//!   references from [`crate::reference`];
//! - [`quadrature_scenes`]: a Lambert and a Phong point under a sphere light, with references by
//!   [`sphere_light_quadrature`];
//! - [`grid_scenes`]: the lecture's MIS figure, Phong exponents {10, 100, 1000, 10000} × sphere
//!   lights of angular radius {0.005, 0.05, 0.2, 0.5} rad centred on the mirror direction,
//!   named `grid_n{exponent}_r{radius}`.
//!
//! Every scene is white (Le = 1, white reflectances), so the three channels agree and the
//! runner measures the first.

use std::format;
use std::string::String;
use std::vec::Vec;

use glam::{DVec3, Vec3};

use crate::direct::{self, Config, Lights, ShadingPoint, Strategy};
use crate::estimate::MeanVar;
use crate::lane::{F32x8, Lane, V3};
use crate::point::Point3;
use crate::scene::{
    Bsdf, BsdfSample, DiskLight, Lambert, Light, Phong, PowerTable, RectangleLight, SphereLight,
    TriangleLight,
};
use crate::seq::{Generator, Sequence};
use crate::x8::{U32x8, Vec3x8};

/// A BSDF of either kind, so that scenes can hold one.
#[derive(Clone, Copy, Debug)]
pub enum Material<V: Point3 = Vec3> {
    /// Lambert.
    Lambert(Lambert<V>),
    /// Modified Phong.
    Phong(Phong<V>),
}

impl<V: Point3> Bsdf<V> for Material<V>
where
    Lambert<V>: Bsdf<V>,
    Phong<V>: Bsdf<V>,
{
    fn eval(&self, wo: V, wi: V) -> V {
        match self {
            Self::Lambert(b) => b.eval(wo, wi),
            Self::Phong(b) => b.eval(wo, wi),
        }
    }
    fn sample(&self, wo: V, u: V::Vec2) -> BsdfSample<V> {
        match self {
            Self::Lambert(b) => b.sample(wo, u),
            Self::Phong(b) => b.sample(wo, u),
        }
    }
    fn pdf(&self, wo: V, wi: V) -> V::Lane {
        match self {
            Self::Lambert(b) => b.pdf(wo, wi),
            Self::Phong(b) => b.pdf(wo, wi),
        }
    }
}

impl Material {
    /// The same material in every lane of width `V`.
    pub fn splat<V: Point3>(&self) -> Material<V> {
        let c = |x: f32| <V::Lane as Lane>::c(f64::from(x));
        let v = |x: Vec3| V::from_lanes(V3::new(c(x.x), c(x.y), c(x.z)));
        match *self {
            Self::Lambert(b) => Material::Lambert(Lambert::new(v(b.rho))),
            Self::Phong(b) => Material::Phong(Phong::new(v(b.kd), v(b.ks), c(b.n))),
        }
    }
}

/// A shading point, its material and lights, and the reference value of L(x, ωo).
#[derive(Clone, Debug)]
pub struct DirectScene {
    /// The name the report and its JSON use.
    pub name: String,
    /// The lights.
    pub lights: Vec<Light>,
    /// The BSDF.
    pub material: Material,
    /// Where the estimate is taken.
    pub at: ShadingPoint,
    /// L(x, ωo) per channel, from an analytic formula or quadrature (f64).
    pub reference: f64,
    /// True where the reference is a closed form rather than quadrature.
    pub analytic: bool,
    /// Spheres (centre, radius) that block shadow rays: the caller's visibility. A light may be
    /// one of them, hiding what is behind it.
    pub occluders: Vec<(Vec3, f32)>,
    /// Lights chosen in proportion to power rather than uniformly.
    pub by_power: bool,
}

impl DirectScene {
    /// The scene's lights as the estimator takes them, chosen by power (a table built in
    /// `table`) or uniformly.
    pub fn lights<'a>(&'a self, table: &'a mut Vec<f32>) -> Lights<'a> {
        if self.by_power {
            table.resize(self.lights.len(), 0.0);
            Lights::by_power(&self.lights, PowerTable::new(&self.lights, table))
        } else {
            Lights::uniform(&self.lights)
        }
    }

    /// Whether the segment from `from` to `to` is clear of every occluder (an end on an
    /// occluder's surface is not blocked by it).
    pub fn visible(&self, from: Vec3, to: Vec3) -> bool {
        let (o, e) = (from.as_dvec3(), to.as_dvec3());
        let len = (e - o).length();
        let d = (e - o) / len;
        self.occluders.iter().all(|&(c, r)| {
            let oc = o - c.as_dvec3();
            let r = f64::from(r);
            let b = oc.dot(d);
            let disc = b * b - (oc.dot(oc) - r * r);
            if disc <= 0.0 {
                return true;
            }
            let (t0, t1) = (-b - disc.sqrt(), -b + disc.sqrt());
            let end = len * (1.0 - 1e-4);
            !(t0 > 1e-6 * len && t0 < end || t1 > 1e-6 * len && t1 < end)
        })
    }
}

fn lambert_point() -> (Material, ShadingPoint) {
    let m = Material::Lambert(Lambert::new(Vec3::ONE));
    let at = ShadingPoint {
        p: Vec3::ZERO,
        n: Vec3::Z,
        wo: Vec3::new(0.3, 0.1, 0.9).normalize(),
    };
    (m, at)
}

/// A sphere of radius `r` at distance `d` from the origin, at angle `theta` from +z.
fn sphere_at(theta: f64, d: f64, r: f64) -> SphereLight {
    let c = DVec3::new(libm::sin(theta), 0.0, libm::cos(theta)) * d;
    SphereLight::new(c.as_vec3(), r as f32, Vec3::ONE)
}

/// The scenes with closed-form references (Lambert, albedo 1: L = E/π): a sphere above and one
/// straddling the horizon, a rectangle and a tilted triangle overhead, a disk on its axis, and
/// the overlapping lights.
pub fn analytic_scenes() -> Vec<DirectScene> {
    use core::f64::consts::PI;
    let (material, at) = lambert_point();
    let scene = |name: &str, light: Light, e: f64| DirectScene {
        name: name.into(),
        lights: std::vec![light],
        material,
        at,
        reference: e / PI,
        analytic: true,
        occluders: Vec::new(),
        by_power: false,
    };
    // The light's own f32 geometry is the one the reference sees.
    let above = sphere_at(0.5, 4.0, 1.0);
    let below = sphere_at(1.4, 2.0, 0.8);
    let sigma = |s: &SphereLight| {
        libm::asin(f64::from(s.shape.radius) / f64::from(s.shape.center.length()))
    };
    let theta = |s: &SphereLight| {
        libm::acos(f64::from(s.shape.center.z) / f64::from(s.shape.center.length()))
    };
    let rect = RectangleLight::new(
        Vec3::new(-0.5, -1.0, 1.5),
        Vec3::new(0.0, 2.0, 0.0),
        Vec3::new(1.5, 0.0, 0.0),
        Vec3::ONE,
    );
    let corners = [
        rect.shape.corner,
        rect.shape.corner + rect.shape.ex,
        rect.shape.corner + rect.shape.ex + rect.shape.ey,
        rect.shape.corner + rect.shape.ey,
    ]
    .map(|v| [f64::from(v.x), f64::from(v.y), f64::from(v.z)]);
    let disk = DiskLight::new(Vec3::new(0.0, 0.0, 2.0), Vec3::NEG_Z, 1.5, Vec3::ONE);
    // Tilted: the receiver's cosine is 0.32 to 0.78 across it.
    let tri = [
        Vec3::new(-1.5, -0.5, 1.0),
        Vec3::new(0.5, 1.5, 2.0),
        Vec3::new(1.5, -1.0, 0.6),
    ];
    let tri_light = TriangleLight::new(tri[0], tri[1], tri[2], Vec3::ONE);
    let tri_vertices = tri.map(|v| [f64::from(v.x), f64::from(v.y), f64::from(v.z)]);
    std::vec![
        scene(
            "sphere_above",
            Light::from(above),
            crate::reference::sphere_irradiance(sigma(&above), theta(&above)),
        ),
        scene(
            "sphere_horizon",
            Light::from(below),
            crate::reference::sphere_irradiance(sigma(&below), theta(&below)),
        ),
        scene(
            "rectangle",
            Light::from(rect),
            crate::reference::polygon_irradiance([0.0, 0.0, 1.0], &corners),
        ),
        scene(
            "triangle",
            Light::from(tri_light),
            crate::reference::polygon_irradiance([0.0, 0.0, 1.0], &tri_vertices),
        ),
        scene(
            "disk_axis",
            Light::from(disk),
            crate::reference::disk_irradiance_on_axis(1.5, 2.0),
        ),
    ]
    .into_iter()
    .chain(overlapping_scenes())
    .collect()
}

/// Lights that overlap in direction, which every other scene avoids: a sphere of radius 0.3 at
/// (0, 0, 1) in front of a disk of radius 1 at (0, 0, 2) facing down, over the Lambertian point
/// (albedo 1, n = +z, ωo towards (0.3, 0, 1)).
/// - `overlap_sphere_disk`: independent emitters, L = 0.09 + 0.2 = 0.29 (the sphere's
///   π sin²σ cos θ over π, and the disk's R²/(R² + h²)).
/// - `overlap_occluded`: the sphere also hides the disk behind it; the part hidden is the
///   sphere's own cone, so L = 0.2.
/// - `overlap_three_by_power`: a 4 × 4 square at height 3 facing down added behind both, the
///   three chosen by power.
fn overlapping_scenes() -> Vec<DirectScene> {
    use core::f64::consts::PI;
    let m = Material::Lambert(Lambert::new(Vec3::ONE));
    let at = ShadingPoint {
        p: Vec3::ZERO,
        n: Vec3::Z,
        wo: Vec3::new(0.3, 0.0, 1.0).normalize(),
    };
    let sphere = SphereLight::new(Vec3::Z, 0.3, Vec3::ONE);
    let disk = DiskLight::new(Vec3::new(0.0, 0.0, 2.0), Vec3::NEG_Z, 1.0, Vec3::ONE);
    let square = RectangleLight::new(
        Vec3::new(-2.0, -2.0, 3.0),
        Vec3::new(0.0, 4.0, 0.0),
        Vec3::new(4.0, 0.0, 0.0),
        Vec3::ONE,
    );
    let e_sphere = crate::reference::sphere_irradiance(libm::asin(0.3), 0.0);
    let e_disk = crate::reference::disk_irradiance_on_axis(1.0, 2.0);
    let e_square = crate::reference::polygon_irradiance(
        [0.0, 0.0, 1.0],
        &[
            [-2.0, -2.0, 3.0],
            [-2.0, 2.0, 3.0],
            [2.0, 2.0, 3.0],
            [2.0, -2.0, 3.0],
        ],
    );
    let scene =
        |name: &str, lights: Vec<Light>, e: f64, occluded: bool, by_power: bool| DirectScene {
            name: name.into(),
            lights,
            material: m,
            at,
            reference: e / PI,
            analytic: true,
            occluders: if occluded {
                std::vec![(sphere.shape.center, sphere.shape.radius)]
            } else {
                Vec::new()
            },
            by_power,
        };
    let two = || std::vec![Light::from(sphere), Light::from(disk)];
    std::vec![
        scene(
            "overlap_sphere_disk",
            two(),
            e_sphere + e_disk,
            false,
            false
        ),
        scene("overlap_occluded", two(), e_disk, true, false),
        scene(
            "overlap_three_by_power",
            std::vec![Light::from(sphere), Light::from(disk), Light::from(square)],
            e_sphere + e_disk + e_square,
            false,
            true,
        ),
    ]
}

/// The modified Phong BSDF in f64, written out for the quadrature: kd/π + ks(n+2)/(2π)cosⁿα.
fn phong_f64(kd: f64, ks: f64, n: f64, wo: DVec3, wi: DVec3) -> f64 {
    use core::f64::consts::PI;
    if wo.z <= 0.0 || wi.z <= 0.0 {
        return 0.0;
    }
    let mirror = DVec3::new(-wo.x, -wo.y, wo.z);
    let c = wi.dot(mirror).max(0.0);
    kd / PI + ks * (n + 2.0) / (2.0 * PI) * libm::pow(c, n)
}

/// L(x, ωo) for a sphere light of radiance 1 seen from the origin (normal +z) by
/// `∫_cone f(ωo, ωi) cos θ dωi`, f the modified Phong BSDF (kd, ks, n) (Lambert: ks = 0).
///
/// The cone is parameterised by t = 1 − cos θ' about its axis and φ: dω = dt dφ. t runs over
/// `panels` Gauss–Legendre panels (8 nodes each) graded as (i/panels)³ towards the axis, where a
/// lobe centred on the axis decays as e^{−nt}; φ by the trapezoid rule on 256 nodes, which is
/// spectrally accurate for a smooth periodic integrand.
pub fn sphere_light_quadrature(
    center: DVec3,
    radius: f64,
    wo: DVec3,
    (kd, ks, n): (f64, f64, f64),
    panels: usize,
) -> f64 {
    use core::f64::consts::PI;
    // 8-point Gauss–Legendre on [−1, 1].
    const X: [f64; 4] = [
        0.183_434_642_495_649_8,
        0.525_532_409_916_329,
        0.796_666_477_413_626_7,
        0.960_289_856_497_536_3,
    ];
    const W: [f64; 4] = [
        0.362_683_783_378_362,
        0.313_706_645_877_887_3,
        0.222_381_034_453_374_5,
        0.101_228_536_290_376_3,
    ];
    let d = center.length();
    let axis = center / d;
    let s2 = (radius / d) * (radius / d);
    let t_max = s2 / (1.0 + libm::sqrt(1.0 - s2));
    let (tx, ty) = axis.any_orthonormal_pair();
    let wo = wo.normalize();
    let phis = 256;
    let mut total = 0.0;
    for i in 0..panels {
        let edge = |k: usize| t_max * libm::pow(k as f64 / panels as f64, 3.0);
        let (a, b) = (edge(i), edge(i + 1));
        let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
        for (x, w) in X
            .iter()
            .flat_map(|&x| [x, -x])
            .zip(W.iter().flat_map(|&w| [w, w]))
        {
            let t = mid + half * x;
            let cos = 1.0 - t;
            let sin = libm::sqrt(t * (2.0 - t));
            let mut ring = 0.0;
            for k in 0..phis {
                let phi = 2.0 * PI * (k as f64 + 0.5) / phis as f64;
                let wi = axis * cos + (tx * libm::cos(phi) + ty * libm::sin(phi)) * sin;
                ring += phong_f64(kd, ks, n, wo, wi) * wi.z.max(0.0);
            }
            total += w * half * ring * (2.0 * PI / phis as f64);
        }
    }
    total
}

/// A Lambert and a Phong point under a sphere light, with quadrature references.
pub fn quadrature_scenes() -> Vec<DirectScene> {
    let wo = Vec3::new(0.5, 0.0, 0.8).normalize();
    let light = sphere_at(-0.7, 3.0, 0.9);
    let mut scenes = Vec::new();
    for (name, kd, ks, n) in [
        ("lambert_sphere", 0.8, 0.0, 1.0),
        ("phong_sphere", 0.2, 0.6, 40.0),
    ] {
        let material = Material::Phong(Phong::new(Vec3::splat(kd), Vec3::splat(ks), n));
        let material = if ks == 0.0 {
            Material::Lambert(Lambert::new(Vec3::splat(kd)))
        } else {
            material
        };
        let reference = sphere_light_quadrature(
            light.shape.center.as_dvec3(),
            f64::from(light.shape.radius),
            wo.as_dvec3(),
            (f64::from(kd), f64::from(ks), f64::from(n)),
            64,
        );
        scenes.push(DirectScene {
            name: name.into(),
            lights: std::vec![Light::from(light)],
            material,
            at: ShadingPoint {
                p: Vec3::ZERO,
                n: Vec3::Z,
                wo,
            },
            reference,
            analytic: false,
            occluders: Vec::new(),
            by_power: false,
        });
    }
    scenes
}

/// The exponents and angular radii of the lecture's MIS grid.
pub const GRID_EXPONENTS: [f32; 4] = [10.0, 100.0, 1000.0, 10000.0];
/// The lights' angular radii (rad) of the grid.
pub const GRID_RADII: [f64; 4] = [0.005, 0.05, 0.2, 0.5];

/// The 4 × 4 grid: a Phong plate (kd = 0, ks = 1, exponent n) seen from 45°, under a sphere of
/// angular radius r at distance 10 centred on the mirror direction.
pub fn grid_scenes() -> Vec<DirectScene> {
    let wo = DVec3::new(1.0, 0.0, 1.0).normalize();
    let mirror = DVec3::new(-wo.x, -wo.y, wo.z);
    let mut scenes = Vec::new();
    for n in GRID_EXPONENTS {
        for r in GRID_RADII {
            let d = 10.0;
            let light =
                SphereLight::new((mirror * d).as_vec3(), (d * libm::sin(r)) as f32, Vec3::ONE);
            let reference = sphere_light_quadrature(
                light.shape.center.as_dvec3(),
                f64::from(light.shape.radius),
                wo,
                (0.0, 1.0, f64::from(n)),
                64,
            );
            scenes.push(DirectScene {
                name: format!("grid_n{n}_r{r}"),
                lights: std::vec![Light::from(light)],
                material: Material::Phong(Phong::new(Vec3::ZERO, Vec3::ONE, n)),
                at: ShadingPoint {
                    p: Vec3::ZERO,
                    n: Vec3::Z,
                    wo: wo.as_vec3(),
                },
                reference,
                analytic: false,
                occluders: Vec::new(),
                by_power: false,
            });
        }
    }
    scenes
}

/// What [`run`] measured.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DirectRun {
    /// The estimates taken.
    pub estimates: u64,
    /// Their mean (channel 0).
    pub mean: f64,
    /// The standard error of the mean.
    pub stderr: f64,
    /// √(mean (estimate − reference)²)/reference.
    pub rel_rmse: f64,
    /// Visibility calls per estimate.
    pub shadow_rays: f64,
}

impl DirectRun {
    /// (mean − reference)/stderr.
    pub fn bias_sigma(&self, reference: f64) -> f64 {
        (self.mean - reference) / self.stderr
    }
}

/// `estimates` estimates of `scene` by `strategy` through the packet path, 8 at a time (the
/// count is rounded up to a multiple of 8), with unit visibility: estimate e reads indices
/// e·N … e·N + N − 1 of `generator` with seed `seed`.
///
/// Use [`Generator::Independent`] to measure bias: optimal MIS's cross-fitting is unbiased only
/// when its two halves of samples are independent, which the stratified Sobol points of one
/// estimate are not.
pub fn run(
    scene: &DirectScene,
    strategy: Strategy,
    config: Config,
    estimates: u64,
    (generator, seed): (Generator, u32),
) -> DirectRun {
    let mut table = Vec::new();
    let lights = scene.lights(&mut table);
    let material = scene.material.splat();
    let at = ShadingPoint {
        p: Vec3x8::splat(scene.at.p),
        n: Vec3x8::splat(scene.at.n),
        wo: Vec3x8::splat(scene.at.wo),
    };
    let n = config.samples();
    let mut stats = MeanVar::default();
    let mut sq = 0.0;
    let mut rays = 0u64;
    let mut visible = |m: F32x8, from: Vec3x8, to: Vec3x8| {
        if scene.occluders.is_empty() {
            return m;
        }
        let (from, to) = (from.to_array(), to.to_array());
        let clear = F32x8::new(core::array::from_fn(|i| {
            if scene.visible(from[i], to[i]) {
                f32::from_bits(u32::MAX)
            } else {
                0.0
            }
        }));
        m & clear
    };
    for packet in 0..estimates.div_ceil(8) {
        let first = U32x8::new(core::array::from_fn(|i| {
            ((packet * 8 + i as u64) as u32).wrapping_mul(n)
        }));
        let mut samples = Sequence {
            first,
            seed,
            generator,
        };
        let e = direct::estimate(
            strategy, &lights, &material, at, config, &mut samples, &mut visible,
        );
        rays += u64::from(e.shadow_rays);
        for x in e.radiance.x.to_array() {
            let x = f64::from(x);
            stats.push(x);
            sq += (x - scene.reference) * (x - scene.reference);
        }
    }
    let count = stats.count();
    DirectRun {
        estimates: count,
        mean: stats.mean(),
        stderr: stats.std_error(),
        rel_rmse: (sq / count as f64).sqrt() / scene.reference,
        shadow_rays: rays as f64 / count as f64,
    }
}
