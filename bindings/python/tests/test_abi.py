"""The ctypes declarations agree with include/circlecollide.h (when the source tree is here).

Field names and C types of every struct, and the name and argument types of every CC_API
function, are parsed from the header and compared with circlecollide._lib; where a C compiler is
at hand, the size of every struct and the offset and size of every field are compiled from the
header and compared with ctypes'. The struct_size handshakes are checked against the loaded
library itself (header or not): 1.0 declarations under a 1.1 library let cc_world_def_init
write past the end of the binding's def, which crashed the interpreter.
"""

import ctypes
import os
import re
import shutil
import subprocess

import pytest

from circlecollide import _lib

HEADER = os.environ.get("CIRCLECOLLIDE_HEADER") or os.path.join(
    os.path.dirname(__file__), "..", "..", "..", "include", "circlecollide.h"
)
needs_header = pytest.mark.skipif(not os.path.exists(HEADER), reason="the C header is not reachable")

C_TYPES = {
    "double": ctypes.c_double,
    "float": ctypes.c_float,
    "int": ctypes.c_int,
    "size_t": ctypes.c_size_t,
    "uint64_t": ctypes.c_uint64,
    "uint32_t": ctypes.c_uint32,
    "unsigned": ctypes.c_uint,
    "void*": ctypes.c_void_p,
    "double*": ctypes.POINTER(ctypes.c_double),
    "cc_contact_fn": _lib.cc_contact_fn,
    "cc_sensor_fn": _lib.cc_sensor_fn,
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


@needs_header
def test_every_struct_matches_field_for_field():
    structs = header_structs()
    assert len(structs) >= 16
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
    "uint32_t": ctypes.c_uint32,
    "unsigned": ctypes.c_uint,
    "uint64_t": ctypes.c_uint64,
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


@needs_header
def test_every_function_is_declared_with_the_header_types():
    decls = re.findall(r"CC_API\s+([\w\s\*]+?)\s*(cc_\w+)\s*\(([^)]*)\)\s*;", header_text())
    names = {n for _, n, _ in decls}
    assert len(names) >= 39
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


def compiled_layout(structs):
    """{struct: (sizeof, {field: (offset, size)})} as the C compiler lays out the header's structs."""
    cc = os.environ.get("CC") or shutil.which("cc") or shutil.which("gcc") or shutil.which("clang")
    if not cc:
        pytest.skip("no C compiler to compile the header's layout")
    lines = ["#include <stdio.h>", "#include <stddef.h>", '#include "circlecollide.h"', "int main(void) {"]
    for name, fields in structs.items():
        lines.append(f'    printf("{name} - %lu 0\\n", (unsigned long)sizeof({name}));')
        for fname, _ in fields:
            lines.append(
                f'    printf("{name} {fname} %lu %lu\\n", (unsigned long)offsetof({name}, {fname}), '
                f"(unsigned long)sizeof((({name} *)0)->{fname}));"
            )
    lines += ["    return 0;", "}"]
    work = os.path.join(os.environ.get("TMPDIR", "/tmp"), f"cc_layout_{os.getpid()}")
    os.makedirs(work, exist_ok=True)
    src, exe = os.path.join(work, "layout.c"), os.path.join(work, "layout")
    with open(src, "w") as f:
        f.write("\n".join(lines) + "\n")
    subprocess.run([cc, "-std=c99", "-I", os.path.dirname(os.path.abspath(HEADER)), src, "-o", exe], check=True)
    out = {}
    for line in subprocess.run([exe], check=True, capture_output=True, text=True).stdout.splitlines():
        name, field, a, b = line.split()
        size, fields = out.setdefault(name, [0, {}])
        if field == "-":
            out[name][0] = int(a)
        else:
            fields[field] = (int(a), int(b))
    return out


@needs_header
def test_every_struct_has_the_compiled_size_and_offsets():
    structs = header_structs()
    layout = compiled_layout(structs)
    assert set(layout) == set(structs)
    for name, (size, fields) in layout.items():
        py = getattr(_lib, name)
        assert ctypes.sizeof(py) == size, f"sizeof({name})"
        for fname, (offset, fsize) in fields.items():
            f = getattr(py, fname)
            assert (f.offset, f.size) == (offset, fsize), f"{name}.{fname}"


def test_world_def_init_writes_exactly_our_def():
    # cc_world_def_init_sized fills our def as we declared it (the same minor version: every field
    # known), and the exported cc_world_def_init, which a 1.0 program calls, writes 1.0's def only
    d, lib_size = _lib.world_def_defaults()
    assert lib_size == ctypes.sizeof(_lib.cc_world_def)
    assert d.struct_size == ctypes.sizeof(_lib.cc_world_def)
    # max_events 0: a 1.2 def's automatic cap (a 1.0 def keeps 10,000,000, below)
    assert (d.max_circles, d.restitution, d.max_events, d.restitution_mix) == (64, 1.0, 0, _lib.MIX_MIN)
    assert (d.rolling_decel, d.period.x, d.period.y) == (0.0, 0.0, 0.0)
    assert not d.on_contact and not d.on_sensor
    # and the library writes nothing beyond that size
    room = (ctypes.c_ubyte * (ctypes.sizeof(_lib.cc_world_def) + 256))(*([0xA5] * (ctypes.sizeof(_lib.cc_world_def) + 256)))
    _lib.lib.cc_world_def_init_sized(ctypes.cast(room, ctypes.POINTER(_lib.cc_world_def)), ctypes.sizeof(_lib.cc_world_def))
    assert bytes(room[ctypes.sizeof(_lib.cc_world_def):]) == b"\xa5" * 256
    # the 1.0 symbol: 1.0's def (up to `user`), nothing after it
    end_1_0 = _lib.field_end(_lib.cc_world_def, "user")
    room = (ctypes.c_ubyte * (ctypes.sizeof(_lib.cc_world_def) + 256))(*([0xA5] * (ctypes.sizeof(_lib.cc_world_def) + 256)))
    _lib.lib.cc_world_def_init(ctypes.cast(room, ctypes.POINTER(_lib.cc_world_def)))
    assert _lib.cc_world_def.from_buffer_copy(room).struct_size == end_1_0
    assert _lib.cc_world_def.from_buffer_copy(room).max_events == 10000000
    assert bytes(room[end_1_0:]) == b"\xa5" * (len(room) - end_1_0)


@pytest.mark.parametrize(
    "struct, getter",
    [
        ("cc_world_stats", lambda w, p: _lib.lib.cc_world_get_stats(w, p)),
        ("cc_circle_props", lambda w, p: _lib.lib.cc_world_get_circle_props(w, 0, p)),
        ("cc_segment_props", lambda w, p: _lib.lib.cc_world_get_segment_props(w, 0, p)),
    ],
)
def test_the_library_fills_no_field_beyond_ours(struct, getter):
    # a getter given a struct_size larger than ours fills only the whole fields it knows: the
    # bytes past our struct stay as they were when the library has no more fields than we do
    from circlecollide import Circle, World

    w = World(max_circles=2, max_segments=1)
    w.add_circle(Circle((0, 0), (1, 0), 1))
    w.add_segment((5, -1), (5, 1))
    n = ctypes.sizeof(getattr(_lib, struct))
    room = (ctypes.c_uint64 * ((n + 256) // 8))(*([0xA5A5A5A5A5A5A5A5] * ((n + 256) // 8)))
    ctypes.cast(room, ctypes.POINTER(ctypes.c_size_t))[0] = n + 256
    assert getter(w._w, ctypes.cast(room, ctypes.POINTER(getattr(_lib, struct)))) == 0
    assert bytes(room)[n:] == b"\xa5" * (len(bytes(room)) - n)
    assert bytes(room)[8:n] != b"\xa5" * (n - 8)
