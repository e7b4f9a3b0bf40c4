//! The spherical rectangle, tested on the rectangle's own parameter square.

use glam::Vec3;
use std::boxed::Box;

use super::{Evidence, Facts, Kind, Param, RoundTrip};
use crate::verify::PlanarLight;
use crate::warp::SolidAngleRectangle;

/// The geometry varies, and a degenerate rectangle returns its corner (documented, NaN corner
/// included). Sampled by area, its round trip is bounded as the triangle's; spherically, Ureña's
/// map forms Ω as Σγ − 2π, which cancels as the rectangle shrinks (1.5e-5 in u₀ at 0.035 sr).
impl Evidence for SolidAngleRectangle {
    fn facts(&self) -> Facts {
        let light = PlanarLight::parallelogram(self.v[0], self.v[1], self.v[2]);
        let roundtrip = RoundTrip::plain(match self.size() {
            "area" => [1.5e-4, 1.5e-4],
            _ => [2e-6, 5e-7],
        });
        let v = Param::Geometry(self.v, Box::new(|v| SolidAngleRectangle { v }.into()));
        Facts::new(Kind::Polygon(roundtrip), v, light)
    }
    fn dropped_at(&self) -> Vec3 {
        self.v[0]
    }
}
