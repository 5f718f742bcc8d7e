"""The freud recipe (docs/recipes/science/hard_disks_freud.py): g(r) and psi6 of dense hard disks,
and the pressure from g at contact beside the virial, agreeing within the stated error bars."""

import math
import pathlib
import runpy

import numpy as np
import pytest

freud = pytest.importorskip("freud")

RECIPE = pathlib.Path(__file__).resolve().parents[4] / "docs" / "recipes" / "science" / "hard_disks_freud.py"


@pytest.fixture(scope="module")
def recipe():
    return runpy.run_path(str(RECIPE), run_name="recipe")


def test_the_recipe_runs_and_checks_itself(recipe, capsys):
    # eta 0.70 and 0.72 at N 1024: main() asserts the agreement, g = 0 inside sigma, the peak
    (dense, hexatic) = recipe["main"]([])
    out = capsys.readouterr().out
    assert out.count("Z from g(sigma+)") == 2
    for res in (dense, hexatic):
        assert recipe["agree"](res)
        # both near the coexistence pressure of Engel et al. (beta P sigma^2 = 9.185, Z 10.3 at
        # 0.70, 10.0 at 0.72) within the small box's few per cent (docs/PHYSICS.md's N = 400 and
        # 1600 runs: 9.8 - 10.5)
        assert 9.5 < res["z_virial"] < 11.5
        # Z from g is only as good as its error bar: a few per cent of Z here, stated
        assert res["z_contact_err"] < 0.05 * res["z_contact"]
    # more order at 0.72 (hexatic-solid) than at 0.70 (liquid side of the coexistence)
    assert hexatic["psi6_local"] > dense["psi6_local"] > 0.5


def test_psi6_of_a_triangular_lattice_is_one(recipe):
    # every bond of a triangular lattice is at a multiple of 60 degrees: exp(6 i theta) = 1
    rows, cols = 10, 12
    a = 1.1
    x, y = np.meshgrid(np.arange(cols), np.arange(rows))
    pos = np.column_stack(((x + 0.5 * (y % 2)).ravel() * a, y.ravel() * a * math.sqrt(3) / 2))
    box = freud.box.Box(Lx=cols * a, Ly=rows * a * math.sqrt(3) / 2, is2D=True)
    points = np.column_stack((pos - [box.Lx / 2, box.Ly / 2], np.zeros(len(pos))))
    order = recipe["psi6"](box, points)
    assert np.allclose(np.abs(order), 1.0, atol=1e-5) and abs(order.mean()) == pytest.approx(1.0, abs=1e-5)


def test_the_contact_value_is_the_limit_of_g(recipe):
    # a g(r) = 5 exp(-20 (r - 1)) binned as the recipe's RDF: the fit recovers g(1) = 5
    class Fake:
        bin_centers = 1.0 + recipe["DR"] * (np.arange(20) + 0.5)
        rdf = 5.0 * np.exp(-20.0 * (bin_centers - 1.0))

    assert recipe["contact_value"](Fake, 0.05) == pytest.approx(5.0, rel=1e-9)
