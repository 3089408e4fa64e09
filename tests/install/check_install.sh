#!/usr/bin/env bash
# check_install.sh PREFIX -- TAP checks of an installed tree (meson install
# --prefix PREFIX): ODE programs build through `pkg-config ode` and with plain
# -lode, odedyn.pc works, ODE's `precision` variable is there, the
# installed libodedyn carries no collision code, libodecollide needs no C++
# runtime, and each installed backend module (libdir/odecollide) is found and
# loaded by an installed program that selects it.
set -u
prefix=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
pcdir=$(dirname "$(find "$prefix" -name ode.pc | head -n 1)")
libdir=$(dirname "$pcdir")
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

build_with_pkgconfig() {
    local flags
    flags=$(PKG_CONFIG_PATH=$pcdir pkg-config --cflags --libs "$1") &&
    cc -std=c99 -Wall -Wextra -o "$work/prog_$1" "$here/ode_program.c" $flags -lm &&
    LD_LIBRARY_PATH=$libdir "$work/prog_$1"
}

build_with_plain_lode() {
    cc -o "$work/prog_lode" "$here/ode_program.c" -I"$prefix/include" -L"$libdir" -lode -lm &&
    LD_LIBRARY_PATH=$libdir "$work/prog_lode"
}

precision_variable() {
    local p
    p=$(PKG_CONFIG_PATH=$pcdir pkg-config --variable=precision ode)
    [ "$p" = dDOUBLE ] || [ "$p" = dSINGLE ]
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
    flags=$(PKG_CONFIG_PATH=$pcdir pkg-config --cflags --libs ode) &&
    cc -std=c99 -Wall -Wextra -o "$work/prog_backend" "$here/backend_program.c" $flags -lm &&
    LD_LIBRARY_PATH=$libdir "$work/prog_backend" "$1"
}

echo "TAP version 13"
check "an ODE program builds and runs with pkg-config ode" build_with_pkgconfig ode
check "a dynamics-only program builds and runs with pkg-config odedyn" build_with_pkgconfig odedyn
check "an ODE program builds and runs with plain -lode (linker script)" build_with_plain_lode
check "ode.pc has ODE's precision variable" precision_variable
check "the installed libodedyn defines no collision function" no_collision_code_in_libodedyn
check "the installed libodecollide needs no C++ runtime or adapter library" \
    no_cpp_in_libodecollide
# Wherever the modules were installed, the installed library must find them.
modules=$(find "$prefix" -name 'libodecollide-*.so' | sort)
for m in $modules; do
    name=${m##*/libodecollide-}
    name=${name%.so}
    check "the installed $name backend module loads when an installed program selects it" \
        backend_module "$name"
done
if [ -z "$modules" ]; then
    n=$((n + 1))
    echo "ok $n - installed backend modules load # SKIP no backend module was built"
fi
if pkg-config --exists ode && [ -z "$(pkg-config --variable=implementation ode)" ]; then
    check "the same program builds against the reference ODE (pkg-config ode)" \
        sh -c "cc -o '$work/prog_ref' '$here/ode_program.c' \$(pkg-config --cflags --libs ode) -lm && '$work/prog_ref'"
fi
echo "1..$n"
[ "$failed" -eq 0 ]
