#!/usr/bin/env python3
"""Mutated copies of the example scenes under `moreau check` (and `moreau run --steps 5`).

usage: mutate_scenes.py MOREAU [--count N] [--seed S] [--run N] [--keep DIR] [--configs DIR]

Each copy of a configs/*.json scene gets one to three mutations (a value replaced by one of
another type or out of range, a key deleted, added or duplicated, an array truncated, a
plugin name swapped for another, a number too large for a double, a value nested 10^5
deep, bytes flipped). Every outcome must be exit 0 (a valid scene) or exit 2 with an
"error:" line; the script counts the others:
  signal        moreau ended by a signal (SIGSEGV, SIGABRT...)
  internal      exit 1 "internal error" (an exception nobody turned into an input error)
  exit1         exit 1 for another reason during `check` (check never runs anything)
  duplicate     a scene with a duplicated key accepted (exit 0)
  no-pointer    exit 2 but the message names no file
Failing inputs are copied to --keep DIR (default: robustness-failures/scenes). Exit status 1
if any failure was found. Seeded: the same seed gives the same copies.
"""
import argparse
import copy
import json
import os
import random
import subprocess
import sys
import tempfile

NAMES = ["disk", "sphere", "polygon", "segment", "box", "convex", "plane", "rigid", "theta", "nlgs", "apgd", "auto",
         "grid", "coulomb", "constant", "energy_log", "shake", "stop_when", "nope", ""]
BIG = "__BIG__"  # written as 1e400 in the text


class Dup:
    """An object whose key list may repeat a key (json.dumps cannot write one)."""

    def __init__(self, pairs):
        self.pairs = pairs


def dump(v):
    if isinstance(v, Dup):
        return "{" + ", ".join(json.dumps(k) + ": " + dump(x) for k, x in v.pairs) + "}"
    if isinstance(v, dict):
        return "{" + ", ".join(json.dumps(k) + ": " + dump(x) for k, x in v.items()) + "}"
    if isinstance(v, list):
        return "[" + ", ".join(dump(x) for x in v) + "]"
    if v == BIG:
        return "1e400"
    return json.dumps(v)


def nodes(v, path=()):
    yield path, v
    if isinstance(v, dict):
        for k, x in v.items():
            yield from nodes(x, path + (k,))
    elif isinstance(v, list):
        for i, x in enumerate(v):
            yield from nodes(x, path + (i,))


def get(root, path):
    for p in path:
        root = root[p]
    return root


def random_value(rng):
    pool = [0, -1, 1, 0.5, -0.0, 1e-300, 1e9, 2 ** 31, 2 ** 63, -2 ** 63, 1e308, BIG, "", "x", "disk", True, False,
            None, [], {}, [1, 2], [1, 2, 3], [0, 0, 0, 0], [[1, 2], [3, 4]], {"type": "x"}, "a" * 300, rng.choice(NAMES)]
    return copy.deepcopy(rng.choice(pool))


def mutate(scene, rng):
    """One mutation in place; returns (scene, kind). May return a Dup or a str (text-level)."""
    all_nodes = list(nodes(scene))
    path, node = rng.choice(all_nodes)
    kind = rng.choice(["replace", "replace", "replace", "delete", "add", "duplicate", "truncate", "name", "big",
                       "deep", "negate"])
    if kind == "replace" and path:
        get(scene, path[:-1])[path[-1]] = random_value(rng)
    elif kind == "delete" and path:
        parent = get(scene, path[:-1])
        del parent[path[-1]]
    elif kind == "add" and isinstance(node, dict):
        node[rng.choice(["extra", "radius", "type", "group", "mass", "fixed", "name"])] = random_value(rng)
    elif kind == "duplicate":
        objs = [(p, n) for p, n in all_nodes if isinstance(n, dict) and n]
        if objs:
            p, n = rng.choice(objs)
            k = rng.choice(list(n.keys()))
            dup = Dup(list(n.items()) + [(k, random_value(rng) if rng.random() < 0.5 else n[k])])
            if p:
                get(scene, p[:-1])[p[-1]] = dup
            else:
                scene = dup
            return scene, "duplicate"
    elif kind == "truncate" and isinstance(node, list) and node:
        del node[rng.randrange(len(node)):]
    elif kind == "name":
        strs = [(p, n) for p, n in all_nodes if isinstance(n, str) and p]
        if strs:
            p, _ = rng.choice(strs)
            get(scene, p[:-1])[p[-1]] = rng.choice(NAMES)
    elif kind == "big" and path:
        get(scene, path[:-1])[path[-1]] = BIG if rng.random() < 0.5 else [BIG, 0, 0]
    elif kind == "deep" and path:
        depth = rng.choice([100, 1000, 100000])
        get(scene, path[:-1])[path[-1]] = "__DEEP%d__" % depth
    elif kind == "negate" and path and isinstance(node, (int, float)) and not isinstance(node, bool):
        get(scene, path[:-1])[path[-1]] = -node * rng.choice([1, 1e6, 1e-6])
    return scene, kind


def text_of(scene, rng, flip):
    t = dump(scene)
    for depth in (100, 1000, 100000):
        t = t.replace('"__DEEP%d__"' % depth, "[" * depth + "1" + "]" * depth)
    if flip:
        b = bytearray(t.encode())
        for _ in range(rng.randint(1, 4)):
            i = rng.randrange(len(b))
            b[i] = rng.choice(b'{}[]:,"0123456789.-eE \x00\xff')
        t = b.decode("utf-8", "replace")
    return t


def classify(proc, is_dup):
    if proc.returncode < 0:
        return "signal"
    err = proc.stderr
    if proc.returncode == 0:
        return "duplicate" if is_dup else "ok"
    if "internal error" in err:
        return "internal"
    if proc.returncode == 2:
        return "rejected" if "error:" in err else "no-pointer"
    return "exit%d" % proc.returncode


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("moreau")
    ap.add_argument("--count", type=int, default=3000)
    ap.add_argument("--seed", type=int, default=11)
    ap.add_argument("--run", type=int, default=0, help="also `run --steps 5` on this many copies")
    ap.add_argument("--keep", default="robustness-failures/scenes")
    ap.add_argument("--configs", default=os.path.join(os.path.dirname(__file__), "..", "..", "configs"))
    a = ap.parse_args()
    rng = random.Random(a.seed)
    scenes = sorted(os.path.join(a.configs, f) for f in os.listdir(a.configs) if f.endswith(".json"))
    originals = {s: json.load(open(s)) for s in scenes}
    counts = {}
    failures = 0
    work = tempfile.mkdtemp(prefix="moreau_mutate_")
    for n in range(a.count + a.run):
        running = n >= a.count
        src = rng.choice(scenes)
        scene = copy.deepcopy(originals[src])
        kinds = []
        for _ in range(rng.randint(1, 3)):
            scene, k = mutate(scene, rng)
            kinds.append(k)
        flip = rng.random() < 0.1
        text = text_of(scene, rng, flip)
        path = os.path.join(work, "scene.json")
        with open(path, "w") as f:
            f.write(text)
        args = [a.moreau, "run", path, "--steps", "5", "--quiet", "--out", os.path.join(work, "out.h5")] if running \
            else [a.moreau, "check", path]
        try:
            proc = subprocess.run(args, capture_output=True, text=True, errors="replace", timeout=120, cwd=work)
            outcome = classify(proc, "duplicate" in kinds and not flip)
            if running and outcome == "exit1" and "run failed" in proc.stderr:
                outcome = "run-failed"  # a run may fail (non-finite values...): exit 1 is its code
        except subprocess.TimeoutExpired:
            outcome, proc = "timeout", None
        key = ("run " if running else "check ") + outcome
        counts[key] = counts.get(key, 0) + 1
        if outcome not in ("ok", "rejected", "run-failed"):
            failures += 1
            os.makedirs(a.keep, exist_ok=True)
            name = "%s-%05d-%s.json" % (outcome, n, os.path.basename(src)[:-5])
            with open(os.path.join(a.keep, name), "w") as f:
                f.write(text)
            msg = (proc.stderr.strip().splitlines() or [""])[-1][:200] if proc else ""
            print("%-10s %-40s %s %s" % (outcome, name, ",".join(kinds), msg), flush=True)
    for k in sorted(counts):
        print("%6d  %s" % (counts[k], k))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
