"""Rolling pair functions (1.1), expected values derived by hand."""
import math

import pytest

from circlecollide import Circle, CircleCollideError, rolling_advance, sweep, sweep_rolling, sweep_segment_rolling


@pytest.mark.parametrize("precision, tol", [("double", 1e-13), ("float", 1e-5)])
def test_a_rolling_ball_into_one_at_rest(precision, tol):
    # radii 0.1, a from 0 at 2 with decel 0.4: 2t - 0.2t^2 = 0.8 at t = (2 - sqrt(3.36)) / 0.4
    a = Circle((0, 0), (2, 0), 0.1)
    b = Circle((1, 0), (0, 0), 0.1)
    c = sweep_rolling(a, 0.4, b, 0.0, 10.0, precision=precision)
    assert c is not None and c.kind == "hit"
    assert abs(c.t - (2 - math.sqrt(3.36)) / 0.4) < tol
    assert abs(c.normal[0] - 1.0) < tol


def test_a_stop_just_short_misses_and_just_long_hits():
    # speed 2, decel 0.5: stops after 4; b's surface at 4.5 +- 1e-9 (two radii of 0.25)
    a = Circle((0, 0), (2, 0), 0.25)
    assert sweep_rolling(a, 0.5, Circle((4.5 + 1e-9, 0), (0, 0), 0.25), 0.0, 10.0) is None
    assert sweep_rolling(a, 0.5, Circle((4.5 - 1e-9, 0), (0, 0), 0.25), 0.0, 10.0) is not None


def test_no_deceleration_is_sweep_bit_for_bit():
    a, b = Circle((0.3, -1.7), (2.1, 0.4), 0.7), Circle((9.1, 0.2), (-0.3, 0.1), 1.3)
    assert sweep_rolling(a, 0.0, b, 0.0, 50.0) == sweep(a, b, 50.0)


def test_a_rolling_ball_into_a_wall():
    # radius 0.25, speed 2, decel 0.5, wall at x = 3.25: 2t - 0.25t^2 = 3 at t = 2
    c = sweep_segment_rolling(Circle((0, 0), (2, 0), 0.25), 0.5, (3.25, -5), (3.25, 5), 10.0)
    assert c is not None and abs(c.t - 2.0) < 1e-14


def test_rolling_advance_stops_where_the_formula_says():
    c = Circle((0, 0), (2, 0), 0.25)
    rolling_advance(c, 0.5, 1.0)              # x = 2 - 0.25, v = 2 - 0.5
    assert (c.pos[0], c.vel[0]) == (1.75, 1.5)
    rolling_advance(c, 0.5, 100.0)            # the rest of the way: 1.5^2 / (2 * 0.5) = 2.25 more
    assert (c.pos[0], c.vel[0]) == (4.0, 0.0)


def test_invalid_deceleration_is_refused():
    with pytest.raises(CircleCollideError):
        sweep_rolling(Circle((0, 0), (1, 0), 1), -1.0, Circle((5, 0), (0, 0), 1), 0.0, 10.0)
    with pytest.raises(CircleCollideError):
        rolling_advance(Circle((0, 0), (1, 0), 1), math.nan, 1.0)
