"""Throughput of circlecollide.sweep_many from Python (pairs/s), next to the C library's own.

    python bindings/python/bench_sweep_many.py [--pairs 1000000] [--rounds 7] [--c-bench PATH]

Times, as the median of several rounds over the same pairs:
  python sweep_many   the public function: (n, 2) arrays in, columns made, one C call, t out
  C call via ctypes   cc_sweep_many alone on ready columns (what the binding adds is the rest)
  python sweep loop   circlecollide.sweep pair by pair, on 20,000 pairs (per-call overhead)
--c-bench runs the benchmark program bench/bench_pair (--only cc_sweep_many) for the pure C
figure. The pairs follow bench_pair's recipe (about half hit within t_max = 1, none overlap).
"""

from __future__ import annotations

import argparse
import ctypes
import re
import statistics
import subprocess
import time

import numpy as np

import circlecollide as cc
from circlecollide import _lib


def make_pairs(n: int, seed: int = 1):
    rng = np.random.default_rng(seed)
    ra, rb = rng.uniform(0.05, 0.5, n), rng.uniform(0.05, 0.5, n)
    ang = rng.uniform(0, 2 * np.pi, n)
    dist = (ra + rb) * 1.01 + rng.uniform(0, 3, n)
    ap = rng.uniform(-50, 50, (n, 2))
    u = np.stack([np.cos(ang), np.sin(ang)], axis=1)
    bp = ap + dist[:, None] * u
    av = rng.uniform(-4, 4, (n, 2))
    bv = -2.0 * u + rng.uniform(-4, 4, (n, 2))
    return ap, av, ra, bp, bv, rb


def median_time(fn, rounds: int) -> float:
    times = []
    for _ in range(rounds):
        t0 = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def main() -> None:
    ap_ = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap_.add_argument("--pairs", type=int, default=1_000_000)
    ap_.add_argument("--rounds", type=int, default=7)
    ap_.add_argument("--c-bench", help="path of bench_pair (built from bench/)")
    args = ap_.parse_args()
    n = args.pairs
    ap, av, ra, bp, bv, rb = make_pairs(n)
    t = cc.sweep_many(ap, av, ra, bp, bv, rb, 1.0)
    print(f"circlecollide {cc.library_version()} from {cc.library_path()}")
    print(f"{n} pairs, {np.isfinite(t).mean():.1%} hit within t_max = 1")

    rows = []
    s = median_time(lambda: cc.sweep_many(ap, av, ra, bp, bv, rb, 1.0), args.rounds)
    rows.append(("python sweep_many", n / s, s / n * 1e9))

    cols = [np.ascontiguousarray(m[:, k]) for m in (ap, av) for k in (0, 1)] + [ra]
    colsb = [np.ascontiguousarray(m[:, k]) for m in (bp, bv) for k in (0, 1)] + [rb]
    P = ctypes.POINTER(ctypes.c_double)
    sa = _lib.cc_circle_soa(*(c.ctypes.data_as(P) for c in cols))
    sb = _lib.cc_circle_soa(*(c.ctypes.data_as(P) for c in colsb))
    out = np.empty(n)
    outp = out.ctypes.data_as(P)
    fn = _lib.lib.cc_sweep_many
    s = median_time(lambda: fn(n, ctypes.byref(sa), ctypes.byref(sb), 1.0, outp, None), args.rounds)
    rows.append(("C call via ctypes", n / s, s / n * 1e9))
    assert np.array_equal(out, t)

    m = min(n, 20_000)
    circles = [(cc.Circle(ap[i], av[i], ra[i]), cc.Circle(bp[i], bv[i], rb[i])) for i in range(m)]
    s = median_time(lambda: [cc.sweep(a, b, 1.0) for a, b in circles], max(1, args.rounds // 2))
    rows.append(("python sweep loop", m / s, s / m * 1e9))

    if args.c_bench:
        o = subprocess.run(
            [args.c_bench, "--pairs", str(n), "--only", "cc_sweep_many", "--no-reference"],
            capture_output=True, text=True, check=True,
        ).stdout
        line = next((ln for ln in o.splitlines() if "cc_sweep_many" in ln), "")
        nums = re.findall(r"(\d+(?:\.\d+)?)", line.split("cc_sweep_many", 1)[-1])
        if len(nums) >= 4:  # medians: cache-resident (blocks of pairs), then streamed (all n)
            rows.append(("C bench_pair, cached", 1e9 / float(nums[0]), float(nums[0])))
            rows.append(("C bench_pair, stream", 1e9 / float(nums[3]), float(nums[3])))
        print("bench_pair:", line.strip())

    print(f"{'':22s} {'pairs/s':>12s} {'ns/pair':>9s}")
    for name, rate, ns in rows:
        print(f"{name:22s} {rate:12.3e} {ns:9.1f}")


if __name__ == "__main__":
    main()
