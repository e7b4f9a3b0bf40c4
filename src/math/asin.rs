//! STUB
use crate::lane::Lane32;
pub fn asin<L: Lane32>(x: L) -> L {
    x
}
pub fn acos<L: Lane32>(x: L) -> L {
    x
}
