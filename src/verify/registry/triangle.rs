//! The uniform triangle's barycentrics, tested on the square through the equal-area map
//! (s, f) = ((b₀+b₁)², b₁/(b₀+b₁)), whose Jacobian is ½.

use super::{Evidence, Facts, Param, Reads, RoundTrip, TestDomain};
use crate::verify::{square_to_triangle, triangle_to_square};
use crate::warp::UniformTriangle;

/// The density is over (b₀, b₁).
impl Evidence for UniformTriangle {
    fn facts(&self) -> Facts {
        let square = TestDomain::Square {
            to: |b| triangle_to_square(b.x, b.y),
            from: |st| square_to_triangle(st).extend(0.0).as_vec3(),
            jacobian: 0.5,
        };
        Facts::warp(RoundTrip::plain([1.2e-7; 2]), Param::None, square)
    }
    fn reads(&self) -> Reads {
        Reads {
            pdf: &[0, 1],
            ..Reads::ALL
        }
    }
}
