"""1.1 per-body properties through Python: restitution and its mix, filters, rolling to rest.

Every expected value is derived by hand in the comments.
"""

import math

import pytest

from circlecollide import Circle, CircleCollideError, CircleProps, SegmentProps, World

from conftest import needs_world

pytestmark = needs_world


def wall_world(**kw):
    # radius 1 at x = 0 moving +x at speed 1, a wall at x = 5: touches at t = 4
    w = World(max_circles=4, max_segments=2, **kw)
    cid = w.add_circle(Circle(pos=(0, 0), vel=(1, 0), radius=1))
    sid = w.add_segment((5, -10), (5, 10))
    return w, cid, sid


def test_new_bodies_get_the_defaults_of_the_def():
    w, cid, sid = wall_world(restitution=0.5, rolling_decel=0.25)
    assert w.circle_props(cid) == CircleProps(0.5, 0.25, 1, 0xFFFFFFFF, False)
    assert w.segment_props(sid) == SegmentProps(0.5, 1, 0xFFFFFFFF)


def test_props_round_trip_and_keyword_changes_keep_the_rest():
    w, cid, sid = wall_world()
    p = w.set_circle_props(cid, restitution=0.25, category=0b100, mask=0b011)
    assert p == CircleProps(0.25, 0.0, 0b100, 0b011, False) == w.circle_props(cid)
    whole = CircleProps(0.75, 2.0, 0x80000000, 0xFFFFFFFF, True)
    assert w.set_circle_props(cid, whole) == whole
    assert w.set_segment_props(sid, restitution=0.125, mask=2) == SegmentProps(0.125, 1, 2)
    assert w.set_segment_props(sid, SegmentProps()) == SegmentProps(1.0, 1, 0xFFFFFFFF)


def test_invalid_props_are_refused_and_change_nothing():
    w, cid, sid = wall_world()
    before = w.circle_props(cid)
    with pytest.raises(CircleCollideError, match="CC_ERR_INVALID"):
        w.set_circle_props(cid, restitution=1.5)
    with pytest.raises(CircleCollideError, match="CC_ERR_INVALID"):
        w.set_circle_props(cid, rolling_decel=-1.0)
    with pytest.raises(CircleCollideError, match="CC_ERR_INVALID"):
        w.set_segment_props(sid, restitution=math.nan)
    with pytest.raises(ValueError, match="mask"):
        w.set_circle_props(cid, mask=2**32)
    with pytest.raises(ValueError, match="category"):
        w.set_segment_props(sid, category=-1)
    with pytest.raises(CircleCollideError, match="CC_ERR_NOT_FOUND"):
        w.circle_props(3)
    with pytest.raises(CircleCollideError, match="CC_ERR_NOT_FOUND"):
        w.set_segment_props(1, SegmentProps())
    with pytest.raises(TypeError):
        w.set_circle_props(cid, restitution_mix=1)
    assert w.circle_props(cid) == before


@pytest.mark.parametrize(
    "mix, expected",
    # circle 0.5 against wall 1.0: min 0.5, max 1.0, product 0.5, mean 0.75
    [("min", 0.5), ("max", 1.0), ("product", 0.5), ("mean", 0.75)],
)
def test_restitution_mix_of_a_circle_and_a_wall(mix, expected):
    w, cid, sid = wall_world(restitution_mix=mix)
    w.set_circle_props(cid, restitution=0.5)
    w.step(6.0)  # impact at t = 4, then 2 time units back at speed e
    c = w.circle(cid)
    assert c.vel == pytest.approx((-expected, 0.0), abs=1e-12)
    assert c.pos == pytest.approx((4.0 - 2.0 * expected, 0.0), abs=1e-12)


@pytest.mark.parametrize("mode", ["exact", "swept", "discrete"])
@pytest.mark.parametrize("mix, expected", [("min", 0.9), ("max", 0.9), ("product", 0.9 * 0.9), ("mean", 0.9)])
def test_the_default_restitution_is_mixed_as_any_value(mode, mix, expected):
    # both sides keep restitution 0.9: the contact gets mix(0.9, 0.9), its square under product
    w, cid, sid = wall_world(restitution=0.9, restitution_mix=mix, mode=mode)
    for _ in range(600):
        w.step(0.01)
    assert w.circle(cid).vel == pytest.approx((-expected, 0.0), abs=1e-12)


def test_a_walls_own_restitution_and_product_mix_of_two_circles():
    w, cid, sid = wall_world()
    w.set_segment_props(sid, restitution=0.25)  # min(1, 0.25)
    w.step(6.0)
    assert w.circle(cid).vel == pytest.approx((-0.25, 0.0), abs=1e-12)
    # two equal masses head-on at speeds +-1 with restitutions 0.5 and 0.5, product: e = 0.25;
    # the relative speed 2 becomes 0.5: each leaves at 0.25
    w = World(max_circles=2, restitution_mix="product")
    a = w.add_circle(Circle((0, 0), (1, 0), 1))
    b = w.add_circle(Circle((10, 0), (-1, 0), 1))
    for i in (a, b):
        w.set_circle_props(i, restitution=0.5)
    w.step(5.0)
    assert w.circle(a).vel == pytest.approx((-0.25, 0.0), abs=1e-12)
    assert w.circle(b).vel == pytest.approx((0.25, 0.0), abs=1e-12)


@pytest.mark.parametrize("mode", ["exact", "swept", "discrete"])
def test_filtered_pairs_pass_through_each_other(mode):
    # head-on pair that would meet at t = 4; b's mask leaves out a's category: no interaction,
    # both keep going, after 10 units a is at 10 and b at 0; the wall still stops a... unless a's
    # mask leaves out the wall's category as well: then a ends at 10 too
    events = []
    w = World(max_circles=2, max_segments=1, mode=mode, on_contact=events.append)
    a = w.add_circle(Circle((0, 0), (1, 0), 1))
    b = w.add_circle(Circle((10, 0), (-1, 0), 1))
    sid = w.add_segment((30, -5), (30, 5))
    w.set_circle_props(a, category=0b01)
    w.set_circle_props(b, mask=0b10)
    w.set_segment_props(sid, category=0b100)
    w.set_circle_props(a, mask=0b010)  # a interacts with category 2 only: not the wall
    for _ in range(100):
        w.step(0.4)  # 40 time units: a crosses x = 30 at t = 29 without a bounce
    assert events == [] and w.stats.collisions == 0
    assert w.circle(a).pos == pytest.approx((40.0, 0.0), abs=1e-9)
    assert w.circle(b).pos == pytest.approx((-30.0, 0.0), abs=1e-9)


def test_def_rolling_decel_brings_a_circle_to_rest_where_computed():
    # speed s = 2, decel k = 0.5: t_stop = s / k = 4, stops at pos + v t_stop / 2 = (4, 0);
    # at t = 2: p = v (t - k t^2 / (2 s)) = 2 (2 - 0.5) = 3, v = 2 (1 - 2/4) = 1
    w = World(max_circles=2, rolling_decel=0.5)
    cid = w.add_circle(Circle((0, 0), (2, 0), 1))
    w.step(2.0)
    c = w.circle(cid)
    assert c.pos == pytest.approx((3.0, 0.0), abs=1e-12) and c.vel == pytest.approx((1.0, 0.0), abs=1e-12)
    w.step(8.0)
    c = w.circle(cid)
    assert c.pos == pytest.approx((4.0, 0.0), abs=1e-12) and c.vel == (0.0, 0.0)



@pytest.mark.parametrize(
    "mode, step_first",
    [
        ("exact", True),
        ("exact", False),
        ("swept", True),
        ("discrete", True),
    ],
)
def test_per_circle_rolling_decel_and_an_immovable_one_ignores_it(mode, step_first):
    # circle a: its own decel 1, speed 2 -> stops at t = 2 at x = 2; b (immovable, kinematic)
    # keeps its speed 1 despite a decel set: at t = 10 it is at y = 10 + 10
    w = World(max_circles=2, mode=mode)
    a = w.add_circle(Circle((0, 0), (2, 0), 1))
    b = w.add_circle(Circle((0, 10), (0, 1), 1, math.inf))
    if step_first:
        w.step(0.0)
    w.set_circle_props(a, rolling_decel=1.0)
    w.set_circle_props(b, rolling_decel=1.0)
    for _ in range(100):
        w.step(0.1)
    assert w.circle(b).pos == pytest.approx((0.0, 20.0), abs=1e-12)
    tol = 1e-12 if mode == "exact" else 0.05  # SWEPT/DISCRETE stop within a step's travel
    assert w.circle(a).pos == pytest.approx((2.0, 0.0), abs=tol) and w.circle(a).vel == (0.0, 0.0)


def test_world_arguments_are_checked():
    with pytest.raises(ValueError, match="restitution_mix"):
        World(max_circles=1, restitution_mix="median")
    with pytest.raises(CircleCollideError, match="CC_ERR_INVALID"):
        World(max_circles=1, rolling_decel=-1.0)
    with pytest.raises(TypeError, match="period"):
        World(max_circles=1, period=5.0)


def test_a_library_with_a_shorter_def_refuses_the_settings_it_cannot_read(monkeypatch):
    # as if the library were 1.0: its cc_world_def_init reports the 1.0 size (up to `user`);
    # a 1.1 setting would be silently ignored there, so the binding refuses it
    from circlecollide import _lib

    real = _lib.world_def_defaults
    monkeypatch.setattr(_lib, "world_def_defaults", lambda: (real()[0], _lib.field_end(_lib.cc_world_def, "user")))
    World(max_circles=2)  # nothing of 1.1 asked: fine
    for kw in ({"rolling_decel": 1.0}, {"restitution_mix": "max"}, {"on_sensor": print}, {"period": (10, 0)}):
        with pytest.raises(NotImplementedError, match="cc_world_def"):
            World(max_circles=2, **kw)
