"""The ctypes declarations agree with include/circlecollide.h (when the source tree is here).

Field names and C types of every struct, and the name and argument count of every CC_API
function, are parsed from the header and compared with circlecollide._lib.
"""

import ctypes
import os
import re

import pytest

from circlecollide import _lib

HEADER = os.environ.get("CIRCLECOLLIDE_HEADER") or os.path.join(
    os.path.dirname(__file__), "..", "..", "..", "include", "circlecollide.h"
)
pytestmark = pytest.mark.skipif(not os.path.exists(HEADER), reason="the C header is not reachable")

C_TYPES = {
    "double": ctypes.c_double,
    "float": ctypes.c_float,
    "int": ctypes.c_int,
    "size_t": ctypes.c_size_t,
    "uint64_t": ctypes.c_uint64,
    "void*": ctypes.c_void_p,
    "double*": ctypes.POINTER(ctypes.c_double),
    "cc_contact_fn": _lib.cc_contact_fn,
}


def header_text():
    with open(HEADER) as f:
        text = f.read()
    return re.sub(r"/\*.*?\*/", "", text, flags=re.S)


def header_structs():
    out = {}
    for body, name in re.findall(r"typedef struct \w+ \{(.*?)\}\s*(\w+);", header_text(), flags=re.S):
        fields = []
        for decl in body.split(";"):
            decl = " ".join(decl.split()).replace("const ", "")
            if not decl:
                continue
            m = re.match(r"([\w ]+?)\s*((?:\*?\s*\w+\s*,\s*)*\*?\s*\w+)$", decl)
            ctype = m.group(1)
            for var in m.group(2).split(","):
                var = var.strip()
                ptr = var.startswith("*")
                fields.append((var.lstrip("* "), ctype + ("*" if ptr else "")))
        out[name] = fields
    return out


def test_every_struct_matches_field_for_field():
    structs = header_structs()
    assert len(structs) >= 12
    for name, fields in structs.items():
        py = getattr(_lib, name)
        assert [f[0] for f in py._fields_] == [f[0] for f in fields], name
        for (fname, ctype), (_, pytype) in zip(fields, py._fields_):
            expected = getattr(_lib, ctype, None) or C_TYPES[ctype]
            assert pytype is expected or ctypes.sizeof(pytype) == ctypes.sizeof(expected) and (
                pytype.__name__ == expected.__name__
            ), f"{name}.{fname}: {ctype}"


SCALARS = {
    "double": ctypes.c_double,
    "float": ctypes.c_float,
    "int": ctypes.c_int,
    "unsigned": ctypes.c_uint,
    "long": ctypes.c_long,
    "size_t": ctypes.c_size_t,
    "void": None,
}


def expected_ctype(c: str):
    """The ctypes type that stands for the C type c ("const cc_circle*", "double", ...)."""
    c = c.replace("const ", "").replace(" ", "")
    if c in ("char*",):
        return ctypes.c_char_p
    if c in ("void*", "cc_world*"):  # the world is opaque: a void pointer
        return ctypes.c_void_p
    if c.endswith("*"):
        base = c[:-1]
        return ctypes.POINTER(SCALARS.get(base) or getattr(_lib, base))
    return SCALARS[c] if c in SCALARS else getattr(_lib, c)


def test_every_function_is_declared_with_the_header_types():
    decls = re.findall(r"CC_API\s+([\w\s\*]+?)\s*(cc_\w+)\s*\(([^)]*)\)\s*;", header_text())
    names = {n for _, n, _ in decls}
    assert len(names) >= 30
    assert names == set(_lib.PROTOTYPES), names ^ set(_lib.PROTOTYPES)
    for ret, name, args in decls:
        restype, argtypes = _lib.PROTOTYPES[name]
        ret = ret.strip()
        stars = ""
        while ret.endswith("*"):
            ret, stars = ret[:-1].strip(), stars + "*"
        assert restype is expected_ctype(ret + stars), f"return type of {name}"
        params = [] if args.strip() in ("", "void") else [" ".join(a.split()) for a in args.split(",")]
        want = []
        for p in params:
            p = p.replace("*", " * ")
            words = p.split()[:-1]  # drop the parameter's name
            want.append(expected_ctype(" ".join(words).replace(" *", "*")))
        assert argtypes == want, f"argument types of {name}"
