//! The pair of tents, tested on [−1, 1]² mapped onto the unit square.

use glam::DVec2;

use super::{Evidence, Facts, Param, Reads, RoundTrip, TestDomain};
use crate::warp::TentPair;

/// Planar: its point is (x, y, 0), and the pdf and the inverse read (x, y).
impl Evidence for TentPair {
    fn facts(&self) -> Facts {
        let square = TestDomain::Square {
            to: |x| DVec2::new((x.x + 1.0) / 2.0, (x.y + 1.0) / 2.0),
            from: |p| (2.0 * p - 1.0).as_vec2().extend(0.0),
            jacobian: 4.0,
        };
        Facts::warp(RoundTrip::plain([1.2e-7; 2]), Param::None, square)
    }
    fn reads(&self) -> Reads {
        Reads::PLANAR
    }
}
