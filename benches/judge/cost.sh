#!/usr/bin/env bash
# What the judge outside the student's process costs: every exercise test (`ex_…`) of the five
# chapters, each in its own process, run in one process (the judge's test binary running the
# reference's bodies itself) and across the wire (the same binary, the exercise run by a server
# built from the reference), side by side, RUNS times each.
#
#   cargo test -p whitted-course --test judge_outside -- --ignored   # builds the two copies
#   bash benches/judge/cost.sh [RUNS]
#
# Prints the sum of the per-test medians for both, their ratio, the median test's extra time,
# and the five tests the wire slows most. Uses the copies judge_outside leaves in
# target/judge-tests; the server's copy is put back to the reference first (judge_outside leaves
# its last mutant in it).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
runs="${1:-3}"
work="$root/target/judge-tests"
[ -d "$work/judge/crates" ] || { echo "cost.sh: $work/judge is missing: run judge_outside first" >&2; exit 2; }
export CARGO_TARGET_DIR="$work/target"
rm -rf "$work/server/crates"
cp -r "$work/judge/crates" "$work/server/crates"
(cd "$work/server" && cargo build --quiet --locked -p whitted --example judged_server)
server="$CARGO_TARGET_DIR/debug/examples/judged_server"
targets=()
for t in ch01_camera_rays ch02_generic_objects ch03_shading ch04_shadows ch05_reflection_refraction; do
  targets+=(--test "$t")
done
bins=$(cd "$work/judge" && cargo test --quiet --locked --no-run --message-format=json -p whitted "${targets[@]}" |
  python3 -c 'import json,sys; [print(v["executable"]) for v in map(json.loads, sys.stdin) if v.get("executable")]')
out="$(mktemp)"
trap 'rm -f "$out"' EXIT
now() { date +%s.%N; }
for bin in $bins; do
  for t in $("$bin" --list --format terse | sed -n 's/: test$//p' | grep -E '(^|::)ex_'); do
    for _ in $(seq "$runs"); do
      a=$(now)
      "$bin" "$t" --exact --test-threads 1 >/dev/null 2>&1 || echo "cost.sh: $t fails in one process" >&2
      b=$(now)
      WHITTED_JUDGE_SERVER="$server" WHITTED_GRADED_TEST="$t" "$bin" "$t" --exact --test-threads 1 >/dev/null 2>&1 ||
        echo "cost.sh: $t fails across the wire" >&2
      c=$(now)
      echo "$t $a $b $c" >>"$out"
    done
  done
done
python3 - "$out" "$runs" <<'PY'
import statistics, sys
from collections import defaultdict
local, wire = defaultdict(list), defaultdict(list)
for line in open(sys.argv[1]):
    t, a, b, c = line.split()
    local[t].append(float(b) - float(a))
    wire[t].append(float(c) - float(b))
ml = {t: statistics.median(v) for t, v in local.items()}
mw = {t: statistics.median(v) for t, v in wire.items()}
sl, sw = sum(ml.values()), sum(mw.values())
print(f"{len(ml)} exercise tests, medians of {sys.argv[2]} runs each")
print(f"one process:     {sl:7.2f} s")
print(f"across the wire: {sw:7.2f} s  ({sw / sl:.1f}x)")
extra = statistics.median(mw[t] - ml[t] for t in ml)
print(f"the median test's extra time across the wire: {extra * 1000:.1f} ms")
print("slowed most (one process -> across the wire):")
for t in sorted(mw, key=lambda t: mw[t] - ml[t], reverse=True)[:5]:
    print(f"  {ml[t]:7.3f} s -> {mw[t]:7.3f} s  {t}")
PY
