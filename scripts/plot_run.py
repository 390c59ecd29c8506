#!/usr/bin/env python3
"""Thin wrapper: mrt_tools' plot_run from the repository, built or not.
usage: scripts/plot_run.py BAG [-w WORLD.yaml] [-o DIR] (--help for all)"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.realpath(__file__)), "..", "mrt_tools", "src"))
from mrt_tools.plot_run import main  # noqa: E402

sys.exit(main())
