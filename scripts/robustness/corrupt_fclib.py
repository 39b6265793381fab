#!/usr/bin/python3
"""Corrupted copies of the shared FCLib problems under `moreau fclib solve`.

usage: corrupt_fclib.py MOREAU [--count N] [--seed S] [--shared DIR] [--keep DIR]

Each copy of a ../shared/fclib/*.hdf5 problem gets one corruption: an entry of a dataset
set to NaN, +-Inf, 1e308, -1, 2^31 or a fraction (integer datasets are rewritten as float64
to hold it), a scalar (m, n, nz, spacedim) set to an absurd value, a dataset truncated,
deleted or replaced by a string. Every outcome must be exit 0 on a file that is still a
sound problem, or exit 2 naming an HDF5 path; the script counts the others:
  signal     moreau ended by a signal
  exit1      exit 1 (bad input must be exit 2; the solver's own failure is not exit 1 either)
  accepted   exit 0 on a file with a non-finite number or changed dimensions
Failing copies go to --keep DIR (default robustness-failures/fclib). Seeded.
"""
import argparse
import os
import random
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

SPECIAL = [np.nan, np.inf, -np.inf, 1e308, -1.0, 2.0 ** 31, 0.5, 1e-320]


def datasets(f):
    """The datasets a reader uses: the problem, and the first guess (others are free text,
    another code's answer or unused bookkeeping such as nzmax)."""
    out = []

    def used(n, o):
        if isinstance(o, h5py.Dataset) and n.startswith("fclib_") and "/info/" not in n and not n.endswith("nzmax"):
            out.append(n)
        elif n == "guesses/1/r":
            out.append(n)

    f.visititems(used)
    return out


def corrupt(path, rng):
    """Returns (kind, clearly_bad)."""
    with h5py.File(path, "r+") as f:
        names = datasets(f)
        name = rng.choice(names)
        data = f[name][()]
        kind = rng.choice(["value", "value", "value", "scalar", "truncate", "delete", "string"])
        if kind == "scalar":
            scalars = [n for n in names if n.split("/")[-1] in ("m", "n", "nz", "spacedim")]
            name = rng.choice(scalars)
            del f[name]
            f[name] = np.array([rng.choice([2 ** 31 - 1, 2 ** 31, -5, 0, 1e300, np.nan, 7])], dtype=np.float64)
            return "scalar " + name, True
        if kind == "truncate" and np.ndim(data) == 1 and len(data) > 1:
            del f[name]
            f[name] = data[: rng.randrange(len(data))]
            return "truncate " + name, True
        if kind == "delete":
            del f[name]
            return "delete " + name, not name.startswith("guesses")  # a guess is optional
        if kind == "string":
            del f[name]
            f[name] = "garbage"
            return "string " + name, True
        a = np.array(data, dtype=np.float64).reshape(-1)
        if a.size == 0:
            return "none", False
        x = rng.choice(SPECIAL)
        a[rng.randrange(a.size)] = x
        del f[name]
        f[name] = a.reshape(np.shape(data)) if np.ndim(data) else a
        return "value %s=%r" % (name, x), not np.isfinite(x)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("moreau")
    ap.add_argument("--count", type=int, default=600)
    ap.add_argument("--seed", type=int, default=11)
    ap.add_argument("--shared", default=os.path.join(os.path.dirname(__file__), "..", "..", "..", "shared", "fclib"))
    ap.add_argument("--keep", default="robustness-failures/fclib")
    a = ap.parse_args()
    rng = random.Random(a.seed)
    files = sorted(os.path.join(a.shared, f) for f in os.listdir(a.shared) if f.endswith(".hdf5"))
    work = tempfile.mkdtemp(prefix="moreau_corrupt_")
    counts, failures = {}, 0
    for n in range(a.count):
        src = rng.choice(files)
        path = os.path.join(work, os.path.basename(src))
        shutil.copy(src, path)
        os.chmod(path, 0o644)
        kind, bad = corrupt(path, rng)
        try:
            p = subprocess.run([a.moreau, "fclib", "solve", path, "--solver", "nlgs", "--max-iter", "200"],
                               capture_output=True, text=True, errors="replace", timeout=300, cwd=work)
            if p.returncode < 0:
                outcome = "signal"
            elif p.returncode == 0:
                outcome = "accepted" if bad else "ok"
            elif p.returncode == 2:
                outcome = "rejected" if "error:" in p.stderr else "no-message"
            else:
                outcome = "exit%d" % p.returncode
        except subprocess.TimeoutExpired:
            outcome, p = "timeout", None
        counts[outcome] = counts.get(outcome, 0) + 1
        if outcome not in ("ok", "rejected"):
            failures += 1
            os.makedirs(a.keep, exist_ok=True)
            keep = os.path.join(a.keep, "%s-%04d-%s" % (outcome, n, os.path.basename(src)))
            shutil.copy(path, keep)
            msg = (p.stderr.strip().splitlines() or [""])[-1][:160] if p else ""
            print("%-9s %-50s %s %s" % (outcome, os.path.basename(keep), kind, msg), flush=True)
    for k in sorted(counts):
        print("%6d  %s" % (counts[k], k))
    shutil.rmtree(work, ignore_errors=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
