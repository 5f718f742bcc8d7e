"""sweep and detect_static on two Circles take a fast path (the fields packed into bytes for the
same C function): it must give exactly what the struct path gives."""

import ctypes
import math

import numpy as np

import circlecollide as cc
from circlecollide import _lib
from circlecollide._types import circle_to_c, contact_from_c


def by_structs(name, a, b, *middle):
    out = _lib.cc_contact()
    code = getattr(_lib.lib, name)(ctypes.byref(circle_to_c(a)), ctypes.byref(circle_to_c(b)), *middle, ctypes.byref(out))
    return None if code == _lib.MISS else contact_from_c(code, out)


def test_the_fast_path_is_the_struct_path_bit_for_bit():
    rng = np.random.default_rng(3)
    hits = overlaps = 0
    for _ in range(3000):
        a = cc.Circle(pos=rng.uniform(-5, 5, 2), vel=rng.uniform(-3, 3, 2), radius=rng.uniform(0.1, 2), mass=rng.uniform(0.5, 3))
        b = cc.Circle(pos=rng.uniform(-5, 5, 2), vel=rng.uniform(-3, 3, 2), radius=rng.uniform(0.1, 2),
                      mass=math.inf if rng.random() < 0.1 else 1.0)
        for t in (1.0, math.inf):
            got, want = cc.sweep(a, b, t), by_structs("cc_sweep", a, b, t)
            assert got == want
            hits += got is not None and got.kind == "hit"
        got, want = cc.detect_static(a, b), by_structs("cc_detect_static", a, b)
        assert got == want
        overlaps += got is not None
    assert hits > 300 and overlaps > 300  # both answers covered


def test_other_inputs_take_the_checked_path():
    a, b = cc.Circle(pos=(0, 0), vel=(1, 0), radius=1), cc.Circle(pos=(10, 0), vel=(-1, 0), radius=1)
    assert cc.sweep(a, b, 10).t == 4.0  # an int t_max
    for bad in (math.nan, -1.0):
        try:
            cc.sweep(a, b, bad)
        except cc.CircleCollideError as e:
            assert "t_max" in str(e)
        else:
            raise AssertionError("accepted t_max %r" % bad)
