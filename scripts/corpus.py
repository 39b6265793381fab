#!/usr/bin/env python3
"""The solver corpus (issue 15): contact problems that represent real use, made from scenes.

Writes OUT/scenes/*.json (generated scenes and every example scene of configs/ that has
contacts, each with `export_problems` at an early step (impacts) and a late one (settled)),
runs them, and collects the exported FCLib local problems in OUT/problems/ (each file keeps
the run's warm start in /guesses/1/r, so it can be solved cold or warm). Then

    python3 scripts/work_precision.py --corpus OUT --out OUT/wp

runs every member and `auto` on all of it (shared FCLib files included) and writes the
guarantee table (guarantee.md).

    python3 scripts/corpus.py [--moreau build/bin/moreau] [--out build/corpus] [--size reduced|full]
                              [--only NAME ...] [--list]

`reduced` (the test suite's corpus, about a minute): small scenes of every family.
`full` (the documented corpus, about 15 minutes on 2 cores): adds the large ones (up to
10^4 spheres, about 3·10^4 contacts, and 3000 disks) and the silo of issue 15.
Deterministic: every scene is seeded.
"""
import argparse
import json
import math
import os
import random
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)


def fail(msg):
    print(f"corpus: error: {msg}", file=sys.stderr)
    sys.exit(2)


# ---- generated scenes -------------------------------------------------------------------

def walls_2d(width, height, thickness=0.01):
    w = width / 2 + thickness / 2
    return [
        {"name": "floor", "fixed": True, "position": [0, -thickness / 2],
         "contactors": [{"shape": "segment", "length": width + 2 * thickness, "thickness": thickness, "group": "wall"}]},
        {"name": "left", "fixed": True, "position": [-w, height / 2], "angle": math.pi / 2,
         "contactors": [{"shape": "segment", "length": height, "thickness": thickness, "group": "wall"}]},
        {"name": "right", "fixed": True, "position": [w, height / 2], "angle": math.pi / 2,
         "contactors": [{"shape": "segment", "length": height, "thickness": thickness, "group": "wall"}]},
    ]


def scene(dim, h, steps, bodies, mu_grain, mu_wall, solver=None, alert=None, export=None, density=2600.0):
    s = {"format": "moreau-scene/1", "dimension": dim, "time": {"step": h, "duration": steps * h},
         "gravity": [0, -9.81] if dim == 2 else [0, 0, -9.81],
         "materials": {"grain": {"density": density}},
         "laws": {"gg": {"type": "coulomb", "friction": mu_grain}, "gw": {"type": "coulomb", "friction": mu_wall}},
         "bodies": bodies,
         "interactions": [{"groups": ["grain", "grain"], "law": "gg"}, {"groups": ["grain", "wall"], "law": "gw"}],
         "output": {"file": "out.h5", "every": max(1, steps // 4), "display": "points"}}
    if alert is not None:
        s["detection"] = {"alert": alert}
    if solver:
        s["solver"] = solver
    if export:
        s["export_problems"] = {"steps": export, "directory": "problems"}
    return s


def disks_2d(n, mu, seed, dense=True, r=0.005, steps=600, h=5e-4):
    """n disks (radius r ± 10 %) in a box; dense: a lattice dropped from 0.5 r apart (a pile
    forms), loose: spread out and thrown (few contacts per grain)."""
    rng = random.Random(seed)
    cols = max(4, int(math.sqrt(n) * (1.0 if dense else 2.0)))
    pitch = 2.5 * r if dense else 4.0 * r  # radii up to 1.1 r, jitter 0.1 r: no initial overlap
    width = cols * pitch
    rows = math.ceil(n / cols)
    bodies = walls_2d(width, rows * pitch + 0.1)
    for k in range(n):
        i, j = k % cols, k // cols
        bodies.append({"name": f"d{k}", "material": "grain",
                       "position": [round(-width / 2 + (i + 0.5) * pitch + rng.uniform(-0.1, 0.1) * r, 7),
                                    round(r * 1.2 + j * pitch, 7)],
                       "velocity": [round(rng.uniform(-0.05, 0.05), 4), 0 if dense else round(rng.uniform(-0.5, 0), 4)],
                       "contactors": [{"shape": "disk", "radius": round(r * rng.uniform(0.9, 1.1), 7), "group": "grain"}]})
    return scene(2, h, steps, bodies, mu, mu, alert=0.2 * r, export=[5, steps])


def silo_2d(steps=1500, seed=15):
    """The silo of issue 15: 405 disks of radius 1.5 mm ± 10 % between two walls, μ = 0.25,
    h = 2e-4 (about 950 contacts once settled)."""
    rng = random.Random(seed)
    r, n, cols = 0.0015, 405, 15
    pitch = 2.5 * r
    width = cols * pitch
    bodies = walls_2d(width, 0.2, thickness=0.002)
    for k in range(n):
        i, j = k % cols, k // cols
        bodies.append({"name": f"g{k}", "material": "grain",
                       "position": [round(-width / 2 + (i + 0.5) * pitch + rng.uniform(-0.1, 0.1) * r, 7),
                                    round(r * 1.2 + j * pitch, 7)],
                       "contactors": [{"shape": "disk", "radius": round(r * rng.uniform(0.9, 1.1), 7), "group": "grain"}]})
    return scene(2, 2e-4, steps, bodies, 0.25, 0.25, export=[10, steps])


def polygons_2d(n, mu, seed, steps=600, h=5e-4, r=0.006):
    """n random convex polygons (5 to 7 corners, radius r ± 20 %) dropped in a box."""
    rng = random.Random(seed)
    cols = max(4, int(math.sqrt(n)))
    pitch = 2.4 * r
    width = cols * pitch
    bodies = walls_2d(width, math.ceil(n / cols) * pitch + 0.1)
    for k in range(n):
        i, j = k % cols, k // cols
        m = rng.randint(5, 7)
        rad = r * rng.uniform(0.8, 1.0)
        start = rng.uniform(0, 2 * math.pi)
        verts = [[round(rad * math.cos(start + 2 * math.pi * (c + rng.uniform(-0.2, 0.2)) / m), 7),
                  round(rad * math.sin(start + 2 * math.pi * (c + rng.uniform(-0.2, 0.2)) / m), 7)] for c in range(m)]
        bodies.append({"name": f"p{k}", "material": "grain",
                       "position": [round(-width / 2 + (i + 0.5) * pitch, 7), round(1.2 * r + j * pitch, 7)],
                       "contactors": [{"shape": "polygon", "vertices": verts, "group": "grain"}]})
    return scene(2, h, steps, bodies, mu, mu, alert=0.1 * r, export=[5, steps])


def spheres_3d(n, mu, seed, steps=400, h=5e-4, r=0.01, touching=False):
    """n spheres (radius r ± 10 %) as a jittered lattice in a box with a floor and four
    walls; `touching`: the bench_spheres lattice (about 3 contacts per sphere at once)."""
    rng = random.Random(seed)
    side = max(2, round(n ** (1 / 3)))
    pitch = 2 * r if touching else 2.3 * r
    L = side * pitch
    planes = [("floor", [0, 0, 0], [0, 0, 1]), ("x0", [0, 0, 0], [1, 0, 0]), ("x1", [L, 0, 0], [-1, 0, 0]),
              ("y0", [0, 0, 0], [0, 1, 0]), ("y1", [0, L, 0], [0, -1, 0])]
    bodies = [{"name": nm, "fixed": True, "position": p, "contactors": [{"shape": "plane", "normal": nr, "group": "wall"}]}
              for nm, p, nr in planes]
    for k in range(n):
        x, y, z = k % side, (k // side) % side, k // (side * side)
        jit = 0 if touching else 0.1 * r
        bodies.append({"name": f"s{k}", "material": "grain",
                       "position": [round(pitch / 2 + x * pitch + rng.uniform(-jit, jit), 7),
                                    round(pitch / 2 + y * pitch + rng.uniform(-jit, jit), 7),
                                    round(r + z * pitch, 7)],
                       "contactors": [{"shape": "sphere", "radius": r if touching else round(r * rng.uniform(0.9, 1.0), 7),
                                       "group": "grain"}]})
    return scene(3, h, steps, bodies, mu, mu, alert=0.1 * r, export=[2, steps] if touching else [5, steps])


def box_wall_3d(courses=9, per=5, mu=0.6, steps=300, h=1e-3):
    """A running-bond wall of boxes standing on a plane (issue 15: 45 boxes, about 450 contacts)."""
    bx, by, bz = 0.2, 0.1, 0.05
    bodies = [{"name": "floor", "fixed": True, "position": [0, 0, 0], "contactors": [{"shape": "plane", "group": "wall"}]}]
    for c in range(courses):
        shift = 0.5 * bx if c % 2 else 0.0
        for k in range(per):
            bodies.append({"name": f"b{c}_{k}", "material": "grain",
                           "position": [round(k * bx + shift, 7), 0, round(bz / 2 + c * bz, 7)],
                           "contactors": [{"shape": "box", "size": [bx, by, bz], "group": "grain"}]})
    return scene(3, h, steps, bodies, mu, mu, alert=0.002, export=[1, steps], density=2000)


def convex_pile_3d(n, mu, seed, steps=400, h=1e-3, r=0.02):
    """n convex rocks (8 to 12 random corners on a sphere of radius r ± 20 %) dropped on a floor."""
    rng = random.Random(seed)
    side = max(2, round(math.sqrt(n)))
    pitch = 2.6 * r
    bodies = [{"name": "floor", "fixed": True, "position": [0, 0, 0], "contactors": [{"shape": "plane", "group": "wall"}]}]
    for k in range(n):
        m = rng.randint(8, 12)
        rad = r * rng.uniform(0.8, 1.2)
        verts = []
        for _ in range(m):
            z = rng.uniform(-1, 1)
            t = rng.uniform(0, 2 * math.pi)
            s = math.sqrt(1 - z * z)
            verts.append([round(rad * s * math.cos(t), 7), round(rad * s * math.sin(t), 7), round(rad * z, 7)])
        x, y, z = k % side, (k // side) % side, k // (side * side)
        bodies.append({"name": f"c{k}", "material": "grain",
                       "position": [round(x * pitch, 7), round(y * pitch, 7), round(1.3 * r + z * pitch, 7)],
                       "contactors": [{"shape": "convex", "vertices": verts, "group": "grain"}]})
    return scene(3, h, steps, bodies, mu, mu, alert=0.002, export=[5, steps])


def mass_ratio_2d(n=60, ratio=1e6, steps=400, seed=11):
    """Issue 11: a pile where every tenth grain is `ratio` times denser."""
    s = disks_2d(n, 0.3, seed, steps=steps)
    s["materials"]["heavy"] = {"density": 2600.0 * ratio}
    k = 0
    for b in s["bodies"]:
        if b.get("material") == "grain":
            if k % 10 == 0:
                b["material"] = "heavy"
            k += 1
    return s


def generated(size):
    """name → scene, for the corpus size."""
    g = {}
    for mu in (0.0, 0.3, 1.0):
        g[f"disks2d_dense_60_mu{mu:g}"] = disks_2d(60, mu, 1)
    g["disks2d_loose_60_mu0.5"] = disks_2d(60, 0.5, 2, dense=False)
    g["disks2d_massratio_60"] = mass_ratio_2d()
    g["polygons2d_40_mu0.5"] = polygons_2d(40, 0.5, 3, steps=400)
    g["spheres3d_64_mu0.3"] = spheres_3d(64, 0.3, 4, steps=300)
    g["boxwall3d_15"] = box_wall_3d(courses=3, per=5, steps=150)
    g["convex3d_8_mu0.6"] = convex_pile_3d(8, 0.6, 5, steps=300)
    if size == "full":
        g["disks2d_dense_400_mu0.3"] = disks_2d(400, 0.3, 6)
        g["disks2d_dense_3000_mu0.5"] = disks_2d(3000, 0.5, 7, steps=400)
        g["silo2d_405_mu0.25"] = silo_2d()
        g["polygons2d_300_mu0.7"] = polygons_2d(300, 0.7, 8)
        g["spheres3d_1000_mu0.3"] = spheres_3d(1000, 0.3, 9, steps=400)
        g["spheres3d_10000_touching_mu0.3"] = spheres_3d(10000, 0.3, 10, steps=3, touching=True)
        g["boxwall3d_45"] = box_wall_3d()
        g["convex3d_27_mu1"] = convex_pile_3d(27, 1.0, 12)
    return g


def examples(size):
    """Every example scene of configs/ with contacts, exported at step 5 and at its last
    step (at most 400 steps in; 100 for the reduced corpus)."""
    out = {}
    cfg = os.path.join(REPO, "configs")
    for f in sorted(os.listdir(cfg)):
        if not f.endswith(".json"):
            continue
        s = json.load(open(os.path.join(cfg, f)))
        if not s.get("interactions"):
            continue
        total = round(s["time"]["duration"] / s["time"]["step"])
        last = min(total, 400 if size == "full" else 100)
        s["time"]["duration"] = last * s["time"]["step"]
        s["export_problems"] = {"steps": sorted({min(5, last), last}), "directory": "problems"}
        s["output"] = {"file": "out.h5", "every": max(1, last // 4), "display": "points"}
        out["example_" + f[:-5]] = s
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--moreau", default=os.path.join(REPO, "build", "bin", "moreau"))
    ap.add_argument("--out", default=os.path.join(REPO, "build", "corpus"))
    ap.add_argument("--size", choices=["reduced", "full"], default="reduced")
    ap.add_argument("--only", nargs="+", metavar="NAME", help="only these scenes (names as --list prints)")
    ap.add_argument("--list", action="store_true", help="print the scene names and stop")
    a = ap.parse_args()
    scenes = {**generated(a.size), **examples(a.size)}
    if a.list:
        print("\n".join(scenes))
        return
    if a.only:
        unknown = [n for n in a.only if n not in scenes]
        if unknown:
            fail(f"no scene {', '.join(unknown)}; --list shows them")
        scenes = {n: scenes[n] for n in a.only}
    moreau = os.path.abspath(a.moreau)
    if not os.access(moreau, os.X_OK):
        fail(f"no moreau binary at {moreau}")
    sdir, pdir = os.path.join(a.out, "scenes"), os.path.join(a.out, "problems")
    os.makedirs(sdir, exist_ok=True)
    os.makedirs(pdir, exist_ok=True)
    for name, s in scenes.items():
        path = os.path.join(sdir, name + ".json")
        with open(path, "w") as f:
            json.dump(s, f, indent=1)
        run = os.path.join(a.out, "runs", name)
        shutil.rmtree(run, ignore_errors=True)
        os.makedirs(run)
        p = subprocess.run([moreau, "run", path, "--out", os.path.join(run, "out.h5"), "--quiet"],
                           capture_output=True, text=True)
        if p.returncode != 0:
            fail(f"{name}: moreau run failed (exit {p.returncode}):\n{p.stderr.strip()}")
        made = sorted(os.listdir(os.path.join(run, "problems"))) if os.path.isdir(os.path.join(run, "problems")) else []
        for m in made:  # <scene>-stepNNNNNNNN.hdf5, renamed after the corpus scene
            shutil.copy(os.path.join(run, "problems", m), os.path.join(pdir, name + m[m.rindex("-step"):]))
        shutil.rmtree(run)
        print(f"{name:40s} {len(made)} problems{'  ' + p.stderr.strip().splitlines()[-1] if p.stderr.strip() else ''}",
              flush=True)
    print(f"wrote {len(os.listdir(pdir))} problems in {pdir}")


if __name__ == "__main__":
    main()
