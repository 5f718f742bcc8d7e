"""Hard disks in a periodic box: the start of a run, its pressure, and the literature's
equations of state (docs/PHYSICS.md derives every formula used here). Needs numpy only.

Disks have diameter sigma = 1 (radius 1/2) and mass 1; kT = 1 (the kinetic energy is exactly
N kT at the start, and an elastic EXACT world keeps it). The area fraction eta = N pi / (4 L^2)
fixes the box's side L. The pressure comes from the world's virial,

    Z = P A / (N kT) = 1 + W / (2 t N kT),

W the sum over impacts of impulse times centre distance (``WorldStats.virial``) over a time t.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Callable, List, Optional, Sequence, Tuple

import numpy as np

from ._world import World

RADIUS = 0.5
KT = 1.0

#: Kolafa and Rottner's fit, powers of x -> coefficient (their rho_max = 0.90 set)
KOLAFA_ROTTNER = {
    0: 1.0, 1: 2.0, 2: 1.12801775, 3: 0.00181895291, 4: -0.0526134737, 5: 0.0504960168,
    6: -0.0325537792, 7: 0.0134578632, 8: 0.00140888182, 9: -0.00834273601, 10: 0.00694127367,
    11: -0.00262254723, 12: 0.000355746352, 22: -5.24672938e-9, 57: 5.88054639e-23,
}  # fmt: skip
#: the fit's range: the reduced density rho sigma^2 <= 0.90
KOLAFA_ROTTNER_ETA_MAX = 0.90 * math.pi / 4.0


def z_kolafa_rottner(eta: float) -> float:
    """Kolafa and Rottner's equation of state of the hard-disk fluid, Z = sum_i A_i x^i with
    x = eta / (1 - eta): J. Kolafa and M. Rottner, "Simulation-based equation of state of the
    hard disk fluid and prediction of higher-order virial coefficients", Mol. Phys. 104, 3435
    (2006), doi:10.1080/00268970600967963 (arXiv:cond-mat/0608356), eq. (7) with the
    coefficients of their fit to rho sigma^2 = 0.90 (section 3.2; tests/hard_disks.h has the
    same in C). NaN beyond eta = 0.9 pi / 4 = 0.7069, where the fit's x^57 term takes over."""
    if not 0.0 <= eta <= KOLAFA_ROTTNER_ETA_MAX + 1e-12:
        return math.nan
    x = eta / (1.0 - eta)
    return math.fsum(a * x**i for i, a in KOLAFA_ROTTNER.items())


def z_henderson(eta: float) -> float:
    """Henderson's equation of state, Mol. Phys. 30, 971 (1975): (1 + eta^2 / 8) / (1 - eta)^2."""
    return (1.0 + eta * eta / 8.0) / (1.0 - eta) ** 2


def box_side(n: int, eta: float) -> float:
    """The side L of the square box in which n disks of radius 1/2 fill the area fraction eta."""
    return math.sqrt(n * math.pi * RADIUS**2 / eta)


def contact_rate(eta: float) -> float:
    """Enskog's collision rate per disk, Gamma = 4 (Z - 1) sqrt(kT / (pi m)) / sigma, with Z
    from Kolafa and Rottner (Henderson beyond their range): what sizes a run's steps."""
    z = z_kolafa_rottner(eta)
    if math.isnan(z):
        z = z_henderson(eta)
    return 4.0 * (z - 1.0) * math.sqrt(KT / math.pi)


def lattice_start(n: int, eta: float, rng: np.random.Generator) -> Tuple[np.ndarray, np.ndarray, float]:
    """n disks on the first n sites of a square lattice (side ceil(sqrt n)) filling eta of a
    periodic square; Maxwell-Boltzmann velocities from rng, the mean taken off and scaled so
    that the kinetic energy is exactly n kT. Returns (positions, velocities, L)."""
    side = box_side(n, eta)
    k = int(math.ceil(math.sqrt(n)))
    a = side / k
    if not a > 2.0 * RADIUS:
        raise ValueError(f"the square lattice of {n} disks overlaps at eta {eta} (eta < pi / 4 needs a full lattice)")
    i = np.arange(n)
    pos = np.column_stack(((i % k + 0.5) * a, (i // k + 0.5) * a))
    vel = rng.normal(0.0, math.sqrt(KT), size=(n, 2))
    vel -= vel.mean(axis=0)
    vel *= math.sqrt(n * KT / (0.5 * float((vel**2).sum())))
    return pos, vel, side


def make_box(n: int, eta: float, rng: np.random.Generator, **world_options: object) -> World:
    """An EXACT periodic world of n disks at area fraction eta, from ``lattice_start``."""
    pos, vel, side = lattice_start(n, eta, rng)
    w = World(max_circles=n, period=(side, side), **world_options)  # type: ignore[arg-type]
    w.add_circles(pos, vel, RADIUS, 1.0)
    return w


def z_from_virial(virial: float, t: float, n: int) -> float:
    """Z = 1 + W / (2 t N kT): the virial theorem for hard disks (docs/PHYSICS.md)."""
    return 1.0 + virial / (2.0 * t * n * KT)


@dataclass
class Measurement:
    """What ``measure`` returns: Z per block and over the whole measurement, and the counts."""

    z: float
    z_blocks: List[float]
    collisions: int  # over the equilibration and the measurement
    sim_time: float
    wall_seconds: float

    @property
    def z_error(self) -> float:
        """The standard error of Z from the block means (their spread over sqrt(B))."""
        b = np.asarray(self.z_blocks)
        return float(b.std(ddof=1) / math.sqrt(len(b))) if len(b) > 1 else math.nan


def advance(world: World, dt: float) -> None:
    """Advances world time by dt whatever the event cap: a step that stops at max_events (the
    automatic cap is sized for a frame, not for a block of a long run) is continued to the same
    end time."""
    end = world.time + dt
    while not world.step(max(end - world.time, 0.0)):
        pass


def run_until(world: World, collisions: int, dt: float, progress: Optional[Callable[[int], None]] = None) -> None:
    """Steps by dt until stats.collisions reaches ``collisions`` (a count since the world was
    made), calling progress(collisions) after each step."""
    while True:
        c = world.stats.collisions
        if progress is not None:
            progress(c)
        if c >= collisions:
            return
        advance(world, dt)


def measure(
    world: World,
    eta: float,
    equil_per_disk: float,
    per_disk: float,
    blocks: int,
    progress: Optional[Callable[[int], None]] = None,
    on_block: Optional[Callable[[World], None]] = None,
) -> Measurement:
    """Equilibrates for ``equil_per_disk`` collisions per disk, then measures Z over ``blocks``
    blocks of fixed duration, together about ``per_disk`` collisions per disk (the duration
    from Enskog's rate). Each impact involves two disks: stats.collisions counts pairs, so C
    collisions per disk are C N / 2 impacts. ``progress`` gets the collisions so far about ten
    times a block, ``on_block`` the world at each block's end."""
    if blocks < 1:
        raise ValueError("blocks must be >= 1")
    started = time.perf_counter()
    n = len(world)
    rate = contact_rate(eta)  # per disk per unit time
    sub = 10
    run_until(world, int(equil_per_disk * n / 2), per_disk / blocks / rate / sub, progress)
    duration = per_disk / blocks / rate
    s0, t0 = world.stats, world.time
    zs: List[float] = []
    last_v, last_t = s0.virial, t0
    for _ in range(blocks):
        for _ in range(sub):
            advance(world, duration / sub)
            if progress is not None:
                progress(world.stats.collisions)
        s, t = world.stats, world.time
        zs.append(z_from_virial(s.virial - last_v, t - last_t, n))
        last_v, last_t = s.virial, t
        if on_block is not None:
            on_block(world)
    s1, t1 = world.stats, world.time
    return Measurement(
        z=z_from_virial(s1.virial - s0.virial, t1 - t0, n),
        z_blocks=zs,
        collisions=int(s1.collisions),
        sim_time=t1,
        wall_seconds=time.perf_counter() - started,
    )


def seed_for(seed: int, eta: float, replica: int) -> np.random.SeedSequence:
    """The generator's seed of one (eta, replica) point: from the run's seed, eta (to 1e-9)
    and the replica's number only, so that a point's result does not depend on which worker
    runs it, in what order, or on what other points the run has."""
    return np.random.SeedSequence([int(seed), int(round(eta * 1e9)), int(replica)])


def state_point(
    eta: float,
    n: int,
    replica: int,
    seed: int,
    equil_per_disk: float,
    per_disk: float,
    blocks: int,
    progress: Optional[Callable[[int], None]] = None,
) -> Measurement:
    """One (eta, replica) point of an equation of state: a fresh box from its own seed
    (``seed_for``), equilibrated, measured (``measure``)."""
    rng = np.random.default_rng(seed_for(seed, eta, replica))
    world = make_box(n, eta, rng)
    return measure(world, eta, equil_per_disk, per_disk, blocks, progress)


def mean_and_error(values: Sequence[float]) -> Tuple[float, float]:
    """The mean of independent values and its standard error (NaN for fewer than two)."""
    v = np.asarray(values, dtype=np.float64)
    if len(v) < 2:
        return float(v.mean()) if len(v) else math.nan, math.nan
    return float(v.mean()), float(v.std(ddof=1) / math.sqrt(len(v)))
