//! The spherical triangle, tested on the triangle's own parameter square.

use glam::{Vec2, Vec3};
use std::boxed::Box;

use super::{Evidence, Facts, Kind, Param, RoundTrip};
use crate::verify::PlanarLight;
use crate::warp::SolidAngleTriangle;

/// The geometry varies. Sampled by area, the map resolves only the f32 direction grid over the
/// light (6e-8/√Ω: 1e-4 at 5e-7 sr), which bounds its round trip; u₀ there is the position
/// across the segment from B at √u₁ of the way, so its resolution is that over √u₁: 1e-3 from
/// u₁ = 1e-2. u₀ is undetermined at the apex B (u₁ → 0).
impl Evidence for SolidAngleTriangle {
    fn facts(&self) -> Facts {
        let [a, b, c] = self.v;
        let bound = match self.size() {
            "area" => [1e-3, 1.5e-4],
            _ => [4e-6, 1.5e-6],
        };
        let v = Param::Geometry(self.v, Box::new(|v| SolidAngleTriangle { v }.into()));
        let kind = Kind::Polygon(RoundTrip::plain(bound));
        Facts::new(kind, v, PlanarLight::triangle(a, b, c))
    }
    fn determined(&self, u: Vec2, _: Vec3) -> [bool; 2] {
        let apex = if self.size() == "area" { 1e-2 } else { 1e-3 };
        [u.y > apex, true]
    }
}
