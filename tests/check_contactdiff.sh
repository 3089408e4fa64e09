#!/bin/sh
# check_contactdiff.sh TOOL -- TAP test of odecontactdiff: its help explains
# the contract; with a seed its CSV is the same on every run (and another
# seed gives other poses); it measures the poses asked for; native passes
# the contract on every pair; a scene file is read and judged (a box resting
# on a plane, a sphere apart); --plot writes an SVG with one mark per
# overlapping pose; bad arguments exit with status 2.
tool="$1"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
n=0
failed=0
check() {   # check NAME COMMAND...: one TAP line
    name="$1"
    shift
    n=$((n + 1))
    if "$@" >"$tmp/out.$n" 2>&1; then
        echo "ok $n - $name"
    else
        echo "not ok $n - $name"
        sed 's/^/# /' "$tmp/out.$n" | head -20
        failed=1
    fi
}
echo "TAP version 13"
echo "1..9"

check "--help explains the contract" sh -c \
    "'$tool' --help | grep -q 'THE CONTRACT' && '$tool' --help | grep -q '5 mm + 5 %'"

"$tool" --seed 7 --count 12 --csv >"$tmp/a.csv" 2>"$tmp/a.err"
"$tool" --seed 7 --count 12 --csv >"$tmp/b.csv" 2>&1
"$tool" --seed 8 --count 12 --csv >"$tmp/c.csv" 2>&1
check "the CSV is the same for a seed" cmp "$tmp/a.csv" "$tmp/b.csv"
check "another seed gives other poses" sh -c "! cmp -s '$tmp/a.csv' '$tmp/c.csv'"
check "the CSV has its header and 14 pairs of truth" sh -c \
    "head -1 '$tmp/a.csv' | grep -q '^backend,pair,poses,overlapping,answered,' &&
     [ \$(grep -c '^truth,[a-z]*-[a-z]*,12,[0-9]*,12,' '$tmp/a.csv') -eq 14 ]"
check "native answers and passes every pair" sh -c \
    "[ \$(grep -c '^native,.*,12,[0-9]*,12,0,0,0,0,.*,pass\$' '$tmp/a.csv') -eq 14 ]"

check "native alone exits 0" "$tool" --backends native --seed 3 --count 5 \
    --pair box:1,1,1 cylinder:0.5,1

cat >"$tmp/scene.txt" <<'SCENE'
# a box resting on the ground, a sphere above it apart
plane 0 0 1 0
box 1 1 1        0 0 0.49
sphere 0.25      0 0 1.5    0.924 0.383 0 0
SCENE
"$tool" --scene "$tmp/scene.txt" --backends native --csv >"$tmp/scene.csv" 2>&1
check "a scene's pairs are judged as posed" sh -c \
    "grep -q '^truth,plane-box,1,1,1,' '$tmp/scene.csv' &&
     grep -q '^truth,plane-sphere,1,0,1,' '$tmp/scene.csv' &&
     grep -q '^truth,box-sphere,1,0,1,' '$tmp/scene.csv' &&
     [ \$(grep -c '^native,.*,pass\$' '$tmp/scene.csv') -eq 3 ]"

"$tool" --backends native --seed 5 --count 10 --pair sphere:0.5 sphere:0.3 \
    --plot "$tmp/plot.svg" --csv >"$tmp/plot.csv" 2>&1
overl=$(grep '^native,' "$tmp/plot.csv" | cut -d, -f4)
check "--plot writes one mark per overlapping pose" sh -c \
    "grep -q '^<svg' '$tmp/plot.svg' && grep -q '</svg>' '$tmp/plot.svg' &&
     [ \$(grep -c '<circle cx=\"[0-9.]*\" cy=\"[0-9.]*\" r=\"2.5\"/>' '$tmp/plot.svg') -eq $overl ]"

check "bad arguments exit with status 2" sh -c \
    "'$tool' --pair box:1,x sphere >/dev/null 2>&1; [ \$? -eq 2 ] &&
     '$tool' --backends nosuch >/dev/null 2>&1; [ \$? -eq 2 ] &&
     '$tool' --scene /nonexistent >/dev/null 2>&1; [ \$? -eq 2 ] &&
     '$tool' --frobnicate >/dev/null 2>&1; [ \$? -eq 2 ]"
exit $failed
