#!/usr/bin/env python3
"""The plane shear flow study (configs/shear_flow_2d.json, docs/analyses.md): 360 disks
between two rough walls moving at -0.25 and +0.25 m/s, under 1000 Pa, without gravity.

Checks, on the profiles across a central box of the layer averaged over every step from
0.15 s to the end (`average`): the velocity rises from the bottom wall's side to the top
wall's; the normal stress Sigma_yy is uniform across the layer (momentum balance in a
steady plane flow: every slice within 4 standard errors of the slices' mean, the error from
the scatter of the 100-step averages between frames) and equals the top wall's load over the
same stretch of wall (`top_centre`, averaged over the same steps) within 10 % of the imposed
pressure (the column also exchanges vertical shear with its neighbours; the end walls make
the load vary along the layer: the imposed 1000 Pa is its mean over the whole wall); the
shear stress is uniform (within 40 % of its mean); the inertia term is reported. Then the
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
    # `average`: each frame holds the mean over the 100 steps before it; their mean is the
    # mean over every step of the window.
    v = np.mean(pa.values(fr, "layer", "average/profile/velocity"), axis=0)[:, 0]
    blocks = pa.values(fr, "layer", "average/profile/total")
    S = np.nanmean(blocks, axis=0)
    se = np.nanstd(blocks[:, :, 1, 1], axis=0) / np.sqrt(len(blocks))
    I = np.nanmean(pa.values(fr, "layer", "average/profile/inertia"), axis=0)
    y = fr[-1][1]["analyses"]["layer/profile/position"][()]
    box = fr[-1][1]["analyses"]["layer/box_max"][()] - fr[-1][1]["analyses"]["layer/box_min"][()]
    top = pa.window(pa.frames_with(f, "top_centre"), 0.15, None, False)
    # The force on the top wall from the layer: up, the pressure times the stretch.
    p_top = np.mean(pa.values(top, "top_centre", "average/force")[:, 0, 1]) / box[0]
    np.set_printoptions(precision=3, suppress=True, linewidth=150)
    print("y (mm)        ", y * 1e3)
    print("v_x (m/s)     ", v)
    print("Sigma_yy (Pa) ", S[:, 1, 1])
    print("  std. error  ", se)
    print("Sigma_xy (Pa) ", S[:, 0, 1])
    print("inertia xy    ", I[:, 0, 1])
    syy = S[:, 1, 1]
    print(f"mean Sigma_yy {syy.mean():.1f} Pa; the top wall's load over the box's {box[0] * 1e3:.0f} mm: {p_top:.1f} Pa "
          f"(imposed on the whole wall: {P:.0f} Pa)")
    check(v[-1] > 0.05 and v[0] < -0.05 and np.corrcoef(y, v)[0, 1] > 0.9, "the velocity rises across the layer")
    check(np.all(np.abs(syy - syy.mean()) < 4 * se), "the normal stress is uniform across the layer")
    check(abs(-syy.mean() - p_top) < 0.1 * P,
          f"the normal stress is the top wall's load: {-syy.mean():.1f} against {p_top:.1f} Pa")
    sxy = S[:, 0, 1]
    check(np.all(np.abs(sxy - sxy.mean()) < 0.4 * abs(sxy.mean())) and sxy.mean() > 0.1 * P,
          f"the shear stress is uniform across the layer: mean {sxy.mean():.1f} Pa, friction {sxy.mean() / P:.3f}")
    check(np.all(np.isfinite(I)) and np.abs(I).max() > 0, "the inertia term is reported")
study.plot(out, "layer", "--from", "0.15")
study.finish()
