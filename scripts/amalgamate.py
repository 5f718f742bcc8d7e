#!/usr/bin/env python3
"""Writes the two-file distribution: circlecollide.h (the public header) and circlecollide.c
(every library source concatenated in build order), for projects that drop two files in
instead of using CMake. Called by scripts/amalgamate.sh; usage: amalgamate.py [--out DIR].

The sources are the ones the build compiles: src/CMakeLists.txt's CC_CORE_SOURCES, then
src/world/sources.cmake's CC_WORLD_SOURCES, so a new file is picked up without touching this
script. Each source is copied with its quoted includes expanded in place:
  - a header with an include guard is copied once, at its first inclusion;
  - a template (*.inc) is copied once per precision (the precision_*.h bound before it), since
    a second copy would define the same static functions again;
  - other headers (precision_*.h, pair_templates.h) are copied at every inclusion;
  - circlecollide.h stays an #include: it is the distribution's other file.
What the separate translation units kept apart is kept apart here:
  - every private function (cc__ name, declared without static or CC_API) becomes static, and so
    does a linkage macro left empty for the shared build (#define CC__ROLL_LINK): the only
    external names are the header's cc_ functions;
  - a static name defined by more than one source gets that source's name as suffix
    (cc__align16 -> cc__align16_cluster, cc__align16_world);
  - every macro a source defines (outside a guarded header) is #undef'd after it.
"""
import argparse
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SRC = os.path.join(ROOT, "src")
INCLUDE = os.path.join(ROOT, "include")
HEADER = "circlecollide.h"


def cmake_list(path, opener):
    """The .c files of the CMake list that opens with `opener` (set(... / list(APPEND ...)."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    files = []
    for line in text[text.index(opener) + len(opener):].splitlines():
        line = line.split("#", 1)[0]
        files += [w for w in line.replace(")", " ").split() if w.endswith(".c")]
        if ")" in line:
            break
    return files


def sources():
    core = cmake_list(os.path.join(SRC, "CMakeLists.txt"), "set(CC_CORE_SOURCES")
    world_list = os.path.join(SRC, "world", "sources.cmake")
    world = cmake_list(world_list, "list(APPEND CC_WORLD_SOURCES") if os.path.exists(world_list) else []
    return core + world


INCLUDE_RE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
SYS_INCLUDE_RE = re.compile(r"^\s*#\s*include\s*<([^>]+)>")
DEFINE_RE = re.compile(r"^\s*#\s*define\s+(\w+)")
EMPTY_LINK_RE = re.compile(r"^(\s*#\s*define\s+\w+_LINK)\s*$")
# a file-scope declaration or definition of a cc__ function that has no storage class: it starts
# in column 0 with its return type (a macro such as CC__NOINLINE already says static)
PRIVATE_FN_RE = re.compile(
    r"^(?!static\b|typedef\b|return\b|extern\b|CC_API\b|CC__|CC_FN\b)"
    r"(?:const\s+)?[A-Za-z_]\w*(?:\s+[A-Za-z_]\w*)*[\s\*]+cc__\w+\s*\(")
# a static definition in a source's own text: the name before the first ( = [ or ;
STATIC_RE = re.compile(r"^(?:static\b|CC__[A-Z_]+\b)[^(=;\[]*?\b(cc__\w+)\s*[(=;\[]")
# a static definition in a template or header: static [inline] TYPE CC_FN(name)( or name(
SHARED_RE = re.compile(r"^static\b[^(=;]*?\b(?:CC_FN\((cc__\w+)\)|(cc__\w+))\s*\(")


def guarded(text):
    """True when the file is wrapped in #ifndef X / #define X."""
    lines = [l for l in text.splitlines() if l.strip() and not l.strip().startswith(("/*", "*"))]
    if len(lines) < 2:
        return False
    m = re.match(r"^\s*#\s*ifndef\s+(\w+)", lines[0])
    return bool(m) and re.match(r"^\s*#\s*define\s+" + m.group(1) + r"\b", lines[1]) is not None


class Amalgamation:
    def __init__(self):
        self.out = []
        self.seen_guarded = set()
        self.seen_inc = set()
        self.seen_sys = set()
        self.header_included = False
        self.precision = None

    def resolve(self, name, from_dir):
        for d in (from_dir, SRC, INCLUDE):
            p = os.path.normpath(os.path.join(d, name))
            if os.path.exists(p):
                return p
        sys.exit("amalgamate: cannot find %s (included from %s)" % (name, from_dir))

    def line_out(self, line):
        if EMPTY_LINK_RE.match(line):
            line = EMPTY_LINK_RE.sub(r"\1 static", line)
        elif PRIVATE_FN_RE.match(line):
            line = "static " + line
        self.out.append(line)

    def copy(self, path, defines, renames, is_guarded):
        """Copies one file, expanding its quoted includes; records its macros in `defines`
        unless the file is a guarded header (whose macros are meant for everything after it)."""
        rel = os.path.relpath(path, ROOT)
        with open(path, encoding="utf-8") as f:
            lines = f.read().splitlines()
        for line in lines:
            m = INCLUDE_RE.match(line)
            if m:
                self.include(m.group(1), os.path.dirname(path), defines)
                continue
            m = SYS_INCLUDE_RE.match(line)
            if m:
                if m.group(1) not in self.seen_sys:
                    self.seen_sys.add(m.group(1))
                    self.out.append("#include <%s>" % m.group(1))
                continue
            m = DEFINE_RE.match(line)
            if m and not is_guarded:
                defines.append(m.group(1))
            for old, new in renames.items():
                line = re.sub(r"\b%s\b" % old, new, line)
            self.line_out(line)
        return rel

    def include(self, name, from_dir, defines):
        if os.path.basename(name) == HEADER:
            if not self.header_included:
                self.header_included = True
                self.out.append('#include "%s"' % HEADER)
            return
        path = self.resolve(name, from_dir)
        rel = os.path.relpath(path, ROOT)
        base = os.path.basename(path)
        if base.startswith("precision_"):
            self.precision = None if base == "precision_end.h" else base
        with open(path, encoding="utf-8") as f:
            text = f.read()
        if path.endswith(".inc"):
            key = (path, self.precision)
            if key in self.seen_inc:
                self.out.append("/* (%s for %s: copied above) */" % (rel, self.precision))
                return
            self.seen_inc.add(key)
            self.out.append("/* ---- %s (%s) ---- */" % (rel, self.precision))
            # clang warns about an unused static inline function in the main file, never in an
            # included one: the template's helpers not every precision uses stay quiet as before
            self.out += ["#ifdef __clang__", "#pragma clang diagnostic push",
                         '#pragma clang diagnostic ignored "-Wunused-function"', "#endif"]
            self.copy(path, defines, {}, False)
            self.out += ["#ifdef __clang__", "#pragma clang diagnostic pop", "#endif"]
        elif guarded(text):
            if path in self.seen_guarded:
                return
            self.seen_guarded.add(path)
            self.out.append("/* ---- %s ---- */" % rel)
            self.copy(path, defines, {}, True)
        else:
            self.copy(path, defines, {}, False)

    def source(self, path, renames):
        rel = os.path.relpath(path, ROOT)
        self.out.append("")
        self.out.append("/* ==== %s %s */" % (rel, "=" * max(0, 90 - len(rel))))
        defines = []
        self.precision = None
        self.copy(path, defines, renames, False)
        self.precision = None
        for d in sorted(set(defines)):
            self.out.append("#undef %s" % d)


def statics(path):
    with open(path, encoding="utf-8") as f:
        return {m.group(1) for m in (STATIC_RE.match(l) for l in f.read().splitlines()) if m}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=os.path.join(ROOT, "dist"))
    args = ap.parse_args()

    files = [os.path.join(SRC, s) for s in sources()]
    stems = {}
    for f in files:
        stem = os.path.splitext(os.path.basename(f))[0]
        if stem in stems:
            sys.exit("amalgamate: two sources named %s" % stem)
        stems[stem] = f
    owners = {}
    for f in files:
        for name in statics(f):
            owners.setdefault(name, []).append(f)
    # names the templates and private headers define: a source's own static of the same name
    # (simultaneous.c's cc__v, helpers.inc's too) is renamed like a clash between two sources
    shared = set()
    for d in (SRC, os.path.join(SRC, "world")):
        for n in os.listdir(d):
            if n.endswith((".inc", ".h")):
                with open(os.path.join(d, n), encoding="utf-8") as f:
                    for l in f.read().splitlines():
                        m = SHARED_RE.match(l)
                        if m:
                            name = m.group(1) or m.group(2)
                            shared.update((name, name + "f") if m.group(1) else (name,))
    renames = {f: {} for f in files}
    for name, fs in owners.items():
        if len(fs) > 1 or name in shared:
            for f in fs:
                renames[f][name] = name + "_" + os.path.splitext(os.path.basename(f))[0]

    with open(os.path.join(INCLUDE, HEADER), encoding="utf-8") as f:
        header = f.read()
    version = ".".join(re.search(r"#define CC_VERSION_%s (\d+)" % k, header).group(1)
                       for k in ("MAJOR", "MINOR", "PATCH"))
    banner = ("/* circlecollide %s, two-file distribution written by scripts/amalgamate.sh from the\n"
              " * repository's %s. Do not edit: change the sources and run the script again. */\n")

    a = Amalgamation()
    a.out.append((banner % (version, "src/ (%d sources)" % len(files))).rstrip("\n"))
    a.out.append("/* Build: cc -std=c99 -O2 -c circlecollide.c (with circlecollide.h beside it; -lm to\n"
                 " * link). Every name outside the header's cc_ functions is static. */")
    for f in files:
        a.source(f, renames[f])

    os.makedirs(args.out, exist_ok=True)
    with open(os.path.join(args.out, "circlecollide.c"), "w", encoding="utf-8") as f:
        f.write("\n".join(a.out) + "\n")
    with open(os.path.join(args.out, HEADER), "w", encoding="utf-8") as f:
        f.write(banner % (version, "include/circlecollide.h"))
        f.write(header)
    renamed = sorted({n for r in renames.values() for n in r})
    print("amalgamate: %s/circlecollide.c (%d sources, %d lines; renamed per source: %s) and %s"
          % (os.path.relpath(args.out), len(files), len(a.out), ", ".join(renamed) or "none", HEADER))


if __name__ == "__main__":
    main()
