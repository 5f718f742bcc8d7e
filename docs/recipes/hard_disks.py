"""Recipe: hard disks in a periodic box, with their pressure (docs/RECIPES.md).

400 disks of diameter 1 fill 30 % of a square torus; after they have forgotten their lattice
start, the world's virial gives the pressure, P A = N kT + virial / (2 t), compared with
Henderson's equation of state for hard disks, Z = (1 + eta^2 / 8) / (1 - eta)^2. The mean
squared displacement, from the unwrapped positions, grows linearly: diffusion.
Run: python docs/recipes/hard_disks.py (bindings/python/tests/test_recipes.py runs it).
"""
import math

import numpy as np

from circlecollide import Circle, World

N, ETA, KT = 400, 0.30, 1.0
side = math.sqrt(N * math.pi * 0.25 / ETA)  # the box's side for N disks of radius 1/2
rng = np.random.default_rng(7)

# whole runs in one call (some 500 collisions per disk): an offline step's cap, not the automatic one
w = World(max_circles=N, period=(side, side), max_events=10**7)
k = int(math.ceil(math.sqrt(N)))
v = rng.normal(0.0, math.sqrt(KT), size=(N, 2))  # Maxwell-Boltzmann at kT, mass 1
v -= v.mean(axis=0)  # no drift
v *= math.sqrt(N * KT / (0.5 * (v**2).sum()))  # kinetic energy exactly N kT (2D)
for i in range(N):
    w.add_circle(Circle(((i % k + 0.5) * side / k, (i // k + 0.5) * side / k), tuple(v[i]), 0.5))

w.step(50.0)  # forget the lattice
s0, t0 = w.stats, w.time
start = np.array([w.unwrapped(i) for i in range(N)])
w.step(200.0)
s1, t1 = w.stats, w.time
t = t1 - t0
z = 1.0 + (s1.virial - s0.virial) / (2.0 * t * N * KT)
z_henderson = (1 + ETA**2 / 8) / (1 - ETA) ** 2
msd = float(((np.array([w.unwrapped(i) for i in range(N)]) - start) ** 2).sum(axis=1).mean())
print(f"eta {ETA}: Z = {z:.4f} from {s1.collisions - s0.collisions} collisions; Henderson {z_henderson:.4f}")
print(f"mean squared displacement over t = {t:.0f}: {msd:.1f} (D = {msd / (4 * t):.3f})")
assert abs(z / z_henderson - 1) < 0.02, "the pressure of a hard-disk fluid"
assert msd > 10.0, "disks diffuse"
