//! The disks: the concentric and the polar map, tested on the disk's equal-area (φ, r²) grid.
//! Both are planar: their point is (x, y, 0), and the pdf and the inverse read (x, y).

use glam::{Vec2, Vec3};

use super::{Evidence, Facts, Kind, Param, RoundTrip, TestDomain};
use crate::warp::{ConcentricDisk, PolarDisk};

impl Evidence for ConcentricDisk {
    fn facts(&self) -> Facts {
        Facts {
            kind: Kind::Warp(RoundTrip {
                bound: [5e-7, 5e-7],
                u1_periodic: false,
            }),
            param: Param::None,
            test: TestDomain::Disk,
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

/// u₁ is the azimuth: periodic, and undetermined within 1e-3 of the centre.
impl Evidence for PolarDisk {
    fn facts(&self) -> Facts {
        Facts {
            kind: Kind::Warp(RoundTrip {
                bound: [3e-7, 3e-7],
                u1_periodic: true,
            }),
            param: Param::None,
            test: TestDomain::Disk,
        }
    }
    fn pdf_reads(&self) -> &'static [usize] {
        ConcentricDisk.pdf_reads()
    }
    fn inverse_reads(&self) -> &'static [usize] {
        ConcentricDisk.inverse_reads()
    }
    fn nan_coords(&self) -> usize {
        ConcentricDisk.nan_coords()
    }
    fn determined(&self, _: Vec2, x: Vec3) -> [bool; 2] {
        [true, x.truncate().length() > 1e-3]
    }
}
