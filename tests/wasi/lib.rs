//! Empty: this package exists for its tests, which are the crate's own (`../all`).
