#!/usr/bin/env python3
"""Plots of the analyses a run wrote into its frames (docs/analyses.md).

    python3 scripts/plot_analyses.py OUT.h5 --list
    python3 scripts/plot_analyses.py OUT.h5 NAME [--from T0] [--to T1] [--out DIR] [--mu MU]
    python3 scripts/plot_analyses.py OUT.h5 network [--frame STEP] [--out DIR]

NAME is an analysis's name (its group /frames/N/analyses/NAME); what is drawn depends on
its type:
  stress        NAME_time.png: the components of the total stress and of its contact,
                gravity and inertia terms over time; with a profile, NAME_profile.png:
                velocity and stress across the slices, averaged over the window (over
                every step of it when the analysis has `average`)
  walls         NAME_forces.png: the resultant force on each body over time; with a
                profile, NAME_janssen.png: the wall normal stress against depth (averaged
                over the walls and the window) with the fitted Janssen curve
                sigma_w(z) = A (1 - exp(-z/l)), lambda = R_h / (mu l), R_h = D/2 (2D)
  polarization  NAME_shares.png: shares of open, sticking and sliding contacts per group
                pair over time; NAME_mobilisation.png: the mobilisation histogram
  fabric        NAME_pdf.png: normal-force pdf (averaged over the window);
                NAME_time.png: coordination and solid fraction over time
  energy        NAME.png: kinetic, potential, dissipated energies and works over time,
                and the balance error
  network       network.png: the force network of a frame (2D; 3D projected on x-z):
                lines between touching bodies, width proportional to the normal force

The window [--from, --to] (s) selects the frames averaged (default: every frame for the
time plots, the last frame for profiles and pdfs). Figures go to --out (default: beside
OUT.h5); the figures written and the main figures are printed.
"""
import argparse
import json
import os
import sys

import h5py
import numpy as np

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402


def frames_with(f, name):
    """(time, group) of every frame that has analysis NAME."""
    out = []
    for key in sorted(f["frames"]):
        g = f["frames"][key]
        if "analyses" in g and name in g["analyses"]:
            out.append((float(g.attrs["time"]), g))
    return out


def window(frames, t0, t1, default_last):
    if t0 is None and t1 is None:
        return frames[-1:] if default_last else frames
    lo = -np.inf if t0 is None else t0
    hi = np.inf if t1 is None else t1
    sel = [x for x in frames if lo - 1e-12 <= x[0] <= hi + 1e-12]
    if not sel:
        sys.exit(f"no frame of the analysis between {t0} and {t1} s")
    return sel


def values(frames, name, path):
    return np.array([g["analyses"][name][path][()] for _, g in frames])


def save(fig, out, fname):
    path = os.path.join(out, fname)
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)
    print("wrote", path)
    return path


def profile_window(frames, name, args):
    """(frames of the window, axis, bin positions) of an analysis with a profile, or None."""
    g = frames[-1][1]["analyses"][name]
    if "profile" not in g:
        return None
    return window(frames, args.t0, args.t1, True), int(g["profile/axis"][()]), g["profile/position"][()]


def strings(ds):
    return [x.decode() if isinstance(x, bytes) else str(x) for x in ds[()]]


def comp_names(d):
    return [("xx", 0, 0), ("yy", 1, 1), ("xy", 0, 1)] if d == 2 else [
        ("xx", 0, 0), ("yy", 1, 1), ("zz", 2, 2), ("xy", 0, 1), ("xz", 0, 2), ("yz", 1, 2)]


# ---- stress -------------------------------------------------------------------------
def plot_stress(f, name, frames, args, out):
    d = int(f.attrs["dimension"])
    t = np.array([x[0] for x in frames])
    terms = ["total", "contact", "gravity", "inertia"]
    fig, axes = plt.subplots(1, len(terms), figsize=(4 * len(terms), 3.4), sharex=True)
    for ax, term in zip(axes, terms):
        s = values(frames, name, term)
        for label, i, j in comp_names(d):
            ax.plot(t, s[:, i, j], label=r"$\Sigma_{%s}$" % label)
        if term == "total" and "average" in frames[-1][1]["analyses"][name]:
            a = values(frames, name, "average/total")
            ax.plot(t, a[:, 1, 1], "k--", lw=1, label=r"$\Sigma_{yy}$ mean since last frame")
        ax.set_title(term if term == "total" else term + " term")
        ax.set_xlabel("time (s)")
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("stress (Pa)")
    axes[0].legend(fontsize=7)
    save(fig, out, f"{name}_time.png")
    prof = profile_window(frames, name, args)
    if prof is None:
        return
    sel, axis, pos = prof
    # With `average`, each frame holds the mean over the steps since the previous one: the
    # mean over the window's frames is then the mean over all its steps.
    src = "average/profile" if "average/profile" in sel[-1][1]["analyses"][name] else "profile"
    vel = np.nanmean(values(sel, name, src + "/velocity"), axis=0)
    tot = np.nanmean(values(sel, name, src + "/total"), axis=0)
    ine = np.nanmean(values(sel, name, src + "/inertia"), axis=0)
    fig, (a0, a1) = plt.subplots(1, 2, figsize=(9, 4), sharey=True)
    for k, c in enumerate("xyz"[:d]):
        a0.plot(vel[:, k], pos, "o-", label=f"$v_{c}$")
    a0.set_xlabel("mean velocity (m/s)")
    a0.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(4))
    a0.set_ylabel("xyz"[axis] + " (m)")
    a0.legend()
    a0.grid(alpha=0.3)
    for label, i, j in comp_names(d):
        line, = a1.plot(tot[:, i, j], pos, "o-", label=r"$\Sigma_{%s}$" % label)
        a1.plot(ine[:, i, j], pos, "--", color=line.get_color(), label=r"inertia term $\Sigma^\gamma_{%s}$" % label)
    a1.set_xlabel("stress (Pa)")
    a1.legend(fontsize=7)
    a1.grid(alpha=0.3)
    over = "every step" if src.startswith("average") else f"{len(sel)} frame(s)"
    fig.suptitle(f"{name}: profile averaged over {over}, t = {sel[0][0]:.3g} to {sel[-1][0]:.3g} s")
    save(fig, out, f"{name}_profile.png")


# ---- walls and Janssen --------------------------------------------------------------
def wall_friction(f, wall_indices):
    """The friction coefficient of the law between the walls' groups and the others."""
    scene = json.loads(f.attrs["scene"])
    groups = [g.decode() if isinstance(g, bytes) else g for g in f["contactors/group"][()]]
    bodies = f["contactors/body"][()]
    wall_groups = {groups[i] for i in range(len(groups)) if bodies[i] in wall_indices}
    for it in scene.get("interactions", []):
        a, b = it["groups"]
        if (a in wall_groups) != (b in wall_groups):
            return float(scene["laws"][it["law"]].get("friction", 0.0))
    return None


def janssen_fit(z, s, gamma=None):
    """sigma(z) = A (1 - exp(-z/l)), least squares: A linear, l by a log scan then refined.
    With gamma (the unit weight, N/m3) Janssen's own form A = gamma l: l alone is fitted."""
    def fit(l):
        fz = 1 - np.exp(-z / l)
        A = gamma * l if gamma else (s @ fz) / (fz @ fz)
        return ((s - A * fz) ** 2).sum(), A, l

    best = min((fit(l) for l in np.logspace(-4, 2, 600)), key=lambda x: x[0])
    best = min([best] + [fit(l) for l in np.linspace(0.9 * best[2], 1.1 * best[2], 400)], key=lambda x: x[0])
    return best[1], best[2]


def plot_walls(f, name, frames, args, out):
    d = int(f.attrs["dimension"])
    t = np.array([x[0] for x in frames])
    walls = strings(frames[-1][1]["analyses"][name]["bodies"])
    force = values(frames, name, "force")
    fig, ax = plt.subplots(figsize=(6, 3.6))
    for w, wname in enumerate(walls):
        for k in range(d):
            ax.plot(t, force[:, w, k], label=f"{wname} $F_{'xyz'[k]}$")
    ax.set_xlabel("time (s)")
    ax.set_ylabel("force (N/m)" if d == 2 else "force (N)")
    ax.legend(fontsize=7)
    ax.grid(alpha=0.3)
    save(fig, out, f"{name}_forces.png")
    prof = profile_window(frames, name, args)
    if prof is None:
        return
    sel, axis, pos = prof
    normal = values(sel, name, "profile/normal").mean(axis=1)  # mean over the walls
    shear = values(sel, name, "profile/shear").mean(axis=1)
    mob = values(sel, name, "profile/mobilisation").mean(axis=(0, 1))
    cone = values(sel, name, "profile/sliding_share").mean(axis=(0, 1))
    surface = values(sel, name, "profile/surface").mean()
    normal, shear = normal.mean(axis=0), shear.mean(axis=0)
    z = surface - pos
    names = [n.decode() if isinstance(n, bytes) else n for n in f["bodies/name"][()]]
    idx = [names.index(w) for w in walls]
    mu = args.mu if args.mu is not None else wall_friction(f, idx)
    # Hydraulic radius: 2D, half the distance between the two walls' contact points.
    rh = args.hydraulic_radius
    if rh is None and d == 2 and len(idx) == 2:
        lateral = 1 - axis
        xs = []
        for w in idx:
            pts = []
            for _, fr in sel:
                if "contacts" not in fr:
                    continue
                b = fr["contacts/bodies"][()]
                p = fr["contacts/point"][()]
                m = (b[:, 0] == w) | (b[:, 1] == w)
                pts.extend(p[m, lateral])
            xs.append(np.mean(pts) if pts else np.nan)
        rh = abs(xs[1] - xs[0]) / 2
    ok = z > 0
    # The vertical stress, from a stress analysis with a profile along the same axis.
    vertical = None
    for other, kind in analysis_types(f).items():
        if kind != "stress":
            continue
        of = window(frames_with(f, other), sel[0][0], sel[-1][0], False)
        og = of[-1][1]["analyses"][other]
        if "profile" in og and int(og["profile/axis"][()]) == axis and np.allclose(og["profile/position"][()], pos):
            vertical = -np.nanmean(values(of, other, "profile/total"), axis=0)[:, axis, axis]
            break
    fig, (a0, a1) = plt.subplots(1, 2, figsize=(10, 4.4))
    a0.plot(normal[ok], z[ok], "o", label=r"wall normal stress $\sigma_w$")
    a0.plot(-shear[ok], z[ok], "s", mfc="none", label=r"wall shear stress $\tau_w$ (upward on the sample)")
    zz = np.linspace(0, z[ok].max(), 200)
    if mu and rh:
        A, l = janssen_fit(z[ok], normal[ok])
        lam = rh / (mu * l)
        a0.plot(A * (1 - np.exp(-zz / l)), zz, "k-",
                label=r"Janssen fit to $\sigma_w$: $\lambda = R_h/(\mu\ell)$ = %.2f" % lam)
        print(f"Janssen fit to the wall normal stress: A = {A:.4g} Pa, l = {l:.4g} m, R_h = {rh:.4g} m, "
              f"mu = {mu:g}: lambda = {lam:.3f}")
        if vertical is not None:
            # Janssen's sigma_zz = gamma l (1 - exp(-z/l)), l = R_h/(mu lambda), with the
            # sample's own unit weight gamma: one parameter, lambda.
            gamma = unit_weight(f, sel[-1][1], axis, surface, rh)
            Av, lv = janssen_fit(z[ok], vertical[ok], gamma)
            lam_v = rh / (mu * lv)
            rms = np.sqrt(np.mean((vertical[ok] - Av * (1 - np.exp(-z[ok] / lv))) ** 2))
            a0.plot(vertical[ok], z[ok], "^", color="tab:green", label=r"vertical stress $\sigma_{zz}$ (stress analysis)")
            a0.plot(Av * (1 - np.exp(-zz / lv)), zz, "-", color="tab:green",
                    label=r"Janssen fit to $\sigma_{zz}$ (sample's $\gamma$): $\lambda$ = %.2f" % lam_v)
            ratio = normal[ok].sum() / vertical[ok].sum()
            mu_eff = -shear[ok].sum() / normal[ok].sum()
            # The wall stress it predicts, with the wall friction the sample mobilises.
            lam_mob = rh / (mu_eff * lv) if mu_eff > 0 else np.nan
            a0.plot(lam_mob * Av * (1 - np.exp(-zz / lv)), zz, "--", color="tab:green",
                    label=r"$\lambda \sigma_{zz}$, $\lambda = R_h/(\mu_{mob}\ell)$ = %.2f: the wall stress it predicts"
                    % lam_mob)
            a0.plot(gamma * zz, zz, ":", color="gray", label=r"hydrostatic $\gamma z$")
            print(f"unit weight of the sample: {gamma:.4g} N/m3 (its weight over its volume below the surface)")
            print(f"Janssen fit to the vertical stress with that unit weight: l = {lv:.4g} m, saturation gamma l = "
                  f"{Av:.4g} Pa: lambda = {lam_v:.3f} with mu = {mu:g}; rms residual {rms:.4g} Pa "
                  f"({rms / vertical[ok].max():.3f} of the largest)")
            print(f"measured: lambda = sum(sigma_w) / sum(sigma_zz) = {ratio:.3f}; wall friction mobilised "
                  f"sum(tau_w) / sum(sigma_w) = {mu_eff:.3f}, with which the vertical fit gives lambda = "
                  f"{lam_mob:.3f}")
    a0.invert_yaxis()
    a0.set_xlabel("stress (Pa)")
    a0.set_ylabel("depth below the surface z (m)")
    a0.legend(fontsize=7)
    a0.grid(alpha=0.3)
    a1.plot(mob[ok], z[ok], "o-", label=r"mean mobilisation $|r_t|/(\mu r_n)$")
    a1.plot(cone[ok], z[ok], "s-", label="share on the Coulomb cone")
    a1.invert_yaxis()
    a1.set_xlim(0, 1.05)
    a1.set_xlabel("wall contacts")
    a1.legend(fontsize=7)
    a1.grid(alpha=0.3)
    print(f"wall contacts: mean mobilisation {np.nanmean(mob[ok]):.3f}, share on the cone {np.nanmean(cone[ok]):.3f}")
    fig.suptitle(f"{name}: {len(sel)} frame(s), t = {sel[0][0]:.3g} to {sel[-1][0]:.3g} s")
    save(fig, out, f"{name}_janssen.png")


def analysis_types(f):
    names = {}
    for key in sorted(f["frames"]):
        g = f["frames"][key]
        if "analyses" in g:
            for n in g["analyses"]:
                t = g["analyses"][n].attrs["type"]
                names[n] = t.decode() if isinstance(t, bytes) else t
    return names


def unit_weight(f, frame, axis, surface, rh):
    """2D: the sample's weight over its area below the surface (width 2 R_h): bodies that are
    neither fixed nor driven, their lowest point from the shapes drawn in the frame."""
    if int(f.attrs["dimension"]) != 2 or "display/points" not in frame:
        return None
    scene = json.loads(f.attrs["scene"])
    names = [n.decode() if isinstance(n, bytes) else n for n in f["bodies/name"][()]]
    driven = {d["body"] for d in scene.get("drivers", [])}
    sample = np.array([not fx and n not in driven for n, fx in zip(names, f["bodies/fixed"][()])])
    g = np.linalg.norm(scene.get("gravity", [0, 0]))
    pts = frame["display/points"][()]
    owner = f["display/point_body"][()]
    low = pts[sample[owner], axis].min()
    return f["bodies/mass"][()][sample].sum() * g / (2 * rh * (surface - low))


# ---- polarization -------------------------------------------------------------------
def plot_polarization(f, name, frames, args, out):
    t = np.array([x[0] for x in frames])
    g = frames[-1][1]["analyses"][name]
    pairs = strings(g["pairs"])
    shares = values(frames, name, "shares")
    fig, axes = plt.subplots(1, len(pairs), figsize=(4.5 * len(pairs), 3.6), squeeze=False)
    for p, ax in enumerate(axes[0]):
        ax.stackplot(t, shares[:, p, 0], shares[:, p, 1], shares[:, p, 2],
                     labels=["open", "sticking", "sliding (on the cone)"], colors=["#cccccc", "#6a9fd4", "#d9534f"])
        ax.set_ylim(0, 1)
        ax.set_title(pairs[p])
        ax.set_xlabel("time (s)")
    axes[0][0].set_ylabel("share of contacts")
    axes[0][0].legend(fontsize=7, loc="lower left")
    save(fig, out, f"{name}_shares.png")
    sel = window(frames, args.t0, args.t1, True)
    hist = values(sel, name, "mobilisation_histogram").sum(axis=0)
    edges = g["mobilisation_edges"][()]
    fig, ax = plt.subplots(figsize=(5, 3.6))
    for p, pair in enumerate(pairs):
        total = hist[p].sum()
        if total > 0:
            ax.step(edges[:-1], hist[p] / total, where="post", label=pair)
    ax.set_xlabel(r"mobilisation $|r_t|/(\mu r_n)$")
    ax.set_ylabel("share of closed contacts")
    ax.legend()
    ax.grid(alpha=0.3)
    save(fig, out, f"{name}_mobilisation.png")
    for p, pair in enumerate(pairs):
        s = values(sel, name, "shares")[:, p].mean(axis=0)
        print(f"{pair}: open {s[0]:.3f}, sticking {s[1]:.3f}, sliding {s[2]:.3f} "
              f"(t = {sel[0][0]:.3g} to {sel[-1][0]:.3g} s)")


# ---- fabric -------------------------------------------------------------------------
def plot_fabric(f, name, frames, args, out):
    t = np.array([x[0] for x in frames])
    sel = window(frames, args.t0, args.t1, True)
    g = frames[-1][1]["analyses"][name]
    edges = g["pdf_edges"][()]
    pdf = values(sel, name, "pdf").mean(axis=0)
    centres = 0.5 * (edges[1:] + edges[:-1])
    fig, ax = plt.subplots(figsize=(5, 3.6))
    ax.semilogy(centres, np.where(pdf > 0, pdf, np.nan), "o-")
    ax.set_xlabel(r"$f_n / \langle f_n \rangle$")
    ax.set_ylabel("pdf")
    ax.set_title(f"{name}: t = {sel[0][0]:.3g} to {sel[-1][0]:.3g} s")
    ax.grid(alpha=0.3, which="both")
    save(fig, out, f"{name}_pdf.png")
    fig, ax = plt.subplots(figsize=(5, 3.6))
    ax.plot(t, values(frames, name, "coordination"), label="coordination z")
    ax.plot(t, values(frames, name, "coordination_no_rattlers"), label="z without rattlers")
    ax2 = ax.twinx()
    ax2.plot(t, values(frames, name, "solid_fraction"), "k--", label="solid fraction")
    ax.set_xlabel("time (s)")
    ax.legend(loc="lower left", fontsize=7)
    ax2.legend(loc="lower right", fontsize=7)
    save(fig, out, f"{name}_time.png")


# ---- energy -------------------------------------------------------------------------
def plot_energy(f, name, frames, args, out):
    t = np.array([x[0] for x in frames])
    v = {k: values(frames, name, k) for k in ["kinetic", "potential", "initial", "dissipated_impacts",
                                              "dissipated_friction", "work_external", "work_boundary",
                                              "work_theta", "balance_error"]}
    fig, (a0, a1) = plt.subplots(1, 2, figsize=(10, 3.8))
    a0.plot(t, v["kinetic"], label="kinetic T")
    a0.plot(t, v["potential"] - v["initial"], label=r"potential $V - (T_0+V_0)$")
    a0.plot(t, v["dissipated_impacts"], label="dissipated by impacts")
    a0.plot(t, v["dissipated_friction"], label="dissipated by friction")
    a0.plot(t, v["work_boundary"], label="work of walls")
    a0.plot(t, v["work_external"], label="work of forces")
    a0.set_xlabel("time (s)")
    a0.set_ylabel("energy (J/m)" if int(f.attrs["dimension"]) == 2 else "energy (J)")
    a0.legend(fontsize=7)
    a0.grid(alpha=0.3)
    scale = np.maximum(np.abs(v["initial"]), 1e-300)
    a1.semilogy(t, np.abs(v["balance_error"]) / scale + 1e-300)
    a1.set_xlabel("time (s)")
    a1.set_ylabel("|balance error| / |T0 + V0|")
    a1.grid(alpha=0.3, which="both")
    save(fig, out, f"{name}.png")
    print(f"largest |balance error| / |T0 + V0| = {np.max(np.abs(v['balance_error']) / scale):.3g}")


# ---- force network ------------------------------------------------------------------
def plot_network(f, args, out):
    keys = sorted(f["frames"])
    key = keys[-1] if args.frame is None else f"{args.frame:08d}"
    if key not in f["frames"]:
        sys.exit(f"no frame for step {args.frame}")
    g = f["frames"][key]
    d = int(f.attrs["dimension"])
    # Rigid-only scenes: the bodies' centres; others: each body's reference point.
    x = g["position"][()] if "position" in g else g["bodies/position"][()]
    axes2 = (0, 1) if d == 2 else (0, 2)
    # Fixed and driven bodies (walls, pistons): lines to them end at the contact point.
    scene = json.loads(f.attrs["scene"])
    driven = {dr["body"] for dr in scene.get("drivers", [])}
    names = [n.decode() if isinstance(n, bytes) else n for n in f["bodies/name"][()]]
    fixed = f["bodies/fixed"][()].astype(bool) | np.array([n in driven for n in names])
    # The view: the moving bodies, with a margin of a tenth of their extent.
    moving = x[~fixed][:, list(axes2)] if (~fixed).any() else x[:, list(axes2)]
    lo, hi = moving.min(axis=0), moving.max(axis=0)
    pad = 0.1 * (hi - lo).max() + 1e-12
    lo, hi = lo - pad, hi + pad
    aspect = (hi[1] - lo[1]) / (hi[0] - lo[0])
    fig, ax = plt.subplots(figsize=(min(10, max(3.5, 8 / aspect)), min(10, max(3.5, 8 * aspect))))
    if d == 2 and "display" in f and "display/points" in g:
        pts = g["display/points"][()]
        cells = f["display/cells"][()]
        from matplotlib.collections import PolyCollection
        polys, i = [], 0
        while i < len(cells):
            kind = cells[i]
            if kind == 3:
                n = cells[i + 1]
                polys.append(pts[cells[i + 2:i + 2 + n]][:, :2])
                i += 2 + n
            elif kind == 1:
                i += 2 + cells[i + 1]
            else:
                i += 1 + {4: 3, 5: 4}.get(kind, 0)
        ax.add_collection(PolyCollection(polys, facecolors="#eeeeee", edgecolors="#aaaaaa", linewidths=0.3))
    if "contacts" in g:
        b = g["contacts/bodies"][()]
        fn = g["contacts/normal_force"][()]
        p = g["contacts/point"][()]
        top = fn.max() if len(fn) and fn.max() > 0 else 1
        from matplotlib.collections import LineCollection
        segs, widths = [], []
        for c in range(len(fn)):
            if fn[c] <= 0:
                continue
            a, bb = b[c]
            # To a wall, the line ends at the contact point rather than the wall's centre.
            ends = [x[a] if not fixed[a] else p[c], x[bb] if not fixed[bb] else p[c]]
            segs.append([[e[axes2[0]], e[axes2[1]]] for e in ends])
            widths.append(0.3 + 4.0 * fn[c] / top)
        ax.add_collection(LineCollection(segs, linewidths=widths, colors="#b22222"))
    ax.set_aspect("equal")
    ax.set_xlim(lo[0], hi[0])
    ax.set_ylim(lo[1], hi[1])
    ax.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(3))
    ax.set_xlabel("xyz"[axes2[0]] + " (m)")
    ax.set_ylabel("xyz"[axes2[1]] + " (m)")
    ax.set_title(f"force network, t = {g.attrs['time']:.4g} s\n(width ∝ normal force)", fontsize=9)
    save(fig, out, "network.png")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file")
    ap.add_argument("analysis", nargs="?", help="analysis name, or 'network'")
    ap.add_argument("--list", action="store_true", help="list the analyses in the file")
    ap.add_argument("--from", dest="t0", type=float)
    ap.add_argument("--to", dest="t1", type=float)
    ap.add_argument("--frame", type=int, help="network: the frame (step number; default the last)")
    ap.add_argument("--mu", type=float, help="walls: wall friction for the Janssen fit (default: the scene's law)")
    ap.add_argument("--hydraulic-radius", type=float, help="walls: R_h (default, 2D: half the distance between the walls)")
    ap.add_argument("--out", help="folder of the figures (default: beside the file)")
    args = ap.parse_intermixed_args()
    out = args.out or os.path.dirname(os.path.abspath(args.file))
    os.makedirs(out, exist_ok=True)
    with h5py.File(args.file, "r") as f:
        names = analysis_types(f)
        if args.list or not args.analysis:
            for n, t in names.items():
                print(f"{n}\t{t}")
            return
        if args.analysis == "network":
            plot_network(f, args, out)
            return
        if args.analysis not in names:
            sys.exit(f"no analysis named {args.analysis!r} in {args.file}; it has: {', '.join(names) or 'none'}")
        kind = names[args.analysis]
        frames = frames_with(f, args.analysis)
        plot = {"stress": plot_stress, "walls": plot_walls, "polarization": plot_polarization,
                "fabric": plot_fabric, "energy": plot_energy}.get(kind)
        if plot is None:
            sys.exit(f"no plot for analyses of type {kind!r}")
        plot(f, args.analysis, frames, args, out)


if __name__ == "__main__":
    main()
