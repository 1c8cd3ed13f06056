#!/usr/bin/env bash
# cargo-mutants on what a change touches: the mutants of the exercise functions (the list in
# .cargo/mutants.toml) whose lines the diff from BASE to the working tree changes. When there
# are more than MAX, one shard of them is run, chosen by the commit, so that CI stays within its
# time; the whole list is `cargo mutants` (docs/src/instructor-guide.md gives its score).
#
#   tools/mutants-diff.sh [BASE] [MAX]      # BASE: a commit (default HEAD~1); MAX: default 12
#
# Exit status: cargo-mutants' (0 every mutant caught or unviable, 2 a mutant missed, 3 a
# timeout), or 0 when the diff touches no exercise function.
set -euo pipefail
cd "$(dirname "$0")/.."
base="${1:-HEAD~1}"
max="${2:-12}"
if ! git rev-parse -q --verify "$base^{commit}" >/dev/null; then
  echo "no commit $base to compare with (a shallow clone?): nothing to mutate"
  exit 0
fi
diff="$(mktemp)"
trap 'rm -f "$diff"' EXIT
git diff "$base" -- crates/whitted/src > "$diff"
if [ ! -s "$diff" ]; then
  echo "the change since $base touches nothing under crates/whitted/src/: nothing to mutate"
  exit 0
fi
n=$(cargo mutants --in-diff "$diff" --list | wc -l)
echo "$n mutants of the exercise functions in the change since $base"
[ "$n" -eq 0 ] && exit 0
shard=()
if [ "$n" -gt "$max" ]; then
  shards=$(( (n + max - 1) / max ))
  k=$(( 16#$(git rev-parse --short=6 HEAD) % shards ))
  shard=(--shard "$k/$shards")
  echo "more than $max: running shard $k of $shards"
fi
cargo mutants --in-diff "$diff" --in-place --baseline skip --timeout 120 "${shard[@]}"
