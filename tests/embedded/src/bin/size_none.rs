//! The flash baseline: the runtime and the semihosting exit, no mcsample.

#![no_std]
#![no_main]

use cortex_m_rt::entry;

#[entry]
fn main() -> ! {
    mcsample_firmware::exit(core::hint::black_box(true))
}
