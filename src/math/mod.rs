//! The crate's own transcendental functions, lane-generic (STUB header; the math work fills it).
pub mod asin;
pub mod atan;
pub mod exp;
pub mod log;
pub mod trig;
