#!/usr/bin/env bash
# examples/screenshots.sh BUILD_DIR -- run every drawstuff example headless for
# 300 frames in BUILD_DIR and write its last frame, 640 x 360, to docs/images/NAME.png.
# Exit status: the number of examples that failed (their checks, or no image).
set -u
[ $# -eq 1 ] || { echo "usage: examples/screenshots.sh BUILD_DIR" >&2; exit 2; }
build=$(cd "$1" && pwd) || exit 2
root=$(cd "$(dirname "$0")/.." && pwd)
images=$root/docs/images
mkdir -p "$images"
failed=0
for name in falling stack chain buggy ragdoll joints friction terrain rays backends; do
    program=$build/examples/$name
    if [ ! -x "$program" ]; then
        echo "$name: not built (is drawstuff built? see meson's summary)"
        failed=$((failed + 1))
        continue
    fi
    rm -f "$images/$name.png"
    if ! "$program" -headless -frames 300 -size 640x360 -png "$images/$name.png" >/dev/null; then
        echo "$name: its checks failed (run $program -headless to see why)"
        failed=$((failed + 1))
    elif [ ! -s "$images/$name.png" ]; then
        echo "$name: ran, but wrote no $images/$name.png (is drawstuff's -png supported?)"
        failed=$((failed + 1))
    else
        echo "docs/images/$name.png"
    fi
done
exit $failed
