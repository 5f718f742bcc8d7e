"""Issue 35, "Feels native, second pass": Vec2 a real vector, every refusal naming its cause,
ignore= on casts and queries, one rule for state reads (properties), strict types at once."""

import copy
import math
import pickle
import warnings

import numpy as np
import pytest

from circlecollide import Circle, CircleCollideError, Vec2, World, respond, separate, sweep, sweep_many

INVALID, RANGE, BUSY = -1, -6, -7


# ---- Vec2: a vector, still a tuple ------------------------------------------------------------


def test_vec2_adds_subtracts_scales_and_divides_as_a_vector():
    a, b = Vec2(1, 2), Vec2(3, 4)
    # a NamedTuple gave (1, 2, 3, 4) and a repeated tuple here: silent wrong numbers
    assert a + b == (4.0, 6.0) and type(a + b) is Vec2
    assert b - a == (2.0, 2.0) and -a == (-1.0, -2.0) and +a == a
    assert 2 * a == (2.0, 4.0) and a * 2 == (2.0, 4.0) and type(2 * a) is Vec2
    assert b / 2 == (1.5, 2.0) and a * np.float64(2) == (2.0, 4.0)
    # a numpy scalar on the left broadcasts over the tuple, as numpy does: an array, same numbers
    assert np.array_equal(np.float64(2) * a, [2.0, 4.0])
    # and arrays of points still take a Vec2 as numpy takes a pair
    assert np.array_equal(np.array([[1.0, 1.0]]) + a, [[2.0, 3.0]])
    # any pair of numbers on either side
    assert a + (1, 1) == (2.0, 3.0) and (1, 1) + a == (2.0, 3.0) and (10, 10) - a == (9.0, 8.0)
    assert a + [1, 1] == (2.0, 3.0)


def test_vec2_dot_cross_length_and_normalized():
    v = Vec2(3, 4)
    assert v.dot((1, 0)) == 3.0 and v.dot(Vec2(0, 1)) == 4.0  # 3*1 + 4*0, 3*0 + 4*1
    assert Vec2(1, 0).cross((0, 1)) == 1.0  # x y' - y x' = 1
    assert v.length == 5.0 and abs(v) == 5.0 and v.length_squared == 25.0  # the 3-4-5 triangle
    assert v.normalized() == (0.6, 0.8) and type(v.normalized()) is Vec2
    assert Vec2(1e200, 1e200).length == pytest.approx(math.sqrt(2) * 1e200)  # no overflow
    with pytest.raises(ZeroDivisionError):
        Vec2(0, 0).normalized()


def test_vec2_is_still_a_tuple_of_two_floats():
    v = Vec2(1, 2)
    x, y = v
    assert (x, y) == (1.0, 2.0) and type(v.x) is float and v[1] == 2.0 and len(v) == 2
    assert v == (1.0, 2.0) and hash(v) == hash((1.0, 2.0)) and {v: 1}[(1.0, 2.0)] == 1
    assert repr(v) == "Vec2(x=1.0, y=2.0)" and isinstance(v, tuple)
    assert pickle.loads(pickle.dumps(v)) == v and type(copy.copy(v)) is Vec2
    assert v._replace(y=5) == (1.0, 5.0) and v._asdict() == {"x": 1.0, "y": 2.0}
    assert np.asarray(v).tolist() == [1.0, 2.0]


def test_vec2_refuses_what_is_not_a_vector():
    v = Vec2(1, 2)
    with pytest.raises(TypeError):
        v * v  # no element-wise product: a vector has dot and cross
    with pytest.raises(TypeError):
        v + (1, 2, 3)
    with pytest.raises(TypeError, match="x must be a real number, got '1'"):
        Vec2("1", 2)
    with pytest.raises(TypeError):
        v * "2"


# ---- refusals that name their cause ---------------------------------------------------------


def test_a_capacity_beyond_2_26_is_named():
    with pytest.raises(CircleCollideError, match=r"World: max_circles must be at most 2\^26 = 67108864, got 100000000 \(CC_ERR_RANGE\)") as info:
        World(max_circles=10**8)
    assert info.value.code == RANGE
    with pytest.raises(CircleCollideError, match=r"max_segments must be at most 2\^26"):
        World(max_circles=1, max_segments=2**26 + 1)
    with pytest.raises(CircleCollideError, match=r"max_circles must be >= 0, got -1 \(CC_ERR_INVALID\)"):
        World(max_circles=-1)


def test_a_circle_wider_than_its_period_is_named():
    # period 10: a diameter d needs 2 d + 1.0625 d <= 10; radius 2 (d = 4) needs 12.25
    w = World(max_circles=4, period=(10, 0))
    i = w.add_circle(Circle((5, 5), radius=1))
    with pytest.raises(CircleCollideError, match=r"add_circle: a circle of radius 2.0 is too wide for the period \(10.0, 0.0\).*= 12.25 \(CC_ERR_RANGE\)") as info:
        w.add_circle(Circle((5, 5), radius=2))
    assert info.value.code == RANGE
    with pytest.raises(CircleCollideError, match=r"set_circle: a circle of radius 2.0 is too wide"):
        w.set_circle(i, Circle((5, 5), radius=2))
    assert len(w) == 1 and w.circle(i).radius == 1.0


def test_a_swept_periodic_step_too_long_is_named():
    # SWEPT, period 10: a circle at speed 10 may move less than half a period (5) per step
    w = World(max_circles=4, mode="swept", period=(10, 10))
    w.add_circle(Circle((5, 5), (10, 0), 0.5))
    h = w.hash
    with pytest.raises(CircleCollideError, match=r"step: dt = 0.5 would carry a circle half a period or more.*\(CC_ERR_RANGE\)") as info:
        w.step(0.5)
    assert info.value.code == RANGE and w.hash == h and w.time == 0.0
    assert w.step(0.4) and w.time == 0.4


def test_a_step_past_the_range_of_the_world_is_named():
    w = World(max_circles=2)
    w.add_circle(Circle((1e306, 0), (1e306, 0), 1))  # 1e306 + 1e306 > 2^1017 ~ 1.4e306
    with pytest.raises(CircleCollideError, match=r"past 2\^1017 .*\(CC_ERR_RANGE\)"):
        w.step(1.0)


def test_query_box_with_lo_above_hi_is_named():
    w = World(max_circles=2)
    with pytest.raises(CircleCollideError, match=r"query_box: lo.x must be <= hi.x, got lo = \(1.0, 0.0\), hi = \(0.0, 1.0\)"):
        w.query_box((1, 0), (0, 1))
    with pytest.raises(CircleCollideError, match=r"lo.y must be <= hi.y"):
        w.query_box((0, 1), (1, 0))


def test_sweep_many_names_the_row_of_a_nan_radius():
    n = 5
    pos, vel = np.zeros((n, 2)), np.zeros((n, 2))
    other = np.tile([10.0, 0.0], (n, 1))
    radii = np.ones(n)
    radii[3] = math.nan
    with pytest.raises(CircleCollideError, match=r"sweep_many: row 3: a_radius\[3\] must be finite and > 0, got nan \(CC_ERR_INVALID\)"):
        sweep_many(pos, vel, radii, other, vel, 1.0)
    vel2 = vel.copy()
    vel2[1, 0] = math.inf  # an earlier row wins
    with pytest.raises(CircleCollideError, match=r"row 1: b_vel\[1\] must be finite, got \(inf, 0.0\)"):
        sweep_many(pos, vel, radii, other, vel2, 1.0)


def test_respond_on_two_immovable_circles_is_named():
    a = Circle((0, 0), (1, 0), 1, math.inf)
    b = Circle((10, 0), (-1, 0), 1, math.inf)
    c = sweep(a, b, 10)
    with pytest.raises(CircleCollideError, match=r"respond: a and b are both immovable \(mass inf\)"):
        respond(a, b, c)
    with pytest.raises(CircleCollideError, match=r"separate: a and b are both immovable"):
        separate(Circle((0, 0), mass=math.inf), Circle((1, 0), mass=math.inf))


def test_changing_the_world_from_a_callback_is_busy():
    holder = {}
    w = World(max_circles=4, max_segments=1, on_contact=lambda e: holder["w"].remove_circle(0))
    holder["w"] = w
    w.add_circle(Circle((0, 0), (1, 0), 1))
    w.add_segment((5, -10), (5, 10))
    with pytest.raises(CircleCollideError, match=r"remove_circle called from a callback.*\(CC_ERR_BUSY\)") as info:
        w.step(10.0)
    assert info.value.code == BUSY and len(w) == 1


# ---- ignore= on casts and queries ------------------------------------------------------------


def test_a_cast_from_the_cue_ball_ignores_it():
    # the cue ball (radius 1) at the origin, an object ball at (10, 0): the cast of the cue
    # ball's radius from its own centre overlaps the cue ball itself; leaving it out, it touches
    # the object ball with its centre at x = 8: t = 8 / 20 = 0.4
    w = World(max_circles=4)
    cue = w.add_circle(Circle((0, 0), radius=1))
    ball = w.add_circle(Circle((10, 0), radius=1))
    assert w.cast_circle((0, 0), (20, 0), radius=1).circle == cue  # kind "overlap"
    hit = w.cast_circle((0, 0), (20, 0), radius=1, ignore=cue)
    assert (hit.kind, hit.circle, hit.t, hit.normal) == ("hit", ball, 0.4, (1.0, 0.0))
    assert w.query_circle((0, 0), 0.5) == [cue] and w.query_circle((0, 0), 0.5, ignore=cue) == []
    assert w.query_box((-2, -2), (12, 2), ignore=ball) == [cue]
    assert w.query_box((-2, -2), (12, 2), ignore=99) == [cue, ball]  # an id not in use: nothing left out
    with pytest.raises(TypeError, match="ignore must be an int"):
        w.cast_circle((0, 0), (1, 0), ignore="cue")


# ---- one rule: reads without arguments are properties -----------------------------------------


def test_state_reads_are_properties_and_the_old_calls_warn():
    w = World(max_circles=4)
    w.add_circle(Circle((0, 0), (3, 4), 1, mass=2))
    # |v|^2 = 25: kinetic energy 2 * 25 / 2 = 25; momentum 2 * (3, 4) = (6, 8)
    assert w.kinetic_energy == 25.0 and w.momentum == (6.0, 8.0) and isinstance(w.hash, int)
    assert isinstance(w.time, float) and w.stats.collisions == 0 and w.ids == [0]
    h = w.hash
    with pytest.warns(DeprecationWarning, match=r"World.kinetic_energy is a property since circlecollide 1.2"):
        assert w.kinetic_energy() == 25.0
    with pytest.warns(DeprecationWarning, match=r"World.momentum is a property"):
        assert w.momentum() == (6.0, 8.0)
    with pytest.warns(DeprecationWarning, match=r"World.hash is a property"):
        assert w.hash() == h
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the properties themselves never warn
        assert w.kinetic_energy + 1 == 26.0 and w.momentum + (1, 1) == (7.0, 9.0) and w.hash == h
        assert type(w.momentum.x) is float and f"{w.kinetic_energy:.1f}" == "25.0"


# ---- strict types, refused at once --------------------------------------------------------


@pytest.mark.parametrize(
    "make, message",
    [
        (lambda: Circle(pos=("1", "2")), r"Circle: pos must be a pair of real numbers \(x, y\), got \('1', '2'\)"),
        (lambda: Circle(vel=(True, 0)), r"Circle: vel must be a pair of real numbers"),
        (lambda: Circle(radius="1"), r"Circle: radius must be a real number, got '1'"),
        (lambda: World(max_circles=4, on_contact=5), r"World: on_contact must be callable or None, got 5"),
        (lambda: World(max_circles=4, on_sensor="print"), r"World: on_sensor must be callable or None"),
        (lambda: World(max_circles="4"), r"World: max_circles must be an int, got '4'"),
        (lambda: World(max_circles=4.0), r"World: max_circles must be an int, got 4.0"),
        (lambda: World(max_circles=4, max_events=5.5), r"World: max_events must be an int, got 5.5"),
        (lambda: World(max_circles=4, mode=1), r"World: mode must be a str"),
        (lambda: World(max_circles=4, callbacks="yes"), r"World: callbacks must be True or False, got 'yes'"),
        (lambda: World(max_circles=4, period="10"), r"World: period must be a pair of real numbers"),
    ],
)
def test_wrong_types_are_refused_at_once_naming_the_argument(make, message):
    with pytest.raises(TypeError, match=message):
        make()


def test_props_and_masks_of_the_wrong_type_are_refused():
    w = World(max_circles=4)
    i = w.add_circle(Circle())
    with pytest.raises(TypeError, match=r"set_circle_props: sensor must be True or False, got 'yes'"):
        w.set_circle_props(i, sensor="yes")
    with pytest.raises(TypeError, match="mask must be an int"):
        w.query_circle((0, 0), 1.0, mask="1")
    with pytest.raises(TypeError, match="category must be an int"):
        w.set_circle_props(i, category=1.0)
    assert not w.circle_props(i).sensor
    w.set_circle_props(i, sensor=np.bool_(True))  # numpy's bool is a bool
    assert w.circle_props(i).sensor
