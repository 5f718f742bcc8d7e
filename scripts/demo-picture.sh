#!/usr/bin/env bash
# Remakes docs/demo.png, the README's picture, from cc_demo's own frames: four scenes at 640x360
# put 2 x 2 and reduced to 256 colours (about 130 KB). Needs ImageMagick (montage, convert); CI
# does not run this. Builds cc_demo in build-demo/ through scripts/demo.sh's build step.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
cmake -S . -B build-demo -DCMAKE_BUILD_TYPE=Release -DCC_BUILD_TESTS=OFF -DCC_BUILD_BENCH=OFF \
  -DCC_BUILD_DEMO=ON >/dev/null
cmake --build build-demo --target cc_demo -j "${CC_JOBS:-2}" >/dev/null
tmp=build-demo/picture
rm -rf "$tmp"
demo=build-demo/demo/cc_demo
# the frame of each scene that shows it best: the break just after the impact, the three
# modes once the fast bullets have had time to escape, a mallet's hit, a gas after a second
"$demo" --scene pool --frames 17 --out "$tmp/pool" 2>/dev/null
"$demo" --scene tunnel --frames 70 --out "$tmp/tunnel" 2>/dev/null
"$demo" --scene air-hockey --frames 45 --out "$tmp/air-hockey" 2>/dev/null
"$demo" --scene gas --frames 61 --out "$tmp/gas" 2>/dev/null
montage "$tmp/pool/frame_0016.ppm" "$tmp/tunnel/frame_0069.ppm" "$tmp/air-hockey/frame_0044.ppm" \
  "$tmp/gas/frame_0060.ppm" -tile 2x2 -geometry 400x225+2+2 -background '#0e1018' "$tmp/all.png"
convert "$tmp/all.png" -colors 256 PNG8:docs/demo.png
ls -l docs/demo.png
