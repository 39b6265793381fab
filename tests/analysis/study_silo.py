#!/usr/bin/env python3
"""The Janssen silo study (configs/silo_janssen_2d.json, docs/analyses.md), full size:
350 disks of radius 1.5 mm ± 10 %, mu = 0.25, settled under gravity (0 to 0.4 s), then the
bottom lowered at 1 mm/s (0.4 to 0.8 s) and stopped.

Checks: the wall contacts are pushed onto the Coulomb cone by the lowering (share sliding
before < 0.1, during > 0.4); the vertical stress saturates with depth (at the bottom well
below the hydrostatic gamma z) and follows Janssen's curve gamma l (1 - exp(-z/l)) with the
sample's own unit weight gamma (one parameter, l; rms residual below 15 % of the largest
stress: force chains in a silo 7 grains wide); Janssen's closure holds: with the wall
friction the sample mobilises, mu_mob = sum(tau_w)/sum(sigma_w), the fitted length gives
lambda = R_h/(mu_mob l) within 15 % of the measured sum(sigma_w)/sum(sigma_zz); the energy
balance closes to rounding. Then every plot of scripts/plot_analyses.py is made.

usage: study_silo.py SOURCE_DIR MOREAU WORK_DIR
"""
import h5py
import numpy as np

from study_common import Study

study = Study()
check = study.check
import plot_analyses as pa  # noqa: E402  (scripts/, put on the path by Study)

out = study.run("silo_janssen_2d.json", "silo.h5")

with h5py.File(out, "r") as f:
    polar = pa.frames_with(f, "polarization")
    before = pa.window(polar, 0.3, 0.4, False)
    during = pa.window(polar, 0.6, 0.8, False)
    s_before = pa.values(before, "polarization", "shares")[:, 0].mean(axis=0)
    s_during = pa.values(during, "polarization", "shares")[:, 0].mean(axis=0)
    check(s_before[2] < 0.1, f"wall contacts sliding before the lowering: {s_before[2]:.3f} (open {s_before[0]:.3f})")
    check(s_during[2] > 0.4, f"wall contacts sliding while the bottom is lowered: {s_during[2]:.3f} (open {s_during[0]:.3f})")

    walls = pa.window(pa.frames_with(f, "walls"), 0.6, 0.8, False)
    stress = pa.window(pa.frames_with(f, "stress"), 0.6, 0.8, False)
    pos = walls[-1][1]["analyses"]["walls"]["profile/position"][()]
    surface = pa.values(walls, "walls", "profile/surface").mean()
    z = surface - pos
    ok = z > 0
    normal = pa.values(walls, "walls", "profile/normal").mean(axis=(0, 1))
    shear = pa.values(walls, "walls", "profile/shear").mean(axis=(0, 1))
    vertical = -np.nanmean(pa.values(stress, "stress", "profile/total"), axis=0)[:, 1, 1]
    rh, mu = 0.01, 0.25
    gamma = pa.unit_weight(f, walls[-1][1], 1, surface, rh)
    A, l = pa.janssen_fit(z[ok], vertical[ok], gamma)
    rms = np.sqrt(np.mean((vertical[ok] - A * (1 - np.exp(-z[ok] / l))) ** 2))
    ratio = normal[ok].sum() / vertical[ok].sum()
    mu_mob = -shear[ok].sum() / normal[ok].sum()
    print(f"Janssen fit of the vertical stress with the sample's unit weight {gamma:.4g} N/m3: length {l:.4g} m, "
          f"saturation {A:.4g} Pa, lambda = {rh / (mu * l):.3f} with mu = {mu}, {rh / (mu_mob * l):.3f} with the "
          f"mobilised mu = {mu_mob:.3f}; rms residual {rms:.4g} Pa; measured sigma_w / sigma_zz = {ratio:.3f}")
    check(rms < 0.15 * vertical[ok].max(),
          f"the vertical stress follows Janssen's curve: rms residual {rms / vertical[ok].max():.3f} of the largest")
    zmax = z[ok].max()
    check(vertical[ok][np.argmax(z[ok])] < 0.7 * gamma * zmax,
          f"saturation: the vertical stress at the bottom is {vertical[ok][np.argmax(z[ok])] / (gamma * zmax):.2f} "
          "of the hydrostatic one")
    check(abs(rh / (mu_mob * l) - ratio) < 0.15 * ratio,
          "Janssen's closure: the fitted length and the mobilised wall friction give the measured lambda")

    energy = pa.frames_with(f, "energy")
    err = np.abs(pa.values(energy, "energy", "balance_error")).max() / abs(energy[-1][1]["analyses"]["energy/initial"][()])
    check(err < 1e-10, f"energy balance closes: largest error {err:.2e} of |T0 + V0|")

for args in (["walls", "--from", "0.6", "--to", "0.8"], ["polarization", "--from", "0.6", "--to", "0.8"],
             ["stress", "--from", "0.6", "--to", "0.8"], ["fabric"], ["energy"], ["bottom_load"], ["network"]):
    study.plot(out, *args)
study.finish()
