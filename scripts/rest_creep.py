#!/usr/bin/env python3
"""Creep of bodies at rest: how far the bodies of a 2D scene drift over a run, per solver.

Runs SCENE once per solver (its `solver` block replaced by {"type": S, "tolerance": T}, the
output every --every steps) and prints, per run, the largest displacement of any body from
its position at step --from to each later frame (every fifth frame shown), the largest
rotation over the same span, and the deepest overlap (most negative gap) of the last frame.
A wall or a stack at rest should not move; what a solver leaves within its tolerance at
every step can add up into a slow drift (docs/solvers-history.md, "A step at rest", in "`auto`: the rule with the measurements behind each part").

    python3 scripts/rest_creep.py configs/mortar_wall_2d.json --solvers auto apgd \
        --tolerance 1e-8 [--from 500] [--every 20] [--moreau build/bin/moreau]

Environment variables (MOREAU_*) are passed to the runs.
"""
import argparse
import json
import os
import subprocess
import tempfile

import h5py
import numpy as np


def run(moreau, scene, solver, tolerance, every, tmp):
    s = json.load(open(scene))
    s["solver"] = {"type": solver, "tolerance": tolerance}
    s["output"] = {"file": "creep.h5", "every": every}
    path = os.path.join(tmp, f"{solver}.json")
    out = os.path.join(tmp, f"{solver}.h5")
    json.dump(s, open(path, "w"))
    subprocess.run([moreau, "run", path, "--out", out], check=True, capture_output=True)
    return out


def creep(path, start, every):
    f = h5py.File(path, "r")
    frames = sorted(f["frames"].keys())
    i0 = min(len(frames) - 1, start // every)
    pos = np.array([np.array(f["frames"][k]["position"]) for k in frames])
    ang = np.array([np.array(f["frames"][k]["angle"]) for k in frames])
    drift = [float(np.abs(p - pos[i0]).max()) for p in pos[i0:]]
    rot = float(np.abs(ang[i0:] - ang[i0]).max())
    gap = np.array(f["frames"][frames[-1]]["contacts/gap"])
    return drift, rot, float(gap.min()) if gap.size else float("nan")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("scene")
    ap.add_argument("--solvers", nargs="+", default=["auto", "apgd", "nlgs"])
    ap.add_argument("--tolerance", type=float, required=True)
    ap.add_argument("--from", dest="start", type=int, default=500, help="the step from which drift is measured")
    ap.add_argument("--every", type=int, default=20, help="output every this many steps")
    ap.add_argument("--moreau", default="build/bin/moreau")
    a = ap.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        for solver in a.solvers:
            out = run(a.moreau, a.scene, solver, a.tolerance, a.every, tmp)
            drift, rot, gap = creep(out, a.start, a.every)
            shown = " ".join(f"{d:.1e}" for d in drift[::5])
            print(f"{solver:6s} tol {a.tolerance:.0e}: drift from step {a.start} to the end {drift[-1]:.2e} m "
                  f"(max {max(drift):.2e}), rotation {rot:.2e} rad, deepest overlap {gap:.2e} m")
            print(f"       drift every {5 * a.every} steps: {shown}")


if __name__ == "__main__":
    main()
