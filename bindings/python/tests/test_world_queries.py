"""1.1 queries and state through Python: casts, disc and box queries, the state hash, periodic
boxes (wrapped and unwrapped positions), the virial and the wall impulse. Expected values are
derived by hand in the comments."""

import math

import pytest

from circlecollide import CastHit, Circle, CircleCollideError, World

from conftest import needs_world

pytestmark = needs_world


def target_world():
    # circle 0: radius 2 at (10, 0); circle 1: radius 1 at (20, 10), away from the x axis; a wall
    # at x = 20 from y = -5 to 5 (id 0)
    w = World(max_circles=4, max_segments=1)
    c0 = w.add_circle(Circle((10, 0), (0, 0), 2))
    c1 = w.add_circle(Circle((20, 10), (0, 0), 1))
    s0 = w.add_segment((20, -5), (20, 5))
    return w, c0, c1, s0


def test_cast_along_x_hits_the_circle_at_the_computed_fraction():
    # a circle of radius 1 from (0, 0) along d = (30, 0): it touches circle 0 when its centre is
    # 2 + 1 = 3 before x = 10, at x = 7: t = 7 / 30, contact point (8, 0), normal (1, 0)
    w, c0, c1, s0 = target_world()
    hit = w.cast_circle((0, 0), (30, 0), radius=1)
    assert isinstance(hit, CastHit) and hit.kind == "hit"
    assert (hit.circle, hit.segment) == (c0, -1)
    assert hit.t == pytest.approx(7 / 30, rel=1e-14)
    assert hit.point == pytest.approx((8.0, 0.0)) and hit.normal == pytest.approx((1.0, 0.0))
    # a ray enters the circle at x = 8: t = 8 / 30
    assert w.cast_circle((0, 0), (30, 0)).t == pytest.approx(8 / 30, rel=1e-14)


def test_cast_off_axis_normal_and_the_mask_that_skips_to_the_wall():
    w, c0, c1, s0 = target_world()
    # circle 0 moved to (10, 1): a radius-1 cast along y = 0 touches it at distance 3:
    # (x - 10)^2 + 1 = 9 -> x = 10 - sqrt(8); normal ((10 - x), 1) / 3 = (sqrt(8), 1) / 3
    w.set_circle(c0, Circle((10, 1), (0, 0), 2))
    hit = w.cast_circle((0, 0), (30, 0), radius=1)
    assert hit.t == pytest.approx((10 - math.sqrt(8)) / 30, rel=1e-13)
    assert hit.normal == pytest.approx((math.sqrt(8) / 3, 1 / 3), abs=1e-13)
    # circles are category 1 and walls too; give the wall category 2 and cast with mask 2: the
    # circle is skipped, the cast touches the wall when its centre is at x = 19: t = 19 / 30
    w.set_segment_props(s0, category=2)
    hit = w.cast_circle((0, 0), (30, 0), radius=1, mask=2)
    assert (hit.kind, hit.circle, hit.segment) == ("hit", -1, s0)
    assert hit.t == pytest.approx(19 / 30, rel=1e-14) and hit.point == pytest.approx((20.0, 0.0))
    # mask 4: nothing has that category; a cast that falls short: nothing
    assert w.cast_circle((0, 0), (30, 0), radius=1, mask=4) is None
    assert w.cast_circle((0, 0), (5, 0), radius=1) is None


def test_cast_overlap_sensors_skipped_ties_and_errors():
    w, c0, c1, s0 = target_world()
    # starting at (9, 0), inside circle 0: an overlap at t = 0, normal towards its centre
    hit = w.cast_circle((9, 0), (1, 0), radius=0.5)
    assert (hit.kind, hit.circle, hit.t) == ("overlap", c0, 0.0) and hit.normal == pytest.approx((1.0, 0.0))
    # circle 0 a sensor: skipped, the cast goes on to the wall (x = 20 - 1 = 19)
    w.set_circle_props(c0, sensor=True)
    assert w.cast_circle((0, 0), (30, 0), radius=1).segment == s0
    w.set_circle_props(c0, sensor=False)
    # circle 0 at (10, 2) and its mirror image, circle 2, at (10, -2): the cast touches both at
    # once, at distance 3: (x - 10)^2 + 4 = 9, x = 10 - sqrt(5); equal times go to the lowest id
    w.set_circle(c0, Circle((10, 2), (0, 0), 2))
    c2 = w.add_circle(Circle((10, -2), (0, 0), 2))
    hit = w.cast_circle((0, 0), (30, 0), radius=1)
    assert hit.circle == min(c0, c2) and hit.t == pytest.approx((10 - math.sqrt(5)) / 30, rel=1e-13)
    with pytest.raises(CircleCollideError, match="CC_ERR_INVALID"):
        w.cast_circle((0, 0), (1, 0), radius=-1)
    with pytest.raises(CircleCollideError, match="CC_ERR_INVALID"):
        w.cast_circle((math.nan, 0), (1, 0))
    with pytest.raises(ValueError, match="mask"):
        w.cast_circle((0, 0), (1, 0), mask=-1)


def query_world():
    # 0: (0, 0) r 1; 1: (5, 0) r 1; 2: (0, 5) r 1 of category 2; 3: (5, 5) r 1, a sensor
    w = World(max_circles=8)
    ids = [w.add_circle(Circle(p, (0, 0), 1)) for p in ((0, 0), (5, 0), (0, 5), (5, 5))]
    w.set_circle_props(ids[2], category=2)
    w.set_circle_props(ids[3], sensor=True)
    return w, ids


def test_query_circle_returns_the_ids_whose_discs_overlap():
    w, ids = query_world()
    assert w.query_circle((0, 0)) == [0]  # the point (0, 0) is inside circle 0 only
    assert w.query_circle((2.5, 0), 1.5) == []  # distance 2.5 = 1.5 + 1 to both: touching only
    assert w.query_circle((2.5, 0), 1.5 + 2**-40) == [0, 1]  # now less than the radii's sum
    assert w.query_circle((2.5, 0), 1.0) == []  # distance 2.5 < 2 to neither
    # a disc of radius 2 at (2.5, 2.5) is at distance sqrt(12.5) ~ 3.54 < 3 of none: [];
    # radius 2.6: 3.54 < 3.6 of all four (the sensor included)
    assert w.query_circle((2.5, 2.5), 2.0) == []
    assert w.query_circle((2.5, 2.5), 2.6) == [0, 1, 2, 3]
    assert w.query_circle((2.5, 2.5), 2.6, mask=2) == [2]
    assert w.query_circle((2.5, 2.5), 2.6, mask=1) == [0, 1, 3]
    w.remove_circle(1)
    assert w.query_circle((2.5, 2.5), 2.6) == [0, 2, 3]


def test_query_box_is_closed_and_exact():
    w, ids = query_world()
    # the box [1, 4] x [-1, 1] is at distance exactly 1 from circles 0 and 1: both count
    assert w.query_box((1, -1), (4, 1)) == [0, 1]
    # shrunk by 2^-40 on the left: circle 0 is just out
    assert w.query_box((1 + 2**-40, -1), (4, 1)) == [1]
    # the box [1.5, 3.5] x [1.5, 3.5]: the corner (1.5, 1.5) is sqrt(4.5) ~ 2.12 from circle
    # 0's centre: none of the four (all at that corner distance) meets it
    assert w.query_box((1.5, 1.5), (3.5, 3.5)) == []
    assert w.query_box((-10, -10), (10, 10), mask=3) == [0, 1, 2, 3]
    with pytest.raises(CircleCollideError, match="CC_ERR_INVALID"):
        w.query_box((1, 1), (0, 0))
    with pytest.raises(CircleCollideError, match="CC_ERR_INVALID"):
        w.query_circle((0, 0), -1.0)


def test_query_results_larger_than_the_first_guess_are_complete():
    w = World(max_circles=64)
    for i in range(50):
        w.add_circle(Circle((3.0 * i, 0), (0, 0), 1))
    assert w.query_box((-1, -1), (3 * 49 + 1, 1)) == list(range(50))


def hash_run(nudge=False):
    w = World(max_circles=16, max_segments=4, restitution=0.9)
    for k, (p, q) in enumerate((((0, 0), (20, 0)), ((20, 0), (20, 20)), ((20, 20), (0, 20)), ((0, 20), (0, 0)))):
        w.add_segment(p, q)
    for i in range(9):
        vx = 1.0 + 0.1 * i
        if nudge and i == 4:
            vx = math.nextafter(vx, 2.0)  # one bit
        w.add_circle(Circle((3.0 + 5 * (i % 3), 3.0 + 5 * (i // 3)), (vx, 0.7 - 0.2 * i), 1))
    return w


def test_hash_is_equal_after_identical_runs_and_differs_after_a_one_bit_change():
    a, b, c = hash_run(), hash_run(), hash_run(nudge=True)
    assert a.hash == b.hash and a.hash != c.hash
    h0 = a.hash
    for w in (a, b, c):
        for _ in range(20):
            w.step(0.5)
    assert a.hash == b.hash and a.hash != h0 and a.hash != c.hash
    assert a.stats.collisions > 5  # the runs did collide
    assert 0 <= a.hash < 2**64
    # properties are state as well
    b.set_circle_props(0, restitution=0.5)
    assert a.hash != b.hash


def test_periodic_box_wraps_positions_and_unwrapped_does_not():
    # period 10 along x, open along y: radius 1 at (9, 5) moving +1: at t = 2.5 it is at x = 11.5,
    # wrapped 1.5; along y its position
    w = World(max_circles=4, period=(10, 0))
    assert w.period == (10.0, 0.0)
    a = w.add_circle(Circle((9, 5), (1, 0.5), 1))
    w.step(2.5)
    assert w.circle(a).pos == pytest.approx((1.5, 6.25), abs=1e-12)
    assert w.unwrapped(a) == pytest.approx((11.5, 6.25), abs=1e-12)
    b = w.add_circle(Circle((-3, 20), (0, 0), 1))  # taken to its image in [0, 10): x = 7
    assert w.circle(b).pos == pytest.approx((7.0, 20.0))
    with pytest.raises(CircleCollideError, match="CC_ERR_NOT_FOUND"):
        w.unwrapped(3)
    with pytest.raises(CircleCollideError, match=r"too wide for the period .*\(CC_ERR_RANGE\)"):
        w.add_circle(Circle((0, 0), (0, 0), 4))  # diameter 8: 2 * 8 + 8.5 = 24.5 > 10


def test_periodic_impact_through_the_edge_and_the_virial():
    # period 10 in x and y; a at x = 1 moving -1, b at x = 8 moving +1 (radius 1, mass 1): through
    # the edge their distance is 1 + (10 - 8) = 3, the gap 1 closes at speed 2: contact at t = 0.5
    # (a at 0.5, b at 8.5, i.e. its image at -1.5). Elastic, equal masses: the velocities swap,
    # impulse 2 at centre distance 2: virial 2 * 2 = 4; no wall.
    events = []
    w = World(max_circles=4, period=(10, 10), on_contact=events.append)
    a = w.add_circle(Circle((1, 5), (-1, 0), 1))
    b = w.add_circle(Circle((8, 5), (1, 0), 1))
    w.step(1.0)
    assert len(events) == 1 and events[0].t == pytest.approx(0.5, abs=1e-12)
    assert w.circle(a).pos == pytest.approx((1.0, 5.0), abs=1e-12)  # back at 0.5 + 0.5
    assert w.circle(b).pos == pytest.approx((8.0, 5.0), abs=1e-12)
    s = w.stats
    assert s.virial == pytest.approx(4.0, rel=1e-12) and s.wall_impulse == 0.0


def test_wall_impulse_sums_the_impulses_on_walls():
    # mass 2 at speed 3 into a wall, restitution 0.5: impulse (1 + 0.5) * 2 * 3 = 9; no circle pair
    w = World(max_circles=1, max_segments=1, restitution=0.5)
    w.add_circle(Circle((0, 0), (3, 0), 1, 2))
    w.add_segment((5, -5), (5, 5))
    w.step(3.0)  # contact at t = 4 / 3
    s = w.stats
    assert s.wall_impulse == pytest.approx(9.0, rel=1e-12) and s.virial == 0.0 and s.collisions == 1


def test_a_period_too_small_for_the_cells_is_refused():
    with pytest.raises(CircleCollideError, match=r"period.x = 1.0 must be wider than cell_size = 2.0 \(CC_ERR_RANGE\)"):
        World(max_circles=4, period=(1.0, 0), cell_size=2.0)
    with pytest.raises(CircleCollideError, match="CC_ERR_INVALID"):
        World(max_circles=4, period=(-1.0, 0))
