"""Figures of Part I chapters 3 and 4 (chapter 1 draws its own in its package).

Every function returns a matplotlib Figure in the report style
(:func:`vibration.presentation.style.figure`), with mathtext symbols and units on the axes
and legends placed where they cover no data (outside the axes or in a measured free corner).
"""

from __future__ import annotations

import math

import numpy as np
from matplotlib.colors import LogNorm
from matplotlib.ticker import LogFormatterSciNotation, LogLocator

from ..physics.exact import Response
from .style import figure, place_legend

TWO_PI = 2.0 * math.pi


def _hz_axis(ax) -> None:
    """Add a top axis in Hz to an axis whose x is angular frequency in rad/s."""
    sec = ax.secondary_xaxis("top", functions=(lambda w: w / TWO_PI, lambda f: f * TWO_PI))
    sec.set_xlabel(r"forcing frequency $f$ (Hz)")


def _legend_above(ax, handles=None, ncol: int = 3):
    """A legend in a row above the axes (outside the data)."""
    kw = {"handles": handles} if handles is not None else {}
    return ax.legend(
        loc="lower left", bbox_to_anchor=(0.0, 1.02, 1.0, 0.1), ncol=ncol, borderaxespad=0.0, frameon=False, **kw
    )


def frequency_response_figure(curves, omegas, marks=(), omega_n: float | None = None):
    """Magnification and phase lag against forcing frequency (rad/s, Hz on top).

    Parameters
    ----------
    curves : list of (label, magnification, phase)
        Arrays on ``omegas`` (dimensionless; rad).
    omegas : array_like
        Forcing frequencies, rad/s.
    marks : list of (label, omega, magnification, phase)
        Operating points to mark (rad/s; 1; rad).
    omega_n : float, optional
        Natural frequency to draw as a vertical line, rad/s.
    """
    fig, (ax_m, ax_p) = figure(2, 1, height=6.2, sharex=True)
    for label, mag, ph in curves:
        ax_m.loglog(omegas, mag, label=label)
        ax_p.semilogx(omegas, np.degrees(ph), label=label)
    for label, w, mag, ph in marks:
        ax_m.plot(w, mag, "o", ms=6, mfc="none", mew=1.5, color="k")
        ax_m.annotate(label, (w, mag), textcoords="offset points", xytext=(6, 4), fontsize=8)
        ax_p.plot(w, math.degrees(ph), "o", ms=6, mfc="none", mew=1.5, color="k")
    if omega_n is not None:
        for ax in (ax_m, ax_p):
            ax.axvline(omega_n, color="0.5", lw=0.8, ls=":")
    lo, hi = ax_m.get_ylim()
    ax_m.set_ylim(lo, hi * 4.0)  # room above the highest peak for its label
    ax_m.set_ylabel(r"magnification $|X|\,/\,(F_0/k)$")
    ax_p.set_ylabel(r"phase lag $\varphi$ (deg)")
    ax_p.set_xlabel(r"forcing frequency $\omega$ (rad/s)")
    ax_p.set_yticks([0, 45, 90, 135, 180])
    _hz_axis(ax_m)
    place_legend(ax_p)
    return fig


def decomposition_figure(t, total, steady, transient, title: str):
    """A response split into its steady-state and transient parts (s; m)."""
    fig, ax = figure(1, 1, height=3.4)
    ax.plot(t, total, lw=1.2, label=r"total $x(t)$")
    ax.plot(t, steady, lw=0.8, ls="--", label=r"steady state $x_\mathrm{ss}(t)$")
    ax.plot(t, transient, lw=0.8, label=r"transient $x(t) - x_\mathrm{ss}(t)$")
    ax.set_xlabel(r"time $t$ (s)")
    ax.set_ylabel(r"displacement $x$ (m)")
    ax.set_title(title)
    _legend_above(ax, ncol=3)
    ax.set_title(title, pad=22)
    return fig


def energy_figure(t, balance, title: str):
    """Work of the force, dissipation, stored energy (J) and the residual (J)."""
    fig, (ax, ax_r) = figure(2, 1, height=5.0, sharex=True, gridspec_kw={"height_ratios": (2.2, 1.0)})
    ax.plot(t, balance.work, label=r"work of the force $W$")
    ax.plot(t, balance.dissipated, label=r"dissipated by the damper $D$")
    ax.plot(t, balance.stored, label=r"stored $\Delta E$ (kinetic + potential)")
    ax.set_ylabel("energy (J)")
    ax.set_title(title)
    place_legend(ax)
    ax_r.plot(t, balance.residual, color="C3", lw=0.8)
    ax_r.set_ylabel(r"$W - D - \Delta E$ (J)")
    ax_r.set_xlabel(r"time $t$ (s)")
    return fig


def work_precision_figure(rows):
    """Error against function evaluations and against wall time, one line per method.

    ``rows``: dicts with ``method``, ``nfev``, ``time_s``, ``max_err_x_m``.
    """
    fig, (ax_n, ax_t) = figure(1, 2, height=3.4, sharey=True)
    for method in dict.fromkeys(r["method"] for r in rows):
        sel = [r for r in rows if r["method"] == method]
        err = [r["max_err_x_m"] for r in sel]
        ax_n.loglog([r["nfev"] for r in sel], err, "o-", ms=4, label=method)
        ax_t.loglog([r["time_s"] for r in sel], err, "o-", ms=4, label=method)
    ax_n.set_xlabel("right-hand-side evaluations")
    ax_t.set_xlabel(r"wall time (s)")
    ax_n.set_ylabel(r"max $|x - x_\mathrm{exact}|$ (m)")
    for ax in (ax_n, ax_t):
        ax.xaxis.set_major_locator(LogLocator(base=10.0, numticks=5))
        # label 2 and 5 times each power of ten only: every minor label collides with its neighbours
        ax.xaxis.set_minor_locator(LogLocator(base=10.0, subs=(2.0, 5.0), numticks=12))
        ax.xaxis.set_minor_formatter(LogFormatterSciNotation(labelOnlyBase=False, minor_thresholds=(3, 3)))
        ax.grid(True, which="major", alpha=0.3)
    place_legend(ax_n)
    return fig


def own_steps_figure(t, x_exact, own: Response, t_from: float):
    """The last periods: exact displacement on the output grid and RK45's own steps (s; m)."""
    fig, ax = figure(1, 1, height=3.0)
    sel = t >= t_from
    ax.plot(t[sel], x_exact[sel], "k-", lw=0.8, label="exact, on the output grid")
    s2 = own.t >= t_from
    ax.plot(own.t[s2], own.x[s2], "o-", ms=3.5, lw=1.0, label="RK45 at SciPy's defaults, its own steps only")
    ax.set_xlabel(r"time $t$ (s)")
    ax.set_ylabel(r"displacement $x$ (m)")
    _legend_above(ax, ncol=2)
    return fig


def design_map_figure(omegas, dampings, peaks, marks=(), omega_n: float | None = None):
    """Heat map of the window's peak |x| (m) over forcing frequency (rad/s) and damping (N s/m)."""
    fig, ax = figure(1, 1, height=4.6)
    mesh = ax.pcolormesh(omegas, dampings, peaks, norm=LogNorm(), shading="nearest", cmap="viridis")
    fig.colorbar(mesh, ax=ax, label=r"peak $|x|$ in the window (m)")
    ax.set_yscale("log")
    ax.grid(False)
    for label, w, c in marks:
        ax.plot(w, c, "o", mfc="none", mec="w", ms=9, mew=1.5)
        ax.annotate(label, (w, c), textcoords="offset points", xytext=(8, 4), color="w", fontsize=8)
    if omega_n is not None:
        ax.axvline(omega_n, color="w", lw=0.6, ls=":")
    ax.set_xlabel(r"forcing frequency $\omega$ (rad/s)")
    ax.set_ylabel(r"damping coefficient $c$ (N s/m)")
    _hz_axis(ax)
    return fig
