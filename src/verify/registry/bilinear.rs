//! The bilinear polygons, tested on the light's own parameter square, as the spherical polygons
//! they compose with.

use glam::{Vec2, Vec3};
use std::boxed::Box;

use super::{Evidence, Facts, Kind, Param, RoundTrip};
use crate::verify::PlanarLight;
use crate::warp::{CosineRectangle, CosineTriangle, SolidAngleRectangle, SolidAngleTriangle};

/// The spherical triangle's facts: the geometry varies (the normal stays), the round trip is
/// the spherical one through the bilinear inverse, whose slope (the density, at most 4) scales
/// its error, and u₀ is undetermined at the apex B, where u′₁ → 0 as u₁ → 0.
impl Evidence for CosineTriangle {
    fn facts(&self) -> Facts {
        let [a, b, c] = self.v;
        let bound = match (SolidAngleTriangle { v: self.v }).size() {
            "area" => [1.5e-4, 1.5e-4],
            _ => [1.6e-5, 6e-6],
        };
        let n = self.n;
        let v = Param::Geometry(self.v, Box::new(move |v| CosineTriangle { v, n }.into()));
        let kind = Kind::Polygon(RoundTrip::plain(bound));
        Facts::new(kind, v, PlanarLight::triangle(a, b, c))
    }
    fn determined(&self, u: Vec2, _: Vec3) -> [bool; 2] {
        [u.y > 1e-2, true]
    }
}

/// The spherical rectangle's facts, its round trip scaled as the triangle's.
impl Evidence for CosineRectangle {
    fn facts(&self) -> Facts {
        let light = PlanarLight::parallelogram(self.v[0], self.v[1], self.v[2]);
        let roundtrip = RoundTrip::plain(match (SolidAngleRectangle { v: self.v }).size() {
            "area" => [1.5e-4, 1.5e-4],
            _ => [8e-6, 2e-6],
        });
        let n = self.n;
        let v = Param::Geometry(self.v, Box::new(move |v| CosineRectangle { v, n }.into()));
        Facts::new(Kind::Polygon(roundtrip), v, light)
    }
    fn dropped_at(&self) -> Vec3 {
        self.v[0]
    }
}
