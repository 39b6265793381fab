"""Tables of the work-precision benchmark (work_precision.py): table.csv with every run,
table.md with the table tolerances and the comparison with the Siconos reference figures."""
import csv

# The reference figures of ../shared/fclib/README.md ("Reference figures (Siconos numerics,
# same class of 2-core machine)"), copied by hand: problem → tolerance → (Siconos NSGS,
# best Siconos solver, the best one's seconds). Error there is the DESIGN §1 measure, time
# the median solve-only wall clock, as here.
SICONOS = {
    "fclib-local_problem_test": {
        1e-4: ("36127 it, 0.43 s", "ADMM: 945 it, 0.008 s", 0.008),
        1e-8: ("fails (1e5 it, err 7e-6, 1.2 s)", "ADMM: 1190 it, 0.010 s", 0.010),
    },
    "faf-Capsules-i97-269": {
        1e-4: ("109 it, 0.005 s", "VI extra-gradient: 112 it, 0.002 s", 0.002),
        1e-8: ("2888 it, 0.088 s", "ADMM: 2902 it, 0.055 s", 0.055),
    },
    "faf-Box_Stacks-i0035-31-0": {
        1e-8: ("NSGS on the reduced problem: 0.0008 s", "same", 0.0008),
    },
    "spheres-in-a-box-98-i10000-256-10": {
        1e-8: ("NSGS on the reduced problem fails (err 2.5e-6 after 7.7 s)",
               "Newton Alart–Curnier on the reduced problem: 0.58 s", 0.58),
    },
    "CubeH8": {
        1e-8: ("0.005 s", "Newton Alart–Curnier: 0.003 s", 0.003),
    },
}

COLUMNS = ["problem", "solver", "tolerance", "iterations", "error", "seconds", "converged", "repeats", "note"]


def tol_text(t):
    """1e-08 → "1e-8", 2.5e-06 → "2.5e-6": tolerances as people write them."""
    mantissa, exponent = f"{t:.6e}".split("e")
    return f"{mantissa.rstrip('0').rstrip('.')}e{int(exponent)}"


def _num(x, fmt):
    return "" if x is None else format(x, fmt)


def write_csv(path, rows):
    """Every run, intermediate tolerances included, in run order."""
    with open(path, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(COLUMNS)
        for r in rows:
            w.writerow([r["problem"], r["solver"], tol_text(r["tolerance"]), _num(r["iterations"], "d"),
                        _num(r["error"], ".6e"), _num(r["seconds"], ".6e"), str(r["converged"]).lower(),
                        r["repeats"], r["note"]])


def _secs(s):
    return "—" if s is None else f"{s:.3g}"


def _fastest(rows):
    ok = [r for r in rows if r["converged"]]
    return min(ok, key=lambda r: r["seconds"]) if ok else None


def _main_table(out, rows, tol, solvers):
    out += [f"## Tolerance {tol_text(tol)}", "",
            "| problem | solver | iterations | error | seconds | converged |", "|---|---|---:|---:|---:|---|"]
    for problem in dict.fromkeys(r["problem"] for r in rows):
        mine = sorted((r for r in rows if r["problem"] == problem and r["tolerance"] == tol),
                      key=lambda r: solvers.index(r["solver"]))
        best = _fastest(mine)
        for r in mine:
            secs = _secs(r["seconds"])
            if r is best:
                secs = f"**{secs}**"  # the fastest that converged
            conv = "yes" if r["converged"] else f"no ({r['note']})"
            err = "—" if r["error"] is None else f"{r['error']:.1e}"
            it = "—" if r["iterations"] is None else str(r["iterations"])
            out.append(f"| {problem} | `{r['solver']}` | {it} | {err} | {secs} | {conv} |")
    out.append("")


def _reference_table(out, rows, tol):
    problems = [p for p in dict.fromkeys(r["problem"] for r in rows) if tol in SICONOS.get(p, {})]
    if not problems:
        return
    out += [f"## Time to {tol_text(tol)} per problem against the Siconos reference", "",
            "Siconos figures from `../shared/fclib/README.md` (same class of 2-core machine, not this run).", "",
            "| problem | Siconos NSGS (default) | best Siconos solver | moreau `auto` | fastest moreau solver "
            "| `auto` / best Siconos |",
            "|---|---|---|---|---|---|"]
    for p in problems:
        nsgs, best_text, best_s = SICONOS[p][tol]
        mine = [r for r in rows if r["problem"] == p and r["tolerance"] == tol]
        auto = next((r for r in mine if r["solver"] == "auto"), None)
        if auto is None:
            auto_text, ratio = "not run", "—"
        elif auto["converged"]:
            auto_text = f"{auto['iterations']} it, {_secs(auto['seconds'])} s"
            ratio = f"{auto['seconds'] / best_s:.2g}×"
        else:
            err = "—" if auto["error"] is None else f"{auto['error']:.1e}"
            auto_text, ratio = f"fails ({auto['note']}, err {err})", "fails"
        fastest = _fastest(mine)
        fast_text = "none converged" if fastest is None else \
            f"`{fastest['solver']}`: {fastest['iterations']} it, {_secs(fastest['seconds'])} s"
        out.append(f"| {p} | {nsgs} | {best_text} | {auto_text} | {fast_text} | {ratio} |")
    out.append("")


def write_markdown(path, rows, table_tols, solvers, command):
    """The table tolerances only; bold: the fastest solver that converged on the problem."""
    table = [r for r in rows if r["table"]]
    out = ["# Work-precision benchmark", "", f"Generated by `{command}`.", "",
           "Error: DESIGN §1 measure recomputed from r. Seconds: solve time from r = 0, the median of "
           "the repeats where the solver converged, a single solve where it did not. "
           "Bold: the fastest that converged.", ""]
    for tol in table_tols:
        _main_table(out, table, tol, solvers)
    for tol in table_tols:
        _reference_table(out, table, tol)
    with open(path, "w") as f:
        f.write("\n".join(out))


def write_guarantee(path, rows, table_tols, k, command):
    """guarantee.md: per problem and table tolerance, the fastest member (any solver but
    auto) and auto's time over it; then the summary. Returns the summary text."""
    members = sorted({r["solver"] for r in rows if r["solver"] != "auto"})
    lines = [f"# auto against its members\n", f"Command: `{command}`\n",
             f"Members: {', '.join('`' + m + '`' for m in members)}. Ratio: auto's seconds over the fastest "
             f"member's (medians of the repeats). k = {k:g}. Work ratio: auto's counted work over the least "
             f"counted work of a member that converged (`work` of `moreau fclib solve`; members that count it: "
             f"nlgs, apgd, newton, admm), the deterministic measure the test of the guarantee uses.\n"]
    summary = []
    for tol in table_tols:
        at = [r for r in rows if r["tolerance"] == tol and r["table"]]
        problems = sorted({r["problem"] for r in at})
        solved = auto_ok = within = 0
        worst = (0.0, "")
        table = ["| problem | fastest member | seconds | auto | seconds | ratio | least-work member | work ratio |",
                 "|---|---|---:|---|---:|---:|---|---:|"]
        misses = []
        for p in problems:
            mem = _fastest([r for r in at if r["problem"] == p and r["solver"] != "auto"])
            au = [r for r in at if r["problem"] == p and r["solver"] == "auto"]
            au = au[0] if au else None
            if mem is None:
                table.append(f"| {p} | none converged | — | {'yes' if au and au['converged'] else 'no'} | "
                             f"{_secs(au and au['seconds'])} | — |")
                if au and au["converged"]:
                    auto_ok += 1
                continue
            solved += 1
            ok = bool(au and au["converged"])
            ratio = au["seconds"] / mem["seconds"] if ok and mem["seconds"] > 0 else None
            if ok:
                auto_ok += 1
                if ratio is not None and ratio <= k:
                    within += 1
                if ratio is not None and ratio > worst[0]:
                    worst = (ratio, p)
            else:
                misses.append(p)
            counted = [r for r in at if r["problem"] == p and r["solver"] != "auto" and r["converged"] and r.get("work")]
            least = min(counted, key=lambda r: r["work"]) if counted else None
            wratio = au["work"] / least["work"] if ok and least and au.get("work") else None
            table.append(f"| {p} | `{mem['solver']}` | {_secs(mem['seconds'])} | {'yes' if ok else 'NO'} | "
                         f"{_secs(au and au['seconds'])} | {'—' if ratio is None else f'{ratio:.2f}'} | "
                         f"{'—' if least is None else '`' + least['solver'] + '`'} | "
                         f"{'—' if wratio is None else f'{wratio:.2f}'} |")
        text = (f"tolerance {tol_text(tol)}: {len(problems)} problems, {solved} solved by some member, "
                f"{auto_ok} by auto, {within} by auto within {k:g}x the fastest member; "
                f"worst ratio {worst[0]:.2f} ({worst[1]})" + (f"; auto failed on {', '.join(misses)}" if misses else ""))
        summary.append(text)
        lines += [f"\n## Tolerance {tol_text(tol)}\n", text + "\n", *table]
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return "\n".join(summary)
