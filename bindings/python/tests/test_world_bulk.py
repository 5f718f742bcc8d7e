"""1.2's bulk calls through Python: World.add_circles (one C call per chunk, every row checked
before any is added, the row named in errors) and World.unwrapped_positions; and the core
binding's promise that importing circlecollide imports none of the science extras."""

import math
import subprocess
import sys

import numpy as np
import pytest

from circlecollide import Circle, CircleCollideError, World

from conftest import needs_world

pytestmark = needs_world


def rows(n, seed=3):
    """n circles of radius 0.4 on a 3 x ceil(n/3) grid of spacing 1: none overlap."""
    rng = np.random.default_rng(seed)
    i = np.arange(n)
    pos = np.column_stack((i % 3, i // 3)).astype(float)
    return pos, rng.normal(size=(n, 2)), np.full(n, 0.4), 1.0 + rng.random(n)


def test_add_circles_is_add_circle_row_by_row():
    pos, vel, r, m = rows(40)
    a, b = World(max_circles=64, period=(20, 20)), World(max_circles=64, period=(20, 20))
    for w in (a, b):
        for k in range(5):
            w.add_circle(Circle((10 + 2 * k, 10), (0, 0), 0.5))
        w.remove_circle(1)
        w.remove_circle(3)  # the free stack hands back 3, then 1, then 5, 6, ...
        w.step(0.5)
    ids = a.add_circles(pos, vel, r, m)
    single = [b.add_circle(Circle(tuple(pos[i]), tuple(vel[i]), r[i], m[i])) for i in range(40)]
    assert ids.tolist() == single
    assert ids[:3].tolist() == [3, 1, 5]
    assert a.hash == b.hash
    a.step(2.0)
    b.step(2.0)
    assert a.hash == b.hash


def test_chunks_are_one_call_each_and_the_same_world():
    # ADD_CHUNK rows per C call: 10 rows in chunks of 3 (4 calls) give the world one call gives
    pos, vel, r, m = rows(10)
    one, chunked = World(max_circles=10), World(max_circles=10)
    chunked.ADD_CHUNK = 3
    one.add_circles(pos, vel, r, m)
    assert chunked.add_circles(pos, vel, r, m).tolist() == list(range(10))
    assert one.hash == chunked.hash


def test_scalars_broadcast_and_the_defaults():
    w = World(max_circles=4)
    ids = w.add_circles([[0, 0], [5, 0]], radius=2)  # vel 0, mass 1
    assert ids.tolist() == [0, 1]
    assert w.circle(1).pos == (5.0, 0.0) and w.circle(1).vel == (0.0, 0.0)
    assert w.radii.tolist() == [2.0, 2.0] and w.masses.tolist() == [1.0, 1.0]
    w.add_circles([[10, 0]], vel=(1, -1), mass=math.inf)
    assert w.circle(2).vel == (1.0, -1.0) and w.circle(2).mass == math.inf
    assert w.add_circles(np.zeros((0, 2))).tolist() == []


@pytest.mark.parametrize(
    "column, value, message",
    [
        ("pos", (1.0, math.nan), r"row 2: pos must be finite, got \(1.0, nan\)"),
        ("vel", (math.inf, 0.0), r"row 2: vel must be finite, got \(inf, 0.0\)"),
        ("radius", 0.0, r"row 2: radius must be finite and > 0, got 0.0"),
        ("radius", math.inf, r"row 2: radius must be finite and > 0, got inf"),
        ("mass", -1.0, r"row 2: mass must be > 0 \(inf: immovable\), got -1.0"),
        ("mass", math.nan, r"row 2: mass must be > 0 \(inf: immovable\), got nan"),
    ],
)
def test_a_bad_row_is_named_and_nothing_is_added(column, value, message):
    pos, vel, r, m = rows(6)
    arrays = {"pos": pos, "vel": vel, "radius": r, "mass": m}
    arrays[column][2] = value
    arrays[column][4] = value  # the first bad row is named
    w = World(max_circles=16)
    w.add_circle(Circle((50, 50), (0, 0), 1))
    before = w.hash
    with pytest.raises(CircleCollideError, match=message) as e:
        w.add_circles(**arrays)
    assert e.value.code == -1
    assert len(w) == 1 and w.hash == before


def test_full_and_too_wide_are_named_and_nothing_is_added():
    pos, vel, r, m = rows(6)
    w = World(max_circles=5)
    w.add_circle(Circle((50, 50), (0, 0), 1))
    before = w.hash
    # 4 places left: rows 0-3 fit, row 4 finds the world full
    with pytest.raises(CircleCollideError, match="row 4 does not fit: the world holds 5 circles") as e:
        w.add_circles(pos, vel, r, m)
    assert e.value.code == -3 and len(w) == 1 and w.hash == before
    # a bad row before the first that does not fit is named instead (as row-by-row adds meet it)
    m[1] = 0.0
    with pytest.raises(CircleCollideError, match="row 1: mass"):
        w.add_circles(pos, vel, r, m)
    # period 10: a circle needs 2 (2r) + 1.0625 (2r) = 6.125 r <= 10, r <= 1.63
    torus = World(max_circles=8, period=(10.0, 0.0))
    with pytest.raises(CircleCollideError, match=r"row 1: radius 1.7 is too wide for the period 10.0 along x"):
        torus.add_circles([[1, 1], [5, 5]], radius=[1.6, 1.7])
    assert len(torus) == 0
    assert torus.add_circles([[1, 1], [5, 5]], radius=[1.6, 1.63]).tolist() == [0, 1]


def test_shapes_are_checked():
    w = World(max_circles=4)
    with pytest.raises(ValueError, match=r"pos must have shape \(n, 2\)"):
        w.add_circles([1.0, 2.0])
    with pytest.raises(ValueError, match=r"radius must be one value or an array of shape \(2,\)"):
        w.add_circles([[0, 0], [5, 5]], radius=[1, 2, 3])
    assert len(w) == 0


def test_add_circles_from_a_callback_is_refused():
    seen = []
    w = World(max_circles=4, callbacks=True)
    w.add_circles([[0, 0], [4, 0]], vel=[[1, 0], [-1, 0]])

    def inside(event):
        try:
            w.add_circles([[20, 20]])
        except CircleCollideError as e:
            seen.append(str(e))

    w.on_contact = inside
    w.step(2.0)  # the gap of 2 closes at speed 2 at t = 1
    assert len(seen) == 1 and "called from a callback" in seen[0]
    assert len(w) == 2


def test_unwrapped_positions_are_unwrapped_for_each():
    w = World(max_circles=8, period=(10, 10))
    # at x = 9 moving at speed 1: at t = 2.5 it is at 1.5 within the period, unwrapped 11.5
    w.add_circles([[9, 5], [2, 2], [5, 8]], vel=[[1, 0], [0, 0], [0, -4]], radius=0.5)
    w.remove_circle(1)
    w.step(2.5)
    u = w.unwrapped_positions
    assert u.shape == (2, 2) and not u.flags.writeable
    assert np.array_equal(u, np.array([w.unwrapped(i) for i in w.ids]))
    assert u[0].tolist() == pytest.approx([11.5, 5.0], abs=1e-12)
    # the third went 10 down: unwrapped y -2, back at 8 within the period: one image below
    assert u[1].tolist() == pytest.approx([5.0, -2.0], abs=1e-12)
    assert np.rint((u - w.positions) / 10.0).tolist() == [[1, 0], [0, -1]]
    assert World(max_circles=2).unwrapped_positions.shape == (0, 2)


def test_a_million_disks():
    # 1000 x 1000 disks of radius 0.5 on a lattice of spacing 1.06 in a torus (eta 0.70)
    n, a = 1_000_000, math.sqrt(math.pi / (4 * 0.70))
    i = np.arange(n)
    pos = np.column_stack(((i % 1000 + 0.5) * a, (i // 1000 + 0.5) * a))
    vel = np.column_stack((np.cos(i * 0.001), np.sin(i * 0.001)))
    w = World(max_circles=n, period=(1000 * a, 1000 * a))
    ids = w.add_circles(pos, vel, 0.5, 1.0)
    assert len(w) == n and ids[0] == 0 and ids[-1] == n - 1
    assert np.array_equal(w.positions, pos) and np.array_equal(w.velocities, vel)
    assert np.array_equal(w.unwrapped_positions, pos)


def test_importing_circlecollide_imports_no_extra():
    code = (
        "import sys, circlecollide, circlecollide.hard_disks; "
        "print(sorted(m for m in ('gsd', 'freud', 'dask', 'distributed', 'matplotlib') if m in sys.modules))"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"
