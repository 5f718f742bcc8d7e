"""sweep_many over numpy columns agrees bit for bit with sweep pair by pair."""

import numpy as np
import pytest

from circlecollide import Circle, sweep, sweep_many


def random_pairs(n, seed=1):
    rng = np.random.default_rng(seed)
    return (
        rng.uniform(-10, 10, (n, 2)),
        rng.uniform(-2, 2, (n, 2)),
        rng.uniform(0.1, 2, n),
        rng.uniform(-10, 10, (n, 2)),
        rng.uniform(-2, 2, (n, 2)),
        rng.uniform(0.1, 2, n),
    )


def test_matches_sweep_pair_by_pair():
    ap, av, ar, bp, bv, br = random_pairs(500)
    t, codes = sweep_many(ap, av, ar, bp, bv, br, 5.0, return_codes=True)
    kinds = {0: None, 1: "hit", 2: "overlap"}
    hits = 0
    for i in range(len(t)):
        c = sweep(Circle(ap[i], av[i], ar[i]), Circle(bp[i], bv[i], br[i]), 5.0)
        assert kinds[int(codes[i])] == (c.kind if c else None)
        assert t[i] == (c.t if c else np.inf)  # bit-identical
        hits += c is not None
    assert 0 < hits < len(t)  # the sample has both outcomes


def test_scalar_radius_broadcasts_and_head_on_example():
    t = sweep_many([[0, 0], [0, 0]], [[1, 0], [0, 1]], 1.0, [[10, 0], [0, 1.5]], [[-1, 0], [0, 0]], 1.0, 10)
    assert t[0] == 4.0 and t[1] == 0.0  # head on: gap 8 at speed 2; second pair overlaps


def test_bad_input_raises_and_shapes_are_checked():
    ap, av, ar, bp, bv, br = random_pairs(4)
    ar[2] = -1.0
    with pytest.raises(ValueError, match="CC_ERR_INVALID"):
        sweep_many(ap, av, ar, bp, bv, br, 1.0)
    with pytest.raises(ValueError, match="shape"):
        sweep_many(ap[:, 0], av, 1, bp, bv, 1, 1.0)
    with pytest.raises(ValueError, match="rows"):
        sweep_many(ap, av[:3], 1, bp, bv, 1, 1.0)
    with pytest.raises(ValueError, match="CC_ERR_INVALID"):
        sweep_many(ap, av, 1, bp, bv, 1, np.nan)


def test_empty_input():
    e = np.zeros((0, 2))
    assert sweep_many(e, e, 1, e, e, 1, 1.0).shape == (0,)
