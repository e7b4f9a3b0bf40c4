//! The polygons sampled by projected solid angle, tested on the light's own parameter square.

use glam::{Vec2, Vec3};
use std::boxed::Box;

use super::{Evidence, Facts, Kind, Param, RoundTrip};
use crate::verify::PlanarLight;
use crate::warp::{
    ProjectedSolidAngleHexagon, ProjectedSolidAngleRectangle, ProjectedSolidAngleTriangle, hexagon,
};

/// The geometry varies (the normal stays). u₁, the azimuth's share of the area, is a fraction of
/// a turn in the central case (0 and 1 meet), and undetermined where u₀ = 0 there (every u₁ maps
/// to the normal); u₀ is undetermined at the decentral case's tips (u₁ = 0 or 1), where the
/// region narrows to a vertex.
impl Evidence for ProjectedSolidAngleTriangle {
    fn facts(&self) -> Facts {
        let [a, b, c] = self.v;
        let n = self.n;
        let v = Param::Geometry(
            self.v,
            Box::new(move |v| ProjectedSolidAngleTriangle { v, n }.into()),
        );
        let kind = Kind::Polygon(RoundTrip::azimuth([2e-5, 2e-5]));
        Facts::new(kind, v, PlanarLight::triangle(a, b, c))
    }
    fn determined(&self, u: Vec2, _: Vec3) -> [bool; 2] {
        [u.y > 1e-2 && u.y < 0.99, u.x > 1e-2]
    }
}

/// As the triangle's, on the parallelogram's square.
impl Evidence for ProjectedSolidAngleRectangle {
    fn facts(&self) -> Facts {
        let light = PlanarLight::parallelogram(self.v[0], self.v[1], self.v[2]);
        let n = self.n;
        let v = Param::Geometry(
            self.v,
            Box::new(move |v| ProjectedSolidAngleRectangle { v, n }.into()),
        );
        Facts::new(Kind::Polygon(RoundTrip::azimuth([2e-5, 2e-5])), v, light)
    }
    fn determined(&self, u: Vec2, _: Vec3) -> [bool; 2] {
        [u.y > 1e-2 && u.y < 0.99, u.x > 1e-2]
    }
}

/// As the triangle's, on the hexagon's fan (its geometry: the centre and two half-axes). Sampled
/// through the fan, by area, its triangles of 6e-7 to 1.3e-6 sr resolve only the f32 direction
/// grid over each (6e-8/√Ωᵢ ≈ 7e-5 of it), coarser towards the apex v₀ as 1/√u₁: its round trip
/// is measured within 1.4e-3, and bounded at 2e-3.
impl Evidence for ProjectedSolidAngleHexagon {
    fn facts(&self) -> Facts {
        let light = PlanarLight::fan(&hexagon(self.v));
        let n = self.n;
        // Through the fan, u₁ is the distance from the apex, not an azimuth: not periodic.
        let roundtrip = match self.case() {
            "solid" => RoundTrip::plain([2e-3, 2e-3]),
            _ => RoundTrip::azimuth([2e-5, 2e-5]),
        };
        let v = Param::Geometry(
            self.v,
            Box::new(move |v| ProjectedSolidAngleHexagon { v, n }.into()),
        );
        Facts::new(Kind::Polygon(roundtrip), v, light)
    }
    fn determined(&self, u: Vec2, _: Vec3) -> [bool; 2] {
        [u.y > 1e-2 && u.y < 0.99, u.x > 1e-2]
    }
}
