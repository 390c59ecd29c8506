#!/usr/bin/env python3
"""Counts test cases in the JUnit XML files catkin writes (gtest, rostest).

rostest writes two files per test: the test node's own gtest XML
(rosunit-*.xml) and a launch-level summary (rostest-*.xml) that repeats the
same cases; the summary is used only when the test node left no XML (it
crashed or never started), so every case is counted once and a crash counts
as a failure. Prints the per-file table, then "N passed, M failed" as the
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


def main(results_dir):
    passed = failed = 0
    for pkg in sorted(os.listdir(results_dir)) if os.path.isdir(results_dir) else []:
        files = sorted(f for f in os.listdir(os.path.join(results_dir, pkg)) if f.endswith(".xml"))
        unit = {f for f in files if not f.startswith("rostest-")}
        for f in files:
            if f.startswith("rostest-"):
                # rostest-test_<name>.xml summarises rosunit-<name>.xml
                name = f[len("rostest-"):-len(".xml")]
                if name.startswith("test_"):
                    name = name[len("test_"):]
                if any(u.startswith("rosunit-") and name in u for u in unit):
                    continue
            p, fl = cases(os.path.join(results_dir, pkg, f))
            print(f"  {pkg}/{f}: {p} passed, {fl} failed")
            passed += p
            failed += fl
    print(f"{passed} passed, {failed} failed")
    return 1 if failed or passed == 0 else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else "build/test_results"))
