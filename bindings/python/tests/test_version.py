"""The load-time version handshake refuses a library of another major version."""

import pytest

import circlecollide
from circlecollide import _lib


def test_loaded_library_has_our_major():
    assert _lib.lib.cc_version() >> 16 == circlecollide.EXPECTED_MAJOR
    assert circlecollide.library_version().split(".")[0] == str(circlecollide.EXPECTED_MAJOR)
    assert circlecollide.__version__.split(".")[0] == str(circlecollide.EXPECTED_MAJOR)


def test_mismatched_major_is_refused_with_a_clear_error():
    # the real library, loaded as if these bindings had been written for the next major
    path = circlecollide.library_path()
    with pytest.raises(circlecollide.LibraryVersionError, match="need major version") as info:
        _lib.load(path, expected_major=circlecollide.EXPECTED_MAJOR + 1)
    assert path in str(info.value)
    assert isinstance(info.value, ImportError)


def test_check_version_decodes_the_number():
    _lib.check_version((1 << 16) | (4 << 8) | 2, 1)  # 1.4.2 is fine for major 1
    with pytest.raises(_lib.LibraryVersionError, match=r"version 2\.0\.7"):
        _lib.check_version((2 << 16) | 7, 1)
