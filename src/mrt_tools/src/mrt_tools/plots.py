"""The figures of plot_run, one function per PNG. Each takes a RunData (and
the world, if any) and returns a matplotlib Figure, or raises Skip with the
reason when the bag lacks what the figure needs."""
import math

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402  (after choosing the backend)
import numpy as np  # noqa: E402

from mrt_tools.bag_data import robot_of  # noqa: E402

MAX_TIMING_TOPICS = 12


class Skip(Exception):
    """The bag lacks what a figure needs; the message says what."""


def wrap(a):
    """Angle(s) wrapped into [-pi, pi)."""
    return (np.asarray(a) + math.pi) % (2.0 * math.pi) - math.pi


def pose_errors(estimate, truth):
    """Position error (m) and heading error (rad, estimate - truth, wrapped)
    of an estimated trajectory against the true one, at the estimate's times
    inside the span of the truth (the truth linearly interpolated, its
    heading unwrapped first). Returns (t, position_error, heading_error) as
    numpy arrays, empty when the spans do not overlap."""
    tt = np.asarray(truth.t)
    te = np.asarray(estimate.t)
    if len(tt) < 2 or len(te) == 0:
        return np.array([]), np.array([]), np.array([])
    order = np.argsort(tt)
    tt = tt[order]
    inside = (te >= tt[0]) & (te <= tt[-1])
    te = te[inside]
    tx = np.interp(te, tt, np.asarray(truth.x)[order])
    ty = np.interp(te, tt, np.asarray(truth.y)[order])
    tyaw = np.interp(te, tt, np.unwrap(np.asarray(truth.yaw)[order]))
    ex = np.asarray(estimate.x)[inside]
    ey = np.asarray(estimate.y)[inside]
    eyaw = np.asarray(estimate.yaw)[inside]
    return te, np.hypot(ex - tx, ey - ty), wrap(eyaw - tyaw)


# Colour names the worlds use for the camera that matplotlib does not know.
_EXTRA_COLOURS = {"bronze": "#cd7f32"}


def colour(name):
    """A matplotlib colour for a world file's colour name (grey if unknown)."""
    if matplotlib.colors.is_color_like(name):
        return name
    return _EXTRA_COLOURS.get(name, "0.5")


def _draw_world(ax, world):
    for x1, y1, x2, y2 in world.lines:
        ax.plot([x1, x2], [y1, y2], color="0.75", lw=1, zorder=1)
    for i, (x1, y1, x2, y2) in enumerate(world.walls):
        ax.plot([x1, x2], [y1, y2], color="black", lw=2, zorder=2, label="walls" if i == 0 else None)
    for x, y, r, c, _ in world.posts:
        ax.add_patch(plt.Circle((x, y), r, facecolor=colour(c), edgecolor="black", lw=0.5, zorder=3))
    for x, y, c, _ in world.goals:
        ax.plot([x], [y], marker="s", ms=8, color=colour(c), markeredgecolor="black", zorder=3)
    for i, (xs, ys, c, _) in enumerate(world.movers):
        if xs:
            ax.plot(xs + xs[:1], ys + ys[:1], ls=":", color=colour(c), lw=1, zorder=1,
                    label="movers' waypoints" if i == 0 else None)


def trajectories(data, world=None):
    if not data.truth and not data.estimates:
        raise Skip("no ground truth (nav_msgs/Odometry .../ground_truth) and no estimate "
                   "(nav_msgs/Odometry, PoseWithCovarianceStamped, PoseStamped) in the bag")
    fig, ax = plt.subplots(figsize=(9, 7))
    if world is not None:
        _draw_world(ax, world)
    for topic, (xs, ys) in sorted(data.paths.items()):
        ax.plot(xs, ys, "o--", color="0.5", ms=4, lw=1, label=f"{topic} (plan)")
    for robot, tr in sorted(data.truth.items()):
        ax.plot(tr.x, tr.y, lw=2.5, label=f"{robot or 'robot'} true ({tr.frame})")
        ax.plot(tr.x[:1], tr.y[:1], "k^", ms=8)
    for topic, tr in sorted(data.estimates.items()):
        ax.plot(tr.x, tr.y, lw=1.2, label=f"{topic} ({tr.frame})")
    ax.set_aspect("equal", adjustable="datalim")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    title = "Trajectories" + (f" on {world.name}" if world is not None and world.name else "")
    ax.set_title(title + " (triangle: start)")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=7, loc="best")
    return fig


def errors(data, world=None):
    pairs = []
    for topic, est in sorted(data.estimates.items()):
        truth = data.truth.get(robot_of(topic))
        if truth is not None:
            t, pos, head = pose_errors(est, truth)
            if len(t):
                pairs.append((topic, t, pos, head))
    if not pairs:
        raise Skip("no estimate overlapping in time with a ground truth of the same robot")
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(10, 6), sharex=True)
    for topic, t, pos, head in pairs:
        a1.plot(t, pos, lw=1, label=f"{topic}: mean {pos.mean():.3f} m, max {pos.max():.3f} m")
        a2.plot(t, np.degrees(head), lw=1,
                label=f"{topic}: mean |e| {np.degrees(np.abs(head)).mean():.2f} deg")
    a1.set_ylabel("position error (m)")
    a2.set_ylabel("heading error (deg)")
    a2.set_xlabel("time since the start of the bag (s)")
    a1.set_title("Estimate - ground truth (estimate frames taken as the world frame)")
    for a in (a1, a2):
        a.grid(True, lw=0.3)
        a.legend(fontsize=7, loc="best")
    return fig


def _channel_axes(groups, ylabel_of, title):
    """One subplot per (topic, Channels); shared time axis."""
    fig, axes = plt.subplots(len(groups), 1, figsize=(10, 2.6 * len(groups) + 0.6), sharex=True, squeeze=False)
    for ax, (topic, ch) in zip(axes[:, 0], groups):
        for name, (ts, vs) in sorted(ch.series.items()):
            ax.plot(ts, vs, lw=1, label=name)
        ax.set_title(topic, fontsize=9)
        ax.set_ylabel(ylabel_of(topic))
        ax.grid(True, lw=0.3)
        ax.legend(fontsize=7, loc="upper right", ncol=2)
    axes[-1, 0].set_xlabel("time since the start of the bag (s)")
    fig.suptitle(title)
    fig.tight_layout()
    return fig


def commands(data, world=None):
    groups = [(t, c) for t, c in sorted(data.twists.items())]
    groups += [(t, c) for t, c in sorted(data.brian_commands.items())]
    groups += [(t, c) for t, c in sorted(data.wheel_commands.items())]
    if not groups:
        raise Skip("no commands (geometry_msgs/Twist, mrt_msgs/CommandArray, mrt_msgs/WheelCommand) in the bag")
    units = {t: "Twist" for t in data.twists}
    units.update({t: "rule-base units" for t in data.brian_commands})
    units.update({t: "wheel set-point" for t in data.wheel_commands})
    return _channel_axes(groups, lambda t: units[t], "Commands")


def wheels(data, world=None):
    groups = [(t, c) for t, c in sorted(data.wheel_speeds.items()) if c.series]
    if not groups:
        raise Skip("no wheel speeds (mrt_msgs/WheelState, sensor_msgs/JointState with velocities) in the bag")
    return _channel_axes(groups, lambda t: "rad/s", "Wheel speeds")


def behaviours(data, world=None):
    tables = [(t, b) for t, b in sorted(data.behaviours.items()) if b]
    if not tables:
        raise Skip("no Mr. BRIAN introspection (mrt_msgs/BrianIntrospection, brian_node's ~introspection) in the bag")
    fig, axes = plt.subplots(2 * len(tables), 1, figsize=(10, 5.5 * len(tables)), sharex=True, squeeze=False)
    for k, (topic, table) in enumerate(tables):
        a_cando, a_weight = axes[2 * k, 0], axes[2 * k + 1, 0]
        for name, b in sorted(table.items(), key=lambda kv: (kv[1].level, kv[0])):
            line, = a_cando.plot(b.t, b.cando, lw=1.2, label=f"{name} (level {b.level})")
            active = np.where(np.asarray(b.active), np.asarray(b.cando), np.nan)
            a_cando.plot(b.t, active, lw=3, alpha=0.35, color=line.get_color())
            a_weight.plot(b.t, b.weight, lw=1.2, color=line.get_color(), label=name)
        a_cando.set_ylabel("CANDO")
        a_cando.set_title(f"{topic}: CANDO (thick where active)", fontsize=9)
        a_weight.set_ylabel("Composer weight")
        a_weight.set_title(f"{topic}: weight given by the Composer", fontsize=9)
        for a in (a_cando, a_weight):
            a.set_ylim(-0.05, 1.05)
            a.grid(True, lw=0.3)
            a.legend(fontsize=7, loc="upper right")
    axes[-1, 0].set_xlabel("time since the start of the bag (s)")
    fig.suptitle("Mr. BRIAN behaviour activations")
    fig.tight_layout()
    return fig


def _histograms(items, xlabel, title):
    n = len(items)
    cols = 3 if n > 4 else min(n, 2)
    rows = math.ceil(n / cols)
    fig, axes = plt.subplots(rows, cols, figsize=(4.2 * cols, 2.8 * rows + 0.6), squeeze=False)
    for ax, (topic, values, note) in zip(axes.flat, items):
        # The range stops at the 99th percentile so that a few stalls do not
        # squash the histogram into one bar; the title says how many it left out.
        lo, hi = float(np.min(values)), float(np.percentile(values, 99))
        if hi <= lo:
            hi = lo + 1.0
        ax.hist(values, bins=40, range=(lo, hi), color="tab:blue")
        beyond = int(np.sum(np.asarray(values) > hi))
        ax.set_title(f"{topic}\n{note}" + (f", {beyond} beyond the axis" if beyond else ""), fontsize=8)
        ax.set_xlabel(xlabel, fontsize=8)
        ax.tick_params(labelsize=7)
    for ax in list(axes.flat)[n:]:
        ax.axis("off")
    fig.suptitle(title)
    fig.tight_layout()
    return fig


def timing(data, world=None):
    """Inter-message periods (recorder receive times) of the busiest topics."""
    busy = sorted((t for t, tm in data.timing.items() if len(tm.received) >= 3),
                  key=lambda t: -len(data.timing[t].received))[:MAX_TIMING_TOPICS]
    if not busy:
        raise Skip("no topic with 3 or more messages")
    items = []
    for topic in sorted(busy):
        periods = np.diff(np.sort(np.asarray(data.timing[topic].received))) * 1e3
        rate = 1e3 / periods.mean() if periods.mean() > 0 else float("inf")
        items.append((topic, periods, f"{len(periods) + 1} msgs, {rate:.1f} Hz, "
                      f"p99 {np.percentile(periods, 99):.1f} ms"))
    return _histograms(items, "period between messages (ms)", "Message periods (as received by the recorder)")


def latency(data, world=None):
    """Receive time minus header stamp of the busiest stamped topics."""
    busy = sorted((t for t, tm in data.timing.items() if len(tm.latency) >= 3),
                  key=lambda t: -len(data.timing[t].latency))[:MAX_TIMING_TOPICS]
    if not busy:
        raise Skip("no stamped topic with 3 or more messages")
    items = []
    for topic in sorted(busy):
        lat = np.asarray(data.timing[topic].latency) * 1e3
        items.append((topic, lat, f"median {np.median(lat):.1f} ms, p99 {np.percentile(lat, 99):.1f} ms"))
    return _histograms(items, "received - header stamp (ms)", "Latencies (recorder clock - header stamp)")


# File name suffix -> figure function, in the order they are written.
FIGURES = [
    ("trajectory", trajectories),
    ("errors", errors),
    ("commands", commands),
    ("wheels", wheels),
    ("behaviours", behaviours),
    ("timing_periods", timing),
    ("timing_latency", latency),
]
