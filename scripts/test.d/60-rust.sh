#!/usr/bin/env bash
# CI step: the Rust bindings. circlecollide-sys's build script compiles the C library with CMake
# (the `cmake` crate); `cargo test` runs the ABI checks against the header, the safe wrapper's
# tests and doc tests; then the example program runs once.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-$root/build/rust}
cd "$root/bindings/rust"
cargo test --locked -j2
cargo run --locked -j2 -q --example billiards > "$CARGO_TARGET_DIR/billiards.txt"
tail -n 3 "$CARGO_TARGET_DIR/billiards.txt"
