//! The uniform triangle's barycentrics, tested on the square through the equal-area map
//! (s, f) = ((b₀+b₁)², b₁/(b₀+b₁)), whose Jacobian is ½. Its density is over (b₀, b₁).

use super::{Evidence, Facts, Kind, Param, RoundTrip, TestDomain};
use crate::verify::{square_to_triangle, triangle_to_square};
use crate::warp::UniformTriangle;

impl Evidence for UniformTriangle {
    fn facts(&self) -> Facts {
        Facts {
            kind: Kind::Warp(RoundTrip {
                bound: [1.2e-7, 1.2e-7],
                u1_periodic: false,
            }),
            param: Param::None,
            test: TestDomain::Square {
                to: |b| triangle_to_square(b.x, b.y),
                from: |st| square_to_triangle(st).extend(0.0).as_vec3(),
                jacobian: 0.5,
            },
        }
    }
    fn pdf_reads(&self) -> &'static [usize] {
        &[0, 1]
    }
}
