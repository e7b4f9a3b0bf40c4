//! STUB
use crate::lane::Lane32;
pub fn ln<L: Lane32>(x: L) -> L {
    x
}
pub fn ln_1p<L: Lane32>(x: L) -> L {
    x
}
