#!/usr/bin/python3
"""cpu_profile: CPU seconds per simulated second of every node of a running launch.

Usage: cpu_profile.py [--warmup S] [--duration S] [--cores N]

Run it next to a simulation (ROS_MASTER_URI of the launch, /clock
published). After --warmup wall seconds it reads the CPU time (utime +
stime, /proc/<pid>/stat) of every process whose command line carries a ROS
node name (__name:=...) and the simulated time, again after --duration wall
seconds, and prints per node the CPU seconds spent per simulated second,
grouped by node name across the robots' namespaces, and the real-time
factor the machine could hold if it were idle:
    RTF achievable = cores / total CPU seconds per simulated second.
Unlike the wall-clock real-time factor (rtf_monitor.py) this does not depend
on what else runs on the machine, for the nodes whose work follows simulated
time; a node working on wall-clock timers (DCDT's Agoras, the AIRBoard's
serial link) costs CPU per wall second instead, which the second column
shows: run twice at two real-time factors (sim_node ~real_time_factor) to
tell the two apart.
"""
import argparse
import os
import re
import sys
import threading
import time

import rospy
from rosgraph_msgs.msg import Clock

TICK = os.sysconf("SC_CLK_TCK")


def node_processes():
    """{pid: node name (with namespace)} of the processes that are ROS nodes."""
    out = {}
    for pid in os.listdir("/proc"):
        if not pid.isdigit():
            continue
        try:
            with open("/proc/%s/cmdline" % pid, "rb") as f:
                args = f.read().decode(errors="replace").split("\0")
        except OSError:
            continue
        name = ns = None
        for a in args:
            if a.startswith("__name:="):
                name = a[len("__name:="):]
            elif a.startswith("__ns:="):
                ns = a[len("__ns:="):]
        if name:
            out[int(pid)] = ((ns or "/").rstrip("/") + "/" + name)
    return out


def cpu_seconds(pid):
    try:
        with open("/proc/%d/stat" % pid) as f:
            fields = f.read().rsplit(")", 1)[1].split()
    except OSError:
        return None
    return (int(fields[11]) + int(fields[12])) / TICK  # utime, stime


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--warmup", type=float, default=20.0)
    ap.add_argument("--duration", type=float, default=60.0)
    ap.add_argument("--cores", type=float, default=2.0)
    a = ap.parse_args(rospy.myargv()[1:])
    rospy.init_node("cpu_profile", anonymous=True, disable_signals=True)
    lock = threading.Lock()
    clock = [None]

    def on_clock(m):
        with lock:
            clock[0] = m.clock.to_sec()

    rospy.Subscriber("/clock", Clock, on_clock, queue_size=1)
    time.sleep(a.warmup)

    def snapshot():
        procs = node_processes()
        with lock:
            sim = clock[0]
        return time.time(), sim, {pid: (name, cpu_seconds(pid)) for pid, name in procs.items()}

    w0, s0, c0 = snapshot()
    time.sleep(a.duration)
    w1, s1, c1 = snapshot()
    if s0 is None or s1 is None or s1 <= s0:
        print("cpu_profile: no simulated time passed (is /clock published?)", file=sys.stderr)
        return 1
    sim = s1 - s0
    per_node, per_kind = {}, {}
    for pid, (name, t1) in c1.items():
        if pid not in c0 or t1 is None or c0[pid][1] is None or name.endswith(rospy.get_name()):
            continue
        rate = (t1 - c0[pid][1]) / sim
        per_node[name] = per_node.get(name, 0.0) + rate
        kind = re.sub(r"^/robot\d+", "/robotN", name)
        per_kind[kind] = per_kind.get(kind, 0.0) + rate
    total = sum(per_node.values())
    print("cpu_profile: %.1f sim s over %.1f wall s (wall RTF %.2f, machine shared)" % (sim, w1 - w0, sim / (w1 - w0)))
    rtf = sim / (w1 - w0)
    print("%-40s %s" % ("node (summed over robots)", "CPU s per sim s  (per wall s)"))
    for k, v in sorted(per_kind.items(), key=lambda kv: -kv[1]):
        print("%-40s %.3f  (%.3f)" % (k, v, v * rtf))
    print("%-40s %.3f  (%.3f)" % ("total", total, total * rtf))
    print("RTF achievable on %g idle cores: %.2f" % (a.cores, a.cores / total if total > 0 else float("inf")))
    return 0


if __name__ == "__main__":
    sys.exit(main())
