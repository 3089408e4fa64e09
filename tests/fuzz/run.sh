#!/usr/bin/env bash
# tests/fuzz/run.sh -- build the libFuzzer targets with clang (ASan + UBSan,
# the libraries instrumented for coverage) and run each one.
#
#   tests/fuzz/run.sh [-t SECONDS_PER_TARGET | -r RUNS_PER_TARGET] [-s SEED]
#                     [-j JOBS] [-b BUILD_DIR] [TARGET...]
#
# Targets: collide space build world (default: all). Each starts from its seed
# corpus tests/fuzz/corpus/<target> and writes new inputs to BUILD_DIR/corpus/
# <target> (merge the interesting ones back by hand: `fuzz_x -merge=1 seed
# new`). A crash leaves crash-* in BUILD_DIR/artifacts/<target>; the script
# prints one "ok"/"not ok" line per target and exits non-zero if any failed.
# -s fixes libFuzzer's random seed (CI: the same inputs on every run of one
# tree, so that a red run can be replayed); without it each run draws its own.
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
build=/tmp/ode-c11-fuzz
limit=(-max_total_time=3600)
jobs=1
seed=()
while getopts "t:r:s:j:b:" opt; do
    case $opt in
    t) limit=(-max_total_time="$OPTARG") ;;
    r) limit=(-runs="$OPTARG") ;;
    s) seed=(-seed="$OPTARG") ;;
    j) jobs=$OPTARG ;;
    b) build=$OPTARG ;;
    *) echo "usage: $0 [-t seconds | -r runs] [-s seed] [-j jobs] [-b dir] [target...]"; exit 2 ;;
    esac
done
shift $((OPTIND - 1))
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(collide space build world)

# -g1: line tables alone, enough for the reports and cheaper to build than full
# debug information
flags="-fsanitize=fuzzer-no-link -fno-sanitize-recover=all -g1"
if [ ! -f "$build/build.ninja" ]; then
    CC=clang CXX=clang++ meson setup "$build" "$root" -Dfuzz=true -Dexamples=false -Ddebug=false \
        -Db_sanitize=address,undefined -Db_lundef=false \
        -Dc_args="$flags" -Dcpp_args="$flags" >"$build.setup.log" 2>&1 ||
        { tail -n 30 "$build.setup.log"; echo "not ok - meson setup"; exit 1; }
fi
# the fuzz targets, and the backend modules they load at run time
modules=$(cd "$build" && ninja -t targets all 2>/dev/null |
          sed -n 's/^\(libodecollide\/libodecollide-[a-z]*\.so\): .*/\1/p')
ninja -C "$build" -j2 $modules $(printf 'tests/fuzz/fuzz_%s ' "${targets[@]}") \
    >"$build.build.log" 2>&1 ||
    { tail -n 30 "$build.build.log"; echo "not ok - build"; exit 1; }

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
failed=0
n=0
for t in "${targets[@]}"; do
    n=$((n + 1))
    mkdir -p "$build/corpus/$t" "$build/artifacts/$t"
    log="$build/fuzz_$t.log"
    parallel=()
    [ "$jobs" -le 1 ] || parallel=(-jobs="$jobs" -workers="$jobs")
    if (cd "$build" && "$build/tests/fuzz/fuzz_$t" "${limit[@]}" "${parallel[@]}" \
        -max_len=4096 -timeout=30 -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="$build/artifacts/$t/" \
        "$build/corpus/$t" "$here/corpus/$t") >"$log" 2>&1; then
        runs=$(grep -h 'stat::number_of_executed_units' "$log" "$build"/fuzz-*.log 2>/dev/null |
               awk '{s += $2} END {print s + 0}')
        echo "ok $n - fuzz_$t ($runs runs)"
    else
        echo "not ok $n - fuzz_$t (see $log, $build/artifacts/$t)"
        grep -hE 'ERROR|SUMMARY|fuzz property' "$log" | head -n 5 | sed 's/^/# /'
        failed=$((failed + 1))
    fi
done
echo "1..$n"
[ "$failed" -eq 0 ]
