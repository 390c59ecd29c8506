#!/usr/bin/env bash
# Builds in Release and runs every package's benchmark program (the
# executables under devel/lib/<pkg>/ whose name ends in _bench), printing
# their "name: value unit" lines prefixed by the package.
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

ensure_setup
cd "$ROOT"
catkin_make "${CATKIN_ARGS[@]}" -DCMAKE_BUILD_TYPE=Release --build build_release \
  -DCATKIN_DEVEL_PREFIX="$ROOT/build_release/devel" -j"$JOBS" >"$ROOT/build_release.log" 2>&1 ||
  { tail -40 "$ROOT/build_release.log"; exit 1; }
found=0
for exe in "$ROOT"/build_release/devel/lib/*/*_bench; do
  [ -x "$exe" ] || continue
  found=1
  pkg="$(basename "$(dirname "$exe")")"
  echo "# $pkg/$(basename "$exe")"
  (cd "$ROOT" && "$exe") | sed "s|^|$pkg.|"
done
[ "$found" -eq 1 ] || echo "# no benchmark programs yet"
