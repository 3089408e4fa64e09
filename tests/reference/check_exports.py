#!/usr/bin/env python3
# check_exports.py REFERENCE_LIB OUR_LIB... -- TAP test: every C function the
# reference ODE's shared library exports is exported by one of our libraries
# (each missing name is listed and fails the case).
#   check_exports.py --skip REASON   prints a skipped case.
import re
import subprocess
import sys


def exported_c_functions(lib):
    out = subprocess.run(['nm', '-D', '--defined-only', lib], check=True,
                         capture_output=True, text=True).stdout
    names = set()
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[1] in 'TW' and re.match(r'^d[A-Z]', parts[2]):
            names.add(parts[2])
    return names


def main():
    print('TAP version 13')
    print('1..1')
    what = 'every C function of the reference exists here'
    if sys.argv[1] == '--skip':
        print(f'ok 1 - {what} # SKIP {sys.argv[2]}')
        return 0
    ref = exported_c_functions(sys.argv[1])
    ours = set()
    for lib in sys.argv[2:]:
        ours |= exported_c_functions(lib)
    missing = sorted(ref - ours)
    print(f'# the reference exports {len(ref)} C functions; {len(ref) - len(missing)} exist here')
    for m in missing:
        print(f'# missing: {m}')
    print(f'{"not ok" if missing else "ok"} 1 - {what}: {len(missing)} missing')
    return 1 if missing else 0


if __name__ == '__main__':
    sys.exit(main())
