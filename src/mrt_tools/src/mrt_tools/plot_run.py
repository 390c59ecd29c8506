"""plot_run: the PNGs of one run from a bag of any MRT bringup (see
mrt_tools/README.md). Exit status: 0 when at least one figure was written,
1 when the bag held nothing to plot, 2 on a usage error or an unreadable
bag or world file."""
import argparse
import os
import sys

import rosbag

from mrt_tools import bag_data
from mrt_tools.world import WorldError, load_world

# The figures, in the order they are written (plots.FIGURES; matplotlib is
# imported only once the command line is good, so --help answers at once).
FIGURE_NAMES = ["trajectory", "errors", "commands", "wheels", "behaviours", "timing_periods", "timing_latency"]


def parse_args(argv):
    p = argparse.ArgumentParser(
        prog="plot_run",
        description="Reads a bag recorded from any MRT bringup and writes PNGs: trajectories on the "
                    "map, position/heading errors, commands, wheel speeds, Mr. BRIAN's behaviour "
                    "activations and timing histograms. A figure whose topics the bag lacks is "
                    "skipped with a message.")
    p.add_argument("bag", help="the bag file (rosbag record -O ...)")
    p.add_argument("-o", "--out-dir", help="directory of the PNGs (default: the bag's directory)")
    p.add_argument("-p", "--prefix", help="file name prefix (default: the bag's name without .bag, "
                   "then '_', e.g. demo_trajectory.png)")
    p.add_argument("-w", "--world", help="mrt_sim world YAML whose walls, field lines and posts are "
                   "drawn under the trajectories")
    p.add_argument("--only", action="append", choices=FIGURE_NAMES,
                   help="write only this figure (repeatable)")
    p.add_argument("--dpi", type=int, default=100, help="resolution of the PNGs (default: 100)")
    p.add_argument("-q", "--quiet", action="store_true", help="no progress and no list of files")
    args = p.parse_args(argv)
    if args.dpi <= 0:
        p.error("--dpi: expected a positive number")
    return args


def main(argv=None):
    args = parse_args(sys.argv[1:] if argv is None else argv)
    import matplotlib.pyplot as plt
    from mrt_tools import plots
    assert [name for name, _ in plots.FIGURES] == FIGURE_NAMES
    world = None
    if args.world:
        try:
            world = load_world(args.world)
        except WorldError as e:
            print(f"plot_run: {e}", file=sys.stderr)
            return 2
    try:
        data = bag_data.read_bag(args.bag, progress=not args.quiet)
    except (rosbag.ROSBagException, OSError) as e:
        print(f"plot_run: {args.bag}: not a readable bag ({e})", file=sys.stderr)
        return 2
    out_dir = args.out_dir or os.path.dirname(os.path.abspath(args.bag))
    prefix = args.prefix if args.prefix is not None else os.path.splitext(os.path.basename(args.bag))[0] + "_"
    os.makedirs(out_dir, exist_ok=True)
    written = 0
    for name, figure in plots.FIGURES:
        if args.only and name not in args.only:
            continue
        path = os.path.join(out_dir, f"{prefix}{name}.png")
        try:
            fig = figure(data, world)
        except plots.Skip as e:
            print(f"plot_run: skipped {path}: {e}", file=sys.stderr)
            continue
        fig.savefig(path, dpi=args.dpi)
        plt.close(fig)
        written += 1
        if not args.quiet:
            print(f"plot_run: wrote {path}")
    if written == 0:
        print(f"plot_run: {args.bag}: nothing to plot", file=sys.stderr)
        return 1
    return 0
