#!/usr/bin/env python3
"""Each solver's time per step, misses and worst error by step range, from MOREAU_SHADOW_TRACE.

    python3 scripts/shadow_phases.py TRACE[:OFFSET[:LABELS]] ... [--bin 500] [--ref auto] [--top 10]

MOREAU_SHADOW_TRACE=1 prints one line per solve and solver on stderr (`shadow: LABEL solve N
cpu S it I err E conv C work W`; docs/solvers.md, "Comparing solvers on one run"). Several
traces of the same problems may be given: OFFSET shifts a trace's solve indices (a run
restarted from step OFFSET counts its solves from 1), LABELS renames its members (`_1e5`
appends a suffix to every member's label, `nlgs=nlgs_2e4,apgd=apgd_1e4` renames some); the
reference solver (--ref, the scene's `auto`) is taken from the first trace that has the solve.
Only solves that every label has are summed. Prints, per range of --bin solves: each solver's
ms per solve, misses and worst error, and the "cheapest converged member" of each solve (the
least time of the members that reached the tolerance on it; a solve that none reached adds
nothing, which flatters that column); then the solves on which --ref lost most against that.
"""
import argparse
import collections

from auto_trace_summary import shadow_line


def label_of(label, spec, ref):
    if label == ref or not spec:
        return label
    if "=" in spec:
        return dict(x.split("=") for x in spec.split(",")).get(label, label)
    return label + spec


def read(specs, ref, drop):
    solves, labels = collections.defaultdict(dict), []
    for spec in specs:
        path, offset, names = (spec.split(":") + ["0", ""])[:3]
        with open(path) as f:
            for line in f:
                shadow = shadow_line(line)
                if not shadow or shadow[0] in drop:
                    continue
                label, index, fields = shadow
                key = label_of(label, names, ref)
                i = index + int(offset or 0)
                if key in solves[i]:
                    continue
                solves[i][key] = (fields["cpu"], fields["err"], fields["ok"])
                if key not in labels:
                    labels.append(key)
    return solves, labels


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("traces", nargs="+")
    ap.add_argument("--bin", type=int, default=500, help="solves per range")
    ap.add_argument("--ref", default="auto", help="the solver compared with the members (a label)")
    ap.add_argument("--drop", nargs="*", default=[], help="labels to leave out")
    ap.add_argument("--top", type=int, default=10, help="how many of the solves where --ref lost most to list")
    a = ap.parse_args()
    solves, labels = read(a.traces, a.ref, a.drop)
    members = [l for l in labels if l != a.ref]
    idx = [i for i in sorted(solves) if all(l in solves[i] for l in labels)]
    print(f"{len(idx)} solves with every label ({len(solves)} seen)")

    def cheapest(i):
        ok = [(solves[i][l][0], l) for l in members if solves[i][l][2]]
        return min(ok) if ok else None

    def row(name, group):
        cells = [f"{name:>11s} {len(group):5d}"]
        for l in labels:
            s = [solves[i][l] for i in group]
            cells.append(f"{l} {1e3 * sum(x[0] for x in s) / len(s):8.2f} ms ({sum(1 for x in s if not x[2])} missed, "
                         f"worst {max(x[1] for x in s):.1e})")
        c = sum(x[0] for x in (cheapest(i) for i in group) if x)
        cells.append(f"cheapest converged {1e3 * c / len(group):8.2f} ms")
        print(" | ".join(cells))

    if not idx:
        return
    row("all", idx)
    ranges = collections.defaultdict(list)
    for i in idx:
        ranges[(i - 1) // a.bin].append(i)
    for b in sorted(ranges):
        row(f"{b * a.bin + 1}-{(b + 1) * a.bin}", ranges[b])
    loss = []
    for i in idx:
        c = cheapest(i)
        if c:
            loss.append((solves[i][a.ref][0] - c[0], i, c[1], c[0], solves[i][a.ref][0]))
    loss.sort(reverse=True)
    gained = sum(x[0] for x in loss if x[0] > 0)
    print(f"\n{a.ref} above the cheapest converged member, summed over the solves where it is: {gained:.2f} s "
          f"(the {a.top} worst: {sum(x[0] for x in loss[:a.top]):.2f} s)")
    for x in loss[:a.top]:
        print(f"  solve {x[1]:5d}: {a.ref} {x[4]:.3f} s, {x[2]} {x[3]:.3f} s")


if __name__ == "__main__":
    main()
