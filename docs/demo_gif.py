"""Makes docs/demo.gif, the README's animation, from cc_demo's own PPM frames with Pillow.

    python docs/demo_gif.py CC_DEMO [--scene pool] [--seconds 6] [--out docs/demo.gif]

CC_DEMO is the built demo program (e.g. build-demo/demo/cc_demo, from `bash scripts/demo.sh`).
It renders the scene at 25 frames per simulated second (played back in real time), 480x270,
then joins the frames with one 128-colour palette shared by all of them (the demo's colours are
few: dark table, speed colours, trails), each frame stored as its change from the one before.
Needs only `pip install pillow`; the result stays under 1 MB (checked). The demo writes the same
bytes for the same command, so the GIF is reproducible.
"""

from __future__ import annotations

import argparse
import glob
import os
import subprocess
import sys
import tempfile

from PIL import Image

LIMIT = 1 << 20  # the README's budget for the animation


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("cc_demo")
    ap.add_argument("--scene", default="pool")
    ap.add_argument("--seconds", type=float, default=7.0)
    ap.add_argument("--size", default="480x270")
    ap.add_argument("--fps", type=int, default=25)  # 40 ms a frame: GIF delays are in 1/100 s
    ap.add_argument("--colors", type=int, default=128)
    ap.add_argument("--out", default=os.path.join(os.path.dirname(os.path.abspath(__file__)), "demo.gif"))
    a = ap.parse_args()
    n = int(round(a.seconds * a.fps))
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([a.cc_demo, "--scene", a.scene, "--frames", str(n), "--fps", str(a.fps), "--size", a.size,
                        "--out", tmp], check=True, stderr=subprocess.DEVNULL)
        paths = sorted(glob.glob(os.path.join(tmp, "frame_*.ppm")))
        frames = [Image.open(p).convert("RGB") for p in paths]
    # one palette for all frames, from a strip of frames spread over the run (a shared palette
    # keeps still areas the same index from frame to frame, which is what compresses)
    w, h = frames[0].size
    picks = frames[:: max(1, len(frames) // 8)]
    strip = Image.new("RGB", (w, h * len(picks)))
    for i, f in enumerate(picks):
        strip.paste(f, (0, h * i))
    palette = strip.quantize(colors=a.colors, method=Image.Quantize.MEDIANCUT)
    indexed = [f.quantize(palette=palette, dither=Image.Dither.NONE) for f in frames]
    indexed[0].save(a.out, save_all=True, append_images=indexed[1:], duration=int(round(1000 / a.fps)), loop=0,
                    optimize=True, disposal=1)
    size = os.path.getsize(a.out)
    print(f"{a.out}: {len(frames)} frames {w}x{h}, {a.colors} colours, {size / 1024:.0f} KiB")
    if size >= LIMIT:
        print(f"too big: {size} bytes >= {LIMIT} (fewer --seconds, a smaller --size or fewer --colors)")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
