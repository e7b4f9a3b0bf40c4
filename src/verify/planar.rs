//! χ² tests for light samplers on a planar light's own parameter square.

use glam::{DVec2, DVec3, Vec3};
use std::vec::Vec;

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
///
/// A convex polygon ([`PlanarLight::fan`]) is its fan of triangles (v₀, vᵢ, vᵢ₊₁), each mapped
/// so onto a strip of the square as tall as its share of the area: the polygon's edges become
/// the square's boundary, the fan's diagonals lines inside it.
#[derive(Clone, Copy, Debug)]
pub struct PlanarLight {
    p0: DVec3,
    e1: DVec3,
    e2: DVec3,
    triangle: bool,
    /// A fan's vertices (up to eight) and how many, or none.
    fan: Option<([Vec3; 8], usize)>,
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
            fan: None,
        }
    }

    /// The parallelogram corner + s·ex + t·ey, relative to the shading point.
    pub fn parallelogram(corner: Vec3, ex: Vec3, ey: Vec3) -> Self {
        PlanarLight {
            p0: corner.as_dvec3(),
            e1: ex.as_dvec3(),
            e2: ey.as_dvec3(),
            triangle: false,
            fan: None,
        }
    }

    /// The convex polygon with vertices `v` in order (3 to 8 of them, coplanar), relative to
    /// the shading point.
    pub fn fan(v: &[Vec3]) -> Self {
        assert!((3..=8).contains(&v.len()), "a fan of 3 to 8 vertices");
        let mut all = [Vec3::ZERO; 8];
        for (a, x) in all.iter_mut().zip(v) {
            *a = *x;
        }
        PlanarLight {
            fan: Some((all, v.len())),
            ..Self::triangle(v[0], v[1], v[2])
        }
    }

    /// A fan's triangles as (v₀, e₁, e₂), with the share of the area before each and its own.
    fn fan_triangles(&self) -> Vec<(DVec3, DVec3, DVec3, f64, f64)> {
        let Some((v, n)) = self.fan else {
            return Vec::new();
        };
        let v = v.map(|x| x.as_dvec3());
        let areas: Vec<f64> = (0..n - 2)
            .map(|i| (v[i + 1] - v[0]).cross(v[i + 2] - v[0]).length())
            .collect();
        let total: f64 = areas.iter().sum();
        let mut before = 0.0;
        (0..n - 2)
            .map(|i| {
                let share = areas[i] / total;
                let t = (v[0], v[i + 1] - v[0], v[i + 2] - v[0], before, share);
                before += share;
                t
            })
            .collect()
    }

    /// The light's area.
    fn area(&self) -> f64 {
        let n = self.normal().length();
        match self.fan {
            Some(_) => self
                .fan_triangles()
                .iter()
                .map(|&(_, e1, e2, _, _)| e1.cross(e2).length() / 2.0)
                .sum(),
            None if self.triangle => n / 2.0,
            None => n,
        }
    }

    fn normal(&self) -> DVec3 {
        // A fan's from all its triangles: its first alone is 0 where v₀, v₁, v₂ are collinear.
        match self.fan {
            Some(_) => self
                .fan_triangles()
                .iter()
                .map(|&(_, e1, e2, _, _)| e1.cross(e2))
                .sum(),
            None => self.e1.cross(self.e2),
        }
    }

    /// The parameter-square point hit by direction `w`.
    pub fn to_square(&self, w: DVec3) -> DVec2 {
        let n = self.normal();
        if self.fan.is_some() {
            // The triangle of the fan whose wedge at v₀ holds the point (the nearest where
            // rounding leaves it in none), then its strip.
            let x = w * (self.p0.dot(n) / w.dot(n)) - self.p0;
            let mut best = (f64::NEG_INFINITY, DVec2::ZERO);
            for (_, e1, e2, before, share) in self.fan_triangles() {
                let m = e1.cross(e2);
                let beta = x.cross(e2).dot(m) / m.dot(m);
                let gamma = e1.cross(x).dot(m) / m.dot(m);
                if beta.min(gamma) > best.0 {
                    let st = triangle_to_square(beta, gamma);
                    best = (beta.min(gamma), DVec2::new(st.x, before + share * st.y));
                }
                if beta >= 0.0 && gamma >= 0.0 {
                    break;
                }
            }
            return best.1;
        }
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
        if self.fan.is_some() {
            let fan = self.fan_triangles();
            let last = fan.len() - 1;
            let i = fan.iter().position(|t| st.y < t.3 + t.4).unwrap_or(last);
            let (p0, e1, e2, before, share) = fan[i];
            let t = ((st.y - before) / share).clamp(0.0, 1.0);
            let bg = square_to_triangle(DVec2::new(st.x, t));
            return p0 + bg.x * e1 + bg.y * e2;
        }
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
        let area = self.area();
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
