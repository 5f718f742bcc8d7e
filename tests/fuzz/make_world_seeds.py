#!/usr/bin/env python3
"""Writes the hand-made seed inputs of the world fuzzer's corpus (tests/fuzz/corpus_world/seed-*):
a def (every mode, small and grid-sized capacities, walls, periods, rolling, callbacks, a def of
1.0's size, a later header's def, invalid defs) then a sequence of calls (fuzz_world_checks.c gives the byte layout).
The fuzzer's own finds are merged in beside them (scripts/test.d/30-fuzz.sh explains how).

    python3 tests/fuzz/make_world_seeds.py tests/fuzz/corpus_world
"""
import os
import random
import sys

(ADD, REMOVE, SET, GET, ADD_SEG, GET_SEG, SET_PROPS, GET_PROPS, SET_SEGPROPS, GET_SEGPROPS, STEP, STEP2,
 CAST, QUERY_CIRCLE, QUERY_BOX, HASH, STATS, UNWRAPPED, GET_CIRCLES, COPY, STEP_SMALL, ADD2, ADD_BATCH,
 UNWRAPPED_ALL) = range(24)
ORD = lambda u: 14 + round(u * 241)  # an ordinary value at u in [0, 1] of its kind's range
HOST = [0, 0]  # a hostile value: 0, then the table index


def hostile(i):
    return [0, i]


def defbytes(mode, maxc, maxs, flags, nz, e=1.0, rest=0.0, cell=0.0, decel=0.0, px=0.0, py=0.0, max_events=5000):
    b = [mode, maxc, maxs, flags, nz, ORD(e), ORD(rest / 5), ORD(cell / 5), ORD(decel / 2.5),
         ORD(px / 30), ORD(py / 30)]
    v = max_events - 1
    return b + [v >> 8, v & 255]


def circle(rng, spread=1.0, hostile_p=0.0):
    out = []
    for k in range(6):
        if rng.random() < hostile_p:
            out += hostile(rng.randrange(32))
        elif k < 2:
            out.append(ORD(0.5 + (rng.random() - 0.5) * spread))
        elif k == 5:
            out.append(ORD(rng.random() * 0.9) if rng.random() < 0.9 else 250)
        else:
            out.append(ORD(rng.random()))
    return out


def calls(rng, n, maxc, hostile_p=0.0, spread=1.0):
    out = []
    for _ in range(n):
        op = rng.choice([ADD, ADD2, ADD2, STEP, STEP_SMALL, STEP2, SET, REMOVE, GET, SET_PROPS, GET_PROPS,
                         CAST, QUERY_CIRCLE, QUERY_BOX, HASH, STATS, UNWRAPPED, GET_CIRCLES, COPY, ADD_SEG,
                         SET_SEGPROPS, GET_SEGPROPS, GET_SEG])
        out.append(op)
        if op in (ADD, ADD2):
            out += circle(rng, spread, hostile_p)
        elif op == SET:
            out += [8 + rng.randrange(max(maxc, 1))] + circle(rng, spread, hostile_p) + [rng.randrange(256)]
        elif op in (REMOVE, GET, UNWRAPPED):
            out += [rng.randrange(256)]
        elif op in (STEP, STEP2):
            out += hostile(rng.randrange(32)) if rng.random() < hostile_p else [ORD(rng.random())]
        elif op == STEP_SMALL:
            out += [rng.randrange(64)]
        elif op in (SET_PROPS, GET_PROPS, SET_SEGPROPS, GET_SEGPROPS):
            out += [rng.randrange(256) for _ in range(9)]
        elif op in (CAST, QUERY_CIRCLE, QUERY_BOX):
            out += [rng.randrange(14, 256) for _ in range(8)]
        elif op in (STATS, GET_CIRCLES, GET_SEG):
            out += [rng.randrange(256)]
        elif op == ADD_SEG:
            out += [ORD(rng.random()) for _ in range(5)]
    return out


def main():
    d = sys.argv[1] if len(sys.argv) > 1 else "corpus_world"
    os.makedirs(d, exist_ok=True)
    rng = random.Random(11)
    seeds = {}
    for mode in range(3):
        for name, maxc, maxs, flags, nz, kw in [
            ("small", 12, 0, 3, 0, {}),
            ("grid", 40, 0, 3, 0, {}),
            ("walls", 20, 8, 3, 0, {}),
            ("rolling", 16, 4, 3, 4, {"decel": 0.5}),
            ("inelastic", 30, 2, 3 | (2 << 5), 1, {"e": 0.6, "rest": 0.1}),
            ("periodic", 36, 0, 3 | 4 | 8, 2, {"cell": 1.0, "px": 20.0, "py": 16.0}),
            ("channel", 36, 2, 3 | 4, 0, {"px": 24.0}),
            ("old_def", 20, 2, 1 | 16, 0, {}),
            ("few_events", 24, 4, 3, 0, {"max_events": 3}),
        ]:
            hp = 0.0 if name != "walls" else 0.05
            body = defbytes(mode, maxc, maxs, flags, nz, **kw)
            spread = 0.6 if maxc > 20 else 0.35
            seeds["%s-%d" % (name, mode)] = body + calls(rng, 60, maxc, hp, spread)
    for k in range(4):
        seeds["hostile-%d" % k] = defbytes(k % 3, 10, 3, 3, 0) + calls(rng, 80, 10, 0.3)
    seeds["invalid-mode"] = defbytes(7, 10, 0, 3, 0) + calls(rng, 5, 10)
    seeds["invalid-period"] = defbytes(0, 10, 0, 4, 2, cell=3.0, px=2.0) + calls(rng, 5, 10)
    seeds["invalid-events"] = defbytes(0, 10, 0, 0, 0)[:-2] + [255, 255]
    seeds["empty"] = []
    # defs of a later header (byte 4 bit 6: struct_size past this header's def), which get the 1.2
    # codes: CC_ERR_BUSY from the callbacks, CC_ERR_RANGE for circles too wide for the period and
    # steps too long (drawn after the seeds above, which the rng leaves as they were)
    for mode in range(3):
        for name, maxc, maxs, flags, nz, kw in [
            ("later-walls", 20, 8, 3, 0x40, {}),
            ("later-periodic", 36, 0, 3 | 4 | 8, 2 | 0x40, {"cell": 1.0, "px": 8.0, "py": 8.0}),
        ]:
            seeds["%s-%d" % (name, mode)] = defbytes(mode, maxc, maxs, flags, nz, **kw) + calls(rng, 60, maxc, 0.05, 0.6)
    seeds["later-invalid-period"] = defbytes(0, 10, 0, 4, 2 | 0x40, cell=3.0, px=2.0) + calls(rng, 5, 10)
    # periods out, in every mode, before the first step and after one: a circle at (6, 6) in a box
    # of 8 x 8, found by queries centred at (-10, -10) (its image there) and hit by a ray from
    # x = 8.5 by +8 (the image at 14); no rng: the seeds above stay as they were
    for mode in range(3):
        body = [ADD, ORD(0.8), ORD(0.8), ORD(0.5), ORD(0.5), ORD(0.3), ORD(0.2)]
        looks = [QUERY_CIRCLE, 40, 0x80, ORD(0.0), ORD(0.0), ORD(0.05),
                 QUERY_BOX, 40, 0x80, ORD(0.0), ORD(0.0), ORD(0.1), 1, ORD(0.1),
                 CAST, 0x80, ORD(0.925), ORD(0.8), ORD(0.7), ORD(0.5), 0]
        seeds["far-images-%d" % mode] = (defbytes(mode, 12, 0, 3 | 4 | 8, 2, cell=1.0, px=8.0, py=8.0) + body + looks
                                          + [STEP, ORD(0.1)] + looks)
    # the batch calls (1.2: cc_world_add_circles against as many single adds, on a copy of the
    # world; cc_world_get_unwrapped_all), between the other calls; their own rng, so that the
    # seeds above stay as they were
    brng = random.Random(34)
    for mode in range(3):
        for name, maxc, maxs, flags, nz, kw in [
            ("batch-walls", 24, 4, 3, 0x40, {}),
            ("batch-periodic", 30, 0, 3 | 4 | 8, 2 | 0x40, {"cell": 1.0, "px": 10.0, "py": 10.0}),
            ("batch-old-def", 12, 2, 3 | 16, 0, {}),
        ]:
            body = defbytes(mode, maxc, maxs, flags, nz, **kw)
            for _ in range(14):
                k = brng.choice([0, 1, 2, 3, 5, 8])
                fl = brng.choice([0, 4, 4, 4, 1, 2, 6 << 5, 7 << 5])
                body += [ADD_BATCH, k, fl]
                for _ in range(k):
                    body += circle(brng, 0.6, 0.08 if brng.random() < 0.3 else 0.0)
                body += [UNWRAPPED_ALL, brng.randrange(256), brng.randrange(4)]
                body += calls(brng, 4, maxc, 0.0, 0.6)
            seeds["%s-%d" % (name, mode)] = body
    # worlds that reserve only what they use (byte 4 bits 4-5: uses 0, SENSORS, PROPS | ROLLING):
    # the property calls that need what the world left out are refused; their own rng
    urng = random.Random(31)
    for mode in range(3):
        for name, maxc, maxs, flags, nz, kw in [
            ("uses-none", 20, 4, 3, 0x10, {}),
            ("uses-none-periodic", 30, 0, 3 | 4 | 8, 2 | 0x10, {"cell": 1.0, "px": 10.0, "py": 10.0}),
            ("uses-sensors", 20, 4, 3, 0x20 | 0x40, {}),
            ("uses-props-rolling", 16, 4, 3, 4 | 0x30, {"decel": 0.5}),
            ("uses-none-rolling", 16, 0, 3, 4 | 0x10, {"decel": 0.5}),  # invalid: decel without ROLLING
        ]:
            body = defbytes(mode, maxc, maxs, flags, nz, **kw)
            for _ in range(5):
                body += [ADD] + circle(urng, 0.6)
            if maxs:
                body += [ADD_SEG] + [ORD(urng.random()) for _ in range(5)]
            for _ in range(12):
                body += calls(urng, 2, maxc, 0.0, 0.6)
                if urng.random() < 0.7:  # a live id (b % (maxc + 1)), the whole struct, then its fields
                    body += [SET_PROPS, maxc + 1 + urng.randrange(5), 0, ORD(urng.choice([1.0, urng.random()]))]
                    body += [1, ORD(urng.random())] if urng.random() < 0.4 else [0]
                    body += [urng.choice([0x80, 0x80, 2]), urng.choice([0x80, 0x80, 3])]
                    body += [0, urng.randrange(256)] if urng.random() < 0.4 else [1]
                else:  # wall 0
                    body += [SET_SEGPROPS, maxc + 1, 0, ORD(urng.choice([1.0, urng.random()])),
                             urng.choice([0x80, 2]), urng.choice([0x80, 3])]
            seeds["%s-%d" % (name, mode)] = body
    for name, b in sorted(seeds.items()):
        with open(os.path.join(d, "seed-" + name), "wb") as f:
            f.write(bytes(b))
    print("wrote %d seeds into %s" % (len(seeds), d))


if __name__ == "__main__":
    main()
