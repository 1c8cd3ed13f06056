#!/usr/bin/env bash
# The grading time per submission of this tree beside an older grader's, on the same class, in
# one run: `grade_scale` (a class graded one submission at a time in the sandbox, the per-
# submission median after the first) run ROUNDS times for each, alternating, so that the
# machine's load falls on both alike.
#
#   bash benches/grade/side_by_side.sh OLD_REV [CLASS_SIZE] [ROUNDS]
#
# OLD_REV is checked out in target/side-by-side/old (a git worktree). Prints each run's median
# and, for each grader, the median of its runs' medians and their ratio (this tree / OLD_REV).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
root="$(cd "$here/../.." && pwd)"
old_rev="${1:?usage: side_by_side.sh OLD_REV [CLASS_SIZE] [ROUNDS]}"
size="${2:-12}"
rounds="${3:-2}"
work="$root/target/side-by-side"
old="$work/old"
mkdir -p "$work"
if [ ! -d "$old" ]; then
  git -C "$root" worktree add --detach "$old" "$old_rev" >/dev/null
else
  git -C "$old" checkout --quiet --detach "$old_rev"
fi
# the older tree reads the course's shared files from beside it, as this one does
[ -e "$work/shared" ] || ln -s "$(cd "$root/.." && pwd)/shared" "$work/shared"
for tree in "$old" "$root"; do
  (cd "$tree" && cargo test --quiet --locked -p whitted-course --test grade_scale --no-run)
done
medians() { sed -n 's/.*after it the median submission \([0-9.]*\) s.*/\1/p'; }
run() {
  (cd "$1" && WHITTED_CLASS_SIZE="$size" cargo test --quiet --locked -p whitted-course \
    --test grade_scale -- --ignored --nocapture 2>&1) | tee -a "$work/log" | medians
}
: >"$work/log"
old_runs=()
new_runs=()
for r in $(seq "$rounds"); do
  o=$(run "$old")
  n=$(run "$root")
  echo "round $r: $old_rev ${o:-?} s, this tree ${n:-?} s (median submission of $size)"
  old_runs+=("${o:-nan}")
  new_runs+=("${n:-nan}")
done
python3 - "${old_runs[*]}" "${new_runs[*]}" "$old_rev" <<'PY'
import statistics, sys
old = [float(x) for x in sys.argv[1].split()]
new = [float(x) for x in sys.argv[2].split()]
o, n = statistics.median(old), statistics.median(new)
print(f"median of the medians: {sys.argv[3]} {o:.1f} s, this tree {n:.1f} s, ratio {n / o:.2f}")
PY
