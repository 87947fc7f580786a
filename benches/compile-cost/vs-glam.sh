#!/usr/bin/env bash
# Clean release builds of two small user crates side by side, in the same run: one that
# uses only G3 in f64 from ga-core, one that uses only glam (the version ga-core's `glam`
# feature converts to). Then ga-core's own time with every feature on. Each build runs
# `runs` times (default 2) in a fresh target directory; the minimum is reported, since
# the cores may be shared. Per-crate times come from `cargo build --timings`.
# Usage: benches/compile-cost/vs-glam.sh [runs]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
runs=${1:-2}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export CARGO_INCREMENTAL=0

mkdir -p "$work/ga/src" "$work/glam/src"
cat > "$work/ga/Cargo.toml" <<TOML
[package]
name = "user-ga"
version = "0.0.0"
edition = "2021"
[workspace]
[dependencies]
ga-core = { path = "$root/ga-core", default-features = false, features = ["std", "g3", "f64"] }
TOML
cat > "$work/ga/src/main.rs" <<'RS'
use ga_core::f64::g3::*;
fn main() {
    let r = (Bivector::E12 * -0.3).exp();
    println!("{:?}", r.sandwich(Vector::new(1.0, 2.0, 3.0)));
}
RS
cat > "$work/glam/Cargo.toml" <<'TOML'
[package]
name = "user-glam"
version = "0.0.0"
edition = "2021"
[workspace]
[dependencies]
glam = "0.32"
TOML
cat > "$work/glam/src/main.rs" <<'RS'
fn main() {
    let q = glam::DQuat::from_rotation_z(0.6);
    println!("{:?}", q * glam::DVec3::new(1.0, 2.0, 3.0));
}
RS
# The lock files of the workspace pin the same versions the user crates get.
cp "$root/Cargo.lock" "$work/ga/Cargo.lock"

seconds() { local start end; start=$(date +%s.%N); "$@" >/dev/null 2>&1; end=$(date +%s.%N); echo "$end - $start" | bc; }
# The duration of one unit from the newest --timings report: `unit_time <target> <crate>`.
unit_time() {
    local html
    html=$(ls -t "$1"/cargo-timings/cargo-timing-*.html | head -1)
    python3 - "$html" "$2" <<'PY'
import json, re, sys
text = open(sys.argv[1]).read()
data = json.loads(re.search(r"const UNIT_DATA = (\[.*?\]);\n", text, re.S).group(1))
print(round(sum(u["duration"] for u in data if u["name"] == sys.argv[2]), 2))
PY
}
min() { printf '%s\n' "$@" | sort -g | head -1; }
# CPU seconds of every rustc run of one build, from the wrapper's log: total and per crate.
export RUSTC_WRAPPER="$root/benches/compile-cost/rustc-cpu.py"
cpu_total() { awk '{s += $2} END {printf "%.2f", s}' "$1"; }
cpu_of() { awk -v c="$2" '$1 == c {s += $2} END {printf "%.2f", s}' "$1"; }

declare -A best
record() { # key value
    if [[ -z "${best[$1]:-}" ]]; then best[$1]=$2; else best[$1]=$(min "${best[$1]}" "$2"); fi
}
for _ in $(seq "$runs"); do
    for c in ga glam; do
        t="$work/target-$c"
        rm -rf "$t"
        export RUSTC_CPU_LOG="$work/cpu-$c.log"
        rm -f "$RUSTC_CPU_LOG"
        total=$(cd "$work/$c" && CARGO_TARGET_DIR="$t" seconds cargo build --release --timings)
        record "$c total" "$total"
        record "$c cpu total" "$(cpu_total "$RUSTC_CPU_LOG")"
        for u in syn proc_macro2 quote ga_macros ga_core glam; do
            record "$c cpu $u" "$(cpu_of "$RUSTC_CPU_LOG" "$u")"
        done
        if [[ $c == ga ]]; then
            for u in syn proc-macro2 quote ga-macros ga-core; do record "ga $u" "$(unit_time "$t" "$u")"; done
        else
            record "glam glam" "$(unit_time "$t" glam)"
        fi
    done
    t="$work/target-all"
    rm -rf "$t"
    export RUSTC_CPU_LOG="$work/cpu-all.log"
    rm -f "$RUSTC_CPU_LOG"
    (cd "$root" && CARGO_TARGET_DIR="$t" cargo build --release --timings -p ga-core --all-features >/dev/null 2>&1)
    record "all cpu ga_core" "$(cpu_of "$RUSTC_CPU_LOG" ga_core)"
    record "all cpu glam" "$(cpu_of "$RUSTC_CPU_LOG" glam)"
    record "all ga-core" "$(unit_time "$t" ga-core)"
    record "all ga-macros" "$(unit_time "$t" ga-macros)"
done
for k in "${!best[@]}"; do echo "$k: ${best[$k]}"; done | sort
