//! Random-number throughput: [`Pcg32x8`] (`next_u32x8`, `next_f32x8`) against eight scalar
//! `rand_pcg::Pcg32` generators producing the same number of values, 4096 values per iteration.
//!
//! `cargo bench --bench sequences`; for the AVX2 build,
//! `RUSTFLAGS="-C target-feature=+avx2,+fma" cargo bench --target-dir target/avx2 --bench sequences`.

use std::hint::black_box;

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use mcsample::rng::Pcg32x8;
use mcsample::x8::{F32x8, U32x8};
use rand_core::Rng;
use rand_pcg::Pcg32;

/// Values per iteration.
const N: usize = 4096;

const STATES: [u64; 8] = [1, 2, 3, 4, 5, 6, 7, 8];
const STREAMS: [u64; 8] = [11, 12, 13, 14, 15, 16, 17, 18];

fn rng(c: &mut Criterion) {
    let mut g = c.benchmark_group("pcg32");
    g.throughput(Throughput::Elements(N as u64));

    let mut packet = Pcg32x8::new(STATES, STREAMS);
    g.bench_function("x8/next_u32x8", |b| {
        b.iter(|| {
            let mut acc = U32x8::ZERO;
            for _ in 0..N / 8 {
                acc ^= packet.next_u32x8();
            }
            black_box(acc)
        })
    });

    let mut packet = Pcg32x8::new(STATES, STREAMS);
    g.bench_function("x8/next_f32x8", |b| {
        b.iter(|| {
            let mut acc = F32x8::ZERO;
            for _ in 0..N / 8 {
                acc += packet.next_f32x8();
            }
            black_box(acc)
        })
    });

    let mut scalars: [Pcg32; 8] = core::array::from_fn(|i| Pcg32::new(STATES[i], STREAMS[i]));
    g.bench_function("scalar_8x/next_u32", |b| {
        b.iter(|| {
            let mut acc = 0u32;
            for _ in 0..N / 8 {
                for s in scalars.iter_mut() {
                    acc ^= s.next_u32();
                }
            }
            black_box(acc)
        })
    });

    let mut scalars: [Pcg32; 8] = core::array::from_fn(|i| Pcg32::new(STATES[i], STREAMS[i]));
    g.bench_function("scalar_8x/next_f32", |b| {
        b.iter(|| {
            let mut acc = 0f32;
            for _ in 0..N / 8 {
                for s in scalars.iter_mut() {
                    acc += (s.next_u32() >> 8) as f32 * (1.0 / 16_777_216.0);
                }
            }
            black_box(acc)
        })
    });

    g.finish();
}

criterion_group!(benches, rng);
criterion_main!(benches);
