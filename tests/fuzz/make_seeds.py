#!/usr/bin/env python3
"""Writes the hand-made seed inputs of the fuzz corpus (tests/fuzz/corpus/seed-*): for every
function of the fuzz target (fuzz_checks.h gives the format), ordinary, touching, grazing,
overlapping, huge, tiny, subnormal and NaN cases. The fuzzer's own finds are added beside them
(scripts/test.d/30-fuzz.sh explains how to merge them in).

    python3 tests/fuzz/make_seeds.py tests/fuzz/corpus
"""
import math
import os
import struct
import sys

SWEEP, SEG, DETECT, SEPARATE, RESPOND, RESPOND_SEG, CLOSEST = 0, 2, 4, 6, 8, 10, 12
MANY = 14
# rolling to rest (1.1): byte 0 from 240 (see fuzz_function in fuzz_checks.h); odd = float
ROLL, ROLL_SEG, ROLL_ADV = 240, 242, 244
NAN, INF = float("nan"), float("inf")
DECELS = {"none": 0.0, "cloth": 0.5, "tiny": 1e-12, "huge": 1e9, "nan": NAN, "neg": -1.0}

# (pos x, pos y, vel x, vel y, radius, mass)
CIRCLES = {
    "still": (0, 0, 0, 0, 1, 1),
    "mover": (-10, 0.5, 3, 0, 1, 2),
    "far": (1e15, -1e15, 1e8, 1e8, 1, 1),
    "tiny": (1e-300, 0, -1e-300, 0, 1e-310, 1e-300),
    "huge": (1e300, 1e300, -1e300, 0, 1e300, 1e300),
    "immovable": (3, 0, -1, 0, 2, INF),
    "nan": (NAN, 0, 0, 0, 1, 1),
    "zero_r": (0, 0, 0, 0, 0, 1),
}
SEGMENTS = {
    "unit": (0, -1, 0, 1),
    "point": (2, 2, 2, 2),
    "long": (-1e9, 3, 1e9, 3.000001),
    "inf": (0, 0, INF, 0),
}
CONTACTS = {  # (t, point x, point y, normal x, normal y, depth)
    "x": (0, 0, 0, 1, 0, 0),
    "diag": (1, 0, 0, math.sqrt(0.5), math.sqrt(0.5), 0),
    "edge": (0, 0, 0, 1 + 1e-6, 0, 0),
    "zero": (0, 0, 0, 0, 0, 0),
}


def pack(fn, values, flags=0, count=0):
    fmt = "<%d%s" % (len(values), "f" if fn % 2 and fn != MANY else "d")
    vals = []
    for v in values:
        if fmt.endswith("f") and isinstance(v, float) and math.isfinite(v) and abs(v) > 3.4e38:
            v = math.copysign(INF, v)
        vals.append(v)
    return bytes([fn, flags, count]) + struct.pack(fmt, *vals)


def cases():
    names = list(CIRCLES)
    for prec in (0, 1):
        for i, a in enumerate(names):
            for b in names[i:]:
                for t_max in (10.0, INF, 0.0):
                    yield "sweep-%s-%s-%g-%d" % (a, b, t_max, prec), pack(SWEEP + prec, CIRCLES[a] + CIRCLES[b] + (t_max,))
                yield "detect-%s-%s-%d" % (a, b, prec), pack(DETECT + prec, CIRCLES[a] + CIRCLES[b])
                yield "separate-%s-%s-%d" % (a, b, prec), pack(SEPARATE + prec, CIRCLES[a] + CIRCLES[b])
                for cn, k in CONTACTS.items():
                    yield "respond-%s-%s-%s-%d" % (a, b, cn, prec), pack(RESPOND + prec, CIRCLES[a] + CIRCLES[b] + k + (1.0,))
            for sn, s in SEGMENTS.items():
                yield "segment-%s-%s-%d" % (a, sn, prec), pack(SEG + prec, CIRCLES[a] + s + (INF,))
                yield "closest-%s-%s-%d" % (a, sn, prec), pack(CLOSEST + prec, CIRCLES[a][:2] + s)
            for cn, k in CONTACTS.items():
                yield "respond_segment-%s-%s-%d" % (a, cn, prec), pack(RESPOND_SEG + prec, CIRCLES[a] + k + (0.5,))
    for n in range(5):
        cols = []
        for i in range(n):
            a, b = CIRCLES[names[i]], CIRCLES[names[-1 - i]]
            cols.append(a[:5] + b[:5])
        yield "many-%d" % n, pack(MANY, [v for c in cols for v in c] + [10.0], count=n)
    # rolling: a ball into a resting one, head-on, stopping short; walls; advance past the stop
    for prec in (0, 1):
        for dn, d in DECELS.items():
            yield "roll-mover-still-%s-%d" % (dn, prec), pack(ROLL + prec, CIRCLES["mover"] + CIRCLES["still"] + (d, 0.0, INF))
            yield "roll-mover-immovable-%s-%d" % (dn, prec), pack(ROLL + prec, CIRCLES["mover"] + CIRCLES["immovable"] + (d, d, 10.0))
            yield "roll_segment-mover-%s-%d" % (dn, prec), pack(ROLL_SEG + prec, (-10, 0.5, 3, 0, 1, 2) + (0, -1, 0, 1) + (d, INF))
            yield "roll_advance-mover-%s-%d" % (dn, prec), pack(ROLL_ADV + prec, CIRCLES["mover"] + (d, 7.0))
        for a in ("far", "tiny", "huge", "nan", "zero_r"):
            yield "roll-%s-mover-%d" % (a, prec), pack(ROLL + prec, CIRCLES[a] + CIRCLES["mover"] + (0.5, 0.25, INF))
            yield "roll_segment-%s-%d" % (a, prec), pack(ROLL_SEG + prec, CIRCLES[a] + SEGMENTS["long"] + (0.5, INF))
            yield "roll_advance-%s-%d" % (a, prec), pack(ROLL_ADV + prec, CIRCLES[a] + (0.5, 1e300))
        # stopping exactly touching (speed 2, decel 0.5: stops after 4, radii 0.125: b at 4.25)
        yield "roll-stop-touch-%d" % prec, pack(ROLL + prec, (0, 0, 2, 0, 0.125, 1) + (4.25, 0, 0, 0, 0.125, 1) + (0.5, 0.0, INF))
        yield "roll-head-on-%d" % prec, pack(ROLL + prec, (0, 0, 2, 0, 1, 1) + (10, 0, -2, 0, 1, 1) + (0.5, 0.5, INF))
    # the same numbers made valid by the harness (flag bit 0)
    yield "sweep-valid-nan", pack(SWEEP, CIRCLES["nan"] + CIRCLES["mover"] + (NAN,), flags=1)
    yield "many-valid", pack(MANY, [NAN] * 20 + [1.0], flags=1, count=2)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "corpus")
    os.makedirs(out, exist_ok=True)
    n = 0
    for name, data in cases():
        with open(os.path.join(out, "seed-" + name.replace(".", "_").replace("+", "")), "wb") as f:
            f.write(data)
        n += 1
    print("%d seeds written to %s" % (n, out))


if __name__ == "__main__":
    main()
