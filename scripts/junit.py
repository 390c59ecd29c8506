#!/usr/bin/env python3
"""JUnit result files for the sanitizer and fuzzing stage (scripts/sanitize.sh).

  junit.py case OUT.xml SUITE NAME RC LOG
      One test case, failed when RC is not 0; the failure text is the end of
      LOG (the sanitizer or libFuzzer report).
  junit.py collect SRC_RESULTS DEST_RESULTS SUFFIX CTEST_JUNIT
      Copies the gtest result files a sanitizer build's ctest wrote
      (SRC_RESULTS/<pkg>/gtest-*.xml) to DEST_RESULTS/<pkg>_<SUFFIX>/, so
      count_results.py counts every case again. A test ctest reported failed
      (CTEST_JUNIT: ctest --output-junit) whose file shows no failure gets
      one more failed case, with the test's output: the binary's exit
      status, e.g. a LeakSanitizer report at exit after the last case passed.
      A binary that left no result file (catkin's MISSING-gtest-*.xml: not
      built, or killed by a sanitizer report) is one failed case with its
      output (the report).
"""
import os
import shutil
import sys
import xml.etree.ElementTree as ET
from xml.sax.saxutils import escape, quoteattr

TAIL = 6000  # characters of a log kept in a failure


def tail(path):
    try:
        with open(path, errors="replace") as f:
            return f.read()[-TAIL:]
    except OSError:
        return f"(no log {path})"


def write_case(out, suite, name, ok, text):
    os.makedirs(os.path.dirname(out), exist_ok=True)
    failure = "" if ok else f"<failure message={quoteattr(name + ' failed')}>{escape(text)}</failure>"
    with open(out, "w") as f:
        f.write(f'<testsuite name={quoteattr(suite)} tests="1"><testcase classname={quoteattr(suite)} '
                f'name={quoteattr(name)}>{failure}</testcase></testsuite>\n')


def has_failure(path):
    try:
        root = ET.parse(path).getroot()
    except (ET.ParseError, OSError):
        return False
    return any(tc.find("failure") is not None or tc.find("error") is not None for tc in root.iter("testcase"))


def ctest_failures(ctest_junit):
    """{ctest name: output} of the tests ctest's JUnit file marks failed."""
    try:
        root = ET.parse(ctest_junit).getroot()
    except (ET.ParseError, OSError):
        return {}
    return {tc.get("name"): (tc.findtext("system-out") or "")[-TAIL:]
            for tc in root.iter("testcase") if tc.get("status") == "fail"}


def collect(src, dest, suffix, ctest_junit):
    failed = ctest_failures(ctest_junit)
    for pkg in sorted(os.listdir(src)) if os.path.isdir(src) else []:
        for f in sorted(os.listdir(os.path.join(src, pkg))):
            if not f.endswith(".xml"):
                continue
            # gtest-<target>.xml, or MISSING-gtest-<target>.xml (a failure
            # catkin writes when the binary left no result: not built, or
            # killed by a sanitizer report).
            out_dir = os.path.join(dest, f"{pkg}_{suffix}")
            os.makedirs(out_dir, exist_ok=True)
            missing = f.startswith("MISSING-gtest-")
            target = f[len("MISSING-gtest-" if missing else "gtest-"):-len(".xml")]
            ctest_name = f"_ctest_{pkg}_gtest_{target}"
            if missing and ctest_name in failed:
                # The binary died (e.g. a sanitizer report ends it): one
                # failed case whose text is its output, the report.
                write_case(os.path.join(out_dir, f), f"{pkg}_{suffix}", f"{target} left no result",
                           False, failed[ctest_name])
                continue
            shutil.copy(os.path.join(src, pkg, f), os.path.join(out_dir, f))
            if not f.startswith("gtest-"):
                continue
            if ctest_name in failed and not has_failure(os.path.join(src, pkg, f)):
                write_case(os.path.join(out_dir, f"exit-{target}.xml"), f"{pkg}_{suffix}",
                           f"{target} exit status", False, failed[ctest_name])


def main(argv):
    if argv[:1] == ["case"] and len(argv) == 6:
        _, out, suite, name, rc, log = argv
        write_case(out, suite, name, rc == "0", tail(log))
    elif argv[:1] == ["collect"] and len(argv) == 5:
        collect(*argv[1:])
    else:
        sys.exit(__doc__)


if __name__ == "__main__":
    main(sys.argv[1:])
