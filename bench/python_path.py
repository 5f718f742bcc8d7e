"""What the Python path costs: stepping a world from Python against the same world stepped by C,
and the cost of one pair-function call from Python against C and against the Python peers.

Usage: python bench/python_path.py BENCH_DIR [--n 10000] [--phi 0.3] [--t-end 1] [--rounds 5]
                                            [--pairs 20000] [--quick]

BENCH_DIR holds the bench_world and bench_pair programs (e.g. build-bench/bench). Run it with
CIRCLECOLLIDE_LIBRARY set to the shared library of that same build (bench/run.sh does), so that
Python and C run the same compiled library. Every round measures every row once, interleaved,
so that a slow moment of the machine hits all rows of that round alike; a ratio is taken per
round and its median and range [min, max] over the rounds are printed, and beside it the ratio
of minima (fastest over fastest: noise only adds time, so on a shared machine it is the steadier
estimate, as in bench_world features; the figures report it).

World: the benchmark's gas (bench_world dump-gas N PHI: N circles of radius 0.5, area fraction
PHI, in a box of 4 walls), EXACT, restitution 1, frames of 1/60 for T_END simulated seconds.
  C              bench_world peer N PHI T_END DT (median of its own 5 timed runs)
  python step    World.step(dt) per frame (the loop in Python, one C call a frame; median of 5)
  python +pos    the same, reading World.positions (an (N, 2) numpy array) every frame
Python's world is built from the printed state, so it runs the same events: its collision count
must equal C's (checked).

Pairs: P random approaching pairs (about half hit within t_max = 1), one call per pair, as a
Python loop over ready inputs (only the calls are timed; each row's time is its fastest burst
of 1000 calls in the round):
  C cc_sweep     bench_pair --only cc_sweep (cache-resident median): the C function alone
  sweep          circlecollide.sweep(a, b, 1.0) on Circle values (checks, structs, Contact out)
  ctypes floor   the C function called through ctypes on ready structs (what ctypes alone costs)
  billiards      billiards.physics.time_of_impact (pure Python + numpy; PyPI billiards)
  detect_static  circlecollide.detect_static(a, b)
  pymunk         pymunk Shape.shapes_collide of two circles (Chipmunk2D in C through cffi)
sweep and time_of_impact answer the same question (first touch of two moving circles), and
detect_static and shapes_collide the same static one (do they overlap, where, how deep).
Prints `figure NAME VALUE` lines for docs/BENCHMARKS.md.
"""

from __future__ import annotations

import argparse
import ctypes
import math
import os
import statistics
import subprocess
import sys
import time

import numpy as np

import circlecollide as cc
from circlecollide import _lib

DT = 1.0 / 60.0


def stat(xs):
    return statistics.median(xs), min(xs), max(xs)


def show(xs, fmt="%.3g"):
    m, lo, hi = stat(xs)
    return (fmt % m) + " [" + (fmt % lo) + ", " + (fmt % hi) + "]"


# ---- world --------------------------------------------------------------------------------------


def load_gas(bench_dir, n, phi):
    out = subprocess.run([os.path.join(bench_dir, "bench_world"), "dump-gas", str(n), str(phi)], check=True,
                         capture_output=True, text=True).stdout.splitlines()
    box = [float(v) for v in out[0].split()[2:]]
    balls = [[float(v) for v in line.split()] for line in out[1:]]
    return box, balls


def make_world(box, balls):
    x0, y0, x1, y1 = box
    w = cc.World(max_circles=len(balls), max_segments=4, mode="exact", restitution=1.0)
    for px, py, vx, vy, r, m in balls:  # circles first, then walls, as bench_world does
        w.add_circle(cc.Circle(pos=(px, py), vel=(vx, vy), radius=r, mass=m))
    for a, b in (((x0, y0), (x1, y0)), ((x1, y0), (x1, y1)), ((x1, y1), (x0, y1)), ((x0, y1), (x0, y0))):
        w.add_segment(a, b)
    return w


def python_world(box, balls, t_end, read_positions, reps=5):
    """Seconds per simulated second: the median of `reps` runs, as bench_world peer takes it."""
    steps = int(math.ceil(t_end / DT - 1e-9))
    per = []
    for _ in range(reps):
        w = make_world(box, balls)
        sink = 0.0
        t0 = time.perf_counter()
        for _ in range(steps):
            while not w.step(DT):
                w.step(0.0)  # EVENT_LIMIT: continue (never happens in this gas)
            if read_positions:
                sink += w.positions[0, 0]
        per.append((time.perf_counter() - t0) / (steps * DT))
    return statistics.median(per), w.stats.collisions


def c_world(bench_dir, n, phi, t_end):
    line = subprocess.run([os.path.join(bench_dir, "bench_world"), "peer", str(n), str(phi), str(t_end), repr(DT)],
                          check=True, capture_output=True, text=True).stdout
    fields = dict(kv.split("=", 1) for kv in line.split() if "=" in kv)
    return float(fields["sec_per_sim_s"]), int(fields["collisions"])


# ---- pairs --------------------------------------------------------------------------------------


def make_pairs(p, seed=1):
    rng = np.random.default_rng(seed)
    ra, rb = rng.uniform(0.05, 0.5, p), rng.uniform(0.05, 0.5, p)
    ang = rng.uniform(0, 2 * np.pi, p)
    u = np.stack([np.cos(ang), np.sin(ang)], axis=1)
    ap = rng.uniform(-50, 50, (p, 2))
    bp = ap + ((ra + rb) * 1.01 + rng.uniform(0, 3, p))[:, None] * u
    av = rng.uniform(-4, 4, (p, 2))
    bv = -2.0 * u + rng.uniform(-4, 4, (p, 2))
    return [(tuple(ap[i]), tuple(av[i]), float(ra[i]), tuple(bp[i]), tuple(bv[i]), float(rb[i])) for i in range(p)]


def per_call(fn, args, burst=1000):
    """ns per call: the fastest burst of `burst` calls (a burst is short enough that most run
    without the process being preempted; noise only adds time)."""
    best = math.inf
    for k in range(0, len(args), burst):
        chunk = args[k:k + burst]
        t0 = time.perf_counter()
        for a in chunk:
            fn(*a)
        best = min(best, (time.perf_counter() - t0) / len(chunk) * 1e9)
    return best


def c_sweep_ns(bench_dir, pairs):
    out = subprocess.run([os.path.join(bench_dir, "bench_pair"), "--pairs", str(max(pairs, 100000)), "--rounds", "3",
                          "--no-reference", "--only", "cc_sweep"], check=True, capture_output=True, text=True).stdout
    for line in out.splitlines():
        if line.startswith("figure sweep_ns_per_pair "):
            return float(line.split()[2])
    raise RuntimeError("bench_pair printed no sweep_ns_per_pair:\n" + out)


def pair_rows(bench_dir, raw, have):
    """One round of every pair row: ns per call."""
    ours = [(cc.Circle(pos=a, vel=va, radius=ra), cc.Circle(pos=b, vel=vb, radius=rb)) for a, va, ra, b, vb, rb in raw]
    structs = [(_lib.cc_circle(_lib.cc_vec2(*a), _lib.cc_vec2(*va), ra, 1.0),
                _lib.cc_circle(_lib.cc_vec2(*b), _lib.cc_vec2(*vb), rb, 1.0)) for a, va, ra, b, vb, rb in raw]
    out = _lib.cc_contact()
    fn, byref = _lib.lib.cc_sweep, ctypes.byref
    row = {"C cc_sweep": c_sweep_ns(bench_dir, len(raw))}
    row["sweep"] = per_call(lambda a, b: cc.sweep(a, b, 1.0), ours)
    row["ctypes floor"] = per_call(lambda a, b: fn(byref(a), byref(b), 1.0, byref(out)), structs)
    row["detect_static"] = per_call(cc.detect_static, ours)
    if "billiards" in have:
        from billiards.physics import time_of_impact  # noqa: PLC0415 (optional peer)
        args = [(np.array(a), np.array(va), ra, np.array(b), np.array(vb), rb) for a, va, ra, b, vb, rb in raw]
        row["billiards"] = per_call(time_of_impact, args)
    if "pymunk" in have:
        import pymunk  # noqa: PLC0415 (optional peer)
        shapes = []
        for a, _va, ra, b, _vb, rb in raw:
            ba, bb = pymunk.Body(1.0, float("inf")), pymunk.Body(1.0, float("inf"))
            ba.position, bb.position = a, b
            shapes.append((pymunk.Circle(ba, ra), pymunk.Circle(bb, rb)))
        row["pymunk"] = per_call(lambda s, t: s.shapes_collide(t), shapes)
    return row


def check_pair_answers(raw, have):
    """The rows answer the same questions: our sweep's hits and billiards' agree."""
    if "billiards" not in have:
        return ""
    from billiards.physics import time_of_impact  # noqa: PLC0415
    worst, disagree = 0.0, 0
    for a, va, ra, b, vb, rb in raw[:2000]:
        c = cc.sweep(cc.Circle(pos=a, vel=va, radius=ra), cc.Circle(pos=b, vel=vb, radius=rb), 1.0)
        t = time_of_impact(np.array(a), np.array(va), ra, np.array(b), np.array(vb), rb)
        ours = c.t if c is not None and c.kind == "hit" else math.inf
        theirs = t if t <= 1.0 else math.inf
        if math.isinf(ours) != math.isinf(theirs):
            disagree += 1
        elif not math.isinf(ours):
            worst = max(worst, abs(ours - theirs) / max(ours, 1e-300))
    return f"sweep vs billiards on 2000 pairs: {disagree} hit/miss disagreements, worst relative time difference {worst:.2g}"


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("bench_dir")
    ap.add_argument("--n", type=int, default=10000)
    ap.add_argument("--phi", type=float, default=0.3)
    ap.add_argument("--t-end", type=float, default=1.0)
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--pairs", type=int, default=20000)
    ap.add_argument("--quick", action="store_true", help="n = 2000, 3 rounds, 5000 pairs")
    a = ap.parse_args()
    if a.quick:
        a.n, a.rounds, a.pairs = 2000, 3, 5000
    have = []
    for name in ("billiards", "pymunk"):
        try:
            __import__(name)
            have.append(name)
        except ImportError:
            print(f"(peer {name} not installed: its rows are skipped)")
    print(f"circlecollide {cc.__version__}, C library {cc.library_version()} at {cc.library_path()}")
    print(f"python {sys.version.split()[0]}, numpy {np.__version__}" +
          "".join(f", {m} {getattr(__import__(m), '__version__', getattr(__import__(m), 'version', '?'))}" for m in have))

    box, balls = load_gas(a.bench_dir, a.n, a.phi)
    rows = {"C": [], "python step": [], "python +pos": []}
    r_step, r_pos, coll = [], [], set()
    for _ in range(a.rounds):
        c, cc_coll = c_world(a.bench_dir, a.n, a.phi, a.t_end)
        s, s_coll = python_world(box, balls, a.t_end, False)
        p, p_coll = python_world(box, balls, a.t_end, True)
        coll |= {cc_coll, s_coll, p_coll}
        rows["C"].append(c)
        rows["python step"].append(s)
        rows["python +pos"].append(p)
        r_step.append(s / c)
        r_pos.append(p / c)
    steps = int(math.ceil(a.t_end / DT - 1e-9))
    print(f"\n== world: gas N={a.n} phi={a.phi}, EXACT, {steps} frames of 1/60 s, {a.rounds} rounds"
          f" (median [min, max])")
    print(f"collisions in one run: {sorted(coll)} ({'the same in C and Python' if len(coll) == 1 else 'DIFFERENT'})")
    mins = {k: min(v) for k, v in rows.items()}
    print(f"{'':14s} {'s per simulated s':>28s} {'ratio to C':>28s} {'ratio of minima':>16s}")
    print(f"{'C':14s} {show(rows['C']):>28s} {'1':>28s} {'1':>16s}")
    print(f"{'python step':14s} {show(rows['python step']):>28s} {show(r_step):>28s} "
          f"{mins['python step'] / mins['C']:16.3g}")
    print(f"{'python +pos':14s} {show(rows['python +pos']):>28s} {show(r_pos):>28s} "
          f"{mins['python +pos'] / mins['C']:16.3g}")
    frame_us = (mins["python +pos"] - mins["C"]) * DT * 1e6
    read_us = (mins["python +pos"] - mins["python step"]) * DT * 1e6
    print(f"from the minima, per frame: python's whole cost {frame_us:.0f} us over C's, of which reading "
          f"positions {read_us:.0f} us")

    raw = make_pairs(a.pairs)
    print(f"\n== pair calls: {a.pairs} pairs, one call each, {a.rounds} rounds (ns per call, median [min, max])")
    print(check_pair_answers(raw, have))
    per = []
    for _ in range(a.rounds):
        per.append(pair_rows(a.bench_dir, raw, have))
    names = list(per[0])
    ratio = {
        "sweep / C cc_sweep": [r["sweep"] / r["C cc_sweep"] for r in per],
        "sweep / ctypes floor": [r["sweep"] / r["ctypes floor"] for r in per],
    }
    if "billiards" in have:
        ratio["billiards / sweep"] = [r["billiards"] / r["sweep"] for r in per]
    if "pymunk" in have:
        ratio["pymunk / detect_static"] = [r["pymunk"] / r["detect_static"] for r in per]
    for name in names:
        print(f"{name:16s} {show([r[name] for r in per], '%.1f'):>30s}")
    print("ratios (per round):")
    pmin = {k: min(r[k] for r in per) for k in names}
    min_ratio = {
        "sweep / C cc_sweep": pmin["sweep"] / pmin["C cc_sweep"],
        "sweep / ctypes floor": pmin["sweep"] / pmin["ctypes floor"],
    }
    if "billiards" in have:
        min_ratio["billiards / sweep"] = pmin["billiards"] / pmin["sweep"]
    if "pymunk" in have:
        min_ratio["pymunk / detect_static"] = pmin["pymunk"] / pmin["detect_static"]
    print(f"  {'':24s} {'median [min, max]':>28s} {'ratio of minima':>16s}")
    for name, xs in ratio.items():
        print(f"  {name:24s} {show(xs, '%.3g'):>28s} {min_ratio[name]:16.3g}")

    print()
    print(f"figure py_world_step_ratio {mins['python step'] / mins['C']:.4g}")
    print(f"figure py_world_positions_ratio {mins['python +pos'] / mins['C']:.4g}")
    print(f"figure py_sweep_ns {pmin['sweep']:.4g}")
    print(f"figure py_sweep_over_c {min_ratio['sweep / C cc_sweep']:.4g}")
    if "billiards" in have:
        print(f"figure billiards_toi_over_py_sweep {min_ratio['billiards / sweep']:.4g}")
    if "pymunk" in have:
        print(f"figure pymunk_collide_over_py_detect {min_ratio['pymunk / detect_static']:.4g}")
    return 0 if len(coll) == 1 else 1


if __name__ == "__main__":
    sys.exit(main())
