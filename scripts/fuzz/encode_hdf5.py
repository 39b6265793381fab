#!/usr/bin/python3
"""Writes an HDF5 file as an input of the HDF5 fuzz targets (tests/fuzz/h5_records.hpp).

usage: encode_hdf5.py IN.h5 OUT [--prefix BYTE]

Every group, dataset and attribute becomes a record; the targets write them back as an
HDF5 file. Used to make the seed corpora from real files (scripts/fuzz/make_seeds.sh).
--prefix: a first byte (the restart target's choice of scene).
"""
import argparse
import struct
import sys

import h5py
import numpy as np

TYPES = {np.dtype("<f8"): 0, np.dtype("<i4"): 1, np.dtype("<f4"): 4, np.dtype("i1"): 5, np.dtype("<i8"): 6}


def name(s):
    b = s.encode()
    if len(b) > 255:
        raise ValueError("name too long: " + s)
    return bytes([len(b)]) + b


def payload(value):
    """type byte, rank, dims, values — or None if the type has no record form."""
    a = np.asarray(value)
    if a.ndim > 2 or any(d > 65535 for d in a.shape):
        return None
    if h5py.check_string_dtype(a.dtype) is not None or a.dtype.kind in "SUO":
        kind = 2
        flat = [x if isinstance(x, bytes) else str(x).encode() for x in a.reshape(-1)]
        body = b"".join(struct.pack("<H", len(s)) + s for s in flat)
    elif a.dtype.kind in "iu" and a.dtype.itemsize == 4:
        kind, body = 1, a.astype("<i4").tobytes()
    elif a.dtype.kind in "iu" and a.dtype.itemsize == 1:
        kind, body = 5, a.astype("i1").tobytes()
    elif a.dtype.kind in "iu":
        kind, body = 6, a.astype("<i8").tobytes()
    elif a.dtype == np.float32:
        kind, body = 4, a.astype("<f4").tobytes()
    elif a.dtype.kind == "f":
        kind, body = 0, a.astype("<f8").tobytes()
    else:
        return None
    return bytes([kind, a.ndim]) + b"".join(struct.pack("<H", d) for d in a.shape) + body


def encode(path):
    out = bytearray()
    with h5py.File(path, "r") as f:
        def attrs(obj_path, obj):
            for k, v in obj.attrs.items():
                p = payload(v)
                if p is not None:
                    out.extend(bytes([1]) + name(obj_path) + name(k) + p)

        attrs("", f)
        items = []
        f.visititems(lambda n, o: items.append((n, o)))
        for n, o in items:
            if isinstance(o, h5py.Group):
                out.extend(bytes([2]) + name(n))
            elif isinstance(o, h5py.Dataset):
                p = payload(o[()])
                if p is not None:
                    out.extend(bytes([0]) + name(n) + p)
            attrs(n, o)
    return bytes(out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("input")
    ap.add_argument("output")
    ap.add_argument("--prefix", type=int)
    a = ap.parse_args()
    data = encode(a.input)
    if a.prefix is not None:
        data = bytes([a.prefix]) + data
    with open(a.output, "wb") as f:
        f.write(data)


if __name__ == "__main__":
    sys.exit(main())
