//! The sphere's cap sampled by projected solid angle, tested on the cap about its centre.

use glam::{Vec2, Vec3};
use std::boxed::Box;

use super::{Evidence, Facts, Kind, Param, RoundTrip};
use crate::verify::Cap;
use crate::warp::{ProjectedCap, ProjectedSolidAngleCap, cone_h_from_sin2};

/// The radius varies. u₁ is the ellipse's angle (a fraction of a turn where the ellipse is all
/// there is) followed by the lune's height: undetermined where u₀ = 0 in the ellipse (its centre),
/// at the seam between the two (both ends of the ellipse's angle map to its far side), and at the
/// lune's horns, where u₀ is undetermined too (the lune narrows to a point).
impl Evidence for ProjectedSolidAngleCap {
    fn facts(&self) -> Facts {
        let (c, n) = (self.c, self.n);
        let r = Param::Scalar(
            self.r,
            Box::new(move |r| ProjectedSolidAngleCap { c, r, n }.into()),
        );
        let s2 = (self.r as f64 / self.c.as_dvec3().length()).powi(2);
        let h = cone_h_from_sin2(s2);
        let test = Cap::new(self.c.as_dvec3(), (1.5 * h).min(2.0));
        Facts::new(Kind::Polygon(RoundTrip::azimuth([2e-5, 2e-5])), r, test)
    }
    fn determined(&self, u: Vec2, _: Vec3) -> [bool; 2] {
        let cap = ProjectedCap::new(self.c, self.r, self.n);
        let (ellipse, lune) = cap.pieces();
        if !lune {
            return [true, u.x > 1e-2];
        }
        let split = if ellipse { split(self) } else { 0.0 };
        let near = |a: f32| (u.y - a).abs() < 1e-2;
        // Where the ellipse's rim meets the lune (u₀ near 1 in the ellipse, near 1 in the lune
        // too: its inner edge) a direction has a preimage in each.
        let seam = near(0.0) || near(split) || near(1.0) || u.x < 1e-2 || u.x > 0.99;
        [!seam, !seam]
    }
}

/// The share of u₁ that goes to the ellipse: its area over P.
fn split(s: &ProjectedSolidAngleCap) -> f32 {
    let cap = ProjectedCap::new(s.c, s.r, s.n);
    let c = s.c.normalize();
    let cz = c.dot(s.n);
    let sin2 = (s.r / s.c.length()).powi(2);
    core::f32::consts::PI * sin2 * cz / cap.projected_area()
}
