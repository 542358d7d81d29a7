"""Figures of the report. Every function returns a matplotlib Figure; axes carry units."""

from __future__ import annotations

import math

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.colors import LogNorm

from ..physics.exact import Response

TWO_PI = 2.0 * math.pi


def _hz_axis(ax) -> None:
    """Add a top axis in Hz to an axis whose x is angular frequency in rad/s."""
    sec = ax.secondary_xaxis("top", functions=(lambda w: w / TWO_PI, lambda f: f * TWO_PI))
    sec.set_xlabel("forcing frequency f (Hz)")


def response_figure(runs: list[tuple[str, Response, Response]], title: str):
    """Position, velocity and the paper's error against the exact solution.

    Parameters
    ----------
    runs : list of (label, paper_response, exact_response)
        Responses on the same times (s; m; m/s).
    title : str
        Figure title.
    """
    fig, axes = plt.subplots(3, 1, figsize=(10, 9), sharex=True, layout="constrained")
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for (label, paper, exact), col in zip(runs, colors, strict=False):
        axes[0].plot(paper.t, paper.x, color=col, lw=1.0, label=f"{label}: RK45 (paper's method)")
        axes[0].plot(exact.t, exact.x, color="k", lw=0.6, ls="--")
        axes[1].plot(paper.t, paper.v, color=col, lw=1.0, label=label)
        axes[1].plot(exact.t, exact.v, color="k", lw=0.6, ls="--")
        err = np.abs(paper.x - exact.x)
        axes[2].semilogy(paper.t, np.where(err > 0, err, np.nan), color=col, lw=0.8, label=label)
    axes[0].plot([], [], color="k", lw=0.6, ls="--", label="exact closed form")
    axes[0].set_ylabel("displacement x (m)")
    axes[1].set_ylabel("velocity v (m/s)")
    axes[2].set_ylabel("|x_RK45 - x_exact| (m)")
    axes[2].set_xlabel("time t (s)")
    axes[0].legend(loc="upper left", fontsize=8, ncol=2)
    for ax in axes:
        ax.grid(alpha=0.3)
    fig.suptitle(title)
    return fig


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
    fig, (ax_m, ax_p) = plt.subplots(2, 1, figsize=(10, 7.5), sharex=True, layout="constrained")
    for label, mag, ph in curves:
        ax_m.loglog(omegas, mag, label=label)
        ax_p.semilogx(omegas, np.degrees(ph), label=label)
    for label, w, mag, ph in marks:
        ax_m.plot(w, mag, "o", ms=6, mfc="none", mew=1.5)
        ax_m.annotate(label, (w, mag), textcoords="offset points", xytext=(6, 4), fontsize=8)
        ax_p.plot(w, math.degrees(ph), "o", ms=6, mfc="none", mew=1.5)
    if omega_n is not None:
        for ax in (ax_m, ax_p):
            ax.axvline(omega_n, color="0.5", lw=0.8, ls=":")
    ax_m.set_ylabel("magnification |x| / (F0/k) (-)")
    ax_p.set_ylabel("phase lag of x behind F (deg)")
    ax_p.set_xlabel("forcing frequency omega (rad/s)")
    ax_p.set_yticks([0, 45, 90, 135, 180])
    _hz_axis(ax_m)
    ax_m.legend(fontsize=8)
    for ax in (ax_m, ax_p):
        ax.grid(alpha=0.3, which="both")
    return fig


def decomposition_figure(t, total, steady, transient, title: str):
    """A response split into its steady-state and transient parts (s; m)."""
    fig, ax = plt.subplots(figsize=(10, 4), layout="constrained")
    ax.plot(t, total, lw=1.2, label="total x(t)")
    ax.plot(t, steady, lw=0.8, ls="--", label="steady state")
    ax.plot(t, transient, lw=0.8, label="transient")
    ax.set_xlabel("time t (s)")
    ax.set_ylabel("displacement x (m)")
    ax.set_title(title)
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    return fig


def energy_figure(t, balance, title: str):
    """Work of the force, dissipation, stored energy (J) and the residual (J)."""
    fig, (ax, ax_r) = plt.subplots(2, 1, figsize=(10, 6), sharex=True, layout="constrained")
    ax.plot(t, balance.work, label="work done by the force")
    ax.plot(t, balance.dissipated, label="dissipated by the damper")
    ax.plot(t, balance.stored, label="stored (kinetic + potential)")
    ax.set_ylabel("energy (J)")
    ax.set_title(title)
    ax.legend(fontsize=8)
    ax_r.plot(t, balance.residual, color="C3", lw=0.8)
    ax_r.set_ylabel("residual W - D - E (J)")
    ax_r.set_xlabel("time t (s)")
    for a in (ax, ax_r):
        a.grid(alpha=0.3)
    return fig


def work_precision_figure(rows):
    """Error against function evaluations and against wall time, one line per method.

    ``rows``: dicts with ``method``, ``nfev``, ``time_s``, ``max_err_x_m``.
    """
    fig, (ax_n, ax_t) = plt.subplots(1, 2, figsize=(11, 4.5), layout="constrained")
    for method in dict.fromkeys(r["method"] for r in rows):
        sel = [r for r in rows if r["method"] == method]
        err = [r["max_err_x_m"] for r in sel]
        ax_n.loglog([r["nfev"] for r in sel], err, "o-", label=method)
        ax_t.loglog([r["time_s"] for r in sel], err, "o-", label=method)
    ax_n.set_xlabel("right-hand-side evaluations (-)")
    ax_t.set_xlabel("wall time (s)")
    for ax in (ax_n, ax_t):
        ax.set_ylabel("max |x - x_exact| (m)")
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=8)
    return fig


def design_map_figure(omegas, dampings, peaks, marks=(), omega_n: float | None = None):
    """Heat map of the window's peak |x| (m) over forcing frequency (rad/s) and damping (N s/m)."""
    fig, ax = plt.subplots(figsize=(10, 6), layout="constrained")
    mesh = ax.pcolormesh(omegas, dampings, peaks, norm=LogNorm(), shading="nearest", cmap="viridis")
    fig.colorbar(mesh, ax=ax, label="peak |x| over the window (m)")
    ax.set_yscale("log")
    for label, w, c in marks:
        ax.plot(w, c, "o", mfc="none", mec="w", ms=9, mew=1.5)
        ax.annotate(label, (w, c), textcoords="offset points", xytext=(8, 4), color="w", fontsize=8)
    if omega_n is not None:
        ax.axvline(omega_n, color="w", lw=0.6, ls=":")
    ax.set_xlabel("forcing frequency omega (rad/s)")
    ax.set_ylabel("damping coefficient c (N s/m)")
    _hz_axis(ax)
    return fig
