#!/usr/bin/env bash
# Screenshots a page of the built course book the way a reader's browser shows it, with the
# network cut off (every request goes to a proxy that does not exist), so math that was not
# typeset at build time, a missing figure or a stylesheet from a CDN shows on the picture.
#
#   whitted book                                     # build docs/book first
#   tools/book-screenshot.sh [PAGE] [OUT.png] [WIDTH,HEIGHT]
#   tools/book-screenshot.sh ch05-reflection-refraction.html shot.png
#   tools/book-screenshot.sh 'ch02-generic-objects.html?search=cylinder' search.png   # the search box, opened on a query
#
# Needs Debian's chromium (apt-get install chromium). Exit status: chromium's.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
page="${1:-ch02-generic-objects.html}"
out="${2:-book-page.png}"
size="${3:-1280,1600}"
file="${page%%[?#]*}"
if [ ! -f "$root/docs/book/$file" ]; then
  echo "error: $root/docs/book/$file does not exist: build the book with \`whitted book\` first" >&2
  exit 2
fi
profile="$(mktemp -d)"
trap 'rm -rf "$profile"' EXIT
chromium --headless --no-sandbox --disable-gpu --disable-quic --no-first-run \
  --disable-background-networking --disable-component-update --disable-sync \
  --proxy-server=127.0.0.1:9 --user-data-dir="$profile" \
  --window-size="$size" --virtual-time-budget=5000 --hide-scrollbars \
  --screenshot="$(realpath -m "$out")" "file://$root/docs/book/$page" 2>/dev/null
echo "wrote $out ($page)"
