"""The Python recipes of docs/RECIPES.md run as tests: each checks what it prints with asserts."""
import pathlib
import runpy

import pytest

RECIPES = pathlib.Path(__file__).resolve().parents[3] / "docs" / "recipes"


@pytest.mark.parametrize("name", sorted(p.name for p in RECIPES.glob("*.py")))
def test_recipe(name, capsys):
    runpy.run_path(str(RECIPES / name), run_name="__main__")
    assert capsys.readouterr().out  # it says what it found


def test_the_recipes_are_found():
    assert (RECIPES / "hard_disks.py").is_file()
