#!/usr/bin/env python3
"""Benchmark: 3D spheres in a box, N = 10^4 (and 10^5 with --large), time per step split by
stage and the NLGS sweep throughput (contact updates per second).

The spheres start as a touching cubic lattice resting on the floor, so every step has
~3 contacts per sphere from the start. The run goes `--steps` steps with a frame each step;
stage times come from `moreau run`'s table, iterations and contact counts from the frames.
`--friction 0.3,0` compares with a frictionless run (the sweep then packs the normal rows
and the translations only); `--layout apart` spaces the spheres 1 cm apart and 5 mm above
the floor, so no step has a contact (only detection runs).

    python3 scripts/bench_spheres.py [--moreau build/bin/moreau] [--steps 20] [--large | --sizes 10000,100000]
                                     [--exchange auto,nlgs,apgd] [--tolerance 1e-4] [--timeout 600]
                                     [--friction 0.3,0] [--layout touching,apart] [--cold]

With MOREAU_STAGE_CLOCK=cpu in the environment the stage times are CPU times.
"""
import argparse, json, math, os, re, subprocess, sys, tempfile, time

import h5py


def solver(variant, tolerance=1e-4, sweeps=200):
    """`w` / `bodies`: nlgs with that exchange, `sweeps` sweeps at most (`nlgs`: its own
    default exchange and cap); `auto`: the default solver; other names: that solver with its
    defaults. All at `tolerance`; the table's `error max` is the worst step's final error."""
    if variant in ("w", "bodies"):
        return {"type": "nlgs", "tolerance": tolerance, "max_iterations": sweeps, "exchange": variant}
    # `auto/nlgs_sweeps=0/remember=true`: a solver with some parameters set (JSON values).
    name, *params = variant.split("/")
    out = {"type": name, "tolerance": tolerance}
    for p in params:
        key, value = p.split("=", 1)
        out[key] = json.loads(value)
    return out


def scene(n, steps, path_h5, exchange, friction=0.3, layout="touching", tolerance=1e-4, sweeps=200):
    side = round(n ** (1 / 3))
    nz = math.ceil(n / (side * side))
    r = 0.01
    pitch, lift = (0.02, 0.0) if layout == "touching" else (0.03, 0.005)  # touching: ~3 contacts per sphere
    bodies = [{"name": "floor", "fixed": True, "position": [0, 0, 0], "contactors": [{"shape": "plane", "group": "wall"}]}]
    L = side * pitch
    for nx, p in (([1, 0, 0], [0, 0, 0]), ([-1, 0, 0], [L, 0, 0]), ([0, 1, 0], [0, 0, 0]), ([0, -1, 0], [0, L, 0])):
        bodies.append({"name": f"wall_{len(bodies)}", "fixed": True, "position": p,
                       "contactors": [{"shape": "plane", "normal": nx, "group": "wall"}]})
    k = 0
    for z in range(nz):
        for y in range(side):
            for x in range(side):
                if k == n:
                    break
                bodies.append({"name": f"s{k}", "material": "grain",
                               "position": [pitch / 2 + x * pitch, pitch / 2 + y * pitch, r + lift + z * pitch],
                               "contactors": [{"shape": "sphere", "radius": r, "group": "grain"}]})
                k += 1
    return {"format": "moreau-scene/1", "dimension": 3, "time": {"step": 5e-4, "duration": steps * 5e-4},
            "gravity": [0, 0, -9.81], "materials": {"grain": {"density": 2600}},
            "laws": {"rough": {"type": "coulomb", "friction": friction}},
            "bodies": bodies,
            "interactions": [{"groups": ["grain", "grain"], "law": "rough"}, {"groups": ["grain", "wall"], "law": "rough"}],
            "solver": solver(exchange, tolerance, sweeps),
            "output": {"file": path_h5, "every": 1, "display": "points"}}  # no shape meshes: 10^5 spheres would write 50 MB a frame


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--moreau", default=os.path.join(os.path.dirname(__file__), "..", "build", "bin", "moreau"))
    ap.add_argument("--steps", type=int, default=20)
    ap.add_argument("--large", action="store_true", help="also 10^5 spheres")
    ap.add_argument("--sizes", default="", help="numbers of spheres (comma-separated; overrides --large)")
    ap.add_argument("--exchange", default="w,bodies",
                    help="solvers to compare (comma-separated: w, bodies = nlgs with that exchange and --sweeps; "
                         "auto, nlgs, apgd, psor, newton, admm, prox = that solver; auto/nlgs_sweeps=0 sets parameters)")
    ap.add_argument("--tolerance", type=float, default=1e-4)
    ap.add_argument("--sweeps", type=int, default=200, help="sweep cap of the w / bodies variants")
    ap.add_argument("--timeout", type=float, default=0, help="seconds a run may take (0: no limit); a run over it is reported")
    ap.add_argument("--friction", default="0.3", help="friction coefficients to run (comma-separated)")
    ap.add_argument("--layout", default="touching", help="touching (contacts from the start) and/or apart (none)")
    ap.add_argument("--cold", action="store_true",
                    help="also run each case for 1 step and print the cold first step and the warm steps apart "
                         "(warm solve ms/step = (solve of all steps - solve of the 1-step run) / (steps - 1))")
    a = ap.parse_args()
    sizes = [int(x) for x in a.sizes.split(",")] if a.sizes else [10_000] + ([100_000] if a.large else [])
    # ms/step: the whole step (every stage); solve ms/step and µs/contact: the solve stage
    # alone, per step and per contact and step (contacts: the mean over the steps).
    print(f"{'spheres':>8} {'layout':>8} {'mu':>4} {'exchange':>8} {'contacts':>9} {'sweeps/step':>11} {'ms/step':>8} "
          f"{'solve ms/step':>13} {'solve us/contact':>16} {'error max':>9} {'missed':>6} "
          f"{'detect %':>8} {'solve %':>8} {'update %':>8} {'output %':>8} {'NLGS updates/s':>15}")
    runs = [(n, lay, float(mu), x) for n in sizes for lay in a.layout.split(",") for mu in a.friction.split(",")
            for x in a.exchange.split(",")]
    for n, layout, mu, exchange in runs:
        r = run(a, n, layout, mu, exchange, a.steps)
        if r is None:
            print(f"{n:>8} {layout:>8} {mu:>4g} {exchange:>8.24} did not finish {a.steps} steps in {a.timeout:g} s", flush=True)
            continue
        total, solve, stages, detect, update = r["total"], r["solve"], r["stages"], r["detect"], r["update"]
        # `auto`'s iterations mix sweeps with APGD steps: no sweep throughput for it.
        rate = f"{r['updates'] / solve:>15.3g}" if r["updates"] and solve > 0 and exchange in ("w", "bodies") else f"{'-':>15}"
        per_contact = 1e6 * solve / a.steps / r["mean_contacts"] if r["mean_contacts"] else 0.0
        print(f"{n:>8} {layout:>8} {mu:>4g} {exchange:>8.24} {r['contacts']:>9} {sum(r['iterations']) / a.steps:>11.1f} "
              f"{1000 * total / a.steps:>8.2f} {1000 * solve / a.steps:>13.2f} {per_contact:>16.2f} {r['worst']:>9.1e} {r['missed']:>6} "
              f"{100 * detect / total:>8.1f} {100 * solve / total:>8.1f} "
              f"{100 * update / total:>8.1f} {100 * stages.get('output', 0) / total:>8.1f} {rate}", flush=True)
        if a.cold and a.steps > 1 and r["contacts"]:
            c = run(a, n, layout, mu, exchange, 1)
            if c is None:
                print(f"{'':>8} cold step of {exchange} did not finish in {a.timeout:g} s", flush=True)
                continue
            warm_solve = (solve - c["solve"]) / (a.steps - 1)
            warm_assembly = (r["assembly"] - c["assembly"]) / (a.steps - 1)
            warm_it = sum(r["iterations"][1:]) / (a.steps - 1)
            warm_contacts = sum(r["contacts_per_step"][1:]) / (a.steps - 1)
            print(f"{'':>8}   cold step: {c['iterations'][0]} iterations, solve {1000 * c['solve']:.2f} ms "
                  f"({1e6 * c['solve'] / c['contacts_per_step'][0]:.2f} us/contact); warm steps 2-{a.steps}: "
                  f"{warm_it:.1f} iterations/step, solve {1000 * warm_solve:.2f} ms/step "
                  f"({1e6 * warm_solve / warm_contacts:.2f} us/contact; of which W assembly {1000 * warm_assembly:.2f} ms), worst error {max(r['errors'][1:]):.1e}", flush=True)


def run(a, n, layout, mu, exchange, steps):
    """One run of `steps` steps: stage times (s) and, per step, iterations, contacts and errors."""
    with tempfile.TemporaryDirectory() as d:
        h5 = os.path.join(d, "out.h5")
        sp = os.path.join(d, "scene.json")
        json.dump(scene(n, steps, h5, exchange, mu, layout, a.tolerance, a.sweeps), open(sp, "w"))
        try:
            out = subprocess.run([a.moreau, "run", sp], capture_output=True, text=True, timeout=a.timeout or None)
        except subprocess.TimeoutExpired:
            return None
        if out.returncode != 0:
            sys.exit(out.stderr)
        stages = {m.group(1): float(m.group(2)) for m in re.finditer(r"^\s+(\w+)\s+([0-9.]+) s", out.stdout + out.stderr, re.M)}
        m = re.search(r"\(of which W assembly\)\s+([0-9.]+) s", out.stdout + out.stderr)
        assembly = float(m.group(1)) if m else 0.0
        with h5py.File(h5) as f:
            frames = [f["frames"][k] for k in sorted(f["frames"])][1:]
            iterations = [int(fr["solver"].attrs["iterations"]) for fr in frames]
            contacts = [len(fr["contacts/gap"]) for fr in frames]
            errors = [float(fr["solver"].attrs["error"]) for fr in frames]
    return {"stages": stages, "assembly": assembly, "total": stages["total"], "solve": stages.get("solve", 0.0),
            "detect": sum(stages.get(s, 0) for s in ("detection_configuration", "broad_phase", "narrow_phase")),
            "update": sum(stages.get(s, 0) for s in ("free_velocity", "update_dofs", "end_step", "warm_start", "store_reactions")),
            "iterations": iterations, "contacts_per_step": contacts, "contacts": contacts[-1],
            "mean_contacts": sum(contacts) / len(contacts), "updates": sum(i * c for i, c in zip(iterations, contacts)),
            "worst": max(errors), "missed": sum(e > a.tolerance for e in errors), "errors": errors}

if __name__ == "__main__":
    main()
