"""World(uses=...): a world reserves only what it uses (cc_world_def.uses, 1.2)."""
import pytest

import circlecollide as cc
from circlecollide import Circle, CircleCollideError, World


def gas(uses):
    w = World(64, 4, uses=uses)
    for i in range(16):
        w.add_circle(Circle((3.0 * (i % 4), 3.0 * (i // 4)), (1.0 - 0.125 * i, 0.5), 0.5, 1.0))
    w.step(2.0)
    return w


def test_the_default_uses_everything_and_costs_more_memory():
    assert cc.USES_ALL == 0xFFFF
    assert (cc.USES_PROPS, cc.USES_SENSORS, cc.USES_ROLLING, cc.USES_CLOTH) == (1, 2, 4, 8)
    assert World(1000)._size == World(1000, uses=cc.USES_ALL)._size
    assert World(1000, uses=0)._size + 48 * 1000 <= World(1000, uses=cc.USES_PROPS)._size


def test_a_world_of_no_uses_refuses_properties_and_stays_unchanged():
    w = gas(0)
    h = w.hash
    p = w.circle_props(0)
    assert p.restitution == 1.0 and p.sensor is False
    for change in (dict(restitution=0.5), dict(category=2), dict(rolling_decel=0.25), dict(sensor=True)):
        with pytest.raises(CircleCollideError) as e:
            w.set_circle_props(0, **change)
        assert e.value.code == -1  # CC_ERR_INVALID
        assert w.hash == h
    with pytest.raises(CircleCollideError):
        World(8, rolling_decel=0.5, uses=cc.USES_PROPS)
    with pytest.raises((TypeError, ValueError, CircleCollideError)):
        World(8, uses=0x10000)


def test_each_use_allows_its_calls_and_a_plain_scene_runs_alike():
    w = gas(cc.USES_SENSORS)
    w.set_circle_props(1, sensor=True)
    with pytest.raises(CircleCollideError):
        w.set_circle_props(0, restitution=0.5)
    assert gas(0).hash == gas(cc.USES_ALL).hash
    copy = gas(0).copy()  # a copy keeps its uses
    with pytest.raises(CircleCollideError):
        copy.set_circle_props(0, restitution=0.5)
