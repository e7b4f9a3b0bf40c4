//! The lane abstraction: every algorithm in the crate is written once over [`Lane`] (and
//! [`Math`](crate::math::Math), which adds the transcendental functions).
//!
//! Four instances exist:
//!
//! - `f32`: the scalar form that the glam-facing API uses;
//! - [`F32x8`]: the 8-wide packet form;
//! - [`F32x16`]: the 16-wide packet form, one register with AVX-512 and two 8-wide halves
//!   without;
//! - `f64`: the reference instance. Its transcendental functions delegate to libm, so it measures
//!   the error of the f32 polynomials rather than repeating it.
//!
//! The f32 and packet instances are built so that lane *i* of a packet computation equals the scalar
//! computation on lane *i*'s inputs, bit for bit:
//!
//! - `+ − × ÷` and `sqrt` are IEEE operations, correctly rounded in both widths;
//! - [`Lane::mul_add`] is fused in both widths exactly when the build has FMA (the scalar form goes
//!   through lane 0 of a `wide::f32x4`, which wide fuses under the same condition as `f32x8`);
//! - `min`, `max` and `clamp` are written as compare-and-select, so NaN handling does not depend on
//!   which min/max instruction a target has;
//! - conversions between floats and integers use bit tricks on integer-valued floats, never a
//!   platform conversion whose out-of-range behaviour differs between widths.

//!
//! # Files
//!
//! - `float`: [`Lane`] (arithmetic, compares to a [`Mask`], selects) for `f32`, [`F32x8`] and
//!   `f64`, and [`F64x8`] for the packet accumulators; [`Lanes`], lane-by-lane access, and
//!   [`Widen`], an f32 lane with the f64 lane of its width;
//! - `int`: [`U32Lane`], the 32-bit integer lane of the same two widths (`u32`, [`U32x8`]) that
//!   the sequence generators use, and [`Lane32`], the f32 lanes with their bits in it. It stands
//!   on `float`, which needs no integer lane, so the files import in one direction;
//! - `vector`: [`V2`] and [`V3`], vectors whose components are lanes, and their conversions to
//!   glam's types.

/// The lanes' trait impls are tables of one-line methods, every one `#[inline(always)]` (a lane
/// operation must vanish into the algorithm that calls it). This writes the attribute once.
macro_rules! inline_fns {
    ($(fn $name:ident $args:tt -> $ret:ty $body:block)*) => {
        $(#[inline(always)] fn $name $args -> $ret $body)*
    };
}
pub(crate) use inline_fns;

mod float;
mod int;
mod vector;

pub use float::{F32x8, F32x16, F64x8, F64x16, Lane, Lanes, Mask, Widen};
#[cfg(not(target_feature = "avx512f"))]
pub(crate) use float::{halves16, join16};
pub use int::{Lane32, U32Lane, U32x8, U32x16};
pub(crate) use vector::packet_vectors;
pub use vector::{V2, V3};

/// `[f(a₀, b₀), f(a₁, b₁), …]`: the element-wise map of two arrays of one length, without
/// indexing (so without a bounds check to prove or a panic path to leave behind).
#[inline(always)]
pub(crate) fn zip_map<A, B, C: Copy + Default, const N: usize>(
    a: [A; N],
    b: [B; N],
    mut f: impl FnMut(A, B) -> C,
) -> [C; N] {
    let mut out = [C::default(); N];
    for ((o, x), y) in out.iter_mut().zip(a).zip(b) {
        *o = f(x, y);
    }
    out
}

/// Element `i mod N` of an array of a packet's width N (8 or 16, a power of two): the lane index
/// of a packet, which callers form as `0..N`; reduced rather than checked, so there is no panic
/// path.
#[inline(always)]
pub(crate) fn lane_of<T: Copy + Default, const N: usize>(a: &[T; N], i: usize) -> T {
    // The fallback is unreachable (i & (N − 1) < N), and the compiler drops it.
    a.get(i & N.wrapping_sub(1)).copied().unwrap_or_default()
}
