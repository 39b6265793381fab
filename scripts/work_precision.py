#!/usr/bin/env python3
"""Work-precision benchmark (issue 4): runs contact solvers on FCLib problems at several
tolerances through `moreau fclib solve` and writes

  OUT/table.md, OUT/table.csv     problem, solver, tolerance, iterations, error, seconds,
                                  converged (table.md: the table tolerances only, and time
                                  to 1e-8 against the Siconos reference figures)
  OUT/error_vs_time_PROBLEM.png   error against time, one line per solver (all tolerances)
  OUT/profiles.png                Dolan–Moré performance profiles, one panel per table tolerance

    python3 scripts/work_precision.py [--moreau build/bin/moreau] [--problems F.hdf5 ...]
        [--corpus build/corpus] [--solvers nlgs psor:relaxation=0.8 ...] [--tolerances 1e-4 1e-8]
        [--repeat 5] [--max-iter N] [--timeout S] [--out build/work_precision]

With --corpus DIR (made by scripts/corpus.py), the problems are the shared FCLib files and
every DIR/problems/*.hdf5, each of those solved twice: cold (r = 0) and warm (its
/guesses/1/r, the run's warm start; named PROBLEM+warm). It also writes guarantee.md: for
each problem and table tolerance, the fastest member (every solver but `auto`) and auto's
time over it, and the summary (problems some member solves, those auto solves, those auto
solves within k× the fastest member, the worst ratio).

Times are the median of --repeat solves from r = 0 (each with a fresh solver object),
measured inside moreau around the solve only, after one untimed solve that checks the
solver converges; a run that fails is not repeated, and a solver that failed at one
tolerance is not run at the tighter intermediate ones (the table tolerances always run).
Needs numpy and matplotlib.
"""
import argparse
import json
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
sys.path.insert(0, HERE)

# Gauss–Seidel-like and first-order methods may need many cheap iterations on hard problems
# (Siconos NSGS needs 36127 at 1e-4 on fclib-local_problem_test); Newton steps are expensive
# and converge fast or not at all. A solver not listed keeps its own default.
MAX_ITER = {"nlgs": 100000, "psor": 100000, "apgd": 100000, "admm": 100000, "prox": 100000, "auto": 100000,
            "newton": 1000}
BASE_SOLVERS = ["nlgs", "psor", "apgd", "admm", "newton", "auto"]
# Between the table tolerances, so that each solver draws a curve in the error-vs-time plots.
CURVE_TOLERANCES = [1e-2, 1e-3, 1e-5, 1e-6, 1e-7]


SHARED_STEMS = {"CubeH8", "faf-Box_Stacks-i0035-31-0", "faf-Capsules-i97-269", "fclib-local_problem_test",
                "spheres-in-a-box-98-i10000-256-10"}


def stem_of(problem):
    """The problem's name in tables: the file's stem, +warm when solved from its warm start."""
    path, warm = problem if isinstance(problem, tuple) else (problem, False)
    return os.path.splitext(os.path.basename(path))[0] + ("+warm" if warm else "")


def fail(msg):
    print(f"work_precision: error: {msg}", file=sys.stderr)
    sys.exit(2)


def parse_spec(spec):
    """`name` or `name:key=value,key=value` → (label, name, [\"key=value\", ...])."""
    name, _, rest = spec.partition(":")
    params = [kv for kv in rest.split(",") if kv] if rest else []
    for kv in params:
        if "=" not in kv or kv.startswith("="):
            fail(f"solver spec {spec!r}: {kv!r} is not key=value")
    if not name:
        fail(f"solver spec {spec!r}: no solver name")
    return spec, name, params


def plugins(moreau):
    """The solver plugins of the binary: name → {parameter name → parameter description}."""
    p = subprocess.run([moreau, "plugins", "--json"], capture_output=True, text=True)
    if p.returncode != 0:
        fail(f"`{moreau} plugins --json` failed (exit {p.returncode}): {p.stderr.strip()}")
    return {s["name"]: {q["name"]: q for q in s["parameters"]} for s in json.loads(p.stdout).get("solver", [])}


def default_solvers(available):
    """The base families, then whatever optional solvers and nlgs variants this build has."""
    missing = [s for s in BASE_SOLVERS if s not in available]
    if missing:
        fail(f"the binary lacks the solver plugin(s) {', '.join(missing)} (was every plugin built?)")
    specs = list(BASE_SOLVERS)
    local = available["nlgs"].get("local_solver")
    if local:
        specs += [f"nlgs:local_solver={c}" for c in local.get("choices", []) if c != local.get("default")]
    if "prox" in available:
        specs.append("prox")
    return specs


def check_specs(specs, available):
    """Every solver exists and every key is in its schema, before hours of runs."""
    for label, name, params in specs:
        if name not in available:
            fail(f"solver spec {label!r}: no solver plugin {name!r}; available: {', '.join(sorted(available))}")
        for kv in params:
            key = kv.split("=", 1)[0]
            if key not in available[name]:
                fail(f"solver spec {label!r}: {name} has no parameter {key!r}; "
                     f"valid: {', '.join(available[name])}")


def invoke(moreau, problem, name, params, tol, max_iter, repeat, timeout):
    """One `moreau fclib solve`: its JSON line as a dict, or a failed record (timeout, crash).
    `problem`: a path, or (path, warm) to start from the file's warm start."""
    path, warm = problem if isinstance(problem, tuple) else (problem, False)
    cmd = [moreau, "fclib", "solve", path, "--solver", name, "--tol", repr(tol), "--repeat", str(repeat)]
    if warm:
        cmd.append("--warm-start")
    explicit = {kv.split("=", 1)[0] for kv in params}
    if max_iter and "max_iterations" not in explicit:
        cmd += ["--max-iter", str(max_iter)]
    for kv in params:
        cmd += ["--param", kv]
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"iterations": None, "error": None, "seconds": None, "converged": False, "repeats": 0,
                "note": "timeout"}
    if p.returncode == 2:  # bad input: the benchmark itself is wrong, stop
        fail(f"`{' '.join(cmd)}` refused its input:\n{p.stderr.strip()}")
    if p.returncode != 0:
        last = p.stderr.strip().splitlines()[-1] if p.stderr.strip() else ""
        return {"iterations": None, "error": None, "seconds": None, "converged": False, "repeats": 0,
                "note": f"exit {p.returncode}: {last}"}
    line = json.loads(p.stdout.strip().splitlines()[-1])
    line["note"] = "" if line["converged"] else "not converged"
    return line


def caps_of(name, params, max_iter):
    """`auto`'s Newton runs get the cap `newton` gets here (its steps are capped apart from
    the other members'), so that auto and each member run under the same caps: the
    guarantee compares like with like (docs/solvers.md "Guarantee")."""
    if name != "auto" or any(kv.split("=", 1)[0] == "newton_max_iterations" for kv in params):
        return params
    return list(params) + [f"newton_max_iterations={max_iter or MAX_ITER['newton']}"]


def run_one(moreau, problem, name, params, tol, max_iter, repeat, timeout):
    """A first solve finds out whether the solver converges within `timeout` seconds; only
    then are the `repeat` timed solves made (their median is kept). A failed run is not
    repeated: it would cost up to `repeat` × the time limit and its time matters less."""
    first = invoke(moreau, problem, name, params, tol, max_iter, 1, timeout + 10)
    if first["note"] == "timeout":
        first["note"] = f"timeout ({timeout:g} s)"
        first["seconds"] = float(timeout)
    if not first["converged"] or repeat == 1:
        return first
    timed = invoke(moreau, problem, name, params, tol, max_iter, repeat, timeout * repeat + 10)
    return timed if timed["converged"] else first


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--moreau", default=os.path.join(REPO, "build", "bin", "moreau"), help="the moreau binary")
    ap.add_argument("--problems", nargs="+", metavar="FILE",
                    help="FCLib files (default: every *.hdf5 in ../shared/fclib beside the repository)")
    ap.add_argument("--corpus", metavar="DIR",
                    help="the shared files plus DIR/problems/*.hdf5 (scripts/corpus.py), cold and warm; "
                         "default solvers then: the families and auto (no nlgs local-solver variants)")
    ap.add_argument("--k", type=float, default=1.5, help="the guarantee's time factor in guarantee.md (default 1.5)")
    ap.add_argument("--solvers", nargs="+", metavar="SPEC",
                    help="`name` or `name:key=value,key=value` (passed as --param); default: every family, "
                         "plus prox and the nlgs local solvers when the binary has them")
    ap.add_argument("--tolerances", nargs="+", type=float, default=[1e-4, 1e-8], metavar="TOL",
                    help="tolerances of the table and the profiles (default 1e-4 1e-8)")
    ap.add_argument("--no-curves", action="store_true",
                    help="only the table tolerances (no intermediate points in the error-vs-time plots)")
    ap.add_argument("--repeat", type=int, default=5, help="solves per run; the median time is kept (default 5)")
    ap.add_argument("--max-iter", type=int, help="maximum iterations for every solver (default: per solver)")
    ap.add_argument("--timeout", type=float, default=120.0,
                    help="seconds per solve before it counts as failed (default 120)")
    ap.add_argument("--out", default=os.path.join(REPO, "build", "work_precision"), help="output folder")
    a = ap.parse_args()
    if a.repeat < 1 or a.timeout <= 0 or (a.max_iter is not None and a.max_iter < 1):
        fail("--repeat, --timeout and --max-iter must be positive")
    if any(not (t > 0) for t in a.tolerances):
        fail("tolerances must be positive")

    moreau = os.path.abspath(a.moreau)
    if not (os.path.isfile(moreau) and os.access(moreau, os.X_OK)):
        fail(f"no moreau binary at {moreau} (build it, or pass --moreau PATH)")
    if a.problems:
        problems = a.problems
    elif a.corpus:
        shared = os.path.join(os.path.dirname(REPO), "shared", "fclib")
        problems = sorted(os.path.join(shared, f) for f in os.listdir(shared) if f.endswith(".hdf5")) \
            if os.path.isdir(shared) else []
    else:
        shared = os.path.join(os.path.dirname(REPO), "shared", "fclib")
        problems = sorted(os.path.join(shared, f) for f in os.listdir(shared) if f.endswith(".hdf5")) \
            if os.path.isdir(shared) else []
        if not problems:
            fail(f"no *.hdf5 problem in {shared}; pass --problems")
    for f in problems:
        if not os.path.isfile(f):
            fail(f"no problem file {f}")
    if a.corpus:
        pdir = os.path.join(a.corpus, "problems")
        if not os.path.isdir(pdir):
            fail(f"no {pdir}: make the corpus first (python3 scripts/corpus.py --out {a.corpus})")
        exported = sorted(os.path.join(pdir, f) for f in os.listdir(pdir) if f.endswith(".hdf5"))
        problems = problems + exported + [(f, True) for f in exported]
    stems = [stem_of(f) for f in problems]
    if len(set(stems)) != len(stems):
        fail("two problem files have the same name; the outputs are named after it")

    available = plugins(moreau)
    default = (BASE_SOLVERS + (["prox"] if "prox" in available else [])) if a.corpus else default_solvers(available)
    specs = [parse_spec(s) for s in (a.solvers or default)]
    if len({s[0] for s in specs}) != len(specs):
        fail("a solver spec is given twice")
    check_specs(specs, available)
    table_tols = sorted(set(a.tolerances), reverse=True)
    all_tols = sorted(set(table_tols) | (set() if a.no_curves else set(CURVE_TOLERANCES)), reverse=True)

    import work_precision_plots as plots  # numpy/matplotlib: only once the arguments are good
    import work_precision_tables as tables

    try:  # before the runs, not after an hour of them
        os.makedirs(a.out, exist_ok=True)
    except OSError as e:
        fail(f"cannot create the output folder {a.out}: {e}")

    rows = []
    for problem in problems:
        stem = stem_of(problem)
        for label, name, params in specs:
            failed_at = None
            for tol in all_tols:  # loose to tight
                if failed_at is not None and tol not in table_tols:
                    # A solver that failed at a looser tolerance fails here too; only the
                    # table tolerances are always run, so that the table is complete.
                    continue
                r = run_one(moreau, problem, name, caps_of(name, params, a.max_iter), tol, a.max_iter or MAX_ITER.get(name),
                            a.repeat, a.timeout)
                r.update(problem=stem, solver=label, tolerance=tol, table=tol in table_tols)
                rows.append(r)
                if not r["converged"] and failed_at is None:
                    failed_at = tol
                err = "-" if r["error"] is None else f"{r['error']:.2e}"
                secs = "-" if r["seconds"] is None else f"{r['seconds']:.4g}"
                print(f"{stem:40s} {label:30s} tol {tol:.0e}  it {r['iterations']}  err {err}  {secs} s  "
                      f"{'ok' if r['converged'] else r['note']}", flush=True)

    tables.write_csv(os.path.join(a.out, "table.csv"), rows)
    command = " ".join(["python3", os.path.relpath(__file__, REPO)] + sys.argv[1:])
    tables.write_markdown(os.path.join(a.out, "table.md"), rows, table_tols, [s[0] for s in specs], command)
    for problem in problems:
        stem = stem_of(problem)
        if a.corpus and stem not in SHARED_STEMS:
            continue  # one figure per shared problem; the corpus is summed up in guarantee.md
        plots.error_vs_time(os.path.join(a.out, f"error_vs_time_{stem}.png"), stem,
                            [r for r in rows if r["problem"] == stem], [s[0] for s in specs])
    plots.profiles(os.path.join(a.out, "profiles.png"), rows, table_tols, [s[0] for s in specs])
    if any(s[1] == "auto" for s in specs):
        summary = tables.write_guarantee(os.path.join(a.out, "guarantee.md"), rows, table_tols, a.k, command)
        print(summary)
    print(f"wrote {a.out}/table.md, table.csv, profiles.png and {len(problems)} error_vs_time_*.png")


if __name__ == "__main__":
    main()
