//! The disks, tested on the disk's equal-area (φ, r²) grid. Both are planar: their point is
//! (x, y, 0), and the pdf and the inverse read (x, y).

use glam::{Vec2, Vec3};

use super::{Evidence, Facts, Param, Reads, RoundTrip, TestDomain};
use crate::warp::{ConcentricDisk, PolarDisk};

impl Evidence for ConcentricDisk {
    fn facts(&self) -> Facts {
        Facts::warp(RoundTrip::plain([5e-7; 2]), Param::None, TestDomain::Disk)
    }
    fn reads(&self) -> Reads {
        Reads::PLANAR
    }
}

/// u₁ is the azimuth: periodic, and undetermined within 1e-3 of the centre.
impl Evidence for PolarDisk {
    fn facts(&self) -> Facts {
        Facts::warp(RoundTrip::azimuth([3e-7; 2]), Param::None, TestDomain::Disk)
    }
    fn determined(&self, _: Vec2, x: Vec3) -> [bool; 2] {
        [true, x.truncate().length() > 1e-3]
    }
    fn reads(&self) -> Reads {
        Reads::PLANAR
    }
}
