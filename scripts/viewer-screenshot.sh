#!/usr/bin/env bash
# Retakes docs/viewer/transfer-function.png, the viewer's window with its panel over the tornado,
# on a machine without a display: `texsplat view` runs under Xvfb (Debian's xvfb), and once its
# --time-report says the view is at full quality the screen is grabbed with Pillow (python3-pil,
# whose ImageGrab reads an X display through XCB) and written compressed as well as Pillow can
# (optimize=True: the same pixels), then the viewer is closed. (`view --screenshot` writes the
# view alone, without the panel.)
#
# Usage: scripts/viewer-screenshot.sh [texsplat executable, or a build dir holding apps/texsplat;
#                                      default build/release]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
source "$root/scripts/texsplat-executable.sh"
texsplat=$(texsplat_executable "${1:-}")
size=900x560
if [ -z "${VIEWER_SCREENSHOT_XVFB:-}" ]; then
    # A screen as large as the window, so that the grab is the window.
    VIEWER_SCREENSHOT_XVFB=1 exec xvfb-run -a -s "-screen 0 ${size}x24" "$0" "$texsplat"
fi

work=$(mktemp -d)
viewer=
cleanup() {
    if [ -n "$viewer" ]; then
        kill "$viewer" 2>/dev/null || true
        wait "$viewer" 2>/dev/null || true
    fi
    rm -rf "$work"
}
trap cleanup EXIT
"$texsplat" view "$root/examples/tornado.iv" --size "$size" --time-report 2> "$work/view.log" &
viewer=$!
for _ in $(seq 600); do
    grep -q "full quality" "$work/view.log" && break
    kill -0 "$viewer" 2>/dev/null || { cat "$work/view.log" >&2; exit 1; }
    sleep 0.2
done
grep -q "full quality" "$work/view.log" || {
    echo "$0: the viewer did not reach full quality in 120 s" >&2
    exit 1
}
sleep 1 # the full-quality frame is on the screen
"${PYTHON:-/usr/bin/python3}" - "$root/docs/viewer/transfer-function.png" <<'PYTHON'
import os
import sys

from PIL import ImageGrab

ImageGrab.grab(xdisplay=os.environ["DISPLAY"]).save(sys.argv[1], optimize=True)
PYTHON
echo "$0: wrote docs/viewer/transfer-function.png"
