"""The pair functions through Python: results derived by hand beside each check."""

import math

import numpy as np
import pytest

from circlecollide import (
    Circle,
    CircleCollideError,
    Contact,
    closest_point_on_segment,
    detect_static,
    respond,
    respond_segment,
    separate,
    sweep,
    sweep_segment,
)


def head_on():
    # centres 10 apart, radii 1 + 1: a gap of 8 closing at speed 2 -> contact at t = 4
    return Circle(pos=(0, 0), vel=(1, 0), radius=1), Circle(pos=(10, 0), vel=(-1, 0), radius=1)


def test_sweep_head_on_hits_at_t4():
    a, b = head_on()
    c = sweep(a, b, t_max=10)
    assert c == Contact("hit", 4.0, (5.0, 0.0), (1.0, 0.0), 0.0)  # point: 1 from a's centre at x = 4


def test_sweep_misses_after_t_max_and_when_separating():
    a, b = head_on()
    assert sweep(a, b, t_max=3.9) is None
    a.vel, b.vel = (-1, 0), (1, 0)
    assert sweep(a, b) is None


def test_sweep_default_t_max_is_infinite():
    a, b = head_on()
    a.vel, b.vel = (1e-3, 0), (0, 0)  # gap 8 at speed 1e-3 -> t = 8000
    assert sweep(a, b).t == pytest.approx(8000.0, rel=1e-15)


def test_overlap_reports_depth():
    # centres 1.5 apart, radii 1 + 1: depth 0.5, point midway through the overlap: x = 0.75
    a, b = Circle(pos=(0, 0), radius=1), Circle(pos=(1.5, 0), radius=1)
    c = detect_static(a, b)
    assert c.kind == "overlap" and c.depth == 0.5 and c.normal == (1.0, 0.0) and c.t == 0.0
    assert c.point == pytest.approx((0.75, 0.0))
    assert sweep(a, b, 1.0).kind == "overlap"


def test_touching_is_not_overlapping():
    assert detect_static(Circle(pos=(0, 0), radius=1), Circle(pos=(2, 0), radius=1)) is None


def test_sweep_segment_wall_at_x5():
    # radius 1 moving +x at speed 1 towards the wall x = 5: the front reaches it at t = 4
    c = sweep_segment(Circle(pos=(0, 0), vel=(1, 0), radius=1), (5, -1), (5, 1), 10)
    assert c.kind == "hit" and c.t == 4.0 and c.point == (5.0, 0.0) and c.normal == (1.0, 0.0)


def test_closest_point_on_segment():
    assert closest_point_on_segment((0, 5), (-1, 0), (1, 0)) == (0.0, 0.0)
    assert closest_point_on_segment((7, 1), (-1, 0), (1, 0)) == (1.0, 0.0)  # clamped to the end
    assert closest_point_on_segment((7, 1), (2, 2), (2, 2)) == (2.0, 2.0)  # a point segment


def test_separate_equal_masses_move_half_each():
    # overlap 0.5 along x: each moves 0.25
    a, b = Circle(pos=(0, 0), radius=1), Circle(pos=(1.5, 0), radius=1)
    assert separate(a, b) is True
    assert a.pos == pytest.approx((-0.25, 0.0)) and b.pos == pytest.approx((1.75, 0.0))
    assert separate(a, b) is False  # now touching: nothing to do


def test_separate_immovable_stays():
    a, b = Circle(pos=(0, 0), radius=1, mass=math.inf), Circle(pos=(1.5, 0), radius=1)
    assert separate(a, b)
    assert a.pos == (0.0, 0.0) and b.pos == pytest.approx((2.0, 0.0))


def test_respond_elastic_equal_masses_swap_velocities():
    a, b = head_on()
    c = sweep(a, b, 10)
    a, b = a.at(c.t), b.at(c.t)
    assert respond(a, b, c) is True
    assert a.vel == (-1.0, 0.0) and b.vel == (1.0, 0.0)
    assert respond(a, b, c) is False  # separating now: nothing changes
    assert a.vel == (-1.0, 0.0)


def test_respond_restitution_half():
    # equal masses, relative normal speed 2 -> 1 after (e = 0.5); momentum 0 stays 0
    a, b = head_on()
    c = sweep(a, b, 10)
    respond(a, b, c, restitution=0.5)
    assert a.vel == pytest.approx((-0.5, 0.0)) and b.vel == pytest.approx((0.5, 0.0))


def test_respond_segment_reflects():
    c = Circle(pos=(4, 0), vel=(1, 1), radius=1)
    contact = Contact("hit", 0.0, (5.0, 0.0), (1.0, 0.0), 0.0)
    assert respond_segment(c, contact) is True
    assert c.vel == (-1.0, 1.0)  # normal part reversed, tangential kept


def _unchecked(pos, vel, radius, mass):
    # writes the private fields, past the binding's checks, to reach the library's own
    c = Circle()
    c._pos, c._vel, c._radius, c._mass = pos, vel, radius, mass
    return c


@pytest.mark.parametrize(
    "a",
    [
        ((math.nan, 0), (0, 0), 1.0, 1.0),
        ((0, 0), (math.inf, 0), 1.0, 1.0),
        ((0, 0), (0, 0), 0.0, 1.0),
        ((0, 0), (0, 0), 1.0, -1.0),
    ],
)
def test_bad_circle_raises_value_error_with_library_message(a):
    b = Circle(pos=(10, 0), radius=1)
    with pytest.raises(ValueError, match="CC_ERR_INVALID") as info:
        sweep(_unchecked(*a), b, 1.0)
    assert isinstance(info.value, CircleCollideError) and info.value.code == -1


def test_bad_arguments_raise_and_change_nothing():
    a, b = head_on()
    before = (a.copy(), b.copy())
    with pytest.raises(ValueError, match="CC_ERR_INVALID"):
        sweep(a, b, -1.0)
    c = sweep(a, b, 10)
    with pytest.raises(ValueError, match="CC_ERR_INVALID"):
        respond(a, b, c, restitution=1.5)
    a.mass = b.mass = math.inf
    with pytest.raises(ValueError):
        respond(a, b, c)  # two immovable circles
    a.mass = b.mass = 1.0
    assert (a, b) == before
    with pytest.raises(ValueError, match="pos"):
        Circle(pos=(1, 2, 3))
    with pytest.raises(ValueError, match="precision"):
        sweep(a, b, 1.0, precision="half")


def test_float_precision_uses_the_float_functions():
    # gap 1 closing at speed 3: t = 1/3, which float holds only to 24 bits
    a, b = Circle(pos=(0, 0), vel=(3, 0), radius=1), Circle(pos=(3, 0), radius=1)
    t64 = sweep(a, b, 1.0).t
    t32 = sweep(a, b, 1.0, precision="float").t
    assert t64 == pytest.approx(1 / 3, rel=1e-15)
    assert float(np.float32(t32)) == t32 and t32 != t64
    assert abs(t32 - 1 / 3) <= 2 * np.finfo(np.float32).eps / 3
    # values beyond float's range are infinite in float: invalid there, fine in double
    big = Circle(pos=(1e300, 0), radius=1)
    assert sweep(big, Circle(pos=(1e300 + 1e290, 0), radius=1)) is None
    with pytest.raises(ValueError):
        sweep(big, b, precision="float")
