#!/usr/bin/env bash
# The README's first command: builds the library and the headless demo (cc_demo) in build-demo/
# and renders the pool break into frames/pool/ as PPM frames, then says how to make a video or
# a GIF of them. Needs a C compiler and CMake only. Other scenes: pass cc_demo's options, e.g.
#   scripts/demo.sh --scene tunnel --frames 120 --out frames/tunnel
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root"
build=build-demo
gen=()
if [ ! -f "$build/CMakeCache.txt" ] && command -v ninja >/dev/null; then gen=(-G Ninja); fi
echo "building cc_demo in $build/ ..."
cmake -S . -B "$build" "${gen[@]}" -DCMAKE_BUILD_TYPE=Release -DCC_BUILD_TESTS=OFF \
  -DCC_BUILD_BENCH=OFF -DCC_BUILD_DEMO=ON >/dev/null
cmake --build "$build" --target cc_demo -j "${CC_JOBS:-2}" >/dev/null

if [ $# -eq 0 ]; then
  set -- --scene pool --frames 150 --out frames/pool
fi
"$build/demo/cc_demo" "$@"

# the folder the frames went to, and the frame rate, from the arguments
out=frames/pool fps=60
while [ $# -gt 1 ]; do
  case $1 in
    --out) out=$2 ;;
    --fps) fps=$2 ;;
  esac
  shift
done
echo
echo "frames: $out/frame_0000.ppm ..."
if command -v ffmpeg >/dev/null; then
  echo "video:  ffmpeg -framerate $fps -i $out/frame_%04d.ppm -pix_fmt yuv420p -vf 'pad=ceil(iw/2)*2:ceil(ih/2)*2' demo.mp4"
else
  echo "video:  install ffmpeg, then: ffmpeg -framerate $fps -i $out/frame_%04d.ppm -pix_fmt yuv420p demo.mp4"
fi
if command -v magick >/dev/null; then
  echo "GIF:    magick -delay 2 -loop 0 '$out/frame_*.ppm' -layers Optimize demo.gif"
elif command -v convert >/dev/null; then
  echo "GIF:    convert -delay 2 -loop 0 '$out/frame_*.ppm' -layers Optimize demo.gif"
else
  echo "GIF:    install ImageMagick, then: convert -delay 2 -loop 0 '$out/frame_*.ppm' demo.gif"
fi
