#!/usr/bin/env bash
# Static estimates of the emitted loops on Intel and AMD cores (BENCHMARKS.md, issue 7):
# release assembly of one-item loops, each loop body through llvm-mca for Skylake and Zen 3.
# Needs llvm-mca (Debian: apt-get install llvm-14). Prints cycles per iteration.
set -euo pipefail
cd "$(dirname "$0")"
target=$(mktemp -d)
CARGO_TARGET_DIR="$target" cargo rustc --release --quiet -- --emit asm
python3 mca.py "$target"/release/deps/ga_mca-*.s skylake,znver3
# The slice kernels are compiled in ga-core itself: its assembly, the AVX2 copies.
CARGO_TARGET_DIR="$target" cargo rustc --release --quiet -p ga-core -- --emit asm
python3 mca.py "$target"/release/deps/ga_core-*.s skylake,icelake-server,znver3 kernels
rm -rf "$target"
