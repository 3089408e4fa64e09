#!/bin/sh
# check_split.sh LIB -- TAP test: the dynamics library's undefined symbols
# include no collision function except the three documented hooks.
lib="$1"
echo "TAP version 13"
echo "1..1"
if ! command -v nm >/dev/null 2>&1; then
    echo "ok 1 - libodedyn references no collision symbol # SKIP nm not installed"
    exit 0
fi
bad=$(nm -D --undefined-only "$lib" | awk '{print $NF}' \
      | grep -E '^d(Geom|Space|Collide|Create|SimpleSpace|HashSpace|QuadTreeSpace|Closest|BoxTouches|InfiniteAABB)' \
      | grep -vxE 'dGeomMoved|dGeomGetBodyNext|dGeomSetBody')
if [ -n "$bad" ]; then
    echo "# collision symbols referenced by $lib:"
    echo "$bad" | sed 's/^/# /'
    echo "not ok 1 - libodedyn references no collision symbol"
    exit 1
fi
echo "ok 1 - libodedyn references no collision symbol"
