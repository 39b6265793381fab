#!/usr/bin/env python3
"""Compares two moreau output files frame by frame, bit for bit.

Every dataset of the first file's frames (and of /bodies, /contactors, /display) must be in
the second with the same shape and exactly the same values (a moreau-output/2 file holds
every moreau-output/1 dataset at its place, so a v1 file compares with a v2 one); datasets
only the second file has are listed. Exit 0 when identical, 1 otherwise.

    python3 scripts/compare_outputs.py OLD.h5 NEW.h5 [--quiet]
"""
import sys

import h5py
import numpy as np


def datasets(group, prefix=""):
    out = {}
    for name, obj in group.items():
        path = prefix + "/" + name
        if isinstance(obj, h5py.Dataset):
            out[path] = obj
        else:
            out.update(datasets(obj, path))
    return out


def main():
    args = [a for a in sys.argv[1:] if not a.startswith("--")]
    quiet = "--quiet" in sys.argv
    a, b = h5py.File(args[0], "r"), h5py.File(args[1], "r")
    da, db = datasets(a), datasets(b)
    bad = 0
    for path, x in da.items():
        if path not in db:
            print("missing in the second file:", path)
            bad += 1
            continue
        y = db[path]
        xv, yv = x[()], y[()]
        if np.shape(xv) != np.shape(yv):
            print("shape differs:", path, np.shape(xv), np.shape(yv))
            bad += 1
        elif x.dtype.kind in "fiu" and not np.array_equal(np.asarray(xv), np.asarray(yv), equal_nan=True):
            diff = np.max(np.abs(np.asarray(xv, float) - np.asarray(yv, float)))
            print("values differ:", path, "max |diff|", diff)
            bad += 1
        elif x.dtype.kind not in "fiu" and list(np.ravel(xv)) != list(np.ravel(yv)):
            print("values differ:", path)
            bad += 1
    extra = sorted(set(db) - set(da))
    if not quiet:
        print(f"{len(da)} datasets compared, {bad} differ; {len(extra)} only in the second file")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
