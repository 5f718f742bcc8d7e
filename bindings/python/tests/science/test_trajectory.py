"""GSD trajectories (circlecollide.trajectory, World.write_gsd) read back with gsd and freud:
every field of every frame against the world it was written from."""

import math

import numpy as np
import pytest

gsd_hoomd = pytest.importorskip("gsd.hoomd")
freud = pytest.importorskip("freud")

from circlecollide import Circle, World  # noqa: E402
from circlecollide.trajectory import Trajectory  # noqa: E402


def gas(period=(12.0, 10.0)):
    """12 disks of radius 0.4 (one heavy, one immovable) moving fast enough to cross the box's
    edges many times in the run; circle 3 removed, so that row and id differ."""
    w = World(max_circles=16, period=period)
    rng = np.random.default_rng(11)
    i = np.arange(12)
    pos = np.column_stack(((i % 4) * 3.0 + 1.0, (i // 4) * 3.0 + 1.5))
    vel = rng.normal(0.0, 3.0, size=(12, 2))
    mass = np.ones(12)
    mass[5], mass[7] = 4.0, math.inf
    vel[7] = 0.0
    w.add_circles(pos, vel, 0.4, mass)
    w.remove_circle(3)
    return w


def snapshot(w):
    return {
        "ids": np.array(w.ids),
        "pos": w.positions.copy(),
        "unwrapped": w.unwrapped_positions.copy(),
        "vel": w.velocities.copy(),
        "radii": w.radii.copy(),
        "masses": w.masses.copy(),
        "time": w.time,
    }


def check_frame(frame, s, step, period, precision):
    eps = np.finfo(np.float32 if precision == "single" else np.float64).eps
    n = len(s["ids"])
    lx, ly = period
    assert frame.configuration.step == step
    assert frame.configuration.dimensions == 2
    assert np.allclose(frame.configuration.box, [lx, ly, 0, 0, 0, 0], rtol=0, atol=0)
    assert frame.particles.N == n
    assert frame.particles.types == ["disk"]
    assert frame.particles.typeid.tolist() == [0] * n
    p = frame.particles.position
    assert p.shape == (n, 3) and (p[:, 2] == 0).all()
    # HOOMD's box is centred on the origin: the world's [0, L) is [-L/2, L/2)
    half = np.array([lx, ly]) / 2
    assert (p[:, :2] >= -half).all() and (p[:, :2] < half).all()
    assert np.allclose(p[:, :2], s["pos"] - half, rtol=0, atol=2 * eps * half.max())
    # the image counts the periods between the unwrapped position and the one in the box
    image = frame.particles.image
    assert image.dtype == np.int32 and (image[:, 2] == 0).all()
    assert image[:, :2].tolist() == np.rint((s["unwrapped"] - s["pos"]) / [lx, ly]).astype(int).tolist()
    unwrapped = p[:, :2].astype(np.float64) + half + image[:, :2] * np.array([lx, ly])
    assert np.allclose(unwrapped, s["unwrapped"], rtol=0, atol=4 * eps * (np.abs(s["unwrapped"]).max() + half.max()))
    v = frame.particles.velocity
    assert (v[:, 2] == 0).all() and np.allclose(v[:, :2], s["vel"], rtol=2 * eps, atol=0)
    assert np.array_equal(frame.particles.diameter, (2 * s["radii"]).astype(np.float32))
    assert np.array_equal(frame.particles.mass, s["masses"].astype(np.float32))
    assert frame.log["circlecollide/time"].tolist() == [s["time"]]
    assert frame.log["circlecollide/periodic"].tolist() == [1 if lx > 0 else 0, 1 if ly > 0 else 0]
    assert frame.log["particles/circlecollide/id"].tolist() == s["ids"].tolist()
    # freud reads the box and unwraps to the same positions (up to its float32)
    box = freud.box.Box.from_box(frame.configuration.box, dimensions=2)
    assert box.is2D and (box.Lx, box.Ly) == (lx, ly)
    assert box.contains(p).all()
    assert np.allclose(box.unwrap(p, image)[:, :2] + half, s["unwrapped"], rtol=0, atol=1e-4 * (1 + np.abs(s["unwrapped"]).max()))
    return unwrapped


@pytest.mark.parametrize("precision", ["single", "double"])
def test_a_trajectory_reads_back_field_for_field(tmp_path, precision):
    period = (12.0, 10.0)
    w = gas(period)
    path = tmp_path / "run.gsd"
    snaps = []
    with Trajectory(path, precision=precision) as traj:
        for k in range(5):
            if k:
                w.step(1.5)
            snaps.append(snapshot(w))
            assert traj.append(w) == k
    assert w.stats.collisions > 0
    with gsd_hoomd.open(str(path), "r") as f:
        assert len(f) == 5
        for k, frame in enumerate(f):
            check_frame(frame, snaps[k], k, period, precision)
        if precision == "double":  # every bit of the world's doubles
            assert np.array_equal(f[4].particles.position[:, :2], snaps[4]["pos"] - np.array(period) / 2)
    # the disks crossed the edges: images other than 0 were written and read back
    with gsd_hoomd.open(str(path), "r") as f:
        assert np.abs(f[4].particles.image).max() > 0


def test_write_gsd_writes_and_appends(tmp_path):
    w = gas()
    path = tmp_path / "one.gsd"
    assert w.write_gsd(path) == 0
    w.step(0.5)
    s = snapshot(w)
    assert w.write_gsd(path, mode="a", step=1000) == 1
    with gsd_hoomd.open(str(path), "r") as f:
        assert len(f) == 2
        check_frame(f[1], s, 1000, (12.0, 10.0), "single")
    assert w.write_gsd(path) == 0  # "w" makes the file anew
    with gsd_hoomd.open(str(path), "r") as f:
        assert len(f) == 1


def test_an_open_axis_keeps_its_coordinates_and_one_box(tmp_path):
    # a channel: periodic along x (period 20), open along y; the disks at y in [-3, 3]
    w = World(max_circles=4, period=(20.0, 0.0))
    w.add_circles([[2, -3], [8, 0], [15, 3]], vel=[[5, 0], [-5, 1], [3, -1]], radius=0.5)
    path = tmp_path / "channel.gsd"
    with Trajectory(path) as traj:
        traj.append(w)
        w.step(0.5)
        traj.append(w)
    with gsd_hoomd.open(str(path), "r") as f:
        # the first frame sizes the open axis: 2 (|y| 3 + radius 0.5) = 7, up to a power of two: 8
        assert [fr.configuration.box[:2].tolist() for fr in f] == [[20.0, 8.0], [20.0, 8.0]]
        assert f[1].log["circlecollide/periodic"].tolist() == [1, 0]
        y = f[1].particles.position[:, 1]
        assert np.allclose(y, w.positions[:, 1], rtol=0, atol=1e-6)  # as it is, not moved
        assert (f[1].particles.image[:, 1] == 0).all()


def test_bad_arguments(tmp_path):
    with pytest.raises(ValueError, match="precision"):
        Trajectory(tmp_path / "x.gsd", precision="half")
    traj = Trajectory(tmp_path / "y.gsd")
    with pytest.raises(ValueError, match="step must be >= 0"):
        traj.append(gas(), step=-1)
    traj.close()
    with pytest.raises(ValueError, match="closed"):
        traj.append(gas())
