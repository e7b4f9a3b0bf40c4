//! The crate's tests, in one binary so that the generic library is compiled for them once.
//!
//! A module per layer, in the crate's own order (lanes and math, sequences, warps, camera,
//! estimators, scene, direct lighting, the verification layer). Run one layer or one test by its path:
//! `cargo test --test all warp::lanes`, `cargo test --test all case_04`.
//!
//! Two modules are left out of the wasm32-wasip1 build: `math` spawns threads, which WASI
//! preview 1 lacks, and `warp::properties` needs proptest, which does not build for wasm.

mod common;

#[cfg(not(target_family = "wasm"))]
mod math;

mod seq {
    mod convergence;
    mod generators;
    /// The integer generators' golden values, shared with the firmware (`tests/embedded`).
    mod golden {
        include!("seq/golden.in");
    }
    mod independent;
    mod quality;
    mod rng;
}

mod warp {
    mod accuracy;
    mod distribution;
    mod hard_cases;
    mod lanes;
    mod polygon_regressions;
    #[cfg(not(target_family = "wasm"))]
    mod properties;
    mod rectangle_accuracy;
    mod roundtrip;
    mod sweep;
}

mod camera;

mod estimate {
    mod accumulators;
    mod hard_cases;
    mod mis;
    mod mis_estimators;
    mod reference;
}

mod scene {
    mod hard_cases;
    mod lights;
}

mod direct;
mod verify;

#[cfg(feature = "rand")]
mod distr;
