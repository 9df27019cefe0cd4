#!/usr/bin/env bash
# SPDX-License-Identifier: EPL-2.0
#
# Builds the ROS 2 test node written on ros2-client (examples/sut/ros2/rust_nav_node: a navigation node on RustDDS,
# a ROS 2 implementation independent of the Cyclone DDS REI's bridge uses) with cargo, from crates.io, and prints
# the path of its binary on the last line. The ROS 2 bridge's tests (tests/ros/test_ros2_bridge.py) run it as the
# system under test; it is a test node, not part of REI's Python package or jars.
#
# The crates are the unmodified releases pinned in the crate's Cargo.lock (`--locked`); ros2-client and RustDDS
# are Apache-2.0, the rest Apache-2.0 or MIT (docs/ros.md). The build goes to a folder outside the clone,
# ~/.cache/rei/cargo-target, so a CI re-run reuses the compiled dependencies: the first build takes about two
# minutes on two cores (its time is printed), a rebuild of the node alone seconds, an up-to-date one nothing.
# A debug build: it compiles faster than a release one, and the node's step is not what the tests measure.
#
# Needs: cargo and rustc (1.88 or newer, ros2-client's minimum), and crates.io for the first build.
#
# Environment:
#   REI_CARGO_TARGET_DIR  cargo's target folder instead of ~/.cache/rei/cargo-target
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
crate="$root/examples/sut/ros2/rust_nav_node"
target="${REI_CARGO_TARGET_DIR:-${XDG_CACHE_HOME:-$HOME/.cache}/rei/cargo-target}"
binary="$target/debug/rei-ros2-nav-node"

say() { echo "setup-ros2-node: $*" >&2; }

if ! command -v cargo >/dev/null 2>&1; then
    say "error: cargo not found: install Rust 1.88 or newer (https://rustup.rs or your distribution's rustc and cargo)"
    exit 1
fi
mkdir -p "$target"
first=""
[ -x "$binary" ] || first=" (first build: the dependencies compile once)"
say "building $crate with $(cargo --version) into $target$first"
started=$SECONDS
cargo build --locked --quiet --manifest-path "$crate/Cargo.toml" --target-dir "$target" >&2
say "built in $((SECONDS - started)) s"
echo "$binary"
