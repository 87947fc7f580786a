#!/usr/bin/env bash
# Measures what the generated code costs at build time: ga-core's own release build, and
# for G4, full G6 and G6 restricted to rotors and vectors: `cargo check` (expansion and
# type-checking), a release build, and the size of the expanded source.
# Usage: benches/compile-cost/run.sh   (takes a few minutes; run on an idle machine)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export CARGO_TARGET_DIR="$work/target"
# Incremental compilation would reuse the type-checking of the unchanged expansion.
export CARGO_INCREMENTAL=0

seconds() { local start end; start=$(date +%s.%N); "$@" >/dev/null 2>&1; end=$(date +%s.%N); printf '%.1f' "$(echo "$end - $start" | bc)"; }

echo "| what | seconds |"
echo "|---|---|"
CARGO_TARGET_DIR="$work/core" cargo build --release -p ga-core --features g2,g3,g4,f32,f64,batch --manifest-path "$root/Cargo.toml" >/dev/null 2>&1
touch "$root/ga-core/src/lib.rs"
echo "| ga-core release build, dependencies built | $(CARGO_TARGET_DIR="$work/core" seconds cargo build --release -p ga-core --features g2,g3,g4,f32,f64,batch --manifest-path "$root/Cargo.toml") |"

make_crate() { # name, algebra body
    mkdir -p "$work/$1/src"
    cat > "$work/$1/Cargo.toml" <<TOML
[package]
name = "$1"
version = "0.0.0"
edition = "2021"
[dependencies]
ga-macros = { path = "$root/ga-macros" }
TOML
    echo "ga_macros::algebra! { pub mod a { $2 } }" > "$work/$1/src/lib.rs"
}
make_crate g4 "metric: [1, 1, 1, 1], scalar: f64"
make_crate g6 "metric: [1, 1, 1, 1, 1, 1], scalar: f64"
make_crate g6_rotors "metric: [1, 1, 1, 1, 1, 1], scalar: f64, types: [Rotor, Vector], ops: [geometric, sandwich, reverse, norm]"
for c in g4 g6 g6_rotors; do
    (cd "$work/$c" && cargo check >/dev/null 2>&1 && cargo build --release >/dev/null 2>&1)
    touch "$work/$c/src/lib.rs"
    check=$(cd "$work/$c" && seconds cargo check)
    touch "$work/$c/src/lib.rs"
    release=$(cd "$work/$c" && seconds cargo build --release)
    size=$(cd "$work/$c" && RUSTC_BOOTSTRAP=1 cargo rustc --quiet -- -Zunpretty=expanded 2>/dev/null | wc -c)
    touch "$work/$c/src/lib.rs"
    expand=$(cd "$work/$c" && RUSTC_BOOTSTRAP=1 cargo rustc --quiet -- -Ztime-passes 2>&1 | awk '$1 == "time:" && $NF == "expand_crate" {sub(";", "", $2); print $2}')
    echo "| $c: macro expansion (rustc's expand_crate pass) | $expand |"
    echo "| $c: cargo check (expand + type-check) | $check |"
    echo "| $c: release build | $release |"
    echo "| $c: expanded source, bytes | $size |"
done
