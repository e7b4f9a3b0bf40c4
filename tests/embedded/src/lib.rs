//! What the firmware binaries share: leaving QEMU with a status, and a panic handler that
//! reports the panic and fails.

#![no_std]

use cortex_m_semihosting::{debug, hprintln};

/// Ends the run: QEMU exits with status 0 if `ok`, 1 otherwise.
pub fn exit(ok: bool) -> ! {
    debug::exit(if ok {
        debug::EXIT_SUCCESS
    } else {
        debug::EXIT_FAILURE
    });
    // Without a semihosting host (real hardware), stay here.
    loop {
        cortex_m::asm::wfi();
    }
}

#[panic_handler]
fn panic(info: &core::panic::PanicInfo) -> ! {
    hprintln!("PANIC {}", info);
    exit(false)
}
