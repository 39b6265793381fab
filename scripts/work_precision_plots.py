"""Figures of the work-precision benchmark (work_precision.py): error against time per
problem, and Dolan–Moré performance profiles."""
import matplotlib

matplotlib.use("Agg")  # files only; no display needed (CI, ssh)
import matplotlib.pyplot as plt
import numpy as np

from work_precision_tables import tol_text

DPI = 100  # the PNGs go into docs/: keep them small


def _style(i, n):
    """A fixed colour (and dash pattern past ten solvers) per solver index: same solver, same look."""
    cmap = plt.get_cmap("tab10" if n <= 10 else "tab20")
    return {"color": cmap(i % cmap.N), "linestyle": "-" if i < 10 else "--"}


def error_vs_time(path, problem, rows, solvers):
    """One line per solver through its runs from loose to tight tolerance: filled circles where
    it converged, crosses where it did not (timeouts have no error and are left out)."""
    fig, ax = plt.subplots(figsize=(7, 4.8))
    tols = sorted({r["tolerance"] for r in rows if r["table"]})
    for t in tols:
        ax.axhline(t, color="0.8", linewidth=0.8, zorder=0)
    for i, s in enumerate(solvers):
        pts = sorted((r for r in rows if r["solver"] == s and r["error"] is not None and r["seconds"]),
                     key=lambda r: -r["tolerance"])
        if not pts:
            continue
        st = _style(i, len(solvers))
        # A zero error (exact solution) still needs a place on a log axis.
        t = np.array([r["seconds"] for r in pts])
        e = np.array([max(r["error"], 1e-17) for r in pts])
        ok = np.array([r["converged"] for r in pts])
        ax.plot(t, e, label=s, linewidth=1.2, **st)
        ax.plot(t[ok], e[ok], "o", color=st["color"], markersize=4)
        ax.plot(t[~ok], e[~ok], "x", color=st["color"], markersize=8, markeredgewidth=2)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("solve time [s] (median of repeats)")
    ax.set_ylabel("error (DESIGN §1)")
    ax.set_title(f"{problem}: error against time (o converged, × failed)", fontsize=10)
    ax.grid(True, which="major", alpha=0.3)
    ax.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def performance_ratios(rows, tol, solvers):
    """problems × solvers array of time / best time on the problem (inf: failed)."""
    problems = list(dict.fromkeys(r["problem"] for r in rows))
    t = np.full((len(problems), len(solvers)), np.inf)
    for r in rows:
        if r["tolerance"] == tol and r["converged"] and r["solver"] in solvers:
            # Clock resolution: no time below a microsecond, so no ratio divides by zero.
            t[problems.index(r["problem"]), solvers.index(r["solver"])] = max(r["seconds"], 1e-6)
    best = t.min(axis=1, keepdims=True)
    with np.errstate(invalid="ignore"):
        ratios = np.where(np.isfinite(best), t / best, np.inf)
    return ratios


def profiles(path, rows, tols, solvers):
    """Dolan–Moré (2002): for each solver, the fraction of problems it solves within τ × the
    best time, against log2 τ; one panel per tolerance. Problems no solver solved count too."""
    fig, axes = plt.subplots(1, len(tols), figsize=(5.5 * len(tols) + 1.5, 4.5), squeeze=False)
    for ax, tol in zip(axes[0], tols):
        ratios = performance_ratios(rows, tol, solvers)
        n = ratios.shape[0]
        finite = np.log2(ratios[np.isfinite(ratios)])
        x_max = max(1.0, 1.05 * finite.max()) if finite.size else 1.0
        for i, s in enumerate(solvers):
            lr = np.sort(np.log2(ratios[:, i]))
            lr = lr[np.isfinite(lr)]
            x = np.concatenate([[0.0], lr, [x_max]])
            y = np.searchsorted(lr, x, side="right") / n  # ρ(τ) = #{problems: ratio ≤ τ} / n
            ax.step(x, y, where="post", label=s, linewidth=1.4, **_style(i, len(solvers)))
        ax.set_xlim(0, x_max)
        ax.set_ylim(-0.02, 1.02)
        ax.set_xlabel("log2 τ")
        ax.set_ylabel("fraction of problems solved within τ × best time")
        ax.set_title(f"tolerance {tol_text(tol)} ({n} problems)", fontsize=10)
        ax.grid(True, alpha=0.3)
    axes[0][-1].legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    fig.tight_layout()
    fig.savefig(path, dpi=DPI)
    plt.close(fig)
