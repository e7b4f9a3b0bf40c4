//! χ² tests for narrow lobes and small lights: a cap of directions zoomed onto the sphere.

use glam::{DVec3, Vec3};

use super::chi2::{ChiSquare, ChiSquareResult, Sphere};

/// A cap of directions 1 − cos θ ∈ [0, `hs`] about `axis`, stretched onto the whole sphere for a
/// [`ChiSquare`] test.
///
/// A Phong lobe with n = 500 or a light of 10⁻³ sr falls into one row of the sphere's 50 × 101
/// cells, where the test sees almost nothing. The zoom z' = 1 − 2(1 − cos θ)/hs, with the azimuth
/// about `axis` kept, maps the cap onto the sphere. It is equal-area up to the constant 2/hs, so a
/// pdf per steradian becomes pdf·hs/2 and stays exact; the cells now resolve the lobe.
///
/// A sample outside the cap becomes NaN and fails the test, so choose `hs` to hold all the
/// mass: the cone's own h, or for a cosⁿ lobe an hs with (1 − hs)^{n+1} far below 1/N.
///
/// ```
/// use glam::Vec3;
/// use mcsample::verify::{Cap, ChiSquare};
/// use mcsample::warp;
///
/// let h = 1e-3;
/// let mut k = 0u32;
/// let result = Cap::z(h as f64).test(
///     ChiSquare::sphere().samples(100_000),
///     |i| {
///         // A tiny stratified sequence (any deterministic u sequence works).
///         k = k.wrapping_add(0x9E37_79B9);
///         let u = glam::Vec2::new((i as f32 + 0.5) / 100_000.0, (k >> 8) as f32 / 16_777_216.0);
///         warp::uniform_cone(u, h)
///     },
///     |w| warp::uniform_cone_pdf(w.as_vec3(), h) as f64,
/// );
/// assert!(result.p_value > 1e-3, "{result}");
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Cap {
    t: DVec3,
    b: DVec3,
    axis: DVec3,
    hs: f64,
}

impl Cap {
    /// The cap 1 − cos θ ≤ `hs` about `axis` (normalised here); `hs` = 2 is the whole sphere.
    pub fn new(axis: DVec3, hs: f64) -> Self {
        let axis = axis.normalize();
        let (t, b) = axis.any_orthonormal_pair();
        Cap {
            t,
            b,
            axis,
            hs: hs.clamp(f64::MIN_POSITIVE, 2.0),
        }
    }

    /// The cap about +z, where the crate's warps put their lobes.
    pub fn z(hs: f64) -> Self {
        Cap {
            t: DVec3::X,
            b: DVec3::Y,
            axis: DVec3::Z,
            hs: hs.clamp(f64::MIN_POSITIVE, 2.0),
        }
    }

    /// The smallest cap about the mean direction of `points` (seen from the origin) that holds all
    /// of them, widened by 20 %: for a spherical polygon, whose farthest direction from its centre
    /// is a vertex.
    pub fn around(points: &[Vec3]) -> Self {
        let dirs = points.iter().map(|p| p.as_dvec3().normalize());
        let axis = dirs.clone().sum::<DVec3>().normalize();
        let t_max = dirs.map(|d| 1.0 - d.dot(axis)).fold(0.0, f64::max);
        Cap::new(axis, (1.2 * t_max).min(2.0))
    }

    /// Direction → zoomed direction; outside the cap, NaN.
    pub fn zoom(&self, w: DVec3) -> DVec3 {
        let w = w.normalize();
        let (x, y, z) = (w.dot(self.t), w.dot(self.b), w.dot(self.axis));
        // 1 − z without cancellation near the axis.
        let t = if z > 0.0 {
            (x * x + y * y) / (1.0 + z)
        } else {
            1.0 - z
        };
        // NaN fails this test too, so it is written as "inside" negated.
        let inside = t <= self.hs * (1.0 + 1e-9);
        if !inside {
            return DVec3::splat(f64::NAN);
        }
        let zp = (1.0 - 2.0 * t / self.hs).clamp(-1.0, 1.0);
        let rp = ((1.0 - zp) * (1.0 + zp)).max(0.0).sqrt();
        let phi = y.atan2(x);
        DVec3::new(rp * phi.cos(), rp * phi.sin(), zp)
    }

    /// Zoomed direction → direction, with the factor hs/2 that turns its pdf into the zoomed pdf.
    pub fn unzoom(&self, wp: DVec3) -> (DVec3, f64) {
        self.unzoom_polar(wp.z, wp.y.atan2(wp.x).sin_cos())
    }

    /// [`unzoom`](Self::unzoom) of the zoomed direction of height `zp` and azimuth φ, given as
    /// (sin φ, cos φ): a grid over the zoomed sphere reuses one table of azimuths.
    pub fn unzoom_polar(&self, zp: f64, (sin_phi, cos_phi): (f64, f64)) -> (DVec3, f64) {
        let t = (1.0 - zp) * self.hs / 2.0;
        let sin = (t * (2.0 - t)).max(0.0).sqrt();
        let (x, y, z) = (sin * cos_phi, sin * sin_phi, 1.0 - t);
        (x * self.t + y * self.b + z * self.axis, self.hs / 2.0)
    }

    /// Runs `config` on the zoomed samples against the zoomed pdf. `sample(i)` returns a unit
    /// direction; `pdf` is per steradian, as a function of an f64 direction.
    pub fn test<S, F>(
        &self,
        config: ChiSquare<Sphere>,
        mut sample: S,
        mut pdf: F,
    ) -> ChiSquareResult
    where
        S: FnMut(usize) -> Vec3,
        F: FnMut(DVec3) -> f64,
    {
        let cap = *self;
        config.run(
            move |i| cap.zoom(sample(i).as_dvec3()),
            move |wp: DVec3| {
                let (w, k) = cap.unzoom(wp);
                pdf(w) * k
            },
        )
    }
}
