#!/usr/bin/env python3
"""Time per step of elastic (finite-element) bodies against their number of DOFs, in 2D and
3D (issue 12, Performance): a clamped elastic slab (Q4 rectangle, H8 box) with rigid
disks/spheres falling on it, run through `moreau run`; the run's own stage table splits a
step into free velocity (RHS and the back-substitution of LHS_ff), W build (H and the
blocks of LHS⁻¹ among the contact nodes: the stage table's "(of which W assembly)"), solve
(the contact solve), update (LHS⁻¹ Hᵀr, positions; stresses only for written frames)
and the rest; set-up (mesh, matrices, the one factorisation of LHS_ff) is the wall time
before the first step. Peak memory is the process's maximum resident set.

    nice -n 19 python3 scripts/bench_elastic.py --moreau build/bin/moreau [--steps 20] [--quick] [--cases 3:0.014]

With MOREAU_STAGE_CLOCK=cpu in the environment every figure is processor time (the
stages', and the set-up's: the process's user + system time minus the stages'), steadier
than wall time on a shared machine.

Prints a Markdown table (docs/deformable.md, "Benchmark: time per step").
"""
import argparse
import json
import os
import re
import subprocess
import tempfile
import time


def scene(dim, size, steps):
    h = 1e-3
    if dim == 2:
        mesh = {"generate": "rectangle", "origin": [-0.5, -0.1], "extent": [1.0, 0.1], "size": size, "element": "Q4"}
        grains = [{"name": f"g{i}", "material": "hard", "position": [-0.3 + 0.15 * i, 0.0505], "velocity": [0, -1],
                   "contactors": [{"shape": "disk", "radius": 0.05, "group": "grain"}]} for i in range(5)]
        boundary, facet, gravity = "ymax", "edge", [0, -9.81]
    else:
        mesh = {"generate": "box", "origin": [-0.5, -0.5, -0.1], "extent": [1.0, 1.0, 0.1], "size": size, "element": "H8"}
        grains = [{"name": f"g{i}{j}", "material": "hard", "position": [-0.3 + 0.3 * i, -0.3 + 0.3 * j, 0.0505],
                   "velocity": [0, 0, -1], "contactors": [{"shape": "sphere", "radius": 0.05, "group": "grain"}]}
                  for i in range(3) for j in range(3)]
        boundary, facet, gravity = "zmax", "face", [0, 0, -9.81]
    slab = {"name": "slab", "model": "elastic", "material": "soft", "mesh": mesh, "fixed": ["xmin", "xmax"],
            "contactors": [{"shape": facet, "boundary": boundary, "group": "slab"}]}
    return {"format": "moreau-scene/1", "dimension": dim, "time": {"step": h, "duration": steps * h, "theta": 0.5},
            "gravity": gravity,
            "materials": {"soft": {"density": 1000, "young": 1e7, "poisson": 0.3}, "hard": {"density": 2000}},
            "laws": {"rough": {"type": "coulomb", "friction": 0.3}},
            "bodies": [slab] + grains,
            "interactions": [{"groups": ["grain", "slab"], "law": "rough"}],
            "solver": {"type": "nlgs", "tolerance": 1e-6, "max_iterations": 500},
            "output": {"every": 1000000}}


def run(moreau, dim, size, steps, work):
    path = os.path.join(work, f"bench_{dim}d_{size}.json")
    with open(path, "w") as f:
        json.dump(scene(dim, size, steps), f)
    out = os.path.join(work, "out.h5")
    start = time.perf_counter()
    p = subprocess.run(["/usr/bin/time", "-f", "maxrss %M cpu %U %S", moreau, "run", path, "--out", out],
                       capture_output=True, text=True)
    wall = time.perf_counter() - start
    if p.returncode != 0:
        raise SystemExit(p.stderr)
    stages = {m.group(1): float(m.group(2)) for m in re.finditer(r"^\s+(\w+)\s+([0-9.]+) s", p.stderr, re.M)}
    w = re.search(r"^\s+\(of which W assembly\)\s+([0-9.]+) s", p.stderr, re.M)
    stages["w_build"] = float(w.group(1)) if w else 0.0
    rss = int(re.search(r"maxrss (\d+)", p.stderr).group(1)) / 1024
    if os.environ.get("MOREAU_STAGE_CLOCK") == "cpu":  # stages in CPU time: the set-up too
        cpu = re.search(r"cpu ([0-9.]+) ([0-9.]+)", p.stderr)
        wall = float(cpu.group(1)) + float(cpu.group(2))
    nodes = int(subprocess.run(["h5ls", out + "/elastic.nodes/body"], capture_output=True, text=True).stdout.split("{")[1]
                .split("}")[0])
    return nodes * dim, stages, wall, rss


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--moreau", default="build/bin/moreau")
    ap.add_argument("--steps", type=int, default=20)
    ap.add_argument("--quick", action="store_true", help="the two smallest sizes only")
    ap.add_argument("--cases", help="only these, e.g. 2:0.0025,3:0.014 (dimension:element size)")
    args = ap.parse_args()
    cases = [(2, 0.02), (2, 0.01), (2, 0.005), (2, 0.0025), (2, 0.0014), (3, 0.05), (3, 0.033), (3, 0.02), (3, 0.014)]
    if args.quick:
        cases = [c for c in cases if c[1] in (0.02, 0.01, 0.05, 0.033)]
    if args.cases:
        cases = [(int(c.split(":")[0]), float(c.split(":")[1])) for c in args.cases.split(",")]
    print(f"| dim | DOFs | set-up incl. factorisation (s) | free velocity (ms/step) | W build (ms/step) | "
          f"solve (ms/step) | update (ms/step) | total (ms/step) | peak memory (MB) |")
    print("|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory() as work:
        for dim, size in cases:
            dofs, st, wall, rss = run(args.moreau, dim, size, args.steps, work)
            n = args.steps
            solve = st.get("solve", 0) + st.get("warm_start", 0) + st.get("store_reactions", 0) - st["w_build"]
            per_step = st.get("total", 0) - st.get("output", 0)
            setup = wall - st.get("total", 0)
            print(f"| {dim}D | {dofs} | {setup:.2f} | {1e3 * st.get('free_velocity', 0) / n:.2f} | {1e3 * st['w_build'] / n:.2f} | "
                  f"{1e3 * solve / n:.2f} | "
                  f"{1e3 * st.get('update_dofs', 0) / n:.2f} | {1e3 * per_step / n:.2f} | {rss:.0f} |", flush=True)


if __name__ == "__main__":
    main()
