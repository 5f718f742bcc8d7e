"""Trajectories in GSD, HOOMD-blue's file format (read by OVITO, freud, MDAnalysis, gsd itself).

Needs the ``gsd`` package (``pip install circlecollide[science]``); importing circlecollide does
not import it, this module does when a file is opened.

A frame holds, for the live circles in id order (``World.ids``):

==============================  ===============================================================
``configuration.dimensions``    2
``configuration.box``           ``[Lx, Ly, 0, 0, 0, 0]`` (Lz 0: a 2D box, as HOOMD writes it): the
                                period along a periodic axis, the ``open_box`` length along an
                                open one (see ``Trajectory``)
``configuration.step``          the frame's step (``append(step=...)``; by default 0, 1, 2, ...)
``particles.position``          (N, 3), z = 0: the position within the period, moved by -L/2
                                along each periodic axis (HOOMD's box is centred on the origin:
                                [-L/2, L/2) is the world's [0, L)); along an open axis as it is
``particles.image``             (N, 3) int32: the periods taken off, from the unwrapped
                                positions: unwrapped = position + L/2 + image L
``particles.velocity``          (N, 3), z = 0
``particles.diameter``          2 radius
``particles.mass``              mass (inf for an immovable circle)
``particles.types``, ``typeid``  one type, ``"disk"``
``log/circlecollide/time``      the world's time (float64)
``log/circlecollide/periodic``  (2,) uint8: which axes wrap (HOOMD's box always does)
``log/particles/circlecollide/id``  (N,) int32: each row's circle id
==============================  ===============================================================

``precision="single"`` (the default, what HOOMD writes and viewers expect) stores positions and
velocities as float32; ``"double"`` keeps every bit of the world's doubles.
"""

from __future__ import annotations

import math
import os
from typing import TYPE_CHECKING, Any, Optional, Sequence, Union

import numpy as np

from ._extras import extra

if TYPE_CHECKING:  # pragma: no cover
    from ._world import World

PathLike = Union[str, "os.PathLike[str]"]

#: the particle type every circle gets
TYPE_NAME = "disk"


class Trajectory:
    """A GSD file that frames of a ``World`` are appended to.

    ``mode`` is gsd's: ``"w"`` creates (or overwrites), ``"a"`` appends to an existing file (or
    creates it), ``"x"`` creates and refuses an existing one. Along an open (non-periodic) axis
    the box has the length ``open_box`` gives for that axis (a pair; only the open axes' values
    are read), by default twice the largest |coordinate| plus the largest radius of the first
    frame along that axis, rounded up to a power of two, and kept for the whole file so that viewers see one box.
    Use as a context manager, or call ``close``::

        with Trajectory("run.gsd") as traj:
            for _ in range(100):
                world.step(1.0)
                traj.append(world)
    """

    def __init__(
        self,
        path: PathLike,
        mode: str = "w",
        precision: str = "single",
        open_box: Optional[Sequence[float]] = None,
    ) -> None:
        if precision not in ("single", "double"):
            raise ValueError(f"precision must be 'single' or 'double', got {precision!r}")
        hoomd = extra("gsd.hoomd")
        self.path = os.fspath(path)
        self.precision = precision
        self._float = np.float32 if precision == "single" else np.float64
        self._open_box = None if open_box is None else (float(open_box[0]), float(open_box[1]))
        self._file = hoomd.open(self.path, mode, precision=precision)
        self._frame_type = hoomd.Frame
        #: frames in the file (those already there when appending, and those appended since)
        self.frames = len(self._file)

    def __enter__(self) -> "Trajectory":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()

    def close(self) -> None:
        """Flushes and closes the file (appending after this raises)."""
        if self._file is not None:
            self._file.close()
            self._file = None

    def flush(self) -> None:
        """Writes what was appended so far to disk (readers see those frames)."""
        if self._file is None:
            raise ValueError("the trajectory is closed")
        self._file.flush()

    def _box_lengths(self, world: "World", pos: np.ndarray, radii: np.ndarray) -> "tuple[float, float]":
        if self._open_box is None:  # the first frame's extent along each axis
            sizes = []
            for axis in range(2):
                reach = float(np.abs(pos[:, axis]).max() + radii.max()) if len(radii) else 0.5
                sizes.append(2.0 ** math.ceil(math.log2(2.0 * max(reach, 0.5))))
            self._open_box = (sizes[0], sizes[1])
        lx = world.period[0] if world.period[0] > 0 else self._open_box[0]
        ly = world.period[1] if world.period[1] > 0 else self._open_box[1]
        return lx, ly

    def append(self, world: "World", step: Optional[int] = None) -> int:
        """Appends the world's state now as a frame; ``step`` (an int >= 0) is its
        ``configuration.step``, by default the frame's index. Returns that index."""
        if self._file is None:
            raise ValueError("the trajectory is closed")
        frame = self.frame(world, self.frames if step is None else int(step))
        self._file.append(frame)
        self.frames += 1
        return self.frames - 1

    def frame(self, world: "World", step: int = 0) -> Any:
        """The ``gsd.hoomd.Frame`` that ``append`` would write (not written)."""
        if step < 0:
            raise ValueError(f"step must be >= 0, got {step}")
        ids = np.asarray(world.ids, dtype=np.int32)
        pos, vel, radii, masses = world.positions, world.velocities, world.radii, world.masses
        unwrapped = world.unwrapped_positions
        lengths = self._box_lengths(world, pos, radii)
        n = len(ids)
        position = np.zeros((n, 3), dtype=self._float)
        image = np.zeros((n, 3), dtype=np.int32)
        for axis in range(2):
            period = world.period[axis]
            if period > 0:
                image[:, axis] = np.rint((unwrapped[:, axis] - pos[:, axis]) / period)
                column = (pos[:, axis] - 0.5 * period).astype(self._float)
                # a position just below the period rounds to +L/2 in float32: keep it inside
                half = self._float(0.5 * period)
                position[:, axis] = np.where(column < half, column, np.nextafter(half, self._float(0)))
            else:
                position[:, axis] = pos[:, axis]
        velocity = np.zeros((n, 3), dtype=self._float)
        velocity[:, 0:2] = vel
        f = self._frame_type()
        f.configuration.step = int(step)
        f.configuration.dimensions = 2
        f.configuration.box = [lengths[0], lengths[1], 0.0, 0.0, 0.0, 0.0]
        f.particles.N = n
        f.particles.types = [TYPE_NAME]
        f.particles.typeid = np.zeros(n, dtype=np.uint32)
        f.particles.position = position
        f.particles.image = image
        f.particles.velocity = velocity
        f.particles.diameter = (2.0 * radii).astype(np.float32)
        f.particles.mass = masses.astype(np.float32)
        f.log["circlecollide/time"] = np.array([world.time], dtype=np.float64)
        f.log["circlecollide/periodic"] = np.array([p > 0 for p in world.period], dtype=np.uint8)
        f.log["particles/circlecollide/id"] = ids
        return f


def write_gsd(world: "World", path: PathLike, mode: str = "w", step: Optional[int] = None, **options: Any) -> int:
    """``World.write_gsd``: one frame of the world into a GSD file (``mode`` ``"w"`` makes a new
    file, ``"a"`` appends); ``options`` are ``Trajectory``'s. Returns the frame's index."""
    with Trajectory(path, mode, **options) as traj:
        return traj.append(world, step)
