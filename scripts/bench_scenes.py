#!/usr/bin/env python3
"""Time stepping (issue 15, point 3): `auto` against each member solver on every example
scene of configs/ that has contacts and on the silo of issue 15, per step.

Each scene runs with its own solver tolerance (the default's when it names none) for every
solver in --solvers; `auto` uses the same tolerance. Runs are interleaved (round r runs
every solver once before round r + 1) and the table gives medians over --repeat rounds of
the solve stage's seconds per step (from `moreau run`'s stage table), the steps whose solve
missed the tolerance (from the end-of-run summary), and auto over the best member.

    python3 scripts/bench_scenes.py [--moreau build/bin/moreau] [--steps 1000 | --full-length] [--repeat 3]
        [--solvers auto nlgs newton admm apgd] [--only NAME ...] [--skip NAME ...] [--tolerance X]
        [--cpu | --stage-cpu] [--timeout SECONDS] [--shadow [--from-solve K]] [--out build/bench_scenes]

--full-length runs every scene over its whole duration (its own number of steps: the issue's
silo 5000, silo_janssen_2d 4500, masonry_arch_2d 6000, ...) instead of the first --steps.

A solver may carry parameters: `auto/remember=false` (JSON values after `=`, comma-separated).

With --cpu the time is the run's CPU time (user + system, the whole process, every stage)
per step instead of the solve stage's wall time: on a loaded shared machine wall times
move by tens of per cent between runs, CPU times much less (stages other than the solve
are included and add the same to every solver, so ratios lean towards 1). With --stage-cpu
it is the solve stage's CPU time (MOREAU_STAGE_CLOCK=cpu): the solver's own cost, without
the process start that dominates scenes of few, light steps.

With --shadow each scene runs once per round (one realisation): the first of --solvers is the
scene's solver, the others solve every one of its problems beside it from the same warm start
(MOREAU_SHADOW_SOLVERS, docs/solvers.md "Comparing solvers on one run"), and each solver's
time is its thread CPU time in solve() per step of the run (W's assembly, which the
stage time counts for a solver that reads W, is not in it). Whole runs of scenes whose
outcome depends on the answers within the tolerance (a silo that jams or flows) then compare
the solvers on the same sequence of problems.

--from-solve K (with --shadow) leaves a run's first K − 1 solves out of every solver's time
(MOREAU_SHADOW_TRACE gives each solve's CPU time): the warm-started steps only, without the
run's cold start, where each solver's code and data are touched for the first time (`auto`
runs two or three members there). Times stay per step: the kept solves' time over the kept
steps (the solves a step makes being taken as the run's average).
"""
import argparse
import json
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, HERE)
import corpus  # noqa: E402  (the silo scene)

DEFAULT_TOLERANCE = 1e-3  # auto's default (docs/solvers.md)


def scenes(steps):
    out = {}
    cfg = os.path.join(REPO, "configs")
    for f in sorted(os.listdir(cfg)):
        if f.endswith(".json"):
            s = json.load(open(os.path.join(cfg, f)))
            if s.get("interactions"):
                out[f[:-5]] = s
    out["silo_issue15"] = corpus.silo_2d(steps=5000)  # the silo (configs/silo_2d is another)
    for s in out.values():
        s.pop("export_problems", None)
        s["output"] = {"file": "out.h5", "every": 10 ** 9, "display": "points"}  # first and last frames only
    return out


def solver_block(scene, spec, tolerance=None):
    """`spec`: a solver name, optionally with parameters: auto/remember=true,nlgs_sweeps=0."""
    name, _, extra = spec.partition("/")
    sv = dict(scene.get("solver") or {})
    tol = tolerance or sv.get("tolerance", DEFAULT_TOLERANCE)
    block = {"type": name, "tolerance": tol}
    for kv in filter(None, extra.split(",")):
        k, _, v = kv.partition("=")
        block[k] = json.loads(v)
    if name == "nlgs" and sv.get("type") == "nlgs" and "max_iterations" in sv:
        block["max_iterations"] = sv["max_iterations"]
    return block, tol


def child_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


def run(moreau, scene, name, steps, tmp, tolerance=None, cpu=False, stage_cpu=False, timeout=None):
    s = json.loads(json.dumps(scene))
    s["solver"], tol = solver_block(scene, name, tolerance)
    path = os.path.join(tmp, "scene.json")
    json.dump(s, open(path, "w"))
    total = round(s["time"]["duration"] / s["time"]["step"])
    n = min(steps, total)
    c0 = child_cpu()
    try:
        p = subprocess.run([moreau, "run", path, "--out", os.path.join(tmp, "out.h5"), "--steps", str(n)], capture_output=True,
                           text=True, env=dict(os.environ, MOREAU_STAGE_CLOCK="cpu") if stage_cpu else None, timeout=timeout)
    except subprocess.TimeoutExpired as e:  # the progress line says how far it got
        done = re.findall(r"step (\d+)/", (e.stderr or b"").decode(errors="replace") if isinstance(e.stderr, bytes) else e.stderr or "")
        return {"error": f"timeout after {timeout:g} s" + (f" at step {done[-1]} of {n}" if done else "")}
    used = child_cpu() - c0
    if p.returncode != 0:
        return {"error": p.stderr.strip().splitlines()[-1] if p.stderr.strip() else f"exit {p.returncode}"}
    text = p.stdout + p.stderr
    stages = {m.group(1): float(m.group(2)) for m in re.finditer(r"^\s+(\w+)\s+([0-9.]+) s", text, re.M)}
    miss = re.search(r"contact solves: (\d+) of (\d+) steps ended above", text)
    worst = re.search(r"worst error ([0-9.e+-]+)", text)
    return {"solve": (used if cpu else stages.get("solve", 0.0)) / n, "total": stages.get("total", 0.0) / n, "steps": n, "tol": tol,
            "misses": int(miss.group(1)) if miss else 0, "worst": float(worst.group(1)) if worst else 0.0}


def run_shadow(moreau, scene, names, steps, tmp, tolerance=None, timeout=None, from_solve=1):
    """One run with names[0] as the scene's solver and the others as shadows: per solver the
    same fields as run() gives, from the run's MOREAU_SHADOW_REPORT (from its trace when
    from_solve > 1: the solves from that one on)."""
    s = json.loads(json.dumps(scene))
    s["solver"], tol = solver_block(scene, names[0], tolerance)
    shadows = [solver_block(scene, n, tolerance)[0] for n in names[1:]]
    path = os.path.join(tmp, "scene.json")
    json.dump(s, open(path, "w"))
    report = os.path.join(tmp, "shadow.json")
    if os.path.exists(report):
        os.remove(report)
    n = min(steps, round(s["time"]["duration"] / s["time"]["step"]))
    env = dict(os.environ, MOREAU_SHADOW_SOLVERS=json.dumps(shadows), MOREAU_SHADOW_REPORT=report)
    if from_solve > 1:
        env["MOREAU_SHADOW_TRACE"] = "1"
    try:
        p = subprocess.run([moreau, "run", path, "--out", os.path.join(tmp, "out.h5"), "--steps", str(n)], capture_output=True,
                           text=True, env=env, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {sv: {"error": f"timeout after {timeout:g} s"} for sv in names}
    if p.returncode != 0:
        msg = p.stderr.strip().splitlines()[-1] if p.stderr.strip() else f"exit {p.returncode}"
        return {sv: {"error": msg} for sv in names}
    rows = json.load(open(report))["solvers"]
    if from_solve > 1:  # per label: the CPU time of the solves from `from_solve` on, and their count
        kept = {}
        for m in re.finditer(r"^shadow: (.+) solve (\d+) cpu ([0-9.e+-]+) ", p.stderr, re.M):
            if int(m.group(2)) >= from_solve:
                t, c = kept.get(m.group(1), (0.0, 0))
                kept[m.group(1)] = (t + float(m.group(3)), c + 1)
        for r in rows:
            t, c = kept.get(r["label"], (0.0, 0))
            if not c and r["solves"] >= from_solve:
                raise SystemExit(f"--from-solve: no trace line for solver {r['label']!r} (labels in the trace: {sorted(kept)})")
            # per kept step: the kept solves' time over the steps they make at the run's solves per step
            r["cpu_seconds"] = t / c * r["solves"] if c else 0.0
    return {sv: {"solve": r["cpu_seconds"] / n, "steps": n, "tol": tol, "misses": r["misses"], "worst": r["worst_error"],
                 "solves": r["solves"], "iterations_per_solve": r["iterations_per_solve"]}
            for sv, r in zip(names, rows)}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0], formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--moreau", default=os.path.join(REPO, "build", "bin", "moreau"))
    ap.add_argument("--steps", type=int, default=1000, help="steps per run (at most the scene's own)")
    ap.add_argument("--full-length", action="store_true", help="each scene's whole run (its own number of steps), not --steps")
    ap.add_argument("--skip", nargs="+", default=[], metavar="NAME", help="scenes not to run")
    ap.add_argument("--timeout", type=float, help="seconds after which a run is stopped (reported as 'timeout')")
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--solvers", nargs="+", default=["auto", "nlgs", "newton", "admm", "apgd"])
    ap.add_argument("--only", nargs="+", metavar="NAME")
    ap.add_argument("--tolerance", type=float, help="one tolerance for every scene (default: each scene's own)")
    ap.add_argument("--cpu", action="store_true", help="the run's CPU time per step instead of the solve stage's wall time")
    ap.add_argument("--stage-cpu", action="store_true",
                    help="the solve stage's CPU time per step (MOREAU_STAGE_CLOCK=cpu): no process start, no other stage")
    ap.add_argument("--shadow", action="store_true",
                    help="one run per scene: the first solver runs the scene, the others solve its problems as shadows "
                         "(times: each solver's thread CPU time in solve(); --cpu and --stage-cpu do not apply)")
    ap.add_argument("--from-solve", type=int, default=1, metavar="K",
                    help="with --shadow: leave each run's first K - 1 solves (its cold start) out of every solver's time")
    ap.add_argument("--out", default=os.path.join(REPO, "build", "bench_scenes"))
    a = ap.parse_args()
    if a.from_solve > 1 and not a.shadow:
        ap.error("--from-solve needs --shadow (the per-solve times come from the shadows' trace)")
    moreau = os.path.abspath(a.moreau)
    all_scenes = scenes(a.steps)
    names = [n for n in a.only or list(all_scenes) if n not in a.skip]
    if a.full_length:
        a.steps = 10 ** 9  # run() takes the scene's own number of steps
    os.makedirs(a.out, exist_ok=True)
    rows = []
    hdr = f"{'scene':24s} {'tol':>7s} {'steps':>5s} " + " ".join(f"{s + ' ms':>12s}" for s in a.solvers) + \
          f" {'best member':>12s} {'auto/best':>9s}  misses"
    if a.shadow:
        print(f"one realisation per scene: {a.solvers[0]}'s run; every solver on its problems (thread CPU ms per step"
              + (f", solves {a.from_solve} on)" if a.from_solve > 1 else ")"))
    print(hdr, flush=True)
    with tempfile.TemporaryDirectory() as tmp:
        for name in names:
            results = {s: [] for s in a.solvers}
            for _ in range(a.repeat):  # interleaved: each round runs every solver once
                if a.shadow:
                    one = run_shadow(moreau, all_scenes[name], a.solvers, a.steps, tmp, a.tolerance, a.timeout, a.from_solve)
                    for sv in a.solvers:
                        results[sv].append(one[sv])
                    continue
                for sv in a.solvers:
                    results[sv].append(run(moreau, all_scenes[name], sv, a.steps, tmp, a.tolerance, a.cpu, a.stage_cpu, a.timeout))
            med, misses = {}, {}
            for sv, rs in results.items():
                good = [r for r in rs if "error" not in r]
                med[sv] = statistics.median(r["solve"] for r in good) if good else None
                misses[sv] = (good[0]["misses"], good[0]["worst"]) if good else None
            members = {sv: t for sv, t in med.items() if not sv.startswith("auto") and t is not None and misses[sv][0] == 0}
            best = min(members, key=members.get) if members else None
            autos = [sv for sv in a.solvers if sv.startswith("auto")]  # each variant over the best member
            ratios = {sv: med[sv] / members[best] if best and med.get(sv) else None for sv in autos}
            ratio = ratios[autos[0]] if autos else None
            first = next((r for rs in results.values() for r in rs if "error" not in r), {"tol": a.tolerance or 0, "steps": 0})
            errors = {sv: next((r["error"] for r in rs if "error" in r), None) for sv, rs in results.items()}
            cells = " ".join(f"{('timeout' if (errors[s] or '').startswith('timeout') else 'fail') if med[s] is None else f'{1e3 * med[s]:.3f}':>12s}"
                             for s in a.solvers)
            miss_txt = ", ".join(f"{s} {m[0]} (worst {m[1]:.1e})" for s, m in misses.items() if m and m[0])
            print(f"{name:24s} {first['tol']:7.0e} {first['steps']:5d} {cells} {best or '-':>12s} "
                  f"{' '.join('-' if x is None else f'{x:.2f}' for x in ratios.values()):>9s}  {miss_txt}", flush=True)
            rows.append({"scene": name, "tolerance": first["tol"], "steps": first["steps"],
                         "ms_per_step": {s: None if t is None else 1e3 * t for s, t in med.items()},
                         "misses": {s: m for s, m in misses.items()}, "best_member": best, "auto_over_best": ratio,
                         "over_best": ratios, "errors": {s: e for s, e in errors.items() if e},
                         "realisation": a.solvers[0] if a.shadow else "each solver's own"})
            for sv, e in errors.items():
                if e:
                    print(f"  {sv}: {e}", flush=True)
    json.dump(rows, open(os.path.join(a.out, "bench_scenes.json"), "w"), indent=1)
    print(f"wrote {a.out}/bench_scenes.json")


if __name__ == "__main__":
    main()
