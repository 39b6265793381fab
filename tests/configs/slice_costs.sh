#!/usr/bin/env bash
# usage: slice_costs.sh SOURCE_DIR MOREAU — scripts/slice_costs.py (docs/solvers.md "CPU time
# per counted unit by scene") still reads `auto`'s trace: on masonry_arch_2d's first 100 steps
# at 1e-3 (APGD's slices every step, NLGS's first stages) it fits APGD's slices with a
# positive time per counted unit; an unknown scene name is refused (exit 2) with the list.
set -euo pipefail
src=$1
moreau=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
script="$src/scripts/slice_costs.py"

/usr/bin/python3 "$script" --moreau "$moreau" --steps 100 --tolerance 1e-3 --only masonry_arch_2d --json "$work/fits.json" > "$work/out.txt" \
  || { cat "$work/out.txt" >&2; fail "slice_costs.py failed"; }
/usr/bin/python3 - "$work/fits.json" <<'PY' || fail "no fit of APGD's slices"
import json, sys
f = json.load(open(sys.argv[1]))["masonry_arch_2d"]
a = f["fits"]["apgd"]
assert f["contacts"] > 50, f
assert a["slices"] >= 50 and a["ns_per_unit"] > 0, a
PY

set +e
/usr/bin/python3 "$script" --moreau "$moreau" --only no_such_scene 2> "$work/bad.err"
code=$?
set -e
[ "$code" -eq 2 ] || fail "unknown scene name: exit $code, expected 2"
grep -q "unknown scene no_such_scene; valid: .*masonry_arch_2d" "$work/bad.err" || { cat "$work/bad.err" >&2; fail "no list of valid names"; }
echo "slice_costs.py: ok"
