#!/usr/bin/env python3
"""tap_cases.py TESTLOG_JSON -- print the TAP case lines of every test in a
meson test log; a test that failed without printing a `not ok` line (a crash,
a timeout) is printed as one failing case of its own. A skipped case is printed
as `# skipped: TEST: CASE`, so a log names each skipped test."""
import json
import re
import sys

for line in open(sys.argv[1]):
    test = json.loads(line)
    name = test.get("name", "?")
    out = test.get("stdout", "") or ""
    cases = [l for l in out.splitlines() if re.match(r"^(not )?ok \d+", l)]
    if not cases and test.get("protocol", "tap") == "exitcode" and test.get("result") == "OK":
        cases = ["ok 1 - " + name]
    if not cases and test.get("result") == "SKIP":
        cases = ["ok 1 - %s # SKIP (the whole test)" % name]
    for c in cases:
        print(c if "# SKIP" not in c else "# skipped: %s: %s" % (name, c))
    if test.get("result") not in ("OK", "EXPECTEDFAIL", "SKIP") and \
            not any(c.startswith("not ok") for c in cases):
        print("not ok 0 - %s: %s" % (name, test.get("result")))
