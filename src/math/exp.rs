//! STUB
use crate::lane::Lane32;
pub fn exp<L: Lane32>(x: L) -> L {
    x
}
pub fn exp_m1<L: Lane32>(x: L) -> L {
    x
}
