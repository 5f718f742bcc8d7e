"""Peers on the benchmark's gas: PyPI billiards (exact, event-driven, Python) and pymunk
(Chipmunk2D, fixed steps), started from the very state our world starts from.

Usage: python peers.py BENCH_WORLD N PHI T_END DT OUTDIR [billiards] [pymunk]

BENCH_WORLD is the bench_world program: `dump-gas` gives the initial state and `check-trace`
judges the recorded trajectory by the same rules as our world (tunnelling, escapes, overlap,
energy drift). Only the engines' own stepping is timed. Prints one `peer NAME ...` line each.
"""
import struct
import subprocess
import sys
import time


def load_gas(bench_world, n, phi):
    out = subprocess.run([bench_world, "dump-gas", str(n), str(phi)], check=True, capture_output=True,
                         text=True).stdout.splitlines()
    box = [float(v) for v in out[0].split()[2:]]
    balls = [[float(v) for v in line.split()] for line in out[1:]]
    return box, balls


class Trace:
    """States after every step, in the binary layout that `bench_world check-trace` reads."""

    def __init__(self, path, n, dt, steps):
        self.f = open(path, "wb")
        self.f.write(struct.pack("<iid", n, steps, dt))

    def add(self, states):
        self.f.write(struct.pack("<%dd" % (4 * len(states)), *[v for s in states for v in s]))

    def close(self):
        self.f.close()


def check(bench_world, n, phi, path):
    out = subprocess.run([bench_world, "check-trace", str(n), str(phi), path], check=True, capture_output=True,
                         text=True).stdout
    return out.strip()


def run_billiards(box, balls, t_end, dt, trace):
    import billiards  # noqa: PLC0415 (optional peer)
    from billiards.obstacles import InfiniteWall  # noqa: PLC0415
    x0, y0, x1, y1 = box
    walls = [InfiniteWall((x0, y0), (x1, y0)), InfiniteWall((x1, y0), (x1, y1)),
             InfiniteWall((x1, y1), (x0, y1)), InfiniteWall((x0, y1), (x0, y0))]
    sim = billiards.Billiard(walls)
    for px, py, vx, vy, r, m in balls:
        sim.add_ball((px, py), (vx, vy), radius=r, mass=m)
    steps = int(round(t_end / dt))
    trace.add([(b[0], b[1], b[2], b[3]) for b in balls])
    spent, coll = 0.0, 0
    for k in range(1, steps + 1):
        t0 = time.perf_counter()
        coll += len(sim.evolve(k * dt))
        spent += time.perf_counter() - t0
        trace.add([(p[0], p[1], v[0], v[1]) for p, v in zip(sim.balls_position, sim.balls_velocity)])
    return spent, coll


def run_pymunk(box, balls, t_end, dt, trace):
    import pymunk  # noqa: PLC0415 (optional peer)
    x0, y0, x1, y1 = box
    space = pymunk.Space()
    space.gravity = (0.0, 0.0)
    for a, b in (((x0, y0), (x1, y0)), ((x1, y0), (x1, y1)), ((x1, y1), (x0, y1)), ((x0, y1), (x0, y0))):
        seg = pymunk.Segment(space.static_body, a, b, 0.0)
        seg.elasticity, seg.friction = 1.0, 0.0
        space.add(seg)
    bodies = []
    for px, py, vx, vy, r, m in balls:
        body = pymunk.Body(m, float("inf"))
        body.position, body.velocity = (px, py), (vx, vy)
        shape = pymunk.Circle(body, r)
        shape.elasticity, shape.friction = 1.0, 0.0
        space.add(body, shape)
        bodies.append(body)
    count = [0]

    def begin(arbiter, space_, data):
        count[0] += 1

    space.on_collision(begin=begin)
    steps = int(round(t_end / dt))
    trace.add([(b[0], b[1], b[2], b[3]) for b in balls])
    spent = 0.0
    for _ in range(steps):
        t0 = time.perf_counter()
        space.step(dt)
        spent += time.perf_counter() - t0
        trace.add([(b.position.x, b.position.y, b.velocity.x, b.velocity.y) for b in bodies])
    return spent, count[0]


def main():
    bench_world, n, phi, t_end, dt, outdir = sys.argv[1:7]
    n, phi, t_end, dt = int(n), float(phi), float(t_end), float(dt)
    which = sys.argv[7:] or ["billiards", "pymunk"]
    box, balls = load_gas(bench_world, n, phi)
    for name, fn in (("billiards", run_billiards), ("pymunk", run_pymunk)):
        if name not in which:
            continue
        path = "%s/trace-%s.bin" % (outdir, name)
        trace = Trace(path, n, dt, int(round(t_end / dt)))
        try:
            spent, coll = fn(box, balls, t_end, dt, trace)
        except ImportError as e:
            print("peer %s skipped: %s" % (name, e))
            continue
        finally:
            trace.close()
        print("peer %s n=%d phi=%g dt=%g sec_per_sim_s=%.6g collisions=%d collisions_per_s=%.6g %s"
              % (name, n, phi, dt, spent / t_end, coll, coll / spent, check(bench_world, n, phi, path)))
        sys.stdout.flush()


if __name__ == "__main__":
    main()
