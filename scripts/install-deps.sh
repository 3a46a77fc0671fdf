#!/usr/bin/env bash
# Installs, with apt-get, whatever of the build's Debian packages is missing. Silent when all are present.
# Idempotent; needs root (or sudo) only when something is missing.
set -euo pipefail
packages=(cmake make g++ clang libeigen3-dev libgtest-dev libgmock-dev libbenchmark-dev clang-format
  # the testbed window (testbed/) and its screenshot test on a virtual display (xvfb-run)
  pkg-config libgl-dev libglfw3-dev libimgui-dev libgl1-mesa-dri xvfb xauth)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "install-deps: installing ${missing[*]}"
sudo=""
[ "$(id -u)" -eq 0 ] || sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
