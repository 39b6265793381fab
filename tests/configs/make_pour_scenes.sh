#!/usr/bin/env bash
# usage: make_pour_scenes.sh SOURCE_DIR — scripts/make_pour_scenes.py as a newcomer runs it:
# `--help` prints usage and writes nothing (it used to regenerate configs/), an unknown name
# is refused, and the scenes it writes elsewhere with --out are the ones in configs/
# (seeded: the same files every time).
set -euo pipefail
src=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
script="$src/scripts/make_pour_scenes.py"

# --help, from the source folder and from configs/ itself: usage, nothing written anywhere.
before=$(cd "$src/configs" && ls -l --time-style=full-iso *.json | sha256sum)
for where in "$src" "$src/configs" "$work"; do
  (cd "$where" && /usr/bin/python3 "$script" --help) > "$work/help.txt" || fail "--help failed in $where"
  grep -q "^usage: make_pour_scenes.py" "$work/help.txt" || fail "--help printed no usage"
done
grep -q -- "--out OUT" "$work/help.txt" || fail "--help does not describe --out"
after=$(cd "$src/configs" && ls -l --time-style=full-iso *.json | sha256sum)
[ "$before" = "$after" ] || fail "--help touched configs/"
[ -z "$(ls -A "$work" | grep -v help.txt)" ] || fail "--help wrote files: $(ls "$work")"

# An unknown scene name: exit 2 (argparse), naming the valid ones, nothing written.
set +e
/usr/bin/python3 "$script" --out "$work/bad" no_such.json 2> "$work/bad.err"
code=$?
set -e
[ "$code" -eq 2 ] || fail "unknown scene name: exit $code, expected 2"
grep -q "unknown scene no_such.json; valid: .*silo_2d.json" "$work/bad.err" || { cat "$work/bad.err" >&2; fail "no list of valid names"; }
[ ! -e "$work/bad" ] || [ -z "$(ls -A "$work/bad")" ] || fail "an unknown name wrote files"

# --out: every scene, byte for byte the file of configs/.
/usr/bin/python3 "$script" --out "$work/out" > /dev/null
n=0
for f in "$work"/out/*.json; do
  cmp -s "$f" "$src/configs/$(basename "$f")" || fail "$(basename "$f") differs from configs/ (rerun the script)"
  n=$((n + 1))
done
[ "$n" -ge 5 ] || fail "only $n scenes written"
echo "make_pour_scenes.py: --help writes nothing; $n scenes written with --out equal configs/"
