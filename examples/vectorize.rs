//! A caller's plain loops over the scalar warps, for checking that LLVM vectorises them (the
//! speed issue's requirement). Build this example alone with the loop vectoriser's remarks on:
//!
//! ```sh
//! cargo rustc --release --example vectorize -- -C remark=loop-vectorize \
//!     -C llvm-args=-pass-remarks=loop-vectorize -C llvm-args=-pass-remarks-missed=loop-vectorize \
//!     -C debuginfo=1
//! ```
//!
//! and again with `RUSTFLAGS="-C target-feature=+avx2,+fma"`. Each loop below is one
//! "vectorized loop" remark (at the `zip` iterator it is inlined into): nine, of width 4 with
//! SSE2 and 8 with AVX2, and no "loop not vectorized".

use glam::{Vec2, Vec3};
use mcsample::warp;

/// Writes `f(u)` for every u; `#[inline(never)]` keeps each loop a loop of its own.
#[inline(never)]
fn each<T: Copy, O>(u: &[T], out: &mut [O], f: impl Fn(T) -> O) {
    for (o, &u) in out.iter_mut().zip(u) {
        *o = f(u);
    }
}

fn main() {
    let u: Vec<Vec2> = (0..64).map(|i| Vec2::new(i as f32 / 64.0, 0.37)).collect();
    let t: Vec<f32> = u.iter().map(|v| v.x).collect();
    let (mut d, mut w, mut x) = (vec![Vec2::ZERO; 64], vec![Vec3::ZERO; 64], vec![0.0f32; 64]);
    each(&u, &mut d, warp::concentric_disk);
    each(&u, &mut d, warp::polar_disk);
    each(&u, &mut w, warp::uniform_hemisphere);
    each(&u, &mut w, warp::cosine_hemisphere);
    each(&u, &mut w, warp::uniform_sphere);
    each(&u, &mut w, |u| warp::uniform_cone(u, 0.3));
    each(&u, &mut w, |u| warp::phong_lobe(u, 20.0));
    each(&u, &mut w, warp::uniform_triangle);
    each(&t, &mut x, warp::tent);
    println!("{:?} {:?} {}", d[5], w[5], x[5]);
}
