"""Recipe: a pool shot from aim to rest, in Python (docs/RECIPES.md).

The same table, balls and shot as docs/recipes/pool_shot.c, through the Python binding: cloth
friction (rolling_decel), cushions of restitution 0.75 (set_segment_props), pockets that are
sensor circles (on_sensor), the aiming line from cast_circle. The binding calls the same library
with the same numbers in the same order, so it ends where the C recipe ends (the cue ball at rest
at (1.8508, 1.2392), checked). Run: python docs/recipes/pool_shot.py
(bindings/python/tests/test_recipes.py runs it).
"""
import math

from circlecollide import Circle, World

W, H = 2.54, 1.27
R = 0.028575  # ball radius
POCKET = 0.06  # a ball whose centre comes this close to a pocket's centre drops
MOUTH = 0.12  # cushions stop this far from a corner (and from a side pocket)
BALL, POCKET_CAT = 1, 2

potted = []  # the sensor callback only notes a ball (a callback may not change the world)
w = World(max_circles=16, max_segments=8, restitution=0.95, rolling_decel=0.15, restitution_mix="min",
          on_sensor=lambda e: potted.append(e.visitor) if e.begin else None)
for p, q in [((MOUTH, 0), (W / 2 - MOUTH / 2, 0)), ((W / 2 + MOUTH / 2, 0), (W - MOUTH, 0)),
             ((MOUTH, H), (W / 2 - MOUTH / 2, H)), ((W / 2 + MOUTH / 2, H), (W - MOUTH, H)),
             ((0, MOUTH), (0, H - MOUTH)), ((W, MOUTH), (W, H - MOUTH))]:
    w.set_segment_props(w.add_segment(p, q), restitution=0.75)  # cushions
for x, y in [(0, 0), (W / 2, 0), (W, 0), (0, H), (W / 2, H), (W, H)]:
    pocket = w.add_circle(Circle(pos=(x, y), radius=POCKET - R, mass=math.inf))
    w.set_circle_props(pocket, sensor=True, category=POCKET_CAT)
C, O, P = (0.6, 0.5), (1.5, 0.4), (W, 0.0)
obj = w.add_circle(Circle(pos=O, radius=R, mass=0.17))

# aim: the ghost ball G touches the object ball on the far side from the pocket
dx, dy = P[0] - O[0], P[1] - O[1]
length = math.sqrt(dx * dx + dy * dy)
G = (O[0] - 2 * R * dx / length, O[1] - 2 * R * dy / length)
d = (G[0] - C[0], G[1] - C[1])
hit = w.cast_circle(C, (2 * d[0], 2 * d[1]), radius=R, mask=BALL)  # a little beyond G
assert hit is not None and hit.kind == "hit" and hit.circle == obj, hit
assert abs(hit.t - 0.5) < 1e-12 and math.dist(hit.normal, (dx / length, dy / length)) < 1e-12
print(f"aiming line: the cue ball first touches circle {hit.circle} at t = {hit.t:.15f} of the path; "
      f"the object ball leaves along ({hit.normal.x:.6f}, {hit.normal.y:.6f})")

# shoot at 2 m/s along the aiming line, step at 60 Hz, remove what drops, until all rest
n = math.sqrt(d[0] * d[0] + d[1] * d[1])
cue = w.add_circle(Circle(pos=C, vel=(2.0 * d[0] / n, 2.0 * d[1] / n), radius=R, mass=0.17))
steps, moving = 0, True
while moving and steps < 6000:
    w.step(1.0 / 60)
    steps += 1
    for b in potted:
        w.remove_circle(b)
    potted.clear()
    moving = any(i in w.ids and w.circle(i).vel != (0.0, 0.0) for i in (cue, obj))
c = w.circle(cue)
print(f"after {steps / 60:.2f} s: object ball {'potted' if obj not in w.ids else 'on the table'}; "
      f"cue ball at rest at ({c.pos.x:.4f}, {c.pos.y:.4f})")
assert obj not in w.ids, "the object ball drops into the bottom right pocket"
assert not moving and 0 < c.pos.x < W and 0 < c.pos.y < H, "the cue ball rolls to rest on the table"
assert (round(c.pos.x, 4), round(c.pos.y, 4)) == (1.8508, 1.2392), "where the C recipe's cue ball rests"
