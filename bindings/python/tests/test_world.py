"""World through Python: scenes whose outcome is derived by hand, errors, callbacks, memory."""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from circlecollide import Circle, CircleCollideError, World

from conftest import needs_world

pytestmark = needs_world


def wall_scene(**kw):
    # radius 1 at x = 0 moving +x at speed 1; a wall at x = 5: touches at t = 4, then x = 4 - (t - 4)
    w = World(max_circles=4, max_segments=2, **kw)
    cid = w.add_circle(Circle(pos=(0, 0), vel=(1, 0), radius=1))
    sid = w.add_segment((5, -10), (5, 10))
    return w, cid, sid


def test_bounce_off_a_wall():
    w, cid, sid = wall_scene()
    assert w.time == 0.0
    assert w.step(10.0) is True
    assert w.time == pytest.approx(10.0)
    c = w.circle(cid)
    assert c.pos == pytest.approx((-2.0, 0.0)) and c.vel == pytest.approx((-1.0, 0.0))
    assert w.stats.collisions == 1
    assert w.segment(sid) == ((5.0, -10.0), (5.0, 10.0))


def test_contact_callback_reports_the_impulse():
    events = []
    w, cid, sid = wall_scene(on_contact=events.append)
    w.step(10.0)
    assert len(events) == 1
    e = events[0]
    # mass 1, speed 1 reversed: impulse 2; normal from the circle towards the wall
    assert (e.a, e.b, e.segment) == (cid, -1, sid)
    assert e.t == pytest.approx(4.0) and e.impulse == pytest.approx(2.0)
    assert e.normal == pytest.approx((1.0, 0.0)) and e.point == pytest.approx((5.0, 0.0))


def test_exception_in_callback_is_raised_after_step_and_the_world_goes_on():
    def boom(event):
        raise RuntimeError("from the callback")

    w, cid, _ = wall_scene(on_contact=boom)
    with pytest.raises(RuntimeError, match="from the callback"):
        w.step(10.0)
    assert w.time == pytest.approx(10.0)  # the step itself completed
    w.on_contact = None
    assert w.step(1.0) is True


def test_head_on_pair_swaps_and_arrays_have_shape_n_by_2():
    w = World(max_circles=3)
    a = w.add_circle(Circle(pos=(0, 0), vel=(1, 0), radius=1))
    b = w.add_circle(Circle(pos=(10, 0), vel=(-1, 0), radius=1))
    w.step(6.0)  # contact at t = 4, then 2 more units apart: a at 4 - 2, b at 6 + 2
    assert w.ids == [a, b] and len(w) == 2
    np.testing.assert_allclose(w.positions, [[2.0, 0.0], [8.0, 0.0]], atol=1e-12)
    np.testing.assert_allclose(w.velocities, [[-1.0, 0.0], [1.0, 0.0]], atol=1e-12)
    assert w.positions.shape == (2, 2) and w.positions.dtype == np.float64


def test_remove_set_and_errors():
    w = World(max_circles=2)
    a = w.add_circle(Circle(pos=(0, 0), radius=1))
    b = w.add_circle(Circle(pos=(5, 0), radius=1))
    with pytest.raises(CircleCollideError, match="CC_ERR_FULL"):
        w.add_circle(Circle(pos=(20, 0), radius=1))
    w.remove_circle(a)
    with pytest.raises(ValueError, match="CC_ERR_NOT_FOUND"):
        w.circle(a)
    with pytest.raises(ValueError, match="CC_ERR_NOT_FOUND"):
        w.remove_circle(a)
    w.set_circle(b, Circle(pos=(5, 0), vel=(0, 2), radius=1))
    w.step(1.0)
    assert w.circle(b).pos == pytest.approx((5.0, 2.0))
    with pytest.raises(ValueError, match="CC_ERR_INVALID"):
        w.add_circle(Circle(pos=(0, 0), radius=0))
    with pytest.raises(ValueError, match="CC_ERR_INVALID"):
        w.step(-1.0)
    with pytest.raises(ValueError, match="CC_ERR_INVALID"):
        w.step(math.nan)
    with pytest.raises(ValueError):
        w.circle(2**40)
    with pytest.raises(ValueError):
        World(max_circles=-1)
    with pytest.raises(ValueError, match="mode"):
        World(max_circles=1, mode="magic")


def test_memory_is_owned_and_16_byte_aligned():
    w = World(max_circles=8)
    assert w._addr % 16 == 0
    assert w._addr + 1 >= 1 and len(w._buffer) >= 16


@pytest.mark.parametrize("mode", ["exact", "swept", "discrete"])
def test_every_mode_bounces_with_small_steps(mode):
    # steps of 0.1 move the circle 0.1 < its radius: even the discrete mode cannot tunnel
    w, cid, _ = wall_scene(mode=mode)
    for _ in range(100):
        w.step(0.1)
    c = w.circle(cid)
    assert c.vel[0] == pytest.approx(-1.0) and c.pos[0] < 4.0
    assert w.stats.collisions == 1


@settings(max_examples=25, deadline=None)
@given(st.lists(st.tuples(st.floats(-3, 3), st.floats(-3, 3)), min_size=2, max_size=12), st.integers(0, 2**31))
def test_exact_mode_conserves_momentum_and_energy(vels, seed):
    # circles on a grid 4 apart (radius 1: never overlapping at the start), no walls, e = 1
    w = World(max_circles=len(vels))
    for i, v in enumerate(vels):
        w.add_circle(Circle(pos=(4.0 * (i % 4), 4.0 * (i // 4)), vel=v, radius=1, mass=1 + (seed >> i) % 3))
    p0, k0 = w.momentum, w.kinetic_energy
    w.step(20.0)
    p1, k1 = w.momentum, w.kinetic_energy
    assert p1 == pytest.approx(p0, abs=1e-9 * (1 + k0))
    assert k1 == pytest.approx(k0, rel=1e-9, abs=1e-12)


def test_callback_survives_garbage_collection():
    # the ctypes trampoline is owned by the World: a collection between init and step is harmless
    import gc

    seen = []
    w, _, _ = wall_scene(on_contact=lambda e: seen.append(e.t))
    gc.collect()
    w.step(10.0)
    assert seen == [pytest.approx(4.0)]
    assert "World(" in repr(w)


def test_changing_the_world_from_its_callback_is_refused_not_a_crash():
    # the library refuses step/add/remove from inside the callback (CC_ERR_BUSY): the
    # binding turns that into a ValueError raised by the outer step
    holder = {}
    w, _, _ = wall_scene(on_contact=lambda e: holder["w"].step(1.0))
    holder["w"] = w
    with pytest.raises(ValueError, match="CC_ERR_BUSY"):
        w.step(10.0)
    assert w.time == pytest.approx(10.0)
