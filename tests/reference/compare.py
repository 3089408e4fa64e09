#!/usr/bin/env python3
"""compare.py OURS REF -- run two builds of one differential test program and
print TAP: one case per output line, passing when both print the same name and
the same number of values, each within the line's absolute tolerance.
compare.py --skip REASON prints a single skipped case."""
import math
import subprocess
import sys


def run(exe):
    out = subprocess.run([exe], check=True, capture_output=True, text=True).stdout
    rows = []
    for line in out.splitlines():
        parts = line.split()
        if parts:
            rows.append((parts[0], float(parts[1]), [float(x) for x in parts[2:]]))
    return rows


def main(argv):
    if argv[1] == "--skip":
        print("TAP version 13\n1..1\nok 1 - differential test # SKIP " + " ".join(argv[2:]))
        return 0
    ours, ref = run(argv[1]), run(argv[2])
    n = max(len(ours), len(ref))
    print("TAP version 13\n1..%d" % n)
    failed = 0
    for i in range(n):
        if i >= len(ours) or i >= len(ref):
            print("not ok %d - line %d missing in one build" % (i + 1, i + 1))
            failed += 1
            continue
        (name_o, tol, vals_o), (name_r, _, vals_r) = ours[i], ref[i]
        bad = []
        if name_o != name_r or len(vals_o) != len(vals_r):
            bad.append("names or counts differ: %s/%d vs %s/%d"
                       % (name_o, len(vals_o), name_r, len(vals_r)))
        else:
            for k, (a, b) in enumerate(zip(vals_o, vals_r)):
                if not (abs(a - b) <= tol or (math.isinf(a) and a == b)):
                    bad.append("value %d: ours %.17g, reference %.17g (tolerance %g)"
                               % (k, a, b, tol))
        if bad:
            failed += 1
            for b in bad:
                print("# " + b)
            print("not ok %d - %s agrees with the reference ODE" % (i + 1, name_o))
        else:
            print("ok %d - %s agrees with the reference ODE" % (i + 1, name_o))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
