#!/usr/bin/env python3
"""amalgamation_exports: the objects built from dist/circlecollide.c define, as external
symbols, exactly the cc_ functions the header declares CC_API: nothing private leaks (a
cc__ helper left non-static would be an extra), nothing public is missing.
usage: check_exports.py NM HEADER OBJECT..."""
import re
import subprocess
import sys

C_IDENT = re.compile(r"^[A-Za-z_][A-Za-z0-9_]*$")
# symbols the sanitizers' instrumentation adds to every object (ASan's odr indicators and the like)
INSTRUMENTATION = ("__asan", "__odr_asan", "__ubsan", "__sancov", "__llvm_")


def main():
    nm, header, objects = sys.argv[1], sys.argv[2], sys.argv[3:]
    with open(header, encoding="utf-8") as f:
        text = f.read()
    public = set(re.findall(r"^CC_API\b[^;{]*?\b(cc_\w+)\s*\(", text, re.M))
    if len(public) < 40:
        sys.exit("check_exports: only %d CC_API functions read from %s" % (len(public), header))
    status = 0
    for obj in objects:
        out = subprocess.run([nm, "-g", "--defined-only", obj], check=True, capture_output=True,
                             text=True).stdout
        names = set()
        for line in out.splitlines():
            parts = line.split()
            # "ADDR T name"; members of an archive are announced as "file.o:"
            if len(parts) >= 2 and len(parts[-2]) == 1:
                names.add(parts[-1])
        # names no C program can spell (DW.ref.__gxx_personality_v0 of a C++ object under ASan)
        # and the sanitizers' own are not the library's
        ours = {n for n in names if C_IDENT.match(n) and not n.startswith(INSTRUMENTATION)}
        extra, missing = sorted(ours - public), sorted(public - ours)
        print("%s: %d external names, %d public" % (obj, len(ours), len(public)))
        for n in extra:
            print("  external but not in the header: " + n)
        for n in missing:
            print("  in the header but not defined: " + n)
        if extra or missing:
            status = 1
    print("PASSED" if status == 0 else "FAILED")
    return status


if __name__ == "__main__":
    sys.exit(main())
