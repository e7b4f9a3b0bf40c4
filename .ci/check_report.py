#!/usr/bin/env python3
"""Checks the quick report's JSON (issue: CI checks the report's claims, not only that it ran).

- every warp and light sampler's chi-square p is above the Sidak-corrected level for alpha = 0.01;
- every direct-lighting row has |bias| <= 4 standard errors (rows whose estimates were all equal,
  because no sample of a uniform strategy reached a tiny light, are listed and allowed only for
  the three uniform strategies);
- on the lecture's grid, in every cell: power MIS is never above the worse of light and BSDF
  sampling, it is within Veach's bound (Theorem 9.2: rel^2 <= better^2 + 1/min(n) - 1/sum(n)),
  and optimal MIS is at most 1.05 x power;
- every sampler, sequence and MIS-weight row carries its sixteen-wide time (x16_ns > 0), and
  every direct row
  its x16 / x8 key;
- the direct rows cover both light-sampling modes, the bilinear one on at least three scenes.
"""
import json
import sys

report = json.load(open(sys.argv[1]))
failures = []

warps = [w for w in report["warps"] if w["chi2_p"] is not None]
level = 1.0 - (1.0 - 0.01) ** (1.0 / len(warps))
for w in warps:
    if not w["chi2_p"] > level:
        failures.append(f"chi2: {w['name']} p = {w['chi2_p']} <= {level:.2e}")

for row in report["warps"] + report["sequences"] + report["mis_weights"]:
    if not (row.get("x16_ns") or 0) > 0:
        failures.append(f"x16: {row['name']} has no sixteen-wide time")
if any("x16_vs_x8" not in r for r in report["direct"]):
    failures.append("x16: a direct row has no x16_vs_x8 key")
modes = {}
for r in report["direct"]:
    modes.setdefault(r.get("light_sampling"), set()).add(r["scene"])
cosine_modes = ("bilinear", "projected", "area")
if set(modes) != {"solid_angle", *cosine_modes} or any(len(modes[m]) < 3 for m in cosine_modes):
    failures.append(f"light sampling: scenes per mode {modes}")

uniform = {"uniform_theta_phi", "uniform_hemisphere", "cosine_hemisphere"}
unresolved = []
for r in report["direct"]:
    b = r["bias_sigma"]
    # A zero-variance estimator (projected light sampling of a Lambertian receiver) has no
    # spread to measure bias in: its mean must then equal the reference to the f32 estimates'
    # rounding: the estimator sums its 64 samples in f32, and equal terms round alike, by up to
    # 64 * 2^-24 = 3.8e-6 (measured 1.2e-6 for the sphere's cap).
    if abs(r["mean"] - r["reference"]) <= 1e-5 * abs(r["reference"]):
        continue
    if b is None:
        unresolved.append(f"{r['scene']}/{r['strategy']}")
        if r["strategy"] not in uniform:
            failures.append(f"direct: {r['scene']} {r['strategy']} has no spread")
    elif abs(b) > 4.0:
        failures.append(f"direct: {r['scene']} {r['strategy']} bias {b:.2f} sigma")

cells = {}
for r in report["direct"]:
    if r["scene"].startswith("grid_") and r["light_sampling"] == "solid_angle":
        cells.setdefault(r["scene"], {})[r["strategy"]] = r
if len(cells) != 16:
    failures.append(f"grid: {len(cells)} cells, expected 16")
within_2x = 0
for name, c in sorted(cells.items()):
    rm = {k: v["rel_rmse"] for k, v in c.items()}
    n = c["mis_power"]["samples_per_estimate"] // 2
    better = min(rm["light_solid_angle"], rm["bsdf"])
    worse = max(rm["light_solid_angle"], rm["bsdf"])
    bound = (better**2 + 1.0 / n - 1.0 / (2 * n)) ** 0.5
    if rm["mis_power"] > worse:
        failures.append(f"grid {name}: power {rm['mis_power']:.3e} above the worse {worse:.3e}")
    if rm["mis_power"] > bound:
        failures.append(f"grid {name}: power {rm['mis_power']:.3e} above Veach's bound {bound:.3e}")
    if rm["optimal_mis"] > 1.05 * rm["mis_power"]:
        failures.append(f"grid {name}: optimal {rm['optimal_mis']:.3e} > 1.05 x power {rm['mis_power']:.3e}")
    within_2x += rm["mis_power"] <= 2 * better

print(f"chi2: {len(warps)} samplers, Sidak level {level:.2e}")
print(f"direct: {len(report['direct'])} rows; unresolved (no sample reached the light): {unresolved}")
print(f"grid: power MIS within 2x of the better technique in {within_2x} of {len(cells)} cells")
if failures:
    print("FAILED:\n  " + "\n  ".join(failures))
    sys.exit(1)
print("report checks passed")
