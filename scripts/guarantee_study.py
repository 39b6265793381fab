#!/usr/bin/env python3
"""The guarantee of `auto` checked on the whole corpus (docs/solvers.md "Guarantee").

Makes the reduced corpus (scripts/corpus.py) unless --corpus holds one, then solves every
problem (the shared FCLib files from r = 0, each exported problem cold and warm) at each
tolerance with every member of `auto` (nlgs, apgd, newton, admm: each alone, with auto's
caps) and with `auto`, once each, and compares counted work (`work` of `moreau fclib
solve`, plugins/solver/work.hpp: sizes and iteration counts only, so the same on every
run and machine). Exits 1 when a pair breaks the guarantee: a member reaches the tolerance
and `auto` does not, or auto's work exceeds k times the least work of a member that
reaches it.

    python3 scripts/guarantee_study.py [--moreau build/bin/moreau] [--corpus build/corpus]
        [--tolerances 1e-4 1e-8] [--k K] [--jobs 2] [--csv build/guarantee.csv]
        [--members-from build/guarantee.csv] [--worst N]

--k defaults to the stated k, read from the one place that states it: `stated_k` in
tests/solvers/test_auto_guarantee.cpp (the ctest AutoGuarantee.* checks the same k on its
pairs). About 5 minutes on the shared 2 cores for the reduced corpus (129 problems, 258
pairs), plus ~10 s to make the corpus when --corpus has none; with --members-from (the
members' figures from an earlier --csv of the same corpus and members' code: only auto
runs) about 35 s, to compare versions of auto's rule.
"""
import argparse
import concurrent.futures
import json
import os
import re
import statistics
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
MEMBERS = ["nlgs", "apgd", "newton", "admm"]
# auto's caps (its schema's fallbacks): max_iterations for NLGS, APGD and ADMM, Newton's own.
MAX_ITER, NEWTON_MAX_ITER = 20000, 200
# The stated k lives in the guarantee's ctest (one place for both).
GUARANTEE_TEST = os.path.join(REPO, "tests", "solvers", "test_auto_guarantee.cpp")


def stated_k():
    try:
        with open(GUARANTEE_TEST) as f:
            m = re.search(r"constexpr double stated_k = ([0-9.eE+-]+);", f.read())
    except OSError as e:
        fail(f"cannot read the stated k from {GUARANTEE_TEST}: {e}")
    if not m:
        fail(f"no `constexpr double stated_k = ...;` in {GUARANTEE_TEST}")
    return float(m.group(1))


def fail(msg):
    print(f"guarantee_study: error: {msg}", file=sys.stderr)
    sys.exit(2)


def solve(moreau, path, warm, solver, tol):
    cmd = [moreau, "fclib", "solve", path, "--solver", solver, "--tol", repr(tol)]
    if solver == "newton":
        cmd += ["--max-iter", str(NEWTON_MAX_ITER)]
    else:
        cmd += ["--max-iter", str(MAX_ITER)]
    if warm:
        cmd.append("--warm-start")
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        fail(f"`{' '.join(cmd)}` failed (exit {p.returncode}): {p.stderr.strip()[-300:]}")
    line = json.loads(p.stdout.strip().splitlines()[-1])
    return {"converged": bool(line["converged"]), "work": float(line["work"]), "error": line["error"]}


def members_from(path, cases, tolerances):
    """The members' figures of an earlier --csv: {(case, tolerance, member): figures}."""
    import csv
    names = {os.path.basename(c[0])[:-5] + ("+warm" if c[1] else ""): c for c in cases}
    known = {}
    try:
        with open(path) as f:
            for row in csv.DictReader(f):
                c = names.get(row["problem"])
                tol = float(row["tolerance"])
                if c is None or not any(abs(tol - t) <= 1e-12 * t for t in tolerances):
                    continue
                tol = next(t for t in tolerances if abs(tol - t) <= 1e-12 * t)
                for m in MEMBERS:  # (the least member's work at full precision, from its own column)
                    work = float(row["least_work"] if row["least"] == m else row[m + "_work"])
                    known[(c, tol, m)] = {"converged": row[m + "_converged"] == "true", "work": work, "error": float("nan")}
    except (OSError, KeyError, ValueError) as e:
        fail(f"cannot read the members' figures from {path}: {e}")
    return known


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--moreau", default=os.path.join(REPO, "build", "bin", "moreau"))
    ap.add_argument("--corpus", default=os.path.join(REPO, "build", "corpus"),
                    help="a corpus made by scripts/corpus.py (made there, reduced, if it has no problems/)")
    ap.add_argument("--shared", default=os.path.join(os.path.dirname(REPO), "shared", "fclib"),
                    help="the shared FCLib files (skipped if the folder does not exist)")
    ap.add_argument("--tolerances", nargs="+", type=float, default=[1e-4, 1e-8])
    ap.add_argument("--k", type=float, help="the k to check (default: the stated k, `stated_k` in "
                    "tests/solvers/test_auto_guarantee.cpp; docs/solvers.md \"Guarantee\")")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--csv", help="write every pair's figures there")
    ap.add_argument("--members-from", metavar="CSV",
                    help="take the members' figures from an earlier --csv of the same corpus and members' code "
                         "(only auto runs: about a fifth of the time, to compare versions of auto)")
    ap.add_argument("--worst", type=int, default=0, metavar="N", help="list the N worst pairs of each tolerance")
    a = ap.parse_args()
    if a.k is None:
        a.k = stated_k()
    if not os.path.exists(a.moreau):
        fail(f"no moreau executable at {a.moreau}")
    if a.jobs < 1 or a.k <= 0:
        fail("--jobs and --k must be positive")
    problems_dir = os.path.join(a.corpus, "problems")
    if not os.path.isdir(problems_dir):
        subprocess.run([sys.executable, os.path.join(HERE, "corpus.py"), "--size", "reduced", "--moreau", a.moreau,
                        "--out", a.corpus], check=True, stdout=subprocess.DEVNULL)
    cases = []
    if os.path.isdir(a.shared):
        cases += [(os.path.join(a.shared, f), False) for f in sorted(os.listdir(a.shared)) if f.endswith(".hdf5")]
    for f in sorted(os.listdir(problems_dir)):
        if f.endswith(".hdf5"):
            cases += [(os.path.join(problems_dir, f), False), (os.path.join(problems_dir, f), True)]
    if not cases:
        fail(f"no problems in {problems_dir}")

    known = members_from(a.members_from, cases, a.tolerances) if a.members_from else {}
    jobs = [(c, tol, s) for c in cases for tol in a.tolerances for s in MEMBERS + ["auto"] if (c, tol, s) not in known]
    with concurrent.futures.ThreadPoolExecutor(a.jobs) as pool:
        results = list(pool.map(lambda j: solve(a.moreau, j[0][0], j[0][1], j[2], j[1]), jobs))
    by = dict(known)
    by.update({(j[0], j[1], j[2]): r for j, r in zip(jobs, results)})

    broken, rows = [], []
    for tol in a.tolerances:
        ratios, dominant, some, by_auto = [], [], 0, 0
        for c in cases:
            name = os.path.basename(c[0])[:-5] + ("+warm" if c[1] else "")
            reached = sorted((by[(c, tol, m)]["work"], m) for m in MEMBERS if by[(c, tol, m)]["converged"])
            au = by[(c, tol, "auto")]
            by_auto += au["converged"]
            row = {"problem": name, "tolerance": tol, "auto_work": au["work"], "auto_converged": au["converged"],
                   "least": reached[0][1] if reached else "", "least_work": reached[0][0] if reached else "",
                   "ratio": "", "members": ",".join(f"{by[(c, tol, m)]['work']!r},{str(by[(c, tol, m)]['converged']).lower()}"
                                                    for m in MEMBERS)}
            if reached:
                some += 1
                ratio = au["work"] / reached[0][0]
                row["ratio"] = f"{ratio:.4g}"
                row["raw"] = ratio
                if not au["converged"]:
                    broken.append(f"{name} at {tol:g}: {reached[0][1]} reaches it, auto stops at {au['error']:.3g}")
                else:
                    ratios.append(ratio)
                    if len(reached) == 1 or reached[0][0] <= 0.5 * reached[1][0]:
                        dominant.append(ratio)
                if ratio > a.k:
                    broken.append(f"{name} at {tol:g}: auto's work {au['work']:.4g} is {ratio:.2f}x {reached[0][1]}'s "
                                  f"{reached[0][0]:.4g} (k {a.k:g})")
            rows.append(row)
        ratios.sort()
        worst = max(ratios) if ratios else 0
        worst_of = next((r["problem"] for r in rows if r["tolerance"] == tol and r.get("raw") == worst), "")
        listed = sorted((r for r in rows if r["tolerance"] == tol and "raw" in r), key=lambda r: -r["raw"])[:a.worst]
        within = lambda k, rs=ratios: sum(x <= k for x in rs)
        print(f"tolerance {tol:g}: {len(cases)} problems, {some} reached by some member, {by_auto} by auto; "
              f"counted work auto / least member: median {statistics.median(ratios) if ratios else 0:.2f}, "
              f"worst {worst:.2f} ({worst_of}); within 1x {within(1)}, 1.5x {within(1.5)}, 2x {within(2)}, "
              f"{a.k:g}x {within(a.k)} of {len(ratios)}; where one member dominates (under half the next): "
              f"{len(dominant)} pairs, worst {max(dominant) if dominant else 0:.2f}, within 1x {within(1, dominant)}, "
              f"1.5x {within(1.5, dominant)}")
        for r in listed:
            print(f"  {r['raw']:6.2f}  {r['problem']:<55} least {r['least']:<6} {float(r['least_work']):10.4g}  "
                  f"auto {r['auto_work']:10.4g}{'' if r['auto_converged'] else ' (missed)'}")
    if a.csv:
        with open(a.csv + ".tmp", "w") as f:
            f.write("problem,tolerance,least,least_work,auto_work,auto_converged,ratio,"
                    + ",".join(f"{m}_work,{m}_converged" for m in MEMBERS) + "\n")
            for r in rows:
                f.write(f"{r['problem']},{r['tolerance']:g},{r['least']},{r['least_work']},{r['auto_work']},"
                        f"{str(r['auto_converged']).lower()},{r['ratio']},{r['members']}\n")
        os.replace(a.csv + ".tmp", a.csv)
    for b in broken:
        print("BROKEN: " + b)
    sys.exit(1 if broken else 0)


if __name__ == "__main__":
    main()
