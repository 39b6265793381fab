#!/usr/bin/env python3
"""The plane shear flow study (configs/shear_flow_2d.json, docs/analyses.md): 360 disks
between two rough walls moving at -0.25 and +0.25 m/s, under 1000 Pa, without gravity.

Checks, on the profiles across the layer averaged from 0.15 s to the end: the velocity
rises from the bottom wall's side to the top wall's, the normal stress is the imposed
pressure in every slice (within 20 %), the shear stress is uniform (within 40 % of its
mean: momentum balance in a steady plane flow), and the inertia term is reported. Then the
profile plot is made.

usage: study_shear.py SOURCE_DIR MOREAU WORK_DIR
"""
import h5py
import numpy as np

from study_common import Study

study = Study()
check = study.check
import plot_analyses as pa  # noqa: E402  (scripts/, put on the path by Study)

out = study.run("shear_flow_2d.json", "shear.h5")

P = 1000.0
with h5py.File(out, "r") as f:
    fr = pa.window(pa.frames_with(f, "layer"), 0.15, None, False)
    v = np.mean(pa.values(fr, "layer", "profile/velocity"), axis=0)[:, 0]
    S = np.nanmean(pa.values(fr, "layer", "profile/total"), axis=0)
    I = np.nanmean(pa.values(fr, "layer", "profile/inertia"), axis=0)
    y = fr[-1][1]["analyses"]["layer/profile/position"][()]
    np.set_printoptions(precision=3, suppress=True, linewidth=150)
    print("y (mm)        ", y * 1e3)
    print("v_x (m/s)     ", v)
    print("Sigma_yy (Pa) ", S[:, 1, 1])
    print("Sigma_xy (Pa) ", S[:, 0, 1])
    print("inertia xy    ", I[:, 0, 1])
    check(v[-1] > 0.05 and v[0] < -0.05 and np.corrcoef(y, v)[0, 1] > 0.9, "the velocity rises across the layer")
    check(np.all(np.abs(S[:, 1, 1] + P) < 0.2 * P), "the normal stress is the imposed pressure in every slice")
    sxy = S[:, 0, 1]
    check(np.all(np.abs(sxy - sxy.mean()) < 0.4 * abs(sxy.mean())) and sxy.mean() > 0.1 * P,
          f"the shear stress is uniform across the layer: mean {sxy.mean():.1f} Pa, friction {sxy.mean() / P:.3f}")
    check(np.all(np.isfinite(I)) and np.abs(I).max() > 0, "the inertia term is reported")
study.plot(out, "layer", "--from", "0.15")
study.finish()
