"""Shared fixtures: whether the loaded library has the world yet."""

import pytest

from circlecollide import _lib

HAS_WORLD = not isinstance(_lib.lib.cc_world_init, _lib._Missing)

needs_world = pytest.mark.skipif(not HAS_WORLD, reason="the C library has no cc_world_* yet")
