#!/usr/bin/env python3
"""Where `auto`'s time goes in a run with shadow solvers, step by step (issue 15, point 3).

Run a scene with `auto` as the scene's solver or as a shadow, the members as shadows, and
both traces on stderr:

    MOREAU_AUTO_TRACE=1 MOREAU_SHADOW_TRACE=1 \\
    MOREAU_SHADOW_SOLVERS='[{"type":"nlgs","tolerance":1e-4},{"type":"apgd","tolerance":1e-4}]' \\
        moreau run SCENE.json 2> trace.txt
    python3 scripts/auto_trace_summary.py trace.txt [--member apgd] [--tolerance 1e-4]

MOREAU_SHADOW_TRACE prints one line per solve and solver (its thread CPU time in solve(),
iterations, error, whether it converged, counted work); MOREAU_AUTO_TRACE prints each of
`auto`'s slices (member, kind: first = the remembered member's or NLGS's first stage,
challenger, probe, slice; its work, its CPU time, the errors). With only one `auto` in the
run its slices are those printed before its solve's line. Prints:
- each solver's total CPU time and misses;
- `auto` against --member on the steps that member solves and on those it misses;
- the same split by `auto`'s first member and by the member that reached the tolerance;
- `auto`'s slice time per member and kind, split by whether the slice lowered its error.
"""
import argparse
import collections
import re

SLICE = re.compile(r"auto: (.+?) \[(\w+)\], budget \S+, took ([\d.e+-]+) work \(([\d.e+-]+) ns\), "
                   r"from ([\d.e+inf-]+) reached ([\d.e+inf-]+), best ([\d.e+inf-]+)")
FIRST_NLGS = re.compile(r"auto: first nlgs ([\d.e+-]+) work \(([\d.e+-]+) ns\), best ([\d.e+inf-]+)")


SHADOW = re.compile(r"^shadow: (.+?) solve (\d+) cpu (\S+) it (\d+) err (\S+) conv (\d) work (\S+)")


def shadow_line(line):
    """One MOREAU_SHADOW_TRACE line as (label, solve index, fields), or None for any other line
    (also used by scripts/shadow_phases.py)."""
    m = SHADOW.match(line)
    if not m:
        return None
    return m.group(1), int(m.group(2)), dict(cpu=float(m.group(3)), it=int(m.group(4)), err=float(m.group(5)),
                                              ok=m.group(6) == "1", work=float(m.group(7)))


def read(path):
    """Per solve index: {label: fields}; per solve index: auto's slices (member, kind, work, s, from, reached, best)."""
    solves, slices, pending, labels = collections.defaultdict(dict), {}, [], []
    with open(path) as f:
        for line in f:
            shadow = shadow_line(line)
            if shadow:
                label, index, fields = shadow
                solves[index][label] = fields
                if label not in labels:
                    labels.append(label)
                if label == "auto":
                    slices[index], pending = pending, []
                continue
            m = FIRST_NLGS.search(line)
            if m:
                pending.append(("nlgs", "first", float(m.group(1)), float(m.group(2)) * 1e-9, float("inf"), float(m.group(3)),
                                float(m.group(3))))
                continue
            m = SLICE.search(line)
            if m:
                pending.append((m.group(1), m.group(2), float(m.group(3)), float(m.group(4)) * 1e-9, float(m.group(5)),
                                float(m.group(6)), float(m.group(7))))
    return solves, slices, labels


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("trace")
    ap.add_argument("--member", default="apgd", help="the member to compare auto with (a shadow's label)")
    ap.add_argument("--tolerance", type=float, default=1e-4, help="auto's tolerance (which slice reached it)")
    a = ap.parse_args()
    solves, slices, labels = read(a.trace)
    steps = [s for s in solves.values() if "auto" in s and a.member in s]
    print(f"{len(steps)} solves")
    for label in labels:
        print(f"  {label:10s} {sum(s[label]['cpu'] for s in solves.values() if label in s):9.2f} s CPU, "
              f"{sum(1 for s in solves.values() if label in s and not s[label]['ok'])} missed")

    def row(name, group):
        x, y = sum(s["auto"]["cpu"] for s in group), sum(s[a.member]["cpu"] for s in group)
        print(f"  {name:40s} {len(group):6d} steps  auto {x:8.2f} s  {a.member} {y:8.2f} s  ratio {x / y if y else float('nan'):5.2f}")

    def first(sl):
        return next((s[0] for s in sl if s[1] == "first"), "-")

    def winner(sl):
        return next((s[0] for s in sl if s[6] <= a.tolerance), "none (auto missed, or its start was the answer)")

    print(f"\nauto against {a.member} (CPU in solve()):")
    for ok in (True, False):
        row(f"steps {a.member} {'solves' if ok else 'misses'}", [s for s in steps if s[a.member]["ok"] == ok])
    for title, key in (("auto's first member", first), ("member that reached the tolerance", winner)):
        print(f"\nby {title}:")
        groups = collections.defaultdict(list)
        for i, s in solves.items():
            if i in slices and a.member in s:
                groups[(s[a.member]["ok"], key(slices[i]))].append(s)
        for (ok, k), g in sorted(groups.items()):
            row(f"{a.member} {'solves' if ok else 'misses'}, {k}", g)
    print("\nauto's slices (member, kind, whether the slice lowered its error): count, CPU s")
    kinds = collections.defaultdict(lambda: [0, 0.0])
    for sl in slices.values():
        for who, kind, _, sec, frm, reached, _ in sl:
            gain = "from unknown" if frm == float("inf") else "gain" if reached < 0.99 * frm else "no gain"
            k = kinds[(who, kind, gain)]
            k[0] += 1
            k[1] += sec
    for (who, kind, gain), (n, sec) in sorted(kinds.items(), key=lambda x: -x[1][1]):
        print(f"  {who:22s} {kind:11s} {gain:13s} {n:6d} {sec:8.2f}")


if __name__ == "__main__":
    main()
