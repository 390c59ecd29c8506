# Sourced by the scripts: environment and helpers shared by setup, build,
# test, demo and bench. Not meant to be run on its own.
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
# A pyenv python3 shim may come first on PATH without the ROS modules.
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:$PATH"
export ROS_HOME="${ROS_HOME:-$ROOT/build/ros_home}"
export ROS_LOG_DIR="${ROS_LOG_DIR:-$ROS_HOME/log}"
CATKIN_ARGS=(-DPYTHON_EXECUTABLE=/usr/bin/python3 -DPython3_EXECUTABLE=/usr/bin/python3)
JOBS="${JOBS:-$(nproc)}"

# Packages from packages.txt not installed yet (dpkg), one per line.
missing_packages() {
  local pkg
  grep -v '^\s*\(#\|$\)' "$ROOT/scripts/packages.txt" | while read -r pkg; do
    dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || echo "$pkg"
  done
}

ensure_setup() {
  if [ -n "$(missing_packages)" ]; then "$ROOT/scripts/setup.sh"; fi
}

# Builds the workspace. BUILD_TYPE=Release by default, with the optimisation
# of RelWithDebInfo (-O2 -DNDEBUG) but no debug information: the same
# programs, compiled in less CPU time (-g cost 25-47 % more per file) and
# linked from objects 15-25 times smaller (measured for issue 19).
# BUILD_TYPE=RelWithDebInfo (-O2 -g) or Debug for a debugger.
build_workspace() {
  cd "$ROOT"
  catkin_make "${CATKIN_ARGS[@]}" -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-Release}" \
    -DCMAKE_C_FLAGS_RELEASE="-O2 -DNDEBUG" -DCMAKE_CXX_FLAGS_RELEASE="-O2 -DNDEBUG" -j"$JOBS" "$@"
}

# Picks a free TCP port for a private ROS master, so runs never collide.
free_port() {
  /usr/bin/python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1",0)); print(s.getsockname()[1])'
}
