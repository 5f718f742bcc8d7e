"""Recipe: the structure of dense hard disks with freud, and the pressure two ways
(docs/RECIPES.md, docs/PHYSICS.md "Analysis with freud").

A periodic box of N disks (diameter sigma = 1) at eta 0.70 - 0.72 is equilibrated from a square
lattice (1000 collisions per disk), then F frames are taken, each after about one collision per disk. freud computes from
them the pair distribution g(r) (freud.density.RDF) and the hexatic order psi6
(freud.order.Hexatic over each disk's 6 nearest neighbours): the mean |psi6_j| of the disks and
|<psi6>| of the box. The 2D contact theorem gives the pressure from g at contact,

    Z = 1 + (pi / 2) n sigma^2 g(sigma+) = 1 + 2 eta g(sigma+),

(docs/PHYSICS.md derives it), beside the world's virial, Z = 1 + W / (2 t N kT). g(sigma+) is
extrapolated to r = sigma from the histogram's first bins: a quadratic in r - sigma fitted to
ln g over [sigma, sigma + 0.05] in bins of 0.0025.

Error bars: each Z over B blocks of frames (B = 8), its standard error the blocks' spread over
sqrt(B); for Z from g also the extrapolation's: half the difference between the fits over
[sigma, sigma + 0.05] and [sigma, sigma + 0.03], added in quadrature. The two Z must agree
within 3 times their combined error (they come from the same frames, so that is generous for
the statistics and is there for the extrapolation).

    python docs/recipes/science/hard_disks_freud.py                 # N 1024, eta 0.70 and 0.72
    python docs/recipes/science/hard_disks_freud.py --n 400 --frames 80 --eta 0.71
Needs freud-analysis (pip install circlecollide[science]). Writes nothing.
"""

import argparse
import math

import freud
import numpy as np

from circlecollide import hard_disks

SIGMA = 2 * hard_disks.RADIUS
DR = 0.0025
FIT = (0.05, 0.03)  # the two fitting windows above sigma


def system(world):
    """freud's (box, points) of the world now: positions moved into [-L/2, L/2)."""
    L = world.period[0]
    p = world.positions - L / 2
    return freud.box.Box.square(L), np.column_stack((p, np.zeros(len(p))))


def contact_value(rdf_contact, window):
    """g(sigma+) extrapolated from the contact RDF's bins within `window` above sigma: a
    quadratic in r - sigma fitted to ln g (g is smooth and steep there)."""
    r, g = rdf_contact.bin_centers, rdf_contact.rdf
    use = (r - SIGMA < window) & (g > 0)
    coeffs = np.polyfit(r[use] - SIGMA, np.log(g[use]), 2)
    return float(math.exp(coeffs[-1]))


def psi6(box, points):
    h = freud.order.Hexatic(k=6)
    h.compute((box, points), neighbors={"num_neighbors": 6})
    return h.particle_order


def run(eta, n=1024, frames=160, blocks=8, equil=1000.0, seed=3):
    """One state point: returns a dict with Z from the virial and from g at contact (each with
    its error), g(r) on [0, 3 sigma), |psi6| means, and the frames' count."""
    rng = np.random.default_rng(seed)
    world = hard_disks.make_box(n, eta, rng)
    rate = hard_disks.contact_rate(eta)
    hard_disks.run_until(world, int(equil * n / 2), 10.0 / rate)
    per_block = frames // blocks
    z_virial, z_contact, z_contact_short, local6, global6 = [], [], [], [], []
    rdf_all = freud.density.RDF(bins=120, r_max=3.0 * SIGMA, normalization_mode="finite_size")
    for _ in range(blocks):
        rdf = freud.density.RDF(bins=int(round(FIT[0] / DR)), r_max=SIGMA + FIT[0], r_min=SIGMA,
                                normalization_mode="finite_size")  # fmt: skip
        s0, t0 = world.stats, world.time
        for _ in range(per_block):
            hard_disks.advance(world, 1.0 / rate)  # about one collision per disk between frames
            box, points = system(world)
            rdf.compute((box, points), reset=False)
            rdf_all.compute((box, points), reset=False)
            order = psi6(box, points)
            local6.append(float(np.abs(order).mean()))
            global6.append(float(abs(order.mean())))
        s1, t1 = world.stats, world.time
        z_virial.append(hard_disks.z_from_virial(s1.virial - s0.virial, t1 - t0, n))
        z_contact.append(1.0 + 2.0 * eta * contact_value(rdf, FIT[0]))
        z_contact_short.append(1.0 + 2.0 * eta * contact_value(rdf, FIT[1]))
    zv, zv_err = hard_disks.mean_and_error(z_virial)
    zg, zg_stat = hard_disks.mean_and_error(z_contact)
    zg_short = float(np.mean(z_contact_short))
    zg_err = math.hypot(zg_stat, 0.5 * abs(zg - zg_short))
    return {
        "eta": eta, "n": n, "frames": per_block * blocks, "collisions": int(world.stats.collisions),
        "z_virial": zv, "z_virial_err": zv_err, "z_contact": zg, "z_contact_err": zg_err,
        "z_contact_short_window": zg_short, "g_contact": (zg - 1.0) / (2.0 * eta),
        "r": rdf_all.bin_centers, "g": rdf_all.rdf,
        "psi6_local": float(np.mean(local6)), "psi6_global": float(np.mean(global6)),
        "max_overlap": world.stats.max_overlap,
    }  # fmt: skip


def agree(res, k=3.0):
    """The two pressures agree within k times their combined error."""
    return abs(res["z_contact"] - res["z_virial"]) < k * math.hypot(res["z_contact_err"], res["z_virial_err"])


def report(res):
    r, g = res["r"], res["g"]
    peak = int(np.argmax(g))
    print(
        f"eta {res['eta']:.2f}, N {res['n']}, {res['frames']} frames, {res['collisions']} collisions: "
        f"Z virial {res['z_virial']:.3f} +- {res['z_virial_err']:.3f}, "
        f"Z from g(sigma+) = {res['g_contact']:.3f}: {res['z_contact']:.3f} +- {res['z_contact_err']:.3f}; "
        f"g peaks at r = {r[peak]:.3f} ({g[peak]:.2f}), g(r < sigma) = {g[r < SIGMA - 0.02].max():.0f}; "
        f"|psi6| per disk {res['psi6_local']:.3f}, of the box {res['psi6_global']:.3f}"
    )


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--eta", type=float, action="append", help="(repeatable; default 0.70 and 0.72)")
    ap.add_argument("--n", type=int, default=1024)
    ap.add_argument("--frames", type=int, default=160)
    a = ap.parse_args(argv)
    results = []
    for eta in a.eta or [0.70, 0.72]:
        res = run(eta, n=a.n, frames=a.frames)
        report(res)
        results.append(res)
        assert agree(res), "the virial and the contact theorem give the same pressure"
        assert res["g"][res["r"] < SIGMA - 0.02].max() == 0.0, "no two disks closer than sigma"
        assert res["r"][np.argmax(res["g"])] < SIGMA + 0.05, "g peaks at contact"
        assert 0.0 <= res["psi6_global"] <= res["psi6_local"] <= 1.0
    return results


if __name__ == "__main__":
    main()
