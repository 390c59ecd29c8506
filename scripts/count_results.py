#!/usr/bin/env python3
"""Counts test cases in the JUnit XML files catkin writes (gtest, rostest).

rostest writes two files per test: the test node's own gtest XML
(rosunit-<name>.xml) and a launch-level summary (rostest-test_<name>.xml)
that repeats the outcome; the summary counts only when the test node left no
XML (it crashed or never started) or when it failed while the node's cases
all passed, so every case is counted once and a crash counts as a failure. Prints the per-file table, then "N passed, M failed" as the
last line; exits 1 if anything failed or nothing ran.
"""
import os
import sys
import xml.etree.ElementTree as ET


def cases(path):
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as e:
        print(f"{path}: unreadable result file ({e})")
        return 0, 1
    passed = failed = 0
    for tc in root.iter("testcase"):
        if tc.find("failure") is not None or tc.find("error") is not None:
            failed += 1
        elif tc.find("skipped") is None and tc.get("status", "run") != "notrun":
            passed += 1
    if passed + failed == 0 and (root.get("errors", "0") != "0" or root.get("failures", "0") != "0"):
        failed = 1
    return passed, failed


def main(results_dir, extra_failed=0):
    passed = failed = 0
    for pkg in sorted(os.listdir(results_dir)) if os.path.isdir(results_dir) else []:
        pdir = os.path.join(results_dir, pkg)
        files = sorted(f for f in os.listdir(pdir) if f.endswith(".xml"))
        for f in files:
            p, fl = cases(os.path.join(pdir, f))
            if f.startswith("rostest-"):
                # rostest-test_<name>.xml summarises rosunit-<name>.xml: count
                # it only when the test node left no result of its own, or as
                # one extra failure when it failed beyond the node's cases.
                name = f[len("rostest-"):-len(".xml")]
                name = name[len("test_"):] if name.startswith("test_") else name
                unit = f"rosunit-{name}.xml"
                if unit in files:
                    if fl == 0 or cases(os.path.join(pdir, unit))[1] > 0:
                        continue
                    p, fl = 0, 1
            print(f"  {pkg}/{f}: {p} passed, {fl} failed")
            passed += p
            failed += fl
    if extra_failed and not failed:
        # ctest failed although every result file passed: a test died
        # before writing its result.
        print("  ctest reported a failure no result file shows")
        failed += extra_failed
    print(f"{passed} passed, {failed} failed")
    return 1 if failed or passed == 0 else 0


if __name__ == "__main__":
    args = sys.argv[1:]
    extra = 0
    if "--extra-failed" in args:
        i = args.index("--extra-failed")
        extra = int(args[i + 1])
        del args[i:i + 2]
    sys.exit(main(args[0] if args else "build/test_results", extra))
