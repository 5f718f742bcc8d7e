"""pooltool's ball-ball collision time for rolling balls beside cc_sweep_rolling, on the same
pairs, in the same run (issue 12's benchmark row).

Usage: python pooltool_rolling.py BENCH_PAIR_ROLLING PAIRS [--rounds R] [--times-out FILE]

PAIRS holds 14 doubles per pair (class, pa, va, ra, pb, vb, rb, decel_a, decel_b, t_max: see
bench/bench_pair_rolling.c). pooltool (PyPI pooltool-billiards) models a rolling ball as
r(t) = r0 + v t + a t^2 with a = -mu g / 2 along v (pooltool.evolution.event_based.solve.
ball_ball_collision_coeffs gives the quartic's coefficients, contact distance 2R) and solves the
quartic with pooltool.ptmath.roots.quartic (analytic with a residual check, else companion-matrix
eigenvalues), keeping the least real positive root (ptmath.roots.core.min_real_root). Here
mu = decel / g and R = (ra + rb) / 2, so the quartic is the same as ours.

Timed (per pair, median over rounds, pooltool's own functions only):
  - pooltool per pair: coefficients + quartic.solve + min_real_root, one pair at a time from
    Python, as its event loop does for each pair;
  - pooltool batched: quartic.solve_many over all pairs' coefficient rows at once (numba, no
    Python per pair): the solver's floor.
Then BENCH_PAIR_ROLLING time PAIRS runs ours in the same run; ratios are printed.

--times-out FILE writes pooltool's answer per pair (8 bytes: t, inf for a miss) for
`numerics_report --judge PAIRS FILE`. For that answer the event loop is followed: the quartic
holds until the first ball stops (pooltool's transition event); a root after that is not taken,
the balls are moved to the stop with pooltool's motion, the stopped one made stationary, and
the next piece solved the same way, up to t_max.
"""
import argparse
import subprocess
import sys
import time

import numpy as np

G = 9.81


def load(path):
    return np.fromfile(path, dtype="<f8").reshape(-1, 14)


def rvw_of(x, y, vx, vy):
    rvw = np.zeros((3, 3))
    rvw[0, 0], rvw[0, 1] = x, y
    rvw[1, 0], rvw[1, 1] = vx, vy
    return rvw


def state(vx, vy, decel, const):
    return const.rolling if (vx != 0.0 or vy != 0.0) and decel > 0.0 else (
        const.stationary if vx == 0.0 and vy == 0.0 else const.rolling)


def coeffs(row, pt):
    solve, const = pt
    _, ax, ay, avx, avy, ra, bx, by, bvx, bvy, rb, da, db, _ = row
    R = 0.5 * (ra + rb)
    sa, sb = state(avx, avy, da, const), state(bvx, bvy, db, const)
    return solve.ball_ball_collision_coeffs(rvw_of(ax, ay, avx, avy), rvw_of(bx, by, bvx, bvy), sa, sb,
                                            da / G, db / G, 1.0, 1.0, G, G, R)


def first_root(p, quartic, core):
    roots = quartic.solve(*p)
    r = core.min_real_root(roots)
    return float(np.real(r))


def event_loop_time(row, pt, quartic, core):
    """pooltool's answer for a pair over [0, t_max], following its transitions (see above)."""
    solve, const = pt
    _, ax, ay, avx, avy, ra, bx, by, bvx, bvy, rb, da, db, t_max = [float(v) for v in row]
    t0 = 0.0
    for _ in range(3):
        row2 = (0, ax, ay, avx, avy, ra, bx, by, bvx, bvy, rb, da, db, 0)
        sa = np.hypot(avx, avy)
        sb = np.hypot(bvx, bvy)
        ta = sa / da if sa > 0 and da > 0 else np.inf
        tb = sb / db if sb > 0 and db > 0 else np.inf
        end = min(ta, tb)
        if np.hypot(bx - ax, by - ay) < ra + rb:
            return 0.0 if t0 == 0.0 else t0
        p = coeffs(row2, pt)
        if all(c == 0.0 for c in p[:4]):
            return np.inf
        t = first_root(p, quartic, core)
        if t <= end and t0 + t <= t_max:
            return t0 + t
        if not np.isfinite(end) or t0 + end > t_max:
            return np.inf
        # both balls to the first stop: r0 + v t - (decel / 2) t^2 along v; the stopped one at rest
        def move(x, y, vx, vy, s, d, t):
            if s == 0 or d == 0:
                return x + vx * t, y + vy * t, vx, vy
            ux, uy = vx / s, vy / s
            x += vx * t - 0.5 * d * ux * t * t
            y += vy * t - 0.5 * d * uy * t * t
            s2 = max(s - d * t, 0.0)
            return x, y, ux * s2, uy * s2
        ax, ay, avx, avy = move(ax, ay, avx, avy, sa, da, end)
        bx, by, bvx, bvy = move(bx, by, bvx, bvy, sb, db, end)
        if ta == end:
            avx = avy = 0.0
        if tb == end:
            bvx = bvy = 0.0
        t0 += end
    return np.inf


def load_first_ok(rows):
    return rows[0]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("bench")
    ap.add_argument("pairs")
    ap.add_argument("--rounds", type=int, default=5)
    ap.add_argument("--times-out")
    ap.add_argument("--time-limit", type=float, default=0.0, help="pairs timed per pair at most (0: all)")
    a = ap.parse_args()
    try:
        import pooltool  # noqa: F401
        import pooltool.constants as const
        from pooltool.evolution.event_based import solve
        from pooltool.ptmath.roots import core, quartic
    except Exception as e:  # noqa: BLE001
        print("pooltool: not importable (%s); its rows are skipped" % e)
        return 0
    pt = (solve, const)
    rows = load(a.pairs)
    n = len(rows)
    # compile (numba) before timing
    first_root(coeffs(load_first_ok(rows), pt), quartic, core)
    ps = np.array([coeffs(r, pt) for r in rows], dtype=np.float64)
    try:
        quartic.solve_many(ps)
        batch_ok = True
    except Exception as e:  # noqa: BLE001 (pooltool fails on some degenerate quartics)
        print("pooltool: quartic.solve_many raised on these pairs (%s); batched timing skipped" % str(e).splitlines()[0])
        batch_ok = False

    per_pair, batched = [], []
    m = n if a.time_limit <= 0 else min(n, int(a.time_limit))
    for _ in range(a.rounds):
        t = time.perf_counter()
        for r in rows[:m]:
            try:
                first_root(coeffs(r, pt), quartic, core)
            except Exception:  # noqa: BLE001
                pass
        per_pair.append((time.perf_counter() - t) / m * 1e9)
        if batch_ok:
            t = time.perf_counter()
            quartic.solve_many(ps)
            batched.append((time.perf_counter() - t) / n * 1e9)
    if not batched:
        batched = [float("nan")]
    ours = subprocess.run([a.bench, "time", a.pairs, "--rounds", str(max(a.rounds, 5))], check=True,
                          capture_output=True, text=True).stdout
    print(ours, end="")
    ns_ours = float([ln for ln in ours.splitlines() if ln.startswith("csv ns_per_pair")][0].split()[-1])
    med_pp, med_b = float(np.median(per_pair)), float(np.median(batched))
    print("pooltool %s, %d pairs, %d rounds; ns per pair: median (min - max)" % (pooltool.__version__, n, a.rounds))
    print("  %-36s %10.1f  (%.1f - %.1f)" % ("pooltool per pair (coeffs + solve + min root)", med_pp, min(per_pair),
                                             max(per_pair)))
    print("  %-36s %10.1f  (%.1f - %.1f)" % ("pooltool batched quartic.solve_many", med_b, min(batched), max(batched)))
    print("  pooltool per pair / cc_sweep_rolling: %.1f" % (med_pp / ns_ours))
    print("  pooltool batched solve / cc_sweep_rolling: %.2f" % (med_b / ns_ours))
    print("figure pooltool_per_pair_over_rolling %.6g" % (med_pp / ns_ours))
    print("figure pooltool_batched_over_rolling %.6g" % (med_b / ns_ours))
    if a.times_out:
        def answer(r):
            try:
                return event_loop_time(r, pt, quartic, core)
            except Exception:  # noqa: BLE001 (pooltool raised: NaN, counted wrong by --judge)
                return float("nan")
        out = np.array([answer(r) for r in rows], dtype="<f8")
        out.tofile(a.times_out)
        print("pooltool answers (event loop) written to %s: %d hits, %d raised" % (
            a.times_out, int(np.isfinite(out).sum()), int(np.isnan(out).sum())))
    return 0


if __name__ == "__main__":
    sys.exit(main())
