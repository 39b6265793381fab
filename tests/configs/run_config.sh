#!/usr/bin/env bash
# usage: run_config.sh MOREAU SCENE WORKDIR — check, then run the first 200 steps.
set -euo pipefail
moreau=$1 scene=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
"$moreau" check "$scene"
"$moreau" run "$scene" --steps 200 --out "$work/out.h5" --quiet
test -s "$work/out.h5"
test -s "$work/out.xmf"
