#!/usr/bin/env python3
"""The figures of README.md and docs/WEB.md that a tool prints, checked against (or written from)
what the tools print now, so that no such figure is kept by hand.

A figure in the text is marked <!--fig NAME-->VALUE<!--/fig--> (invisible when rendered), NAME
optionally followed by :FORMAT (below). Its value comes from:

  wasm.*       build/wasm/figures.txt, written by `scripts/wasm.sh --sizes` (module sizes)
  web.*        build/web/figures.txt, written by tests/web/browser_test.py (the CI run's shots)
  build.*      build/figures.txt, written by CMake's configure (tests against the amalgamation)
  demo.*       a run of cc_demo (build/demo/cc_demo) of the pool scene, made here: scripts/demo.sh's
               default frames, and a run to rest
  header.*     include/circlecollide.h itself (its CC_API functions)
  file.*       files of the repository (lines of a source, frames and KiB of docs/demo.gif)

FORMAT: `n` thousands separators (218,004), `kib` KiB rounded (213), `1` one decimal, `int`.

  python3 scripts/doc_figures.py --check    # exit 1 and the differences when a figure is stale
  python3 scripts/doc_figures.py --update   # write the figures into the text

Options: --build DIR (build), --wasm DIR (build/wasm), --web DIR (build/web). CI runs --check in
scripts/test.d/80-doc-figures.sh, after the steps that write the figure files."""
import argparse
import os
import re
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DOCS = ["README.md", os.path.join("docs", "WEB.md")]
MARK = re.compile(r"<!--fig ([\w.:/-]+)-->(.*?)<!--/fig-->", re.S)


def read_figures(path):
    """`name value` lines; a missing file gives nothing (its figures are reported missing)."""
    out = {}
    if os.path.exists(path):
        with open(path) as f:
            for line in f:
                parts = line.split(None, 1)
                if len(parts) == 2:
                    out[parts[0]] = parts[1].strip()
    return out


def gif_frames(path):
    """The number of images in a GIF (its image descriptors, walking the blocks)."""
    with open(path, "rb") as f:
        b = f.read()
    i, frames = 13, 0
    if b[10] & 0x80:
        i += 3 << ((b[10] & 7) + 1)  # the global colour table
    while i < len(b):
        if b[i] == 0x3B:  # trailer
            break
        if b[i] == 0x21:  # an extension: label, then sub-blocks
            i += 2
        elif b[i] == 0x2C:  # an image: descriptor, local table, LZW minimum size, sub-blocks
            frames += 1
            flags = b[i + 9]
            i += 10 + ((3 << ((flags & 7) + 1)) if flags & 0x80 else 0) + 1
        else:
            raise ValueError("%s: not a GIF block at byte %d" % (path, i))
        while b[i]:
            i += b[i] + 1
        i += 1
    return frames


def demo_figures(build):
    """cc_demo's pool scene: scripts/demo.sh's default run (the frames it writes and what they
    end on), and a run long enough to rest (when the last ball stops, how many were potted).
    At 64x36 pixels: the physics does not depend on the frame size, the run takes a second."""
    exe = os.path.join(build, "demo", "cc_demo")
    with open(os.path.join(ROOT, "scripts", "demo.sh")) as f:
        frames = int(re.search(r"--scene pool --frames (\d+)", f.read()).group(1))
    out = {"demo.pool.frames": str(frames)}
    with tempfile.TemporaryDirectory() as tmp:
        for n, key in ((frames, "default"), (1200, "rest")):
            run = subprocess.run([exe, "--scene", "pool", "--frames", str(n), "--size", "64x36", "--out", tmp],
                                 capture_output=True, text=True, check=True)
            text = run.stderr
            out["demo.pool.%s.time" % key] = re.search(r"world time ([0-9.]+)", text).group(1)
            out["demo.pool.%s.potted" % key] = re.search(r"pocketed: (\d+) of", text).group(1)
            rolling = re.search(r"(\d+) still rolling", text)
            out["demo.pool.%s.rolling" % key] = rolling.group(1) if rolling else "0"
            rest = re.search(r"every ball at rest \(the last one still moved at the frame of t = ([0-9.]+) s\)", text)
            if rest:
                out["demo.pool.%s.rest_time" % key] = rest.group(1)
                out["demo.pool.%s.rest_frames" % key] = str(int(round(float(rest.group(1)) * 60)) + 2)
    return out


def local_figures():
    out = {}
    with open(os.path.join(ROOT, "include", "circlecollide.h")) as f:
        out["header.functions"] = str(len(re.findall(r"^CC_API[^;{(]*\b(cc_[a-z0-9_]*)\(", f.read(), flags=re.M)))
    with open(os.path.join(ROOT, "demo", "web", "circlecollide.js")) as f:
        out["file.circlecollide_js.lines"] = str(len(f.read().splitlines()))
    gif = os.path.join(ROOT, "docs", "demo.gif")
    out["file.demo_gif.frames"] = str(gif_frames(gif))
    out["file.demo_gif.bytes"] = str(os.path.getsize(gif))
    return out


def formatted(value, fmt):
    if fmt is None:
        return value
    x = float(value)
    if fmt == "n":
        return "{:,}".format(int(x))
    if fmt == "kib":
        return str(int(round(x / 1024)))
    if fmt == "1":
        return "%.1f" % x
    if fmt == "int":
        return str(int(round(x)))
    raise ValueError("unknown figure format %r" % fmt)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    mode = ap.add_mutually_exclusive_group(required=True)
    mode.add_argument("--check", action="store_true")
    mode.add_argument("--update", action="store_true")
    ap.add_argument("--build", default=os.path.join(ROOT, "build"))
    ap.add_argument("--wasm", default=None)
    ap.add_argument("--web", default=None)
    args = ap.parse_args()
    figures = {}
    figures.update(read_figures(os.path.join(args.wasm or os.path.join(args.build, "wasm"), "figures.txt")))
    figures.update(read_figures(os.path.join(args.web or os.path.join(args.build, "web"), "figures.txt")))
    figures.update(read_figures(os.path.join(args.build, "figures.txt")))
    figures.update(local_figures())
    if os.path.exists(os.path.join(args.build, "demo", "cc_demo")):
        figures.update(demo_figures(args.build))
    stale, missing, count = [], [], 0
    for doc in DOCS:
        path = os.path.join(ROOT, doc)
        with open(path) as f:
            text = f.read()

        def put(m):
            nonlocal count
            count += 1
            name, _, fmt = m.group(1).partition(":")
            if name not in figures:
                missing.append("%s: %s (no tool has printed it here)" % (doc, name))
                return m.group(0)
            want = formatted(figures[name], fmt or None)
            if m.group(2) != want:
                stale.append("%s: %s is %r in the text, %r now" % (doc, m.group(1), m.group(2), want))
            return "<!--fig %s-->%s<!--/fig-->" % (m.group(1), want)

        new = MARK.sub(put, text)
        if args.update and new != text:
            with open(path, "w") as f:
                f.write(new)
    for line in missing + stale:
        print(line)
    if args.update:
        print("doc_figures: %d figures, %d written anew, %d with no value here" % (count, len(stale), len(missing)))
        return 1 if missing else 0
    if stale or missing:
        print("doc_figures: %d of %d figures stale or missing: run the tools (scripts/wasm.sh --sizes, "
              "scripts/test.d/70-web.sh, a configure of build/), then python3 scripts/doc_figures.py --update"
              % (len(stale) + len(missing), count))
        return 1
    print("doc_figures: all %d figures of %s agree with what the tools print" % (count, ", ".join(DOCS)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
