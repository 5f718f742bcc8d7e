"""What the batch add saves from Python: World.add_circles from numpy arrays (one C call per chunk,
cc_world_add_circles) against a loop of World.add_circle, for N circles into an empty world.

Usage: python bench/python_bulk.py [--sizes 10000,1000000] [--rounds 5] [--quick]
(--rounds for N > 1e5; smaller N get three times as many)

Run it with CIRCLECOLLIDE_LIBRARY set to the shared library of the benchmark build and the
binding on PYTHONPATH (bench/run.sh does, as for bench/python_path.py). The circles: radius 0.5
on a square lattice of spacing 1.25 (no overlaps), velocities uniform in [-1, 1) per component,
mass 1, EXACT. Rows, every one in every round, their order rotated each round:
  add_circle loop   for c in circles: w.add_circle(c), the Circle values made before the clock
                    starts (the loop's floor: a script that builds them pays that too)
  add_circles       w.add_circles(pos, vel, radius, mass) from ready numpy arrays
Each row builds a fresh World (outside the clock). Both must end with the same World.hash.
The ratio is taken per round; median [min, max] and the ratio of minima are printed.
Prints `figure NAME VALUE` lines for docs/BENCHMARKS.md.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time

import numpy as np

import circlecollide as cc


def lattice(n: int, seed: int) -> tuple[np.ndarray, np.ndarray]:
    side = int(np.ceil(np.sqrt(n)))
    k = np.arange(n)
    pos = np.stack([(k % side) * 1.25, (k // side) * 1.25], axis=1).astype(np.float64)
    vel = np.random.default_rng(seed).uniform(-1.0, 1.0, size=(n, 2))
    return pos, vel


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sizes", default="10000,1000000")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--quick", action="store_true", help="N = 1000 and 10000, 3 rounds")
    a = ap.parse_args()
    sizes = [1000, 10000] if a.quick else [int(float(s)) for s in a.sizes.split(",")]
    rounds = 3 if a.quick else a.rounds
    print("circlecollide %s, C library %s at %s" % (cc.__version__, cc.library_version(), cc.library_path()))
    print("python %s, numpy %s" % (sys.version.split()[0], np.__version__))
    print()
    print("%9s %7s %20s %26s %20s %26s %28s %10s" % ("N", "rounds", "add_circle loop us", "[min, max]",
                                                    "add_circles us", "[min, max]", "loop / add_circles [min, max]",
                                                    "of minima"))
    for n in sizes:
        rounds_n = rounds if n > 100000 else 3 * rounds
        pos, vel = lattice(n, 7)
        radius = np.full(n, 0.5)
        mass = np.ones(n)
        circles = [cc.Circle(pos=(float(p[0]), float(p[1])), vel=(float(v[0]), float(v[1])), radius=0.5, mass=1.0)
                   for p, v in zip(pos, vel)]
        t = {"loop": [], "batch": []}
        hashes = {}
        for r in range(rounds_n):
            for row in (["loop", "batch"] if r % 2 == 0 else ["batch", "loop"]):
                w = cc.World(max_circles=n)
                t0 = time.perf_counter()
                if row == "loop":
                    add = w.add_circle
                    for c in circles:
                        add(c)
                else:
                    w.add_circles(pos, vel, radius, mass)
                t[row].append((time.perf_counter() - t0) * 1e6 / n)
                hashes.setdefault(row, set()).add(w.hash)
                del w
        ratio = [x / y for x, y in zip(t["loop"], t["batch"])]
        same = hashes["loop"] == hashes["batch"] and len(hashes["loop"]) == 1
        med = statistics.median
        print("%9d %7d %20.3f %26s %20.4f %26s %28s %10.1f%s" % (
            n, rounds_n, med(t["loop"]), "[%.3f, %.3f]" % (min(t["loop"]), max(t["loop"])), med(t["batch"]),
            "[%.4f, %.4f]" % (min(t["batch"]), max(t["batch"])),
            "%.1f [%.1f, %.1f]" % (med(ratio), min(ratio), max(ratio)), min(t["loop"]) / min(t["batch"]),
            "" if same else "  (the worlds differ!)"))
        print("figure python_add_circle_loop_over_add_circles_n%d %.6g" % (n, med(ratio)))
        print("figure python_add_circles_us_per_circle_n%d %.6g" % (n, med(t["batch"])))
        sys.stdout.flush()
        del circles
    print("(us per circle; the same world, World.hash, from both rows)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
