//! STUB: replaced by the math work.
use crate::lane::Lane32;
pub fn sin_cos<L: Lane32>(x: L) -> (L, L) {
    (x, x)
}
pub fn sincos_2pi<L: Lane32>(x: L) -> (L, L) {
    (x, x)
}
pub fn sincos_pi4<L: Lane32>(x: L) -> (L, L) {
    (x, x)
}
