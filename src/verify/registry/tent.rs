//! The pair of tents, tested on [−1, 1]² mapped onto the unit square. It is planar: its point is
//! (x, y, 0), and the pdf and the inverse read (x, y).

use glam::DVec2;

use super::{Evidence, Facts, Kind, Param, RoundTrip, TestDomain};
use crate::warp::TentPair;

impl Evidence for TentPair {
    fn facts(&self) -> Facts {
        Facts {
            kind: Kind::Warp(RoundTrip {
                bound: [1.2e-7, 1.2e-7],
                u1_periodic: false,
            }),
            param: Param::None,
            test: TestDomain::Square {
                to: |x| DVec2::new((x.x + 1.0) / 2.0, (x.y + 1.0) / 2.0),
                from: |p| (2.0 * p - 1.0).as_vec2().extend(0.0),
                jacobian: 4.0,
            },
        }
    }
    fn pdf_reads(&self) -> &'static [usize] {
        &[0, 1]
    }
    fn inverse_reads(&self) -> &'static [usize] {
        &[0, 1]
    }
    fn nan_coords(&self) -> usize {
        2
    }
}
