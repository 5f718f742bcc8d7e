#!/usr/bin/env python3
"""ABI check: abidiff between the committed baseline abi/libcirclecollide.so.<major>.abi and the
shared library just built, restricted to the types of the public header. Any difference
(abidiff exit code not 0) fails, with a hint on what to do.

usage: check_abidiff.py <source root> <path to the shared library>
Exit code 77 (ctest: skipped) when abidiff is not installed or the library has no debug
information (a Release build); abidw/abidiff need DWARF to see the types."""
import os
import re
import shutil
import subprocess
import sys

SKIP = 77


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    root, lib = sys.argv[1], sys.argv[2]
    abidiff = shutil.which("abidiff")
    if not abidiff:
        print("SKIPPED: abidiff is not installed (Debian: apt-get install abigail-tools)")
        return SKIP
    sections = subprocess.run(["readelf", "-S", "-W", lib], check=True, capture_output=True,
                              text=True).stdout
    if ".debug_info" not in sections:
        print("SKIPPED: %s has no debug information; build with -DCMAKE_BUILD_TYPE=RelWithDebInfo "
              "or Debug to compare its ABI" % lib)
        return SKIP
    with open(os.path.join(root, "include", "circlecollide.h"), encoding="utf-8") as fh:
        header = fh.read()
    major = re.search(r"^#define CC_VERSION_MAJOR (\d+)", header, flags=re.M).group(1)
    baseline = os.path.join(root, "abi", "libcirclecollide.so.%s.abi" % major)
    hint = ("The ABI baseline must change only together with the version (abi/README.md):\n"
            "  - unintended change: fix the code or header so that abidiff is clean again;\n"
            "  - added functions or fields at the end of a struct that has struct_size: bump\n"
            "    CC_VERSION_MINOR in include/circlecollide.h, then run abi/update.sh and commit\n"
            "    the new abi/libcirclecollide.so.%s.abi;\n"
            "  - anything else (removed or changed functions, changed types or layout): bump\n"
            "    CC_VERSION_MAJOR (a new SONAME), then run abi/update.sh." % major)
    if not os.path.exists(baseline):
        print("FAIL: no baseline %s for major version %s.\n%s" % (baseline, major, hint))
        return 1
    cmd = [abidiff, "--headers-dir2", os.path.join(root, "include"), baseline, lib]
    print("$ " + " ".join(cmd))
    res = subprocess.run(cmd, capture_output=True, text=True)
    sys.stdout.write(res.stdout + res.stderr)
    if res.returncode != 0:
        print("FAIL: abidiff exit code %d (bits: 1 error, 2 usage, 4 ABI change, 8 incompatible "
              "change)\n%s" % (res.returncode, hint))
        return 1
    print("OK: the ABI of %s equals the baseline abi/%s"
          % (os.path.basename(lib), os.path.basename(baseline)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
