"""max_events: None follows the C default, a 1.2 def's automatic cap (32 events per circle of
max_circles, at least 10,000: the header's "Collapse"); an int is that cap. Read back from a jam
(a kinematic circle pushing rolling ones: every step ends at the cap) through stats.events."""
import math

import pytest

from circlecollide import Circle, World
from circlecollide.hard_disks import advance


def jam(**options: object) -> "tuple[bool, int]":
    w = World(restitution=0.5, rolling_decel=0.5, **options)  # type: ignore[arg-type]
    for i in range(5):
        w.add_circle(Circle((i * 2.2, 0.0), (0.0, 0.0), 1.0))
    w.add_circle(Circle((-3.0, 0.0), (1.0, 0.0), 1.0, math.inf))
    w.step(0.0)
    done = w.step(30.0)
    return done, w.stats.events


@pytest.mark.parametrize("max_circles, cap", [(6, 10000), (400, 12800)])
def test_the_default_is_the_automatic_cap(max_circles: int, cap: int) -> None:
    assert jam(max_circles=max_circles) == (False, cap)


def test_an_explicit_cap_keeps_its_value() -> None:
    assert jam(max_circles=6, max_events=123) == (False, 123)
    with pytest.raises(ValueError, match="max_events"):
        World(max_circles=6, max_events=0)


def test_advance_continues_a_step_to_its_end_time() -> None:
    # two circles in a box of walls crossing many cells: a long step, capped at 7 events a call
    w = World(max_circles=2, max_segments=2, max_events=7)
    w.add_segment((-10.0, -5.0), (-10.0, 5.0))
    w.add_segment((10.0, -5.0), (10.0, 5.0))
    w.add_circle(Circle((0.0, 0.0), (5.0, 0.0), 0.5))
    w.add_circle(Circle((3.0, 0.0), (-5.0, 0.0), 0.5))
    assert not w.step(20.0)
    t = w.time
    advance(w, 20.0)
    assert w.time == pytest.approx(t + 20.0)
