#!/usr/bin/env bash
# ode_demos.sh ODE_SOURCE PREFIX OUTDIR [DEMO...] -- builds ODE's own demo
# programs (ODE_SOURCE/ode/demo, an archive of odedevs/ode; nothing of it is
# copied) unchanged against an installed tree of this project (meson install
# --prefix PREFIX) with `pkg-config ode drawstuff`, runs each headless for
# 300 frames with a few of its command keys typed (DS_KEYS, default
# bsbcybsbyc: boxstack's drop-an-object keys), and writes
# OUTDIR/<demo>.png. Not run by CI (CI has no ODE source). Default demos:
# demo_boxstack demo_buggy demo_chain1. Prints one line per demo and ends
# with `N of M demos built and wrote a PNG`.
set -u
src=$1/ode/demo
prefix=$(cd "$2" && pwd)
mkdir -p "$3" || exit 1
out=$(cd "$3" && pwd)
shift 3
demos=${*:-demo_boxstack demo_buggy demo_chain1}
pcdir=$(dirname "$(find "$prefix" -name drawstuff.pc | head -n 1)")
libdir=$(dirname "$pcdir")
flags=$(PKG_CONFIG_PATH=$pcdir pkg-config --cflags --libs ode drawstuff) || exit 1
good=0
total=0
for demo in $demos; do
    total=$((total + 1))
    file=$(ls "$src/$demo".c* 2>/dev/null | head -n 1)
    case $file in
        *.cpp) compiler=c++ ;;
        *) compiler=cc ;;
    esac
    if ! $compiler -I"$src" -o "$out/$demo" "$file" $flags -lm >"$out/$demo.build.log" 2>&1; then
        echo "$demo: build failed (see $out/$demo.build.log)"
        continue
    fi
    # Run from the demo directory: some demos read files next to them.
    if (cd "$src" && LD_LIBRARY_PATH=$libdir DS_KEYS=${DS_KEYS:-bsbcybsbyc} timeout 300 \
        "$out/$demo" -headless -frames 300 -png "$out/$demo.png") \
        >"$out/$demo.log" 2>&1 && [ -s "$out/$demo.png" ]; then
        echo "$demo: ok, $out/$demo.png"
        good=$((good + 1))
    else
        echo "$demo: run failed (see $out/$demo.log)"
    fi
done
echo "$good of $total demos built and wrote a PNG"
