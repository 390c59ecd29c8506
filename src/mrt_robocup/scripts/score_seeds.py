#!/usr/bin/env python3
"""Issue 21's scoring criterion as one test case: the team scores within 120
simulated seconds in at least NEED of the seeded runs of score.test.

Runs `rostest mrt_robocup score.test seed:=N` once per seed (each its own
master, its results in a scratch directory so that a missed seed is not
counted as a failed case), stops as soon as the verdict is known (NEED runs
scored, or too many missed), and writes one JUnit case whose output lists
every seed's result (rostests.cmake registers it; README "Tests").

  score_seeds.py --out FILE.xml [--seeds 1 2 3 4 5] [--need 4] [--all] [ARG:=VALUE ...]
"""
import argparse
import os
import re
import signal
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET
from xml.sax.saxutils import escape, quoteattr

GOAL = re.compile(r"seed (-?\d+): goal for (\w+) ([0-9.]+) s after the kick-off")


def run_seed(seed, launch_args, timeout):
    """One score.test run: (scored, one-line description)."""
    with tempfile.TemporaryDirectory(prefix="score_seed_") as results:
        cmd = ["rostest", "--text", "--results-base-dir", results, "mrt_robocup", "score.test",
               "seed:=%d" % seed] + launch_args
        start = time.monotonic()
        # Its own process group: on a timeout the launched nodes end with it.
        proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                universal_newlines=True, start_new_session=True)
        try:
            out, _ = proc.communicate(timeout=timeout)
            rc = proc.returncode
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGINT)
            try:
                out, _ = proc.communicate(timeout=30)
            except subprocess.TimeoutExpired:
                os.killpg(proc.pid, signal.SIGKILL)
                out, _ = proc.communicate()
            rc = None
        wall = time.monotonic() - start
        cases, failures = 0, []
        for root, _, files in os.walk(results):
            for name in files:
                if not name.endswith(".xml"):
                    continue
                try:
                    tree = ET.parse(os.path.join(root, name))
                except ET.ParseError as e:
                    failures.append("%s: unreadable (%s)" % (name, e))
                    continue
                for case in tree.iter("testcase"):
                    cases += 1
                    for bad in list(case.iter("failure")) + list(case.iter("error")):
                        failures.append((bad.get("message") or bad.text or "failed").strip().splitlines()[0])
    goal = GOAL.search(out)
    scored = rc == 0 and cases > 0 and not failures
    if scored and goal:
        what = "goal for %s %s s after the kick-off" % (goal.group(2), goal.group(3))
    elif rc is None:
        what = "rostest did not end within %.0f s" % timeout
    elif cases == 0:
        what = "no test result (rostest exit %d)" % rc
    else:
        what = "; ".join(failures) or "rostest exit %d" % rc
    return scored, "seed %d: %s: %s (%.0f s wall)" % (seed, "scored" if scored else "missed", what, wall), out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", required=True, help="the JUnit file to write")
    parser.add_argument("--seeds", type=int, nargs="+", default=[1, 2, 3, 4, 5])
    parser.add_argument("--need", type=int, default=4, help="runs that must score")
    parser.add_argument("--timeout", type=float, default=900.0, help="wall seconds per run")
    parser.add_argument("--all", action="store_true", help="run every seed, even once the verdict is known")
    parser.add_argument("launch_args", nargs="*", help="more score.test arguments, ARG:=VALUE")
    args = parser.parse_args()
    if not 0 < args.need <= len(args.seeds):
        parser.error("--need must be between 1 and the number of seeds")

    lines, logs, scored, missed = [], [], 0, 0
    for seed in args.seeds:
        ok, line, out = run_seed(seed, args.launch_args, args.timeout)
        print(line, flush=True)
        lines.append(line)
        scored += ok
        missed += not ok
        if not ok:
            logs.append("---- seed %d ----\n%s" % (seed, out[-6000:]))
        if not args.all and (scored >= args.need or missed > len(args.seeds) - args.need):
            break
    passed = scored >= args.need
    verdict = "%d of %d seeded runs scored (%d needed of %d)" % (scored, scored + missed, args.need,
                                                                  len(args.seeds))
    print(verdict)
    name = "team_scores_in_%d_of_%d_seeded_runs" % (args.need, len(args.seeds))
    failure = "" if passed else "<failure message=%s>%s</failure>" % (
        quoteattr(verdict), escape("\n".join(lines + logs)))
    os.makedirs(os.path.dirname(os.path.abspath(args.out)), exist_ok=True)
    with open(args.out, "w") as f:
        # catkin's run_tests.py reads tests, errors and failures.
        f.write('<testsuite name="robocup_score_seeds" tests="1" errors="0" failures="%d">'
                '<testcase classname="mrt_robocup.score_seeds" name=%s>%s<system-out>%s</system-out>'
                '</testcase></testsuite>\n' % (0 if passed else 1, quoteattr(name), failure,
                                                escape("\n".join(lines + [verdict]))))
    return 0 if passed else 1


if __name__ == "__main__":
    sys.exit(main())
