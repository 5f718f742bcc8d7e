#!/usr/bin/env bash
# CI step: the Rust bindings. `cargo fmt --check` (rustfmt.toml) and `cargo clippy -D warnings`
# first; circlecollide-sys's build script compiles the C library with CMake (the `cmake` crate);
# `cargo test` runs the ABI checks against the header, the safe wrapper's tests and doc tests;
# then the example program runs once.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
export CARGO_TARGET_DIR=${CARGO_TARGET_DIR:-$root/build/rust}
cd "$root/bindings/rust"
# rustfmt and clippy: the toolchain's components, installed by rustup when it lacks them
for c in rustfmt clippy; do
  rustup component list --installed 2>/dev/null | grep -q "^$c" || rustup component add "$c"
done
cargo fmt --check
cargo clippy --locked -j2 --all-targets -- -D warnings
cargo test --locked -j2
cargo run --locked -j2 -q --example billiards > "$CARGO_TARGET_DIR/billiards.txt"
tail -n 3 "$CARGO_TARGET_DIR/billiards.txt"
