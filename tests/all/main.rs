//! The crate's tests, in one binary so that the generic library is compiled for them once.
//!
//! A module per layer, in the crate's own order (lanes and math, sequences, warps, camera,
//! estimators, scene, direct lighting, the verification layer). Run one layer or one test by its path:
//! `cargo test --test all warp::lanes`, `cargo test --test all case_04`.
//!
//! The wasm32-wasip1 build (`tests/wasi`) leaves out `math`, which spawns threads (WASI preview
//! 1 has none), `warp::properties`, which needs proptest (it does not build for wasm), and the
//! statistical studies (χ², convergence, the direct estimator's statistics, the MIS estimators,
//! the references' quadrature, the rectangle's error bands, the harness's own tests), which
//! measure distributions rather than arithmetic and run natively.

mod common;

#[cfg(not(target_family = "wasm"))]
mod math;

mod seq {
    #[cfg(not(target_family = "wasm"))]
    mod convergence;
    mod generators;
    /// The integer generators' golden values, shared with the firmware (`tests/embedded`).
    mod golden {
        include!("seq/golden.in");
    }
    mod independent;
    #[cfg(not(target_family = "wasm"))]
    mod quality;
    mod rng;
}

mod warp {
    mod accuracy;
    #[cfg(not(target_family = "wasm"))]
    mod bilinear;
    #[cfg(not(target_family = "wasm"))]
    mod distribution;
    mod hard_cases;
    mod lanes;
    mod polygon_regressions;
    // Studies over 1.7·10⁵ random triangles: native only (the registry's lane checks cover the
    // projected triangle on every target).
    #[cfg(not(target_family = "wasm"))]
    mod projected;
    // Sphere lights by projected solid angle: P, zero variance, the three cases, lanes.
    mod projected_cap;
    // Polygons of up to eight vertices: P, zero variance, the fan, hard cases, lanes.
    #[cfg(not(target_family = "wasm"))]
    mod projected_polygon;
    #[cfg(not(target_family = "wasm"))]
    mod properties;
    #[cfg(not(target_family = "wasm"))]
    mod rectangle_accuracy;
    mod roundtrip;
    // Disk lights by solid angle: Ω, the disk's samples, χ² and its control, hard cases, lanes.
    mod spherical_ellipse;
    mod sweep;
}

mod camera;

mod estimate {
    mod accumulators;
    mod hard_cases;
    mod mis;
    #[cfg(not(target_family = "wasm"))]
    mod mis_estimators;
    #[cfg(not(target_family = "wasm"))]
    mod reference;
}

mod scene {
    mod hard_cases;
    mod lights;
}

#[cfg(not(target_family = "wasm"))]
mod direct;
#[cfg(not(target_family = "wasm"))]
mod verify;

#[cfg(feature = "rand")]
mod distr;
