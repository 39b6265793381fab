#!/usr/bin/env bash
# usage: run.sh BUILD_DIR SOURCE_DIR — see CMakeLists.txt beside this file.
set -euo pipefail
build=$1
src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# 1. Install to a temporary prefix.
cmake --install "$build" --prefix "$work/prefix" >/dev/null
moreau="$work/prefix/bin/moreau"
[ -x "$moreau" ] || fail "no installed moreau"

# 2. Build the external example plugin against the installed SDK only.
cmake -S "$src/sdk/examples/external_force" -B "$work/ext" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/ext" >/dev/null
[ -f "$work/ext/libmoreau_force_spring.so" ] || fail "the external plugin was not built"

# 3. A scene loading it by name through plugin_paths: a mass on a spring, period 1 s.
cat > "$work/spring.json" <<JSON
{
  "format": "moreau-scene/1",
  "dimension": 2,
  "time": {"step": 0.0005, "duration": 2.0},
  "plugin_paths": ["ext"],
  "bodies": [{"name": "mass", "position": [0.1, 0], "mass": 1, "inertia": 1}],
  "forces": [{"type": "spring", "body": "mass", "anchor": [0, 0], "stiffness": 39.47841760435743}],
  "output": {"file": "spring.h5", "every": 100}
}
JSON
(cd "$work" && "$moreau" run spring.json --quiet) || fail "moreau run with the external plugin failed"
"$moreau" plugins --json > "$work/plugins.json"
grep -q '"rigid"' "$work/plugins.json" || fail "the installed moreau does not list its own plugins"

# x(t) = 0.1 cos(2πt). The spring force is taken at the start of each step (explicit), which
# makes the amplitude grow by exp(T h ω²/4) over time T: 1 + 0.0197 here (first order);
# the phase error is O(h²) (< 1e-4 here). Tolerance: that growth on A, plus 1e-4.
/usr/bin/python3 - "$work/spring.h5" <<'PY'
import math, sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    x = f["/frames/00004000/position"][0, 0]
    T, h, w, A = 2.0, 0.0005, 2 * math.pi, 0.1
    exact = A * math.cos(w * T)
    tol = A * (math.exp(T * h * w * w / 4) - 1) + 1e-4
    print(f"spring: x(2 s) = {x:.6f}, exact {exact:.6f}, error {abs(x - exact):.2e}, tolerance {tol:.2e}")
    sys.exit(0 if abs(x - exact) <= tol else 1)
PY

# 3b. A third-party contact law with an internal variable (sdk/examples/external_law):
# slip-weakening friction, mu from 0.6 to 0.3 over 0.1 m of slip. A block launched at
# v0 = 2 m/s on a flat floor stops where its kinetic energy equals the friction's work,
# v0^2/2 = g [(mu_s + mu_d)/2 d_c + mu_d (S - d_c)]: S = 0.62957 m. mu is taken from the
# start-of-step slip (one step's lag), which dissipates up to (mu_s - mu_d)/mu_d v0 h more:
# tolerance 2e-3 m. The `slip` variable is in the frames and equals the displacement (the
# same trapezoidal rule as the positions) to 1e-5 m.
cmake -S "$src/sdk/examples/external_law" -B "$work/law" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/law" >/dev/null
[ -f "$work/law/libmoreau_law_slip_weakening.so" ] || fail "the external law was not built"
cat > "$work/slide.json" <<JSON
{
  "format": "moreau-scene/1",
  "dimension": 2,
  "time": {"step": 0.001, "duration": 1.0},
  "plugin_paths": ["law"],
  "gravity": [0, -9.81],
  "materials": {"m": {"density": 1000}},
  "laws": {"fault": {"type": "slip_weakening", "static_friction": 0.6, "friction": 0.3, "weakening_distance": 0.1}},
  "interactions": [{"groups": ["block", "floor"], "law": "fault"}],
  "bodies": [
    {"name": "floor", "fixed": true, "position": [0, -0.05],
     "contactors": [{"shape": "polygon", "vertices": [[-2, -0.05], [2, -0.05], [2, 0.05], [-2, 0.05]], "group": "floor"}]},
    {"name": "block", "material": "m", "position": [0, 0.05], "velocity": [2, 0],
     "contactors": [{"shape": "polygon", "vertices": [[-0.1, -0.05], [0.1, -0.05], [0.1, 0.05], [-0.1, 0.05]], "group": "block"}]}],
  "output": {"file": "slide.h5", "every": 100}
}
JSON
(cd "$work" && "$moreau" run slide.json --quiet) || fail "moreau run with the external law failed"
/usr/bin/python3 - "$work/slide.h5" <<'PY'
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    x = f["/frames/00001000/position"][1, 0]
    slip = f["/frames/00001000/contacts/slip"][:]
    g, v0, ms, md, dc, h = 9.81, 2.0, 0.6, 0.3, 0.1, 1e-3
    exact = dc + (v0 * v0 / (2 * g) - (ms + md) / 2 * dc) / md
    tol = (ms - md) / md * v0 * h
    print(f"slip_weakening: stops at {x:.6f} m, exact {exact:.6f}, error {abs(x - exact):.2e}, tolerance {tol:.1e}; "
          f"slip {slip.min():.6f} .. {slip.max():.6f} m")
    ok = abs(x - exact) <= tol and len(slip) == 2 and all(abs(s - x) <= 1e-5 for s in slip)
    sys.exit(0 if ok else 1)
PY

# 4. A plugin built for another ABI is refused, with the ABI message and exit code 2.
cmake -S "$src/tests/sdk_install/mismatched" -B "$work/bad" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null
cmake --build "$work/bad" >/dev/null
sed -e 's/"ext"/"bad"/' -e 's/"type": "spring", "body": "mass", "anchor": \[0, 0\], "stiffness": 39.47841760435743/"type": "mismatched"/' \
  "$work/spring.json" > "$work/bad.json"
set +e
(cd "$work" && "$moreau" run bad.json --quiet) 2> "$work/bad.err"
code=$?
set -e
[ "$code" -eq 2 ] || fail "expected exit code 2 for the mismatched plugin, got $code"
grep -qE "plugin ABI mismatch: the library was built for moreau plugin ABI [0-9]+, this moreau has ABI [0-9]+" "$work/bad.err" \
  || { cat "$work/bad.err" >&2; fail "no ABI message"; }
# 5. A hook folder copied out of user/ and renamed, as user/README.md says, builds on its
#    own against the installed SDK (the header it shares with the other hooks is installed).
cp -r "$src/user/energy_log" "$work/my_energy"
(cd "$work/my_energy" && mv energy_log.cpp my_energy.cpp &&
  sed -i -e 's/MOREAU_REGISTER(EnergyLog, "energy_log")/MOREAU_REGISTER(EnergyLog, "my_energy")/' \
    -e 's/MOREAU_PLUGIN_LIBRARY("moreau_hook_energy_log")/MOREAU_PLUGIN_LIBRARY("moreau_hook_my_energy")/' my_energy.cpp &&
  sed -i -e 's/energy_log/my_energy/g' CMakeLists.txt)
cmake -S "$work/my_energy" -B "$work/my_energy/build" -DCMAKE_PREFIX_PATH="$work/prefix" >/dev/null \
  || fail "the copied hook folder does not configure on its own"
cmake --build "$work/my_energy/build" >/dev/null || fail "the copied hook folder does not build on its own"
[ -f "$work/my_energy/build/libmoreau_hook_my_energy.so" ] || fail "the copied hook was not built"
sed -e 's/"plugin_paths": \["ext"\]/"plugin_paths": ["ext", "my_energy\/build"]/' \
  -e 's/"output": {/"hooks": [{"type": "my_energy", "file": "mine.csv", "every": 100}], "output": {/' \
  "$work/spring.json" > "$work/hook.json"
(cd "$work" && "$moreau" run hook.json --quiet) || fail "moreau run with the copied hook failed"
[ "$(wc -l < "$work/mine.csv")" -eq 42 ] || fail "the copied hook wrote $(wc -l < "$work/mine.csv") lines, expected 42"

echo "sdk install: external force and law built, loaded by name and validated; mismatched ABI refused; a copied user hook builds on its own"
