#!/usr/bin/env bash
# POV-Ray 3.7 on the scaling scenes: how the classic renderer's own bounding hierarchy grows
# from N = 10 to N = 100 000 spheres, to set beside `cargo bench --bench scaling`.
#
#   bash benches/povray/scaling.sh [RUNS] [LAYOUT] [SIZES]     # defaults: 3 field "10 100000"
#
# Needs povray (Debian: apt-get install povray). For each N, `scatter N --pov` writes the same
# scene whitted renders; POV-Ray renders it at 1280×720 and at 2×2, each RUNS times, and the
# script prints the medians of the whole process. The 2×2 run is parsing and bounding with
# next to no tracing, so "render" = full − 2×2 is the part to compare with whitted's render
# time (this POV-Ray build prints no statistics of its own).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
runs="${1:-3}"
layout="${2:-field}"
sizes="${3:-10 100000}"
OUT="${OUT:-/tmp/whitted-povray-scaling}"
mkdir -p "$OUT"
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$root/target}"
cargo build --release --quiet --manifest-path "$root/Cargo.toml" --bin scatter
scatter="$CARGO_TARGET_DIR/release/scatter"
median() { sort -n | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
seconds() { # whole-process wall time of "$@", in seconds
  local t0 t1
  t0=$(date +%s.%N)
  "$@" >/dev/null 2>&1
  t1=$(date +%s.%N)
  awk -v a="$t0" -v b="$t1" 'BEGIN {print b - a}'
}
echo "POV-Ray, $layout layout, 1280×720, median of $runs runs (seconds)"
echo "| N | whole process | parse + bounding (2×2) | render |"
echo "|---:|---:|---:|---:|"
for n in $sizes; do
  "$scatter" "$n" --layout "$layout" --pov -o "$OUT/scatter-$n.pov"
  pov=(povray "+I$OUT/scatter-$n.pov" "+O$OUT/scatter-$n.png" -D +FN File_Gamma=1.0 -GA)
  full=$(for _ in $(seq "$runs"); do seconds "${pov[@]}" +W1280 +H720; done | median)
  tiny=$(for _ in $(seq "$runs"); do seconds "${pov[@]}" +W2 +H2; done | median)
  awk -v n="$n" -v f="$full" -v t="$tiny" 'BEGIN {printf "| %s | %.3f | %.3f | %.3f |\n", n, f, t, f - t}'
done
