#!/usr/bin/env bash
# beltdyn report: headless Chromium renders report.html of a fake run to a
# screenshot, which must not be blank. Skipped (exit 0) without chromium.
# The fake run and the report come from the test_report helper built next
# to the tests, so this does not depend on the simulator.
set -euo pipefail
helper="$(dirname "$BELTDYN")/tests/test_report"
if [ ! -x "$helper" ]; then
  echo "FAIL: helper $helper not built" >&2
  exit 1
fi
browser=""
for b in chromium chromium-browser; do
  if command -v "$b" >/dev/null 2>&1; then browser="$b"; break; fi
done
if [ -z "$browser" ]; then
  echo "SKIP: chromium is not installed"
  exit 0
fi

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$helper" fake "$work/run" 300 200
"$helper" report "$work/run"

# no network, no sandbox (CI runs as root), a throw-away profile
if ! timeout 120 "$browser" --headless --no-sandbox --disable-gpu --disable-quic \
    --no-first-run --disable-background-networking --disable-component-update \
    --disable-sync --user-data-dir="$work/profile" --screenshot="$work/shot.png" \
    --window-size=1200,2000 "file://$work/run/report.html" >"$work/chromium.log" 2>&1; then
  echo "FAIL: chromium could not render the report" >&2
  cat "$work/chromium.log" >&2
  exit 1
fi
if [ ! -s "$work/shot.png" ]; then
  echo "FAIL: chromium wrote no screenshot" >&2
  cat "$work/chromium.log" >&2
  exit 1
fi
# the tension colour map alone has hundreds of colours; an error page or an
# empty page has few
"$helper" pngcheck "$work/shot.png" 1000
echo "PASS: report.html renders in $browser"
