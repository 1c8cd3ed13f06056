#!/usr/bin/env bash
# whitted against POV-Ray 3.7 on the showcase at 1920×1080, whole process, side by side.
#
#   bash benches/povray/compare.sh [RUNS]
#
# Needs povray and hyperfine (Debian: apt-get install povray hyperfine). Prints hyperfine's
# table (mean, and the medians in the JSON it writes to $OUT), then whitted's own statistics
# line for 2 threads and for 1 thread (rays by kind, render time, M rays/s).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
runs="${1:-5}"
OUT="${OUT:-/tmp/whitted-povray}"
mkdir -p "$OUT"
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$root/target}"
cargo build --release --quiet --manifest-path "$root/Cargo.toml" --bin ch05_reflection_refraction
# both write linear intensities (POV-Ray File_Gamma=1.0, whitted --encoding linear), so the two
# images compare directly, as in the runs logged in docs/performance-log.md
w="$CARGO_TARGET_DIR/release/ch05_reflection_refraction"
pov="povray +I$here/showcase.pov +O$OUT/pov.png +W1920 +H1080 -D +FN File_Gamma=1.0 -GA"
hyperfine --warmup 1 --runs "$runs" --export-json "$OUT/times.json" --export-markdown "$OUT/times.md" \
  -n "povray (all cores)" "$pov >/dev/null 2>&1" \
  -n "whitted f64 (2 threads)" "$w --encoding linear -o $OUT/whitted.png --width 1920 --height 1080 -q" \
  -n "whitted f64 (1 thread)" "RAYON_NUM_THREADS=1 $w --encoding linear -o $OUT/whitted1.png --width 1920 --height 1080 -q"
python3 - "$OUT/times.json" <<'PY'
import json, statistics, sys
r = json.load(open(sys.argv[1]))["results"]
med = {x["command"]: statistics.median(x["times"]) for x in r}
for k, v in med.items():
    print(f"median {v:.3f} s  {k}")
names = list(med)
print(f"POV-Ray / whitted (2 threads): {med[names[0]] / med[names[1]]:.2f}x")
print(f"speed-up 1 -> 2 threads:       {med[names[2]] / med[names[1]]:.2f}x")
PY
"$w" --encoding linear -o "$OUT/whitted.png" --width 1920 --height 1080 2>&1 | tail -1
RAYON_NUM_THREADS=1 "$w" --encoding linear -o "$OUT/whitted1.png" --width 1920 --height 1080 2>&1 | tail -1
