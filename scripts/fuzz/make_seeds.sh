#!/usr/bin/env bash
# Makes the seed corpora of the HDF5 fuzz targets (tests/fuzz/corpus/{fclib,restart}/) from
# real files, in the targets' record format (scripts/fuzz/encode_hdf5.py):
#  - fclib: the problems of ../shared/fclib/;
#  - restart: short runs of the two scenes the restart target knows (its first byte: 0 for
#    configs/block_on_incline_2d.json, 1 for configs/box_tower_3d.json).
# usage: scripts/fuzz/make_seeds.sh BUILD_DIR   (needs BUILD_DIR/bin/moreau and python3-h5py)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
encode="/usr/bin/python3 scripts/fuzz/encode_hdf5.py"
out=tests/fuzz/corpus
mkdir -p "$out/fclib" "$out/restart"
# Three kinds of layout (CSR local, triplet global with diagonal M, full M), the smallest of each.
for f in ../shared/fclib/{fclib-local_problem_test,faf-Box_Stacks-i0035-31-0,CubeH8}.hdf5; do
  $encode "$f" "$out/fclib/$(basename "$f" .hdf5).rec"
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
i=0
for scene in configs/block_on_incline_2d.json configs/box_tower_3d.json; do
  name=$(basename "$scene" .json)
  "$build/bin/moreau" run "$scene" --steps 40 --out "$work/$name.h5" --quiet >/dev/null
  $encode "$work/$name.h5" "$out/restart/$name.rec" --prefix $i
  i=$((i + 1))
done
ls -l "$out/fclib" "$out/restart"
