//! χ² tests for light samplers on a planar light's own parameter square.

use glam::{DVec2, DVec3, Vec3};

use super::chi2::{ChiSquare, ChiSquareResult, Square};

/// Barycentric-style coordinates (β, γ) of a triangle (β, γ ≥ 0, β + γ ≤ 1) → the unit square,
/// by the equal-area map ((β+γ)², γ/(β+γ)): the triangle's three edges become the square's
/// boundary, and a density on the triangle becomes half of it on the square.
pub fn triangle_to_square(beta: f64, gamma: f64) -> DVec2 {
    let r = beta + gamma;
    DVec2::new(r * r, if r > 0.0 { gamma / r } else { 0.0 })
}

/// The inverse of [`triangle_to_square`]: a point of the unit square → (β, γ).
pub fn square_to_triangle(st: DVec2) -> DVec2 {
    let r = st.x.sqrt();
    DVec2::new(r * (1.0 - st.y), r * st.y)
}

/// A planar light seen from the origin: a triangle or a parallelogram, for testing a sampler of
/// directions towards it with [`ChiSquare`].
///
/// Binning directions on the sphere puts the light's edges through cells, where the trapezoid
/// rule is biased and a sample a rounding error outside the support lands in a cell whose pdf
/// integrates to 0. Here directions go back to the light's own parameters instead, where the
/// edges are the boundary of the unit square:
///
/// - a parallelogram p₀ + s·e₁ + t·e₂ has (s, t) ∈ [0, 1]²;
/// - a triangle p₀ + β·e₁ + γ·e₂ (β, γ ≥ 0, β + γ ≤ 1) maps to ((β+γ)², γ/(β+γ)), which is
///   equal-area, so its edges too become the square's boundary.
///
/// A pdf p_ω per steradian becomes p_ω·A·cos θ_l/d² on the square (A the light's area, θ_l the
/// angle at the light, d the distance): exactly 1 for a sampler uniform by area.
#[derive(Clone, Copy, Debug)]
pub struct PlanarLight {
    p0: DVec3,
    e1: DVec3,
    e2: DVec3,
    triangle: bool,
}

impl PlanarLight {
    /// The triangle (a, b, c), vertices relative to the shading point.
    pub fn triangle(a: Vec3, b: Vec3, c: Vec3) -> Self {
        let a = a.as_dvec3();
        PlanarLight {
            p0: a,
            e1: b.as_dvec3() - a,
            e2: c.as_dvec3() - a,
            triangle: true,
        }
    }

    /// The parallelogram corner + s·ex + t·ey, relative to the shading point.
    pub fn parallelogram(corner: Vec3, ex: Vec3, ey: Vec3) -> Self {
        PlanarLight {
            p0: corner.as_dvec3(),
            e1: ex.as_dvec3(),
            e2: ey.as_dvec3(),
            triangle: false,
        }
    }

    fn normal(&self) -> DVec3 {
        self.e1.cross(self.e2)
    }

    /// The parameter-square point hit by direction `w`.
    pub fn to_square(&self, w: DVec3) -> DVec2 {
        let n = self.normal();
        let x = w * (self.p0.dot(n) / w.dot(n)) - self.p0;
        let beta = x.cross(self.e2).dot(n) / n.dot(n);
        let gamma = self.e1.cross(x).dot(n) / n.dot(n);
        if self.triangle {
            triangle_to_square(beta, gamma)
        } else {
            DVec2::new(beta, gamma)
        }
    }

    /// The point of the light at parameter-square point `st`.
    pub fn from_square(&self, st: DVec2) -> DVec3 {
        let bg = if self.triangle {
            square_to_triangle(st)
        } else {
            st
        };
        self.p0 + bg.x * self.e1 + bg.y * self.e2
    }

    /// Runs `config` on the samples' parameter-square points against the transformed pdf.
    /// `sample(i)` returns a direction (any length) towards the light; `pdf` is per steradian, as
    /// a function of a unit f64 direction.
    pub fn test<S, F>(
        &self,
        config: ChiSquare<Square>,
        mut sample: S,
        mut pdf: F,
    ) -> ChiSquareResult
    where
        S: FnMut(usize) -> Vec3,
        F: FnMut(DVec3) -> f64,
    {
        let light = *self;
        let n = self.normal();
        let area = if self.triangle {
            n.length() / 2.0
        } else {
            n.length()
        };
        config.run(
            move |i| light.to_square(sample(i).as_dvec3()),
            move |st: DVec2| {
                // Nodes on the square's boundary lie exactly on the light's edges, where an
                // inside test may go either way; the pdf is continuous from inside, so evaluate
                // a hair inside.
                let st = st.clamp(DVec2::splat(1e-7), DVec2::splat(1.0 - 1e-7));
                let x = light.from_square(st);
                let d = x.length();
                let cos_l = (x.dot(n) / (d * n.length())).abs();
                pdf(x / d) * area * cos_l / (d * d)
            },
        )
    }
}
