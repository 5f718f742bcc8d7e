"""Issue 18, "Python as its users expect": errors that say what is wrong, Circle checked when
set, Vec2 everywhere a vector comes back, read-only arrays with bulk setters, settable
callbacks, docstrings on every public name."""

import inspect
import math

import numpy as np
import pytest

import circlecollide
from circlecollide import (
    Circle,
    CircleCollideError,
    CircleProps,
    Contact,
    SegmentProps,
    Vec2,
    World,
    closest_point_on_segment,
    respond,
    rolling_advance,
    sweep,
    sweep_rolling,
    sweep_segment,
)

INVALID = -1
RANGE = -6  # CC_ERR_RANGE (1.2): a value beyond a documented limit
BUSY = -7  # CC_ERR_BUSY (1.2): a change of the world from inside its own callback


def head_on():
    return Circle(pos=(0, 0), vel=(1, 0), radius=1), Circle(pos=(10, 0), vel=(-1, 0), radius=1)


def wall_world(**kw):
    w = World(max_circles=4, max_segments=1, **kw)
    cid = w.add_circle(Circle(pos=(0, 0), vel=(1, 0), radius=1))
    sid = w.add_segment((5, -10), (5, 10))
    return w, cid, sid


def refused(match):
    """pytest.raises for a CircleCollideError with code CC_ERR_INVALID and a message matching."""
    return pytest.raises(CircleCollideError, match=match)


# ---- 1. errors that name the argument and the value ---------------------------------------


def test_pair_function_errors_name_the_argument_and_value():
    a, b = head_on()
    with refused(r"sweep: t_max must be >= 0, got -1 \(CC_ERR_INVALID\)") as info:
        sweep(a, b, -1)
    assert info.value.code == INVALID and isinstance(info.value, ValueError)
    with refused(r"t_max must be >= 0, got nan"):
        sweep_segment(a, (5, -1), (5, 1), math.nan)
    c = sweep(a, b, 10)
    with refused(r"restitution must be in \[0, 1\], got 2\b"):
        respond(a, b, c, restitution=2)
    with refused(r"decel_b must be finite and >= 0, got -0.5"):
        sweep_rolling(a, 0.0, b, -0.5)
    with refused(r"rolling_advance: t must be finite and >= 0, got inf"):
        rolling_advance(a, 1.0, math.inf)
    # nothing in these messages speaks of NULL, meaningless in Python
    with pytest.raises(CircleCollideError) as info:
        sweep(a, b, -1)
    assert "NULL" not in str(info.value)


def test_world_errors_name_the_argument_and_value():
    with refused(r"World: restitution must be in \[0, 1\], got 2"):
        World(max_circles=1, restitution=2)
    with refused(r"rolling_decel must be finite and >= 0, got -1.0"):
        World(max_circles=1, rolling_decel=-1.0)
    w, cid, sid = wall_world()
    with refused(r"step: dt must be finite and >= 0, got -1"):
        w.step(-1)
    with refused(r"step: dt must be finite and >= 0, got nan"):
        w.step(math.nan)
    with refused(r"set_circle_props: restitution must be in \[0, 1\], got 1.5"):
        w.set_circle_props(cid, restitution=1.5)
    with refused(r"set_segment_props: restitution must be in \[0, 1\], got nan"):
        w.set_segment_props(sid, restitution=math.nan)
    with refused(r"set_circle_props: rolling_decel must be finite and >= 0, got -1.0"):
        w.set_circle_props(cid, props=CircleProps(rolling_decel=-1.0))
    assert w.circle_props(cid) == CircleProps() and w.segment_props(sid) == SegmentProps()
    # the library's own errors keep their code and explanation
    with pytest.raises(CircleCollideError, match="CC_ERR_NOT_FOUND") as info:
        w.circle(3)
    assert info.value.code == -2


@pytest.mark.parametrize("call", ["remove_circle", "add_circle", "set_circle", "step", "add_segment",
                                  "set_circle_props", "set_positions"])
def test_changing_the_world_from_on_contact_says_called_from_a_callback(call):
    holder = {}
    actions = {
        "remove_circle": lambda w: w.remove_circle(0),
        "add_circle": lambda w: w.add_circle(Circle((-20, 0))),
        "set_circle": lambda w: w.set_circle(0, Circle((-20, 0))),
        "step": lambda w: w.step(1.0),
        "add_segment": lambda w: w.add_segment((0, 0), (1, 1)),
        "set_circle_props": lambda w: w.set_circle_props(0, restitution=0.5),
        "set_positions": lambda w: w.set_positions(w.positions),
    }
    w = World(max_circles=4, max_segments=2, on_contact=lambda e: actions[call](holder["w"]))
    w.add_circle(Circle(pos=(0, 0), vel=(1, 0), radius=1))
    w.add_segment((5, -10), (5, 10))
    holder["w"] = w
    with refused(rf"{call} called from a callback") as info:
        w.step(10.0)
    assert info.value.code == BUSY and "(CC_ERR_BUSY)" in str(info.value)
    assert w.time == pytest.approx(10.0) and len(w) == 1  # the step completed, nothing changed
    assert w.circle(0).vel == pytest.approx((-1.0, 0.0))


def test_changing_the_world_from_on_sensor_says_called_from_a_callback():
    w = World(max_circles=4, callbacks=True)
    s = w.add_circle(Circle((5, 0), (0, 0), 1, math.inf))
    w.set_circle_props(s, sensor=True)
    w.add_circle(Circle((0, 0), (1, 0), 0.5))
    w.on_sensor = lambda e: w.remove_circle(e.visitor)
    with refused("remove_circle called from a callback"):
        w.step(10.0)
    assert len(w) == 2


# ---- 2. Circle checked at construction and at assignment -----------------------------------


@pytest.mark.parametrize(
    "kw, message",
    [
        ({"radius": math.nan}, r"radius must be finite and > 0, got nan"),
        ({"radius": 0}, r"radius must be finite and > 0, got 0"),
        ({"radius": math.inf}, r"radius must be finite and > 0, got inf"),
        ({"mass": -1.0}, r"mass must be > 0 \(inf: immovable\), got -1.0"),
        ({"mass": math.nan}, r"mass must be > 0 \(inf: immovable\), got nan"),
        ({"pos": (math.nan, 0)}, r"pos must be finite, got \(nan, 0.0\)"),
        ({"vel": (0, -math.inf)}, r"vel must be finite, got \(0.0, -inf\)"),
    ],
)
def test_circle_refuses_invalid_values_at_construction(kw, message):
    with refused(message) as info:
        Circle(**kw)
    assert info.value.code == INVALID


def test_circle_refuses_invalid_assignments_and_keeps_its_value():
    c = Circle(pos=(1, 2), vel=(3, 4), radius=1, mass=2)
    with refused(r"radius must be finite and > 0, got nan"):
        c.radius = math.nan
    with refused(r"mass must be > 0 \(inf: immovable\), got 0"):
        c.mass = 0
    with refused(r"pos must be finite"):
        c.pos = (math.inf, 0)
    with pytest.raises(TypeError, match="radius must be a real number, got 'x'"):
        c.radius = "x"
    with pytest.raises(TypeError, match="mass"):
        c.mass = None
    with pytest.raises(TypeError, match="vel must be a pair"):
        c.vel = "ab"
    assert c == Circle(pos=(1, 2), vel=(3, 4), radius=1, mass=2)
    c.mass = math.inf  # immovable is valid
    c.radius = np.float32(0.5)
    assert c.immovable and type(c.radius) is float and c.radius == 0.5
    with pytest.raises(AttributeError):
        c.colour = "red"  # __slots__: a typo is not a new field


# ---- 3. Vec2 everywhere a vector comes back ------------------------------------------------


def is_vec2(v, x=None, y=None):
    ok = type(v) is Vec2 and isinstance(v, tuple) and (v.x, v.y) == tuple(v)
    return ok and (x is None or v == (x, y))


def test_vec2_is_a_tuple_that_unpacks_and_compares():
    v = Vec2(1.0, 2.0)
    x, y = v
    assert (x, y) == (1.0, 2.0) and v == (1.0, 2.0) and v.x == 1.0 and v.y == 2.0
    assert repr(v) == "Vec2(x=1.0, y=2.0)" and hash(v) == hash((1.0, 2.0))


def test_every_vector_that_comes_back_is_a_vec2():
    a, b = head_on()
    assert is_vec2(a.pos, 0.0, 0.0) and is_vec2(a.vel, 1.0, 0.0) and is_vec2(a.at(2).pos, 2.0, 0.0)
    c = sweep(a, b, 10)
    assert is_vec2(c.point, 5.0, 0.0) and is_vec2(c.normal, 1.0, 0.0)
    hand = Contact("hit", 0.0, (5.0, 0.0), (1.0, 0.0), 0.0)
    assert is_vec2(hand.point) and is_vec2(hand.normal)
    respond(a, b, c)
    assert is_vec2(a.vel) and is_vec2(b.vel)
    assert is_vec2(closest_point_on_segment((0, 5), (-1, 0), (1, 0)), 0.0, 0.0)
    assert is_vec2(closest_point_on_segment((0, 5), (-1, 0), (1, 0), precision="float"))

    events = []
    w, cid, sid = wall_world(on_contact=events.append, period=(0, 0))
    w.step(10)
    e = events[0]
    assert is_vec2(e.point, 5.0, 0.0) and is_vec2(e.normal, 1.0, 0.0)
    assert all(is_vec2(p) for p in w.segment(sid))
    assert is_vec2(w.circle(cid).pos) and is_vec2(w.circle(cid).vel)
    assert is_vec2(w.unwrapped(cid)) and isinstance(w.momentum, Vec2) and is_vec2(w.period, 0.0, 0.0)
    hit = w.cast_circle((0, 0), (10, 0), 0.5)
    assert hit is not None and is_vec2(hit.point) and is_vec2(hit.normal)


# ---- 4. read-only arrays, bulk setters ----------------------------------------------------


def three():
    w = World(max_circles=4)
    for x in (0, 10, 20):
        w.add_circle(Circle(pos=(x, 0), vel=(0, 1), radius=1))
    return w


def test_bulk_arrays_are_read_only():
    w = three()
    for name in ("positions", "velocities", "radii", "masses"):
        arr = getattr(w, name)
        assert not arr.flags.writeable, name
        with pytest.raises(ValueError, match="read-only"):
            arr[0] = 5.0
        arr2 = arr.copy()  # a copy is the user's to write
        arr2[0] = 5.0


def test_set_positions_and_velocities():
    w = three()
    w.remove_circle(1)  # rows follow the live ids, in order
    w.set_positions(np.array([[1.0, 2.0], [30.0, 4.0]]))
    np.testing.assert_array_equal(w.positions, [[1.0, 2.0], [30.0, 4.0]])
    np.testing.assert_array_equal(w.velocities, [[0.0, 1.0], [0.0, 1.0]])  # kept
    w.set_velocities([[1, 0], [-1, 0]])
    np.testing.assert_array_equal(w.velocities, [[1.0, 0.0], [-1.0, 0.0]])
    np.testing.assert_array_equal(w.positions, [[1.0, 2.0], [30.0, 4.0]])
    w.step(1.0)
    np.testing.assert_allclose(w.positions, [[2.0, 2.0], [29.0, 4.0]])


def test_bulk_setters_validate_and_name_the_row():
    w = three()
    before = w.positions
    with refused(r"set_positions: row 1 \(circle 1\) must be finite, got \(nan, 0.0\)"):
        w.set_positions([[0, 0], [math.nan, 0], [20, 0]])
    with refused(r"set_velocities: row 2 \(circle 2\) must be finite, got \(inf, 0.0\)"):
        w.set_velocities([[0, 0], [0, 0], [math.inf, 0]])
    with pytest.raises(ValueError, match=r"shape \(3, 2\)"):
        w.set_positions([[0, 0], [1, 1]])
    with pytest.raises(ValueError, match="array of numbers"):
        w.set_positions([["a", "b"]] * 3)
    np.testing.assert_array_equal(w.positions, before)  # refused before anything changed


def test_set_positions_goes_through_set_circle_and_fires_on_contact():
    events = []
    w = World(max_circles=2, on_contact=events.append)
    w.add_circle(Circle((0, 0), (1, 0), 1))
    w.add_circle(Circle((10, 0), (-1, 0), 1))
    w.step(0.0)  # the first step builds the grid; from then on overlaps are resolved at once
    w.set_positions([[0, 0], [1.5, 0]])  # on top of circle 0, approaching: pushed apart, impulse
    assert any(1 in (e.a, e.b) for e in events)
    assert w.positions[1, 0] - w.positions[0, 0] >= 2.0 - 1e-12


# ---- 5. on_contact is a plain settable property -------------------------------------------


def test_on_contact_can_be_set_after_construction_and_unset():
    w, cid, _ = wall_world(callbacks=True)
    assert w.on_contact is None
    events = []
    w.on_contact = events.append
    assert w.on_contact == events.append
    w.step(10.0)
    assert len(events) == 1 and events[0].b == -1
    w.on_contact = None
    w.set_circle(cid, Circle((0, 0), (1, 0), 1))
    w.step(10.0)
    assert len(events) == 1
    with pytest.raises(TypeError, match="on_contact must be callable"):
        w.on_contact = 3


def test_on_sensor_can_be_set_after_construction():
    w = World(max_circles=4, callbacks=True)
    s = w.add_circle(Circle((5, 0), (0, 0), 1, math.inf))
    w.set_circle_props(s, sensor=True)
    w.add_circle(Circle((0, 0), (1, 0), 0.5))
    seen = []
    w.on_sensor = seen.append
    w.step(10.0)
    assert [e.begin for e in seen] == [True, False]


# ---- 6. docstrings on every public name, no leaked names -----------------------------------


def public_names():
    for name in circlecollide.__all__:
        obj = getattr(circlecollide, name)
        yield name, obj
        if inspect.isclass(obj) and not issubclass(obj, BaseException):
            for attr, member in vars(obj).items():
                if not attr.startswith("_"):
                    yield f"{name}.{attr}", member


def test_every_public_name_has_a_docstring():
    missing = []
    for name, obj in public_names():
        if isinstance(obj, (int, str)) or name.count(".") and not callable(obj) and not isinstance(obj, property):
            continue  # constants and dataclass field defaults
        if not (getattr(obj, "__doc__", None) or "").strip():
            missing.append(name)
    assert missing == []


def test_dir_shows_no_leaked_names():
    assert "annotations" not in dir(circlecollide)
    assert set(circlecollide.__all__) <= set(dir(circlecollide))


def test_a_world_without_callbacks_says_so_at_assignment():
    # given no callback, a world has no trampolines (it pays nothing for them): setting one
    # later needs callbacks=True at construction, and says so
    for w in (World(max_circles=2), World(max_circles=2, callbacks=False)):
        with pytest.raises(ValueError, match=r"without callbacks \(pass callbacks=True\)"):
            w.on_contact = print
        with pytest.raises(ValueError, match=r"without callbacks \(pass callbacks=True\)"):
            w.on_sensor = print
    w = World(max_circles=2, callbacks=False)
    w.on_contact = None  # unsetting is fine
    with pytest.raises(ValueError, match="callbacks=False"):
        World(max_circles=2, callbacks=False, on_contact=print)


def test_world_queries_and_walls_name_the_argument():
    w, _, _ = wall_world()
    with refused(r"cast_circle: radius must be finite and >= 0, got -1"):
        w.cast_circle((0, 0), (1, 0), -1)
    with refused(r"cast_circle: d must be finite, got \(nan, 0.0\)"):
        w.cast_circle((0, 0), (math.nan, 0))
    with refused(r"query_circle: radius must be finite and >= 0, got inf"):
        w.query_circle((0, 0), math.inf)
    with refused(r"query_box: hi must be finite"):
        w.query_box((0, 0), (math.inf, 1))
    with refused(r"add_segment: q must be finite"):
        w.add_segment((0, 0), (math.nan, 1))
    with refused(r"World: period must be >= 0 \(0: open\), got \(-1.0, 0.0\)"):
        World(max_circles=1, period=(-1, 0))
    from circlecollide import sweep_many

    with refused(r"sweep_many: t_max must be >= 0, got -2"):
        sweep_many([[0, 0]], [[0, 0]], 1, [[3, 0]], [[0, 0]], 1, -2)
