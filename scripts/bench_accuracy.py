#!/usr/bin/env python3
"""Run time against error for whole scenes (issue 15, point 8): which time step and solver
tolerance buy which accuracy at what cost.

Cases with analytic answers (a ball bouncing with restitution, a disk rolling down an
incline, a column of disks at rest, Newton's cradle) and one granular scene against a fine
reference (60 disks poured in a box; reference: h / 8 at tolerance 1e-8). Each runs at
every time step of --steps and every `auto` tolerance of --tolerances; the error and the
run's wall time (moreau's stage table: total less output) go into OUT/accuracy.csv, and
OUT/accuracy.png draws error against h and against wall time, one panel pair per case.

    python3 scripts/bench_accuracy.py [--moreau build/bin/moreau] [--out build/accuracy]
        [--steps 2e-3 1e-3 5e-4 2.5e-4] [--tolerances 1e-2 1e-3 1e-4 1e-6]
"""
import argparse
import csv
import json
import math
import os
import re
import subprocess
import sys
import tempfile

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import corpus  # noqa: E402  (the granular scene)

G = 9.81


def base(dim, h, duration, bodies, laws, interactions, tol, every=1, gravity=True):
    g = ([0, -G] if dim == 2 else [0, 0, -G]) if gravity else ([0, 0] if dim == 2 else [0, 0, 0])
    return {"format": "moreau-scene/1", "dimension": dim, "time": {"step": h, "duration": duration},
            "gravity": g, "materials": {"m": {"density": 1000}}, "laws": laws, "bodies": bodies,
            "interactions": interactions, "solver": {"type": "auto", "tolerance": tol},
            "output": {"file": "out.h5", "every": every, "display": "points"}}


# ---- cases: scene(h, tol) and error(file) -------------------------------------------------

def bounce(h, tol):
    """A sphere (r = 0.1) dropped from 1 m above a plane, e = 0.8: the first apex is e² · 1 m."""
    bodies = [{"name": "floor", "fixed": True, "position": [0, 0, 0], "contactors": [{"shape": "plane", "group": "w"}]},
              {"name": "ball", "material": "m", "position": [0, 0, 1.1], "contactors": [{"shape": "sphere", "radius": 0.1, "group": "b"}]}]
    # A frame every millisecond: near the apex z moves by g (0.5 ms)² / 2 ≈ 1e-6 m between frames.
    return base(3, h, 1.2, bodies, {"e": {"type": "coulomb", "friction": 0, "restitution": 0.8}},
                [{"groups": ["b", "w"], "law": "e"}], tol, every=max(1, round(1e-3 / h)))


def bounce_error(f):
    z = np.array([f["frames"][k]["position"][1, 2] for k in sorted(f["frames"])])
    hit = int(np.argmin(z[: len(z) // 2 + len(z) // 4]))  # the impact, before the apex
    return abs((z[hit:].max() - 0.1) - 0.64) / 0.64


def rolling(h, tol):
    """A disk (r = 0.05) rolling without slip down a 20° incline (μ = 0.5 > tan α / 3):
    s(t) = (1/3) g sin α t²; error of s at t = 0.5 s relative to s."""
    a = math.radians(20)
    n = [math.sin(a), math.cos(a)]  # the normal of a segment turned by −a (it descends to +x)
    c = [-0.005 * n[0], -0.005 * n[1]]  # the slab's centre: its surface through the origin
    bodies = [{"name": "slope", "fixed": True, "position": c, "angle": -a,
               "contactors": [{"shape": "segment", "length": 4, "thickness": 0.01, "group": "w"}]},
              {"name": "disk", "material": "m", "position": [0.05 * n[0], 0.05 * n[1]],
               "contactors": [{"shape": "disk", "radius": 0.05, "group": "b"}]}]
    return base(2, h, 0.5, bodies, {"r": {"type": "coulomb", "friction": 0.5}}, [{"groups": ["b", "w"], "law": "r"}], tol,
                every=10 ** 9)


def rolling_error(f):
    a = math.radians(20)
    k = sorted(f["frames"])
    p0, p1 = f["frames"][k[0]]["position"][1], f["frames"][k[-1]]["position"][1]
    s = math.hypot(p1[0] - p0[0], p1[1] - p0[1])
    t = float(f["frames"][k[-1]].attrs["time"])
    exact = G * math.sin(a) * t * t / 3
    return abs(s - exact) / exact


def column(h, tol):
    """Five frictionless disks (r = 0.05) stacked on a floor: the floor carries their weight."""
    bodies = [{"name": "floor", "fixed": True, "position": [0, -0.005],
               "contactors": [{"shape": "segment", "length": 1, "thickness": 0.01, "group": "w"}]}]
    for i in range(5):
        bodies.append({"name": f"d{i}", "material": "m", "position": [0, 0.05 + 0.1 * i],
                       "contactors": [{"shape": "disk", "radius": 0.05, "group": "b"}]})
    return base(2, h, 0.5, bodies, {"s": {"type": "coulomb", "friction": 0}},
                [{"groups": ["b", "b"], "law": "s"}, {"groups": ["b", "w"], "law": "s"}], tol, every=10 ** 9)


def column_error(f):
    fr = f["frames"][sorted(f["frames"])[-1]]
    b = fr["contacts/bodies"][:]
    fn = fr["contacts/normal_force"][:]
    W = 5 * 1000 * math.pi * 0.05 ** 2 * G
    return abs(fn[(b == 0).any(axis=1)].sum() - W) / W


def cradle(h, tol):
    """Newton's cradle: 5 spheres (r = 0.05, 1 mm apart), no gravity, e = 1, the first at
    1 m/s: after the collisions the last moves at 1 m/s and the others rest."""
    bodies = [{"name": f"s{i}", "material": "m", "position": [0.101 * i, 0, 0],
               "velocity": [1 if i == 0 else 0, 0, 0], "contactors": [{"shape": "sphere", "radius": 0.05, "group": "b"}]}
              for i in range(5)]
    s = base(3, h, 0.1, bodies, {"e": {"type": "coulomb", "friction": 0, "restitution": 1}},
             [{"groups": ["b", "b"], "law": "e"}], tol, every=10 ** 9, gravity=False)
    s["detection"] = {"alert": 0.002}
    return s


def cradle_error(f):
    v = f["frames"][sorted(f["frames"])[-1]]["velocity"][:, 0]
    return float(np.abs(v - np.array([0, 0, 0, 0, 1.0])).max())


def pile(h, tol):
    """60 disks poured in a box (scripts/corpus.py disks_2d), 0.3 s."""
    s = corpus.disks_2d(60, 0.3, 1, steps=max(1, round(0.3 / h)), h=h)
    s.pop("export_problems", None)
    s["solver"] = {"type": "auto", "tolerance": tol}
    s["output"] = {"file": "out.h5", "every": 10 ** 9, "display": "points"}
    return s


def pile_height(f):
    p = f["frames"][sorted(f["frames"])[-1]]["position"][3:, 1]
    return float(p.mean())


CASES = {"bounce": (bounce, bounce_error), "rolling": (rolling, rolling_error), "column": (column, column_error),
         "cradle": (cradle, cradle_error), "pile": (pile, None)}


def run(moreau, scene, tmp):
    path = os.path.join(tmp, "s.json")
    json.dump(scene, open(path, "w"))
    out = os.path.join(tmp, "out.h5")
    p = subprocess.run([moreau, "run", path, "--out", out], capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit(f"bench_accuracy: moreau run failed:\n{p.stderr}")
    stages = {m.group(1): float(m.group(2)) for m in re.finditer(r"^\s+(\w+)\s+([0-9.]+) s", p.stderr, re.M)}
    # Compute time: the run without its output stage (frames every step for the bounce).
    return h5py.File(out, "r"), stages["total"] - stages.get("output", 0.0)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--moreau", default=os.path.join(REPO, "build", "bin", "moreau"))
    ap.add_argument("--out", default=os.path.join(REPO, "build", "accuracy"))
    ap.add_argument("--steps", nargs="+", type=float, default=[2e-3, 1e-3, 5e-4, 2.5e-4])
    ap.add_argument("--tolerances", nargs="+", type=float, default=[1e-2, 1e-3, 1e-4, 1e-6])
    ap.add_argument("--cases", nargs="+", default=list(CASES))
    ap.add_argument("--from-csv", nargs="+", metavar="CSV", help="no runs: plot the rows of these accuracy.csv files")
    a = ap.parse_args()
    moreau = os.path.abspath(a.moreau)
    os.makedirs(a.out, exist_ok=True)
    rows = []
    for f in a.from_csv or []:
        rows += [{"case": r["case"], "h": float(r["h"]), "tolerance": float(r["tolerance"]), "error": float(r["error"]),
                  "seconds": float(r["seconds"])} for r in csv.DictReader(open(f)) if r["case"] in a.cases]
    with tempfile.TemporaryDirectory() as tmp:
        for name in ([] if a.from_csv else a.cases):
            make, error = CASES[name]
            ref = None
            if error is None:  # the granular scene: against a fine reference
                f, _ = run(moreau, make(min(a.steps) / 8, 1e-8), tmp)
                ref = pile_height(f)
                f.close()
            for tol in a.tolerances:
                for h in a.steps:
                    f, secs = run(moreau, make(h, tol), tmp)
                    err = error(f) if error else abs(pile_height(f) - ref) / 0.005  # in grain radii
                    f.close()
                    rows.append({"case": name, "h": h, "tolerance": tol, "error": err, "seconds": secs})
                    print(f"{name:8s} h {h:.1e} tol {tol:.0e}  error {err:.3e}  {secs:.3f} s", flush=True)
    with open(os.path.join(a.out, "accuracy.csv"), "w", newline="") as fh:
        w = csv.DictWriter(fh, fieldnames=list(rows[0]))
        w.writeheader()
        w.writerows(rows)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, len(a.cases), figsize=(4 * len(a.cases), 7), squeeze=False)
    for j, name in enumerate(a.cases):
        for tol in a.tolerances:
            rs = [r for r in rows if r["case"] == name and r["tolerance"] == tol]
            e = [max(r["error"], 1e-16) for r in rs]
            axes[0][j].loglog([r["h"] for r in rs], e, "o-", label=f"tol {tol:.0e}")
            by_time = sorted(zip([r["seconds"] for r in rs], e))
            axes[1][j].loglog([t for t, _ in by_time], [x for _, x in by_time], "o-", label=f"tol {tol:.0e}")
        axes[0][j].set_title(name)
        axes[0][j].set_xlabel("time step h (s)")
        axes[1][j].set_xlabel("wall time (s)")
        axes[0][j].set_ylabel("error" + (" (grain radii)" if name == "pile" else " (relative)"))
        axes[1][j].set_ylabel(axes[0][j].get_ylabel())
        axes[0][j].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(a.out, "accuracy.png"), dpi=90)
    print(f"wrote {a.out}/accuracy.csv and accuracy.png")


if __name__ == "__main__":
    main()
