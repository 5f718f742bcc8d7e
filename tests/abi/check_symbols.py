#!/usr/bin/env python3
"""Symbol check of the shared library: it exports exactly the CC_API functions declared in the
public header, each under the version node CIRCLECOLLIDE_<major>, and its SONAME is
libcirclecollide.so.<major>, with <major> = CC_VERSION_MAJOR of the header.

usage: check_symbols.py <include/circlecollide.h> <path to the shared library>
Uses readelf (binutils). Exit code 0 when all holds, 1 otherwise (with the reasons)."""
import re
import subprocess
import sys


def declared_functions(header_text):
    """Names of the functions declared with CC_API (comments and preprocessor lines removed, so
    that the CC_API definitions themselves do not count)."""
    text = re.sub(r"/\*.*?\*/", " ", header_text, flags=re.S)
    text = re.sub(r"//[^\n]*", " ", text)
    text = "\n".join(l for l in text.splitlines() if not l.lstrip().startswith("#"))
    names = set()
    for decl in re.findall(r"\bCC_API\b([^;{]*)", text):
        m = re.search(r"\b(cc_[A-Za-z0-9_]*)\s*\(", decl)
        if m:
            names.add(m.group(1))
    return names


def header_major(header_text):
    m = re.search(r"^#define CC_VERSION_MAJOR (\d+)", header_text, flags=re.M)
    if not m:
        sys.exit("check_symbols: no CC_VERSION_MAJOR in the header")
    return int(m.group(1))


def readelf(*args):
    return subprocess.run(["readelf", "-W", *args], check=True, capture_output=True,
                          text=True).stdout


def dynamic_symbols(lib):
    """(name, version, type, section index) of every defined global or weak dynamic symbol."""
    out = []
    for line in readelf("--dyn-syms", lib).splitlines():
        f = line.split()
        # Num: Value Size Type Bind Vis Ndx Name
        if len(f) < 8 or not f[0].endswith(":") or f[4] not in ("GLOBAL", "WEAK"):
            continue
        if f[6] == "UND":
            continue
        name, _, version = f[7].partition("@")
        out.append((name, version.lstrip("@"), f[3], f[6]))
    return out


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    header, lib = sys.argv[1], sys.argv[2]
    with open(header, encoding="utf-8") as fh:
        text = fh.read()
    major = header_major(text)
    node = "CIRCLECOLLIDE_%d" % major
    declared = declared_functions(text)
    errors = []

    exported = {}
    for name, version, kind, ndx in dynamic_symbols(lib):
        if name == node and kind == "OBJECT" and ndx == "ABS":
            continue  # the version node's own symbol
        exported[name] = (version, kind)
        if kind != "FUNC":
            errors.append("%s is exported as %s, not a function" % (name, kind))
        if version != node:
            errors.append("%s has version '%s', expected %s" % (name, version, node))
    for name in sorted(set(exported) - declared):
        errors.append("exported but not declared CC_API in the header: %s" % name)
    for name in sorted(declared - set(exported)):
        errors.append("declared CC_API in the header but not exported: %s" % name)

    m = re.search(r"\(SONAME\)\s+Library soname: \[([^\]]+)\]", readelf("-d", lib))
    soname = m.group(1) if m else None
    if soname != "libcirclecollide.so.%d" % major:
        errors.append("SONAME is %s, expected libcirclecollide.so.%d (CC_VERSION_MAJOR)"
                      % (soname, major))

    print("header: %d CC_API functions; library: %d exported functions, SONAME %s, version node %s"
          % (len(declared), len(exported), soname, node))
    if errors:
        print("FAIL:\n  " + "\n  ".join(errors))
        return 1
    print("OK: the library exports exactly the functions of the header")
    return 0


if __name__ == "__main__":
    sys.exit(main())
