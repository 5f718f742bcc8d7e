"""1.1 sensors through Python: begin and end events at times derived by hand."""

import math

import pytest

from circlecollide import Circle, CircleCollideError, SensorEvent, World

from conftest import needs_world

pytestmark = needs_world


def gate(mode="exact", **kw):
    """A sensor (immovable, radius 2) at (10, 0) and a visitor of radius 1 leaving (0, 0) at
    speed 1 along x: their distance 10 - t is below 2 + 1 from t = 7 on, and stops being below
    it at t = 13 (distance t - 10 = 3)."""
    events = []
    w = World(max_circles=4, mode=mode, on_sensor=events.append, **kw)
    s = w.add_circle(Circle((10, 0), (0, 0), 2, math.inf))
    w.set_circle_props(s, sensor=True)
    v = w.add_circle(Circle((0, 0), (1, 0), 1))
    return w, s, v, events


def test_exact_begin_and_end_at_the_computed_times():
    w, s, v, events = gate()
    w.step(20.0)
    assert [(e.sensor, e.visitor, e.begin) for e in events] == [(s, v, True), (s, v, False)]
    assert events[0].t == pytest.approx(7.0, abs=1e-12) and events[1].t == pytest.approx(13.0, abs=1e-12)
    assert isinstance(events[0], SensorEvent)
    # a sensor gives and takes no impulse: the visitor went straight through
    assert w.circle(v).pos == pytest.approx((20.0, 0.0)) and w.stats.collisions == 0
    assert w.circle_props(s).sensor is True


@pytest.mark.parametrize("mode", ["swept", "discrete"])
def test_other_modes_report_at_the_end_of_the_step(mode):
    # unit steps: at t = 7 the distance is 3 (not less): the begin comes at the end of the step
    # to t = 8; at t = 13 it is 3 again: the end comes at the end of the step to t = 13
    w, s, v, events = gate(mode)
    for _ in range(20):
        w.step(1.0)
    assert [(e.begin, e.t) for e in events] == [(True, 8.0), (False, 13.0)]


def test_a_filtered_visitor_and_a_sensor_pair_report_nothing():
    w, s, v, events = gate()
    w.set_circle_props(v, category=0b10)
    w.set_circle_props(s, mask=0b01)  # the sensor does not admit category 2
    # another sensor crosses s along y from t = 27 to 33 (distance 30 - t below 3), when the
    # visitor is at x >= 27, far from it: sensors do not sense sensors
    other = w.add_circle(Circle((10, -30), (0, 1), 1))
    w.set_circle_props(other, sensor=True)
    w.step(40.0)
    assert events == []


def test_making_an_overlapping_circle_a_sensor_begins_at_once_and_removal_ends_nothing():
    events = []
    w = World(max_circles=4, on_sensor=events.append)
    a = w.add_circle(Circle((0, 0), (0, 0), 2, math.inf))
    b = w.add_circle(Circle((1, 0), (0, 0), 1))  # distance 1 < 3: inside it
    w.step(0.0)  # (the overlap with an immovable circle pushes b out along x: to distance 3)
    events.clear()
    c = w.add_circle(Circle((0, 5), (0, 0), 1))
    w.set_circle_props(c, sensor=True)  # c is at distance 5 from a (sensor-free) and b
    assert events == []
    w.set_circle_props(a, sensor=True)  # b at distance 3 is not inside; a new one is
    d = w.add_circle(Circle((0, 1.5), (0, 0), 0.5))  # distance 1.5 < 2.5 from a: begin at once
    assert [(e.sensor, e.visitor, e.begin, e.t) for e in events] == [(a, d, True, 0.0)]
    # a stops being a sensor: d's end comes from inside set_circle_props, and the pair, now two
    # ordinary overlapping circles, is pushed apart (a immovable: d to distance 2.5, at y = 2.5)
    w.set_circle_props(a, sensor=False)
    assert [(e.sensor, e.visitor, e.begin) for e in events[1:]] == [(a, d, False)]
    assert w.circle(d).pos == pytest.approx((0.0, 2.5))
    w.set_circle_props(a, sensor=True)  # touching is not overlapping: no begin
    w.set_circle(d, Circle((0, 2), (0, 0), 0.5))  # set inside it: begin at once
    assert [(e.sensor, e.visitor, e.begin) for e in events[2:]] == [(a, d, True)]
    w.remove_circle(d)  # a removed circle gets no end
    w.step(1.0)
    assert len(events) == 3


def test_an_exception_in_on_sensor_is_raised_by_the_call_that_fired_it():
    def boom(event):
        raise RuntimeError("from on_sensor")

    w, s, v, _ = gate()
    w.on_sensor = boom
    with pytest.raises(RuntimeError, match="from on_sensor"):
        w.step(20.0)
    assert w.time == pytest.approx(20.0)
    # from inside add_circle too: a circle added inside the sensor begins at once
    with pytest.raises(RuntimeError, match="from on_sensor"):
        w.add_circle(Circle((10, 0.5), (0, 0), 0.5))
    w.on_sensor = None
    w.add_circle(Circle((10, -0.5), (0, 0), 0.25))
    with pytest.raises(TypeError, match="on_sensor must be callable"):
        World(max_circles=1).on_sensor = 3


def test_at_most_max_sensors():
    w = World(max_circles=70)
    ids = [w.add_circle(Circle((3.0 * i, 0), (0, 0), 1, math.inf)) for i in range(65)]
    for i in ids[:64]:
        w.set_circle_props(i, sensor=True)
    with pytest.raises(CircleCollideError, match="CC_ERR_FULL"):
        w.set_circle_props(ids[64], sensor=True)
