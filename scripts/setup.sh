#!/usr/bin/env bash
# Installs the Debian packages the MRT stack needs that are not installed
# yet (idempotent: a second run installs nothing).
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

mapfile -t missing < <(missing_packages)
if [ "${#missing[@]}" -eq 0 ]; then
  echo "setup: all $(grep -cv '^\s*\(#\|$\)' "$ROOT/scripts/packages.txt") packages already installed"
  exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "setup: installing ${#missing[@]} packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
echo "setup: installed ${missing[*]}"
