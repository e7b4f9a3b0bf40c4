#![no_std]
#![forbid(unsafe_code)]
#![doc = "mcsample (crate docs are written with the modules)."]

#[cfg(feature = "std")]
extern crate std;

pub mod frame;
pub mod lane;
pub mod math;
pub mod warp;
pub mod x8;

#[cfg(feature = "std")]
pub mod verify;
