#!/usr/bin/env python3
"""A semicircular masonry arch of voussoirs under self-weight (docs/laws.md, "Masonry arch").

N voussoirs with radial joints, centreline radius R, thickness t, dry joints (Coulomb,
mu = 0.8: no sliding), on two fixed abutments. Limit analysis (Heyman's assumptions: no
tension, no sliding, no crushing) says it stands when t/R exceeds the minimum found by
Milankovitch (1907) for radial joints: t/R = 0.1075 (Makris & Alexakis 2013, Arch. Appl.
Mech. 83:1511; Heyman's approximate 0.106 in "The safety of masonry arches", 1969), and
collapses below it with hinges at the crown, at about 54.5 deg from it on the intrados,
and at the springings.

    python3 scripts/masonry_arch.py scene --t-over-r 0.10 --out configs/masonry_arch_2d.json
    python3 scripts/masonry_arch.py threshold --moreau build/bin/moreau --voussoirs 36
    python3 scripts/masonry_arch.py hinges --moreau build/bin/moreau --t-over-r 0.105

`threshold` bisects t/R between 0.09 and 0.13 (collapse: a voussoir moved more than 1 mm
after 3 s) and prints the bracket; `hinges` runs a collapse and prints the joints whose
relative rotation exceeds a fifth of the largest.
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

from make_law_scenes import write_scene  # the scene as JSON, one body per line

MILANKOVITCH = 0.1075


def scene(t_over_r, voussoirs=36, radius=1.0, friction=0.8, duration=3.0, step=5e-4, every=100, floor=False):
    t = t_over_r * radius
    ri, ro = radius - t / 2, radius + t / 2
    bodies = []
    for name, x in (("left_abutment", -radius), ("right_abutment", radius)):
        bodies.append({"name": name, "fixed": True, "position": [x, -0.1],
                       "contactors": [{"shape": "polygon", "vertices": [[-t, -0.1], [t, -0.1], [t, 0.1], [-t, 0.1]],
                                       "group": "ground"}]})
    if floor:  # where the pieces of a collapse land, below the springings
        bodies.append({"name": "floor", "fixed": True, "position": [0, -0.3],
                       "contactors": [{"shape": "polygon", "vertices": [[-3, -0.1], [3, -0.1], [3, 0.1], [-3, 0.1]],
                                       "group": "ground"}]})
    for i in range(voussoirs):
        a0, a1 = math.pi * i / voussoirs, math.pi * (i + 1) / voussoirs
        am = 0.5 * (a0 + a1)
        c = [radius * math.cos(am), radius * math.sin(am)]
        corners = [(ri, a0), (ro, a0), (ro, a1), (ri, a1)]
        vertices = [[round(r * math.cos(a) - c[0], 15), round(r * math.sin(a) - c[1], 15)] for r, a in corners]
        bodies.append({"name": "v%02d" % i, "material": "stone", "position": c,
                       "contactors": [{"shape": "polygon", "vertices": vertices, "group": "stone"}]})
    return {"format": "moreau-scene/1", "dimension": 2, "time": {"step": step, "duration": duration},
            "gravity": [0, -9.81], "materials": {"stone": {"density": 2500}},
            "laws": {"dry_joint": {"type": "coulomb", "friction": friction}},
            "interactions": [{"groups": ["stone", "stone"], "law": "dry_joint"},
                             {"groups": ["stone", "ground"], "law": "dry_joint"}],
            "detection": {"alert": 1e-3},
            "solver": {"type": "auto", "tolerance": 1e-8},
            "output": {"every": every}, "bodies": bodies}


def run(moreau, s, folder):
    path = os.path.join(folder, "arch.json")
    with open(path, "w") as f:
        json.dump(s, f)
    subprocess.run([moreau, "run", path, "--out", os.path.join(folder, "arch.h5"), "--quiet"], check=True,
                   capture_output=True)
    import h5py
    return h5py.File(os.path.join(folder, "arch.h5"), "r")


def largest_displacement(f):
    frames = sorted(f["frames"].keys())
    x0, x1 = f["frames"][frames[0]]["position"][:], f["frames"][frames[-1]]["position"][:]
    return float(abs(x1 - x0).max())


def threshold(args):
    lo, hi = 0.09, 0.13
    with tempfile.TemporaryDirectory() as folder:
        while hi - lo > args.resolution:
            mid = 0.5 * (lo + hi)
            f = run(args.moreau, scene(mid, args.voussoirs, every=10000), folder)
            moved = largest_displacement(f)
            f.close()
            collapses = moved > 1e-3
            print("t/R = %.5f: %s (largest displacement after 3 s %.2e m)" % (mid, "collapses" if collapses else "stands",
                                                                                  moved), flush=True)
            if collapses:
                lo = mid
            else:
                hi = mid
    print("%d voussoirs: threshold t/R in [%.5f, %.5f]; Milankovitch (radial joints, continuous arch) %.4f: %+.2f %%"
          % (args.voussoirs, lo, hi, MILANKOVITCH, 100 * (0.5 * (lo + hi) / MILANKOVITCH - 1)))


def hinges(args):
    with tempfile.TemporaryDirectory() as folder:
        f = run(args.moreau, scene(args.t_over_r, args.voussoirs, duration=0.5, every=100), folder)
        frames = sorted(f["frames"].keys())
        n = args.voussoirs
        for fr in frames[1:]:
            angle = f["frames"][fr]["angle"][:]
            a = [0.0] + list(angle[2:2 + n]) + [0.0]  # the abutments do not turn
            rel = [a[j + 1] - a[j] for j in range(n + 1)]  # joint j: between voussoirs j-1 and j
            top = max(abs(r) for r in rel)
            joints = [j for j in range(n + 1) if abs(rel[j]) > 0.2 * top]
            print("t = %.2f s: largest joint rotation %.2e rad; hinges at joints %s, %s deg from the crown" % (
                f["frames"][fr].attrs["time"], top, joints, [round(abs(90 - 180.0 * j / n), 1) for j in joints]))
        f.close()


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = p.add_subparsers(dest="command", required=True)
    s = sub.add_parser("scene", help="write a scene")
    s.add_argument("--t-over-r", type=float, default=0.10)
    s.add_argument("--voussoirs", type=int, default=36)
    s.add_argument("--out", required=True)
    t = sub.add_parser("threshold", help="bisect the t/R at which the arch collapses")
    t.add_argument("--moreau", default="build/bin/moreau")
    t.add_argument("--voussoirs", type=int, default=36)
    t.add_argument("--resolution", type=float, default=2e-4)
    h = sub.add_parser("hinges", help="the joints that hinge in a collapse")
    h.add_argument("--moreau", default="build/bin/moreau")
    h.add_argument("--voussoirs", type=int, default=36)
    h.add_argument("--t-over-r", type=float, default=0.105)
    args = p.parse_args()
    if args.command == "scene":
        s = scene(args.t_over_r, args.voussoirs, floor=True)
        s["output"]["file"] = "masonry_arch_2d.h5"
        write_scene(s, args.out)
    elif args.command == "threshold":
        threshold(args)
    else:
        hinges(args)


if __name__ == "__main__":
    sys.exit(main())
