"""Mitsuba 3's warps on 2**24 points: Dr.Jit's LLVM backend, one thread, the whole array pass.

The peer of the `peers/2^24` group of `benches/peers.rs` (the same warps, point count and
structure-of-arrays layout). Prints ns per sample, the median of RUNS timed passes after one
that compiles the kernel, as JSON.

    pip install mitsuba drjit          # Mitsuba 3.9.1 and Dr.Jit 1.5.0 were measured
    apt-get install libllvm19          # Dr.Jit's LLVM backend loads it at run time
    DRJIT_LIBLLVM_PATH=/usr/lib/x86_64-linux-gnu/libLLVM.so.19.1 python3 benches/mitsuba_warps.py

Dr.Jit picks its vector width from the CPU: 16 lanes with AVX-512 (the kernels' IR holds
`<16 x float>`). Debian's LLVM 15 aborted on one of these kernels ("Cannot select: fmaximum"),
hence LLVM 19.
"""

import json
import sys
import time

import drjit as dr
import mitsuba as mi

mi.set_variant("llvm_ad_rgb")
dr.set_thread_count(1)
N = 1 << 24
RUNS = int(sys.argv[1]) if len(sys.argv) > 1 else 9

rng = mi.PCG32(N)
u = mi.Point2f(rng.next_float32(), rng.next_float32())
dr.eval(u)
dr.sync_thread()

WARPS = {
    "concentric_disk": mi.warp.square_to_uniform_disk_concentric,
    "cosine_hemisphere": mi.warp.square_to_cosine_hemisphere,
    "uniform_sphere": mi.warp.square_to_uniform_sphere,
    "uniform_cone": lambda u: mi.warp.square_to_uniform_cone(u, 0.7),
    "uniform_triangle": mi.warp.square_to_uniform_triangle,
}

out = {}
for name, warp in WARPS.items():
    times = []
    for run in range(RUNS + 1):
        start = time.perf_counter()
        y = warp(u)
        dr.eval(y)
        dr.sync_thread()
        elapsed = time.perf_counter() - start
        del y
        if run > 0:
            times.append(elapsed)
    times.sort()
    out[name] = times[len(times) // 2] * 1e9 / N
print(json.dumps(out, indent=1))
