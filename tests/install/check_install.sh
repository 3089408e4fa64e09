#!/usr/bin/env bash
# check_install.sh PREFIX -- TAP checks of an installed tree (meson install
# --prefix PREFIX), every way a program consumes it:
# - `pkg-config ode`, `pkg-config odedyn`, plain -lode (the linker script),
#   ODE's `precision` variable;
# - bin/ode-config: its options, and a program built with its flags;
# - bin/odecontactdiff: it runs and measures native and every installed module;
# - the static archives through `pkg-config --static` (a backend module cannot
#   be loaded there: the registry says so and native stays), and a fully
#   static program where a static libccd exists;
# - a CMake project with find_package(ode) (ODE::ODE and ODE's variables);
# - binary drop-in: a program compiled and linked against the reference ODE
#   (libode-dev) runs on our libode.so.8 and prints what it prints on the
#   reference, also with a backend module selected; public struct layouts and
#   constants equal the reference's;
# - PyODE (python3-pyode, compiled against libode8) on our libode.so.8: a
#   scripted scene compared with the reference, or, while it cannot load, a
#   skip listing the functions we lack;
# - the split: libodedyn carries no collision code, libodecollide no C++
#   runtime, and each installed backend module loads when selected;
# - drawstuff (when installed): a program written as ODE's demos are builds
#   as C and C++ through `pkg-config ode drawstuff` and runs headless (by
#   option, by environment, and by falling back when there is no display),
#   writing PNG files.
set -u
prefix=$(cd "$1" && pwd)
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pcdir=$(dirname "$(find "$prefix" -name ode.pc | head -n 1)")
libdir=$(dirname "$pcdir")
ode_config=$(find "$prefix" -name ode-config -type f | head -n 1)
modules=$(find "$prefix" -name 'libodecollide-*.so' | sort)
n=0
failed=0

check() {   # check DESCRIPTION COMMAND...
    local what=$1
    shift
    n=$((n + 1))
    if "$@" >"$work/out" 2>&1; then
        echo "ok $n - $what"
    else
        sed 's/^/# /' "$work/out"
        echo "not ok $n - $what"
        failed=$((failed + 1))
    fi
}

skip() {    # skip DESCRIPTION REASON
    n=$((n + 1))
    echo "ok $n - $1 # SKIP $2"
}

ours_pc() { PKG_CONFIG_PATH=$pcdir pkg-config "$@"; }

# same_results A B: two outputs of lines `name tolerance value...` agree: the
# same names and counts, each value within its line's tolerance.
same_results() {
    [ -s "$1" ] && [ -s "$2" ] || { echo "an output is empty"; return 1; }
    awk 'NR == FNR { line[FNR] = $0; rows = FNR; next }
         { count = split(line[FNR], a, " ")
           if (FNR > rows || a[1] != $1 || count != NF) { print "differs: " $0; bad = 1; next }
           for (i = 3; i <= NF; i++) {
               d = a[i] - $i
               if (d > $2 || -d > $2) { print "value " i - 2 " of " $1 ": " a[i] " vs " $i; bad = 1 }
           } }
         END { if (FNR != rows) { print "line counts differ"; bad = 1 }; exit bad }' "$1" "$2"
}

build_with_pkgconfig() {
    local flags
    flags=$(ours_pc --cflags --libs "$1") &&
    cc -std=c99 -Wall -Wextra -o "$work/prog_$1" "$here/ode_program.c" $flags -lm &&
    LD_LIBRARY_PATH=$libdir "$work/prog_$1"
}

# rpath DIR: what the --libs flags add for a libdir DIR: an rpath, unless the
# prefix is one the loader searches.
rpath() {
    case $prefix in
    /usr | /usr/local) ;;
    *) printf ' %s' "-Wl,-rpath,$1" ;;
    esac
}

# A program built with the flags of pkg-config (or ode-config) runs as
# installed, without LD_LIBRARY_PATH, on the installed libraries.
runs_without_library_path() {
    local flags
    case $1 in
    ode-config) flags="$("$ode_config" --cflags) $("$ode_config" --libs)" ;;
    *) flags=$(ours_pc --cflags --libs "$1") ;;
    esac
    cc -std=c99 -o "$work/norpath_$1" "$here/ode_program.c" $flags -lm &&
    env -u LD_LIBRARY_PATH ldd "$work/norpath_$1" | grep -E 'libode' &&
    ! env -u LD_LIBRARY_PATH ldd "$work/norpath_$1" | grep -E 'libode.* => not found' &&
    [ -z "$(env -u LD_LIBRARY_PATH ldd "$work/norpath_$1" | grep -E 'libode' |
            grep -v " => $libdir/")" ] &&
    env -u LD_LIBRARY_PATH "$work/norpath_$1"
}

build_with_plain_lode() {
    cc -o "$work/prog_lode" "$here/ode_program.c" -I"$prefix/include" -L"$libdir" -lode -lm &&
    LD_LIBRARY_PATH=$libdir "$work/prog_lode"
}

precision_variable() {
    local p
    p=$(ours_pc --variable=precision ode)
    [ "$p" = dDOUBLE ] || [ "$p" = dSINGLE ]
}

# ode-config answers ODE's options, in order, relocated by --prefix=DIR (with
# an rpath to the libdir, as the prefix is not /usr or /usr/local).
ode_config_options() {
    local libdir_rel=${libdir#"$prefix"/}
    [ "$("$ode_config" --version)" = "$(ours_pc --modversion ode)" ] &&
    [ "$("$ode_config" --prefix)" = "$prefix" ] &&
    [ "$("$ode_config" --exec-prefix)" = "$prefix" ] &&
    [ "$("$ode_config" --cflags)" = "-I$prefix/include" ] &&
    [ "$("$ode_config" --libs)" = "-L$libdir -lode$(rpath "$libdir")" ] &&
    [ "$("$ode_config" --prefix=/x --cflags --libs | tr '\n' ' ')" = \
      "-I/x/include -L/x/$libdir_rel -lode$(rpath "/x/$libdir_rel") " ] &&
    [ "$("$ode_config" --exec-prefix=/e --prefix=/x --libs)" = \
      "-L/e/$libdir_rel -lode$(rpath "/e/$libdir_rel")" ] &&
    ! "$ode_config" 2>/dev/null && ! "$ode_config" --bogus 2>/dev/null
}

# The scene, built with ode-config's flags, runs; its output is the expected
# output of the other builds of it.
build_with_ode_config() {
    cc -std=c99 -Wall -Wextra -o "$work/scene_config" "$here/scene_program.c" \
        $("$ode_config" --cflags) $("$ode_config" --libs) -lm &&
    LD_LIBRARY_PATH=$libdir "$work/scene_config" >"$work/scene.expected" &&
    cat "$work/scene.expected"
}

# no_needed PROGRAM: PROGRAM does not load our shared libraries.
no_needed() {
    local bad
    bad=$(readelf -d "$1" | grep NEEDED | grep -E 'libode')
    [ -z "$bad" ] || { echo "$1 needs: $bad"; return 1; }
}

# The scene linked with libode.a (system libraries shared) through
# `pkg-config --static`: only -lode is made static.
static_archives() {
    local libs
    libs=$(ours_pc --static --libs ode | sed 's/-lode\b/-Wl,-Bstatic -lode -Wl,-Bdynamic/') &&
    cc -std=c99 -Wall -Wextra -o "$work/scene_static" "$here/scene_program.c" \
        $(ours_pc --cflags ode) $libs &&
    no_needed "$work/scene_static" &&
    "$work/scene_static" >"$work/scene_static.out" &&
    same_results "$work/scene.expected" "$work/scene_static.out"
}

# A statically linked libodecollide has no module to open: selecting a
# backend by ODE_COLLISION_BACKEND reports it missing, and native does the work.
static_backend_missing() {
    ODE_COLLISION_BACKEND=$1 "$work/scene_static" >"$work/static_b.out" 2>"$work/static_b.err"
    local rc=$?
    cat "$work/static_b.err"
    [ $rc -eq 0 ] && grep -q "no backend named \"$1\"" "$work/static_b.err" &&
    { [ -z "$modules" ] || grep -q 'statically linked' "$work/static_b.err"; } &&
    same_results "$work/scene.expected" "$work/static_b.out"
}

static_odedyn() {
    local libs
    libs=$(ours_pc --static --libs odedyn | sed 's/-lodedyn\b/-Wl,-Bstatic -lodedyn -Wl,-Bdynamic/') &&
    cc -std=c99 -o "$work/prog_static_dyn" "$here/ode_program.c" $(ours_pc --cflags odedyn) $libs &&
    no_needed "$work/prog_static_dyn" &&
    "$work/prog_static_dyn"
}

fully_static() {
    cc -static -std=c99 -o "$work/scene_full_static" "$here/scene_program.c" \
        $(ours_pc --static --cflags --libs ode) &&
    "$work/scene_full_static" >"$work/scene_full_static.out" &&
    same_results "$work/scene.expected" "$work/scene_full_static.out"
}

# A CMake project: the imported target ODE::ODE, and the variables.
cmake_project() {
    mkdir -p "$work/cmake" &&
    cat >"$work/cmake/CMakeLists.txt" <<EOF
cmake_minimum_required(VERSION 3.13)
project(ode_user C)
find_package(ode 0.16 REQUIRED)
add_executable(scene_target "$here/scene_program.c")
target_link_libraries(scene_target ODE::ODE m)
add_executable(scene_variables "$here/scene_program.c")
target_include_directories(scene_variables PRIVATE \${ODE_INCLUDE_DIRS})
target_compile_definitions(scene_variables PRIVATE \${ODE_DEFINITIONS})
target_link_libraries(scene_variables \${ODE_LIBRARIES} m)
if(NOT ODE_VERSION STREQUAL "$(ours_pc --modversion ode)")
  message(FATAL_ERROR "ODE_VERSION is \${ODE_VERSION}")
endif()
EOF
    cmake -S "$work/cmake" -B "$work/cmake/build" -DCMAKE_PREFIX_PATH="$prefix" &&
    cmake --build "$work/cmake/build" &&
    "$work/cmake/build/scene_target" >"$work/cmake_target.out" &&
    "$work/cmake/build/scene_variables" >"$work/cmake_variables.out" &&
    same_results "$work/scene.expected" "$work/cmake_target.out" &&
    same_results "$work/scene.expected" "$work/cmake_variables.out"
}

# Struct layouts and constants, compiled against the reference headers and ours.
same_layout_as_reference() {
    cc -std=c11 -o "$work/layout_ref" "$here/../reference/diff_layout.c" &&
    cc -std=c11 -o "$work/layout_ours" "$here/../reference/diff_layout.c" -I"$prefix/include" &&
    "$work/layout_ref" >"$work/layout_ref.out" && "$work/layout_ours" >"$work/layout_ours.out" &&
    diff "$work/layout_ref.out" "$work/layout_ours.out"
}

# The scene compiled and linked against the reference ODE runs unchanged on
# our libode.so.8 and prints the same.
reference_program_on_ours() {
    cc -std=c99 -o "$work/scene_ref" "$here/scene_program.c" $(pkg-config --cflags --libs ode) -lm &&
    "$work/scene_ref" >"$work/scene_ref.out" &&
    LD_LIBRARY_PATH=$libdir ldd "$work/scene_ref" | grep -q "libode.so.8 => $libdir/libode.so.8" &&
    LD_LIBRARY_PATH=$libdir "$work/scene_ref" >"$work/scene_ref_ours.out" &&
    same_results "$work/scene_ref.out" "$work/scene_ref_ours.out"
}

# ... and with a backend selected: its module loads into the same
# libodecollide (loaded once), and the scene's physics holds (the exit status;
# the narrow phases' contacts differ slightly, so no comparison of values).
reference_program_backend() {
    LD_DEBUG=files LD_LIBRARY_PATH=$libdir ODE_COLLISION_BACKEND=$1 \
        "$work/scene_ref" >"$work/ref_b.out" 2>"$work/ref_b.err"
    local rc=$? loads
    cat "$work/ref_b.out"
    grep -v '^ *[0-9]*:' "$work/ref_b.err"
    loads=$(grep -c 'file=libodecollide.so.0 .*generating link map' "$work/ref_b.err")
    [ $rc -eq 0 ] && [ "$loads" -eq 1 ] &&
    grep -q "file=$libdir/odecollide/libodecollide-$1.so .*dynamically loaded" "$work/ref_b.err" &&
    ! grep -q 'ODE_COLLISION_BACKEND' "$work/ref_b.err"
}

no_collision_code_in_libodedyn() {
    local bad
    bad=$(nm -D --defined-only "$libdir/libodedyn.so" | awk '{print $NF}' |
          grep -E '^d(Geom|Space|Collide|Create|SimpleSpace|HashSpace|QuadTreeSpace)')
    [ -z "$bad" ] || { echo "collision symbols: $bad"; return 1; }
}

no_cpp_in_libodecollide() {
    local bad
    bad=$(readelf -d "$libdir/libodecollide.so" | grep NEEDED |
          grep -E 'stdc\+\+|fcl|octomap|Bullet|LinearMath')
    [ -z "$bad" ] || { echo "libodecollide.so needs: $bad"; return 1; }
}

# backend_module NAME: an installed program selects NAME and collides with it.
backend_module() {
    local flags
    flags=$(ours_pc --cflags --libs ode) &&
    cc -std=c99 -Wall -Wextra -o "$work/prog_backend" "$here/backend_program.c" $flags -lm &&
    LD_LIBRARY_PATH=$libdir "$work/prog_backend" "$1"
}

# PyODE's functions that our libraries do not define (those the reference's
# libode.so.8 defines), one line.
pyode_missing_symbols() {
    local ext=$1 ref
    ref=$(ldd "$ext" | awk '/libode.so.8/ { print $3 }')
    nm -D --undefined-only "$ext" | awk '{ print $NF }' | sort >"$work/pyode_undef"
    nm -D --defined-only "$ref" | awk '{ print $NF }' | sort >"$work/ref_def"
    nm -D --defined-only "$libdir/libodecollide.so" "$libdir/libodedyn.so" |
        awk 'NF == 3 { print $NF }' | sort -u >"$work/our_def"
    comm -12 "$work/pyode_undef" "$work/ref_def" | comm -23 - "$work/our_def" | tr '\n' ' '
}

pyode_scene_on_ours() {
    LD_LIBRARY_PATH=$libdir /usr/bin/python3 "$here/pyode_scene.py" >"$work/pyode_ours.out" &&
    same_results "$work/pyode_ref.out" "$work/pyode_ours.out"
}

echo "TAP version 13"
check "an ODE program builds and runs with pkg-config ode" build_with_pkgconfig ode
check "a dynamics-only program builds and runs with pkg-config odedyn" build_with_pkgconfig odedyn
check "an ODE program builds and runs with plain -lode (linker script)" build_with_plain_lode
for how in ode odedyn ode-config; do
    check "a program built with $how's flags runs without LD_LIBRARY_PATH" \
        runs_without_library_path "$how"
done
check "ode.pc has ODE's precision variable" precision_variable

if [ -n "$ode_config" ]; then
    check "ode-config answers ODE's options" ode_config_options
    check "the scene builds with ode-config's flags and runs" build_with_ode_config
else
    check "ode-config is installed" false
fi

if [ -s "$work/scene.expected" ]; then
    check "the scene links libode.a through pkg-config --static and runs" static_archives
    if [ -x "$work/scene_static" ]; then
        name=fcl
        [ -z "$modules" ] || { name=${modules%%$'\n'*}; name=${name##*/libodecollide-}; name=${name%.so}; }
        check "linked statically, selecting the $name backend reports its module missing; native works" \
            static_backend_missing "$name"
    fi
    ccd_a=$(cc -print-file-name=libccd.a)
    if [ -f "$ccd_a" ]; then
        check "the scene links fully static (-static) and runs" fully_static
    else
        skip "the scene links fully static (-static)" "no static libccd (libccd.a) on this system"
    fi
    if command -v cmake >/dev/null; then
        check "a CMake project with find_package(ode) builds the scene (ODE::ODE, ODE_LIBRARIES)" \
            cmake_project
    else
        skip "a CMake project with find_package(ode)" "cmake not installed"
    fi
fi
check "a dynamics-only program links libodedyn.a through pkg-config --static" static_odedyn

# The reference ODE: found by the system's pkg-config, not ours; libode.so.8
# is built for the reference's precision (double) only.
have_reference=no
if [ -f /usr/include/ode/ode.h ] && pkg-config --exists ode &&
   [ -z "$(pkg-config --variable=implementation ode)" ]; then
    have_reference=yes
fi
if [ $have_reference = yes ] &&
   [ "$(pkg-config --variable=precision ode)" != "$(ours_pc --variable=precision ode)" ]; then
    skip "a program linked against the reference runs on our libode.so.8" \
        "this build's precision is not the reference's"
elif [ $have_reference = yes ]; then
    check "the same program builds against the reference ODE (pkg-config ode)" \
        sh -c "cc -o '$work/prog_ref' '$here/ode_program.c' \$(pkg-config --cflags --libs ode) -lm && '$work/prog_ref'"
    check "public structs and constants are laid out as in the reference ODE" \
        same_layout_as_reference
    check "a program linked against the reference runs on our libode.so.8 with its results" \
        reference_program_on_ours
    for m in $modules; do
        name=${m##*/libodecollide-}
        name=${name%.so}
        check "... and with ODE_COLLISION_BACKEND=$name, the module loads into the same libodecollide" \
            reference_program_backend "$name"
    done
else
    skip "a program linked against the reference runs on our libode.so.8" \
        "the reference ODE (libode-dev) is not installed"
fi

# PyODE, a real client of libode.so.8, with Debian's python (its package's).
if [ ! -f "$libdir/libode.so.8" ]; then
    skip "PyODE runs on our libode.so.8" "no libode.so.8 in this build"
elif [ -x /usr/bin/python3 ] && ext=$(/usr/bin/python3 -c 'import ode; print(ode.__file__)' 2>/dev/null); then
    if ! /usr/bin/python3 "$here/pyode_scene.py" >"$work/pyode_ref.out"; then
        check "PyODE runs the scene on the reference ODE" false
    elif LD_LIBRARY_PATH=$libdir /usr/bin/python3 -c 'import ode' 2>"$work/pyode_err"; then
        check "PyODE runs the scene on our libode.so.8 with the reference's results" \
            pyode_scene_on_ours
    else
        missing=$(pyode_missing_symbols "$ext")
        sed 's/^/# /' "$work/pyode_err"
        skip "PyODE runs on our libode.so.8" \
            "it does not load: $(echo $missing | wc -w) functions missing: $(echo $missing)"
    fi
else
    skip "PyODE runs on our libode.so.8" "python3-pyode is not installed"
fi

# odecontactdiff: installed in bindir, it measures every installed backend.
contactdiff=$(find "$prefix" -name odecontactdiff -type f | head -n 1)
contactdiff_runs() {
    LD_LIBRARY_PATH=$libdir "$contactdiff" --seed 1 --count 3 --pair box sphere --csv \
        >"$work/contactdiff.csv"
    [ $? -le 1 ] || return 1
    for m in native $modules; do
        name=${m##*/libodecollide-}
        name=${name%.so}
        grep -q "^$name,box-sphere,3," "$work/contactdiff.csv" || { echo "no $name row"; return 1; }
    done
}
if [ -n "$contactdiff" ]; then
    check "the installed odecontactdiff measures native and every installed module" contactdiff_runs
else
    check "odecontactdiff is installed" false
fi

check "the installed libodedyn defines no collision function" no_collision_code_in_libodedyn
check "the installed libodecollide needs no C++ runtime or adapter library" \
    no_cpp_in_libodecollide
# Wherever the modules were installed, the installed library must find them.
for m in $modules; do
    name=${m##*/libodecollide-}
    name=${name%.so}
    check "the installed $name backend module loads when an installed program selects it" \
        backend_module "$name"
done
if [ -z "$modules" ]; then
    skip "installed backend modules load" "no backend module was built"
fi

# is_png FILE: FILE starts with the PNG signature.
is_png() {
    [ "$(head -c 8 "$1" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ] ||
        { echo "$1 is not a PNG"; return 1; }
}

# drawstuff_program COMPILER: builds the demo-style program, runs it 200
# frames headless; the box must rest on the ground (z = 0.5) and the PNG exist.
drawstuff_program() {
    local flags exe=$work/ds_$1
    flags=$(ours_pc --cflags --libs ode drawstuff) || return 1
    if [ "$1" = cc ]; then
        cc -std=c99 -Wall -Wextra -Werror -o "$exe" "$here/drawstuff_program.c" $flags -lm ||
            return 1
    else
        c++ -x c++ -Wall -Wextra -Werror -o "$exe" "$here/drawstuff_program.c" $flags -lm ||
            return 1
    fi
    (cd "$work" && LD_LIBRARY_PATH=$libdir "$exe" -headless -frames 200 -png "$work/ds_$1.png") \
        >"$work/ds_$1.out" || return 1
    cat "$work/ds_$1.out"
    grep -qE '^rest -?0\.[0-9]+ -?0\.[0-9]+ 0\.(4[5-9]|5[0-5])$' "$work/ds_$1.out" &&
        is_png "$work/ds_$1.png"
}

# An unchanged program run headless through the environment, and without a
# display at all (it says so and writes <program>.png).
drawstuff_environment() {
    rm -rf "$work/rec" "$work/ds_cc.png"
    (cd "$work" && env -u DISPLAY -u WAYLAND_DISPLAY DS_HEADLESS=1 DS_FRAMES=3 \
        DS_RECORD="$work/rec" DS_PNG="$work/env.png" LD_LIBRARY_PATH=$libdir "$work/ds_cc") &&
        is_png "$work/env.png" && is_png "$work/rec/frame00003.png" &&
        [ ! -e "$work/rec/frame00004.png" ] &&
        (cd "$work" && env -u DISPLAY -u WAYLAND_DISPLAY DS_FRAMES=2 \
            LD_LIBRARY_PATH=$libdir "$work/ds_cc" 2>"$work/fallback.err") &&
        cat "$work/fallback.err" && grep -q 'no display; running headless' "$work/fallback.err" &&
        is_png "$work/ds_cc.png"
}

if [ -n "$(find "$prefix" -name drawstuff.pc)" ]; then
    check "a drawstuff program (C) builds through pkg-config ode drawstuff, runs headless, writes a PNG" \
        drawstuff_program cc
    check "... and as C++" drawstuff_program c++
    check "... and runs headless from DS_* variables alone, and with no display at all" \
        drawstuff_environment
else
    skip "a drawstuff program builds and runs headless" "drawstuff was not built"
fi
echo "1..$n"
[ "$failed" -eq 0 ]
