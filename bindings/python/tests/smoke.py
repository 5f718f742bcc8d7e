"""A smoke test of an installed circlecollide (no pytest needed): the library loads from inside
the package, a pair sweep and a small world give their known results, a world pickles. Run by
scripts/test.d/50-python.sh on the package installed from the sdist, and by cibuildwheel."""

import os
import pickle
import sys

import circlecollide as cc

pkg = os.path.dirname(os.path.abspath(cc.__file__))
assert os.path.dirname(os.path.abspath(cc.library_path())) == pkg, (cc.library_path(), pkg)
assert cc.library_version().split(".")[0] == str(cc.EXPECTED_MAJOR)
a = cc.Circle(pos=(0, 0), vel=(1, 0), radius=1)
b = cc.Circle(pos=(10, 0), vel=(-1, 0), radius=1)
hit = cc.sweep(a, b, t_max=10)
assert hit is not None and hit.t == 4.0, hit
w = cc.World(max_circles=2)
w.add_circle(a)
w.add_circle(b)
w.step(10.0)
assert w.stats.collisions == 1 and w.velocities.tolist() == [[-1.0, 0.0], [1.0, 0.0]]
assert pickle.loads(pickle.dumps(w)).hash == w.hash
print(f"smoke ok: circlecollide {cc.__version__}, C library {cc.library_version()} at {cc.library_path()}")
sys.exit(0)
