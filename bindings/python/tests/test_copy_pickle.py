"""Issue 18: a World can be copied (copy.copy, copy.deepcopy, World.copy) and pickled; the copy
is its own world (the C memory is position-independent: a copy of its bytes is a valid world)
and stepping it gives bit-for-bit what stepping the original gives."""

import copy
import pickle
import subprocess
import sys

import numpy as np
import pytest

from circlecollide import Circle, CircleCollideError, World

from conftest import needs_world

pytestmark = needs_world


def gas(mode="exact", callbacks=None, **kw):
    """A box of 40 circles at random speeds, some friction, walls, a sensor: every kind of state
    a world keeps (queue, grid, props, sensor overlaps, stats)."""
    rng = np.random.default_rng(7)
    w = World(max_circles=48, max_segments=4, mode=mode, restitution=0.9, rolling_decel=0.05, callbacks=callbacks, **kw)
    for p, q in [((0, 0), (20, 0)), ((20, 0), (20, 20)), ((20, 20), (0, 20)), ((0, 20), (0, 0))]:
        w.add_segment(p, q)
    for i in range(40):
        x, y = 1.5 + (i % 8) * 2.3, 1.5 + (i // 8) * 3.5
        w.add_circle(Circle(pos=(x, y), vel=tuple(rng.normal(0, 3, 2)), radius=0.5 + 0.3 * rng.random(), mass=1 + i % 3))
    s = w.add_circle(Circle(pos=(10, 10), vel=(0, 0), radius=2, mass=float("inf")))
    w.set_circle_props(s, sensor=True)
    w.step(0.7)  # mid-flight: predicted events queued, some circles inside the sensor
    return w


def trace(w, steps=30):
    """Everything observable over some steps: positions and velocities bit for bit, the hash."""
    out = []
    for _ in range(steps):
        w.step(0.13)
        out.append((w.positions.tobytes(), w.velocities.tobytes(), w.hash, w.time, w.stats))
    return out


@pytest.mark.parametrize("mode", ["exact", "swept", "discrete"])
@pytest.mark.parametrize("how", ["copy", "deepcopy", "method", "pickle"])
def test_a_copy_steps_bit_for_bit_like_the_original(mode, how):
    w = gas(mode)
    c = {
        "copy": copy.copy,
        "deepcopy": copy.deepcopy,
        "method": lambda w: w.copy(),
        "pickle": lambda w: pickle.loads(pickle.dumps(w)),
    }[how](w)
    assert c is not w and c.hash == w.hash and c.time == w.time
    assert c.stats == w.stats and c.ids == w.ids and c.circle_props(40) == w.circle_props(40)
    assert trace(c) == trace(w)
    assert w.stats.collisions > 0  # the comparison covered impacts


def test_the_copy_is_independent():
    w = gas()
    c = copy.copy(w)
    before = w.positions
    c.step(1.0)
    c.set_velocities(np.zeros((len(c), 2)))
    c.remove_circle(3)
    assert np.array_equal(w.positions, before) and len(w) == 41 and len(c) == 40
    del w  # the copy owns its memory
    c.step(1.0)
    assert len(c) == 40


def test_a_pickle_carries_the_state_to_another_process():
    """The pickled bytes, unpickled by a fresh interpreter, step to the same hash as here."""
    w = gas()
    data = pickle.dumps(w)
    trace(w, 10)
    code = (
        "import pickle, sys\n"
        "w = pickle.loads(sys.stdin.buffer.read())\n"
        "for _ in range(10): w.step(0.13)\n"
        "print(w.hash)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], input=data, capture_output=True, check=True).stdout
    assert int(out) == w.hash


def test_copies_of_a_world_with_callbacks_call_their_own():
    seen = {"w": [], "c": []}
    w = gas(callbacks=True)
    w.on_contact = lambda e: seen["w"].append((e.a, e.b, e.segment, e.t))
    c = copy.copy(w)  # shares the callable: both append to seen["w"]
    c.on_contact = lambda e: seen["c"].append((e.a, e.b, e.segment, e.t))
    w.step(1.0)
    assert seen["w"] and not seen["c"]  # the original's events went to the original's callback
    n = len(seen["w"])
    c.step(1.0)
    assert len(seen["w"]) == n  # and the copy's to the copy's
    assert seen["c"] == seen["w"]  # the same events, bit for bit


def test_deepcopy_copies_the_callbacks_object():
    class Recorder:
        def __init__(self):
            self.events = []

        def __call__(self, e):
            self.events.append(e)

    r = Recorder()
    w = gas(callbacks=True)
    w.on_contact = r
    c = copy.deepcopy(w)
    assert c.on_contact is not r and isinstance(c.on_contact, Recorder)
    c.step(1.0)
    assert not r.events and c.on_contact.events


def test_a_world_with_callbacks_refuses_to_pickle_and_says_why():
    w = gas(callbacks=True)
    with pytest.raises(TypeError, match="callbacks=False"):
        pickle.dumps(w)
    pickle.dumps(gas())  # without: fine


def test_a_copy_from_inside_a_callback_is_a_world_of_its_own():
    # the C world is busy only at its own address: copies made in the callback step at once,
    # and two of them stepped alike end alike
    snaps = []

    def on_contact(e):
        if not snaps:
            snaps.extend([copy.copy(w), copy.deepcopy(w)])

    w = gas(callbacks=True)
    w.on_contact = on_contact
    w.step(0.2)
    assert len(snaps) == 2
    for s in snaps:
        s.on_contact = None
        s.step(0.5)
    assert snaps[0].hash == snaps[1].hash


def test_a_callback_of_one_world_may_step_another():
    seen = []
    inner = gas(callbacks=True)
    inner.on_contact = lambda e: seen.append("inner")

    def outer_cb(e):
        seen.append("outer")
        inner.step(0.01)

    outer = gas(callbacks=True)
    outer.on_contact = outer_cb
    outer.step(0.5)
    assert "outer" in seen and "inner" in seen
    n = seen.count("outer")
    outer.step(0.5)  # after the inner world's calls, the outer one's events still reach outer_cb
    assert seen.count("outer") > n


def test_unpickling_refuses_another_library():
    w = World(max_circles=2)
    fn, (state,) = w.__reduce__()
    state = dict(state, library="0.9.0")
    with pytest.raises(ValueError, match="pickled with C library 0.9.0"):
        fn(state)
    fn, (state,) = w.__reduce__()
    with pytest.raises(ValueError, match="bytes"):
        fn(dict(state, memory=state["memory"][:-8]))
    w.add_circle(Circle(pos=(0, 0), vel=(1, 0), radius=1))
    fn, (state,) = w.__reduce__()
    m = bytearray(state["memory"])
    wrong = World(max_circles=2)
    wrong.add_circle(Circle(pos=(0, 0), vel=(1, 0), radius=2))
    with pytest.raises(ValueError, match="hash"):
        fn(dict(state, hash=wrong.hash))
    assert fn(dict(state, memory=bytes(m))).hash == w.hash


def test_deepcopy_of_a_callback_that_refers_to_its_world_refers_to_the_copy():
    class Counter:
        def __init__(self):
            self.world, self.n = None, 0

        def __call__(self, e):
            self.n += 1

    k = Counter()
    w = gas(callbacks=True)
    w.on_contact, k.world = k, w
    c = copy.deepcopy(w)
    assert c.on_contact is not k and c.on_contact.world is c
