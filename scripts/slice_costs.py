#!/usr/bin/env python3
"""CPU time per counted unit of each member inside `auto`'s own slices (issue 15, point 3).

Runs each scene once with `auto` as its solver and MOREAU_AUTO_TRACE=1 (MOREAU_STAGE_CLOCK=cpu):
every slice's trace line gives its counted work and its thread CPU ns. Per member (NLGS's
first stage apart: it packs NLGS's body records) the slices are fitted by least squares as

    ns = fixed + per_unit * units

`per_unit` is what the cost model (plugins/solver/work.hpp) is for: one counted unit should
cost about the same CPU time in every member, so that `auto`'s choices by counted work are
choices by time. `fixed` is what a slice costs whatever its work (set-up, cold code): the
model does not count it. A whole-slice average (ns over units) mixes the two, which on
microsecond scenes makes the member with the shorter slices look dearer per unit.

    python3 scripts/slice_costs.py --moreau build/bin/moreau --steps 300 --tolerance 1e-3 \\
        --only cannonball_3d masonry_arch_2d box_tower_3d
"""
import argparse
import json
import os
import re
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import bench_scenes  # noqa: E402  (the scene list, solver blocks)

SLICE = re.compile(r"^auto: (first )?(\w+)(?: \[\w+\])?(?:, budget \S+, took| ) ?([0-9.e+-]+) work \(([0-9.e+-]+) ns\).*? it (\d+)", re.M)
CONTACTS = re.compile(r"^auto: solve \d+, contacts (\d+)", re.M)


def fit(points):
    """Least squares ns = a + b units; (a, b), or None below 5 slices."""
    n = len(points)
    if n < 5:
        return None
    mx = sum(u for u, _ in points) / n
    my = sum(t for _, t in points) / n
    sxx = sum((u - mx) ** 2 for u, _ in points)
    if sxx == 0:
        return None
    b = sum((u - mx) * (t - my) for u, t in points) / sxx
    return my - b * mx, b


def slices(moreau, scene, tolerance, steps, tmp):
    s = json.loads(json.dumps(scene))
    s["solver"], _ = bench_scenes.solver_block(scene, "auto", tolerance)
    path = os.path.join(tmp, "scene.json")
    json.dump(s, open(path, "w"))
    n = min(steps, round(s["time"]["duration"] / s["time"]["step"]))
    env = dict(os.environ, MOREAU_AUTO_TRACE="1", MOREAU_STAGE_CLOCK="cpu")
    p = subprocess.run([moreau, "run", path, "--out", os.path.join(tmp, "out.h5"), "--steps", str(n)],
                       capture_output=True, text=True, env=env)
    if p.returncode != 0:
        raise RuntimeError(p.stderr.strip().splitlines()[-1] if p.stderr.strip() else f"exit {p.returncode}")
    per = {}
    for m in SLICE.finditer(p.stderr):
        key = m.group(2) + (" first" if m.group(1) else "")
        per.setdefault(key, []).append((float(m.group(3)), float(m.group(4))))
    nc = [int(m.group(1)) for m in CONTACTS.finditer(p.stderr)]
    return per, (sum(nc) / len(nc) if nc else 0.0)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--moreau", default=os.path.join(bench_scenes.REPO, "build", "bin", "moreau"))
    ap.add_argument("--steps", type=int, default=300, help="steps per run (at most the scene's own)")
    ap.add_argument("--tolerance", type=float, help="one tolerance for every scene (default: each scene's own)")
    ap.add_argument("--only", nargs="+", metavar="NAME")
    ap.add_argument("--json", help="also write the fits here")
    a = ap.parse_args()
    scenes = bench_scenes.scenes(a.steps)
    unknown = [n for n in a.only or [] if n not in scenes]
    if unknown:
        ap.error(f"unknown scene {', '.join(unknown)}; valid: {' '.join(scenes)}")
    rows = {}
    print(f"{'scene':32s} {'contacts':>8s}  member: fixed ns + ns per counted unit (slices)")
    with tempfile.TemporaryDirectory() as tmp:
        for name in a.only or list(scenes):
            per, nc = slices(a.moreau, scenes[name], a.tolerance, a.steps, tmp)
            fits = {k: fit(v) for k, v in sorted(per.items())}
            rows[name] = {"contacts": nc, "fits": {k: {"fixed_ns": f[0], "ns_per_unit": f[1], "slices": len(per[k])}
                                                   for k, f in fits.items() if f}}
            cells = "  ".join(f"{k}: {f[0]:.0f} + {f[1]:.3f} ({len(per[k])})" for k, f in fits.items() if f)
            print(f"{name:32s} {nc:8.1f}  {cells}", flush=True)
    if a.json:
        json.dump(rows, open(a.json, "w"), indent=1)


if __name__ == "__main__":
    main()
