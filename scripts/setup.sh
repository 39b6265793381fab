#!/usr/bin/env bash
# Set-up on a fresh Debian 12 machine (run as root, or with sudo available):
#   bash scripts/setup.sh          install what is missing, build (Release), run the default example
#   bash scripts/setup.sh --test   the same set-up, then the whole test suite (ctest)
# Environment: BUILD_DIR (default: build), JOBS (default: 2).
set -euo pipefail
cd "$(dirname "$0")/.."

mode=example
case "${1:-}" in
  "") ;;
  --test) mode=test ;;
  *) echo "usage: bash scripts/setup.sh [--test]" >&2; exit 2 ;;
esac
build=${BUILD_DIR:-build}
jobs=${JOBS:-2}
default_scene=configs/default.json

# Debian packages (DESIGN §4). Only the missing ones are installed.
packages=(cmake make g++ pkg-config
  libeigen3-dev libboost-dev libboost-filesystem-dev nlohmann-json3-dev libhdf5-dev libfcl-dev libcli11-dev
  libsuitesparse-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  hdf5-tools python3 python3-h5py python3-numpy python3-matplotlib
  clang-14 libfuzzer-14-dev)  # the fuzz targets, run by the test suite (docs/robustness.md)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo=""
  [ "$(id -u)" -ne 0 ] && sudo=sudo
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# The test suite also builds and runs the fuzz targets (clang + sanitizers, docs/robustness.md).
fuzz=OFF
[ "$mode" = test ] && command -v clang++-14 >/dev/null && fuzz=ON
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DMOREAU_FUZZ_CLANG=$fuzz >/dev/null
cmake --build "$build" -j"$jobs"

if [ "$mode" = test ]; then
  ctest --test-dir "$build" -j"$jobs" --output-on-failure --timeout 900
else
  mkdir -p "$build/out"
  out="$build/out/$(basename "$default_scene" .json).h5"
  "$build/bin/moreau" run "$default_scene" --out "$out"
  echo "setup: the example's output is $out (open ${out%.h5}.xmf in ParaView)"
fi
