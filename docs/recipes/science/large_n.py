"""Recipe: a million hard disks at eta 0.70 (docs/PHYSICS.md, "A million disks").

Engel et al. (Phys. Rev. E 87, 042134, 2013) ran N = 1024^2 hard disks to settle the
liquid-hexatic transition; this sets up 1e6 disks at eta 0.70 through the bulk calls
(World.add_circles from numpy arrays), then runs and reports, every ``--every`` collisions per
disk: the pressure of that stretch from the virial, the square lattice's memory (the global
4-fold bond order |psi4| of the start, 1 on the lattice), the global hexatic order |psi6| (freud,
when installed) and the collisions per second. At the end: the world's memory, the process's
peak memory, the set-up time, and how many collisions per disk (and seconds) it took the
pressure to settle (its stretches within 1 % of the last ones' mean) and the lattice to be
forgotten (|psi4| below 3 / sqrt(N)).

    python docs/recipes/science/large_n.py                     # 1e6 disks, 100 collisions per disk
    python docs/recipes/science/large_n.py --n 40000 --collisions 50 --every 5
Writes nothing. Not run by CI (minutes of CPU); its figures are in docs/PHYSICS.md.
"""

import argparse
import math
import resource
import time

import numpy as np

from circlecollide import World, hard_disks


def global_order(world, k, pos):
    """|<psi_k>|, the box average of psi_k,j = mean over the k nearest neighbours of
    exp(i k theta_jl) (freud.order.Hexatic with k neighbours): k = 4 is the square lattice's
    order (1 on the start), k = 6 the hexatic order. NaN without freud."""
    try:
        import freud
    except ImportError:
        return math.nan
    L = world.period[0]
    h = freud.order.Hexatic(k=k)
    h.compute((freud.box.Box.square(L), np.column_stack((pos - L / 2, np.zeros(len(pos))))), neighbors={"num_neighbors": k})
    return float(abs(h.particle_order.mean()))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--n", type=int, default=1_000_000)
    ap.add_argument("--eta", type=float, default=0.70)
    ap.add_argument("--collisions", type=float, default=100.0, help="collisions per disk to run")
    ap.add_argument("--every", type=float, default=10.0, help="collisions per disk between reports")
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    n = a.n
    t0 = time.perf_counter()
    pos, vel, side = hard_disks.lattice_start(n, a.eta, np.random.default_rng(a.seed))
    t1 = time.perf_counter()
    w = World(max_circles=n, period=(side, side))
    w.add_circles(pos, vel, hard_disks.RADIUS, 1.0)
    t2 = time.perf_counter()
    print(f"N {n}, eta {a.eta}, box {side:.2f}: the start drawn in {t1 - t0:.2f} s, World + add_circles {t2 - t1:.2f} s")
    print(f"world memory {w._size / 2**20:.0f} MiB ({w._size / n:.0f} bytes per disk)")
    rate = hard_disks.contact_rate(a.eta)
    dt = a.every / rate
    print(f"{'coll/disk':>9} {'Z (stretch)':>11} {'|psi4|':>7} {'|psi6|':>7} {'coll/s':>9} {'coll/cpu s':>10} {'wall s':>7}")
    last = w.stats
    last_t, start = w.time, time.perf_counter()
    zs, rows = [], []
    while True:
        tw, tc = time.perf_counter(), time.process_time()
        hard_disks.advance(w, dt)  # continued past the automatic event cap
        wall, cpu = time.perf_counter() - tw, time.process_time() - tc
        s = w.stats
        z = hard_disks.z_from_virial(s.virial - last.virial, w.time - last_t, n)
        p = w.positions
        psi4, psi6 = global_order(w, 4, p), global_order(w, 6, p)
        per_disk = 2.0 * s.collisions / n
        cps = (s.collisions - last.collisions) / wall
        cpu_rate = (s.collisions - last.collisions) / cpu  # what the step cost its core (a busy machine shares it)
        rows.append((per_disk, z, psi4, psi6, time.perf_counter() - start))
        zs.append(z)
        print(f"{per_disk:9.1f} {z:11.4f} {psi4:7.4f} {psi6:7.4f} {cps:9.3g} {cpu_rate:10.3g} {time.perf_counter() - start:7.0f}", flush=True)
        last, last_t = s, w.time
        if per_disk >= a.collisions:
            break
    tail = np.mean(zs[-3:])
    settled = next((r for i, r in enumerate(rows) if all(abs(x[1] / tail - 1) < 0.01 for x in rows[i:])), None)
    forgot = next((r for r in rows if r[2] < 3 / math.sqrt(n)), None)
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 2**10
    print(f"peak memory of the process {peak:.0f} MiB; {w.stats.collisions} collisions in {rows[-1][4]:.0f} s "
          f"({w.stats.collisions / rows[-1][4]:.3g} per second, analysis included)")
    if settled:
        print(f"Z settled (within 1 % of the last stretches' {tail:.3f}) after {settled[0]:.0f} collisions per disk, {settled[4]:.0f} s")
    else:
        print(f"Z not settled: the last stretch is more than 1 % from the last stretches' {tail:.3f} (run longer)")
    if forgot:
        print(f"the lattice forgotten (|psi4| < 3/sqrt(N)) after {forgot[0]:.0f} collisions per disk, {forgot[4]:.0f} s")
    else:
        print(f"the lattice not yet forgotten: |psi4| {rows[-1][2]:.4f} > 3/sqrt(N) = {3 / math.sqrt(n):.4f}")


if __name__ == "__main__":
    main()
