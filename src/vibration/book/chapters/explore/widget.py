"""Live explorer of chapter 5: forcing-frequency and damping sliders over the exact response (ipywidgets).

:func:`explorer` returns an :class:`Explorer`, an ``ipywidgets.VBox`` holding the controls, a live
readout table and one matplotlib figure: displacement x(t) (m) and velocity v(t) (m/s) from the closed
form, and the magnification curve against the forcing frequency (rad/s below, Hz on top) with the
operating point marked. Every number comes from :func:`vibration.book.chapters.explore.study.readout` and the
physics library; nothing physical is computed here. :func:`live_explorer` starts it at a study's
parameters. Displayed in a page without a kernel (the book), it shows the kernel-free panel of
:mod:`vibration.book.chapters.explore.panel` at the same parameters instead.

Figure transport
----------------
The figure is a plain :class:`matplotlib.figure.Figure` on an Agg canvas, never registered with
pyplot, so the global backend stays ``inline`` and the report's other figures remain static PNGs. Each
update re-renders that same Figure into PNG bytes shown by an :class:`ipywidgets.Image`, which needs
no frontend extension beyond ipywidgets itself. The artists that move are ``animated`` and blitted onto
a cached background (axes, ticks, labels, legend); the background is redrawn only when an axis' view
limits change. Autoscaling uses ``axes.autolimit_mode = "round_numbers"``, so limits move in tick-sized
steps and most slider steps take the blit path. The PNG is written with zlib level 1 and no row filter
(:func:`vibration.book.chapters.explore.figure.png`). No decimation: all ``n_points`` samples are drawn (Agg's path
simplification keeps that cheap).

Measured with :func:`vibration.book.chapters.explore.bench.benchmark_updates` (5001 samples, 1000 x 540 px,
on the project's 2-core machine): median 17 ms from slider change to new PNG bytes; the steps whose
limits move (10 % of a slow sweep) redraw everything in about 110 ms; rebuilding the figure on every
step would take about 270 ms. An ipympl canvas (``ipympl.backend_nbagg.Canvas``) with the same blitting
measured 38 ms per blitted step, because it PNG-encodes a diff image with Pillow at zlib level 6.
"""

from __future__ import annotations

import base64
import html
import math
from dataclasses import dataclass

import ipywidgets as widgets
import matplotlib as mpl
import numpy as np
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from vibration.book.chapters.explore.figure import STYLE, build_figure, omega_grid, omega_range, png_small
from vibration.book.chapters.explore.figure import png as png_frame
from vibration.book.chapters.explore.panel import slider_panel_html
from vibration.book.chapters.explore.study import C_MAX, C_MIN, N_POINTS, ExploreStudy, readout
from vibration.physics.exact import exact_response, steady_state
from vibration.physics.frequency import magnification
from vibration.physics.model import N_POINTS_MAX, Oscillator, ParameterError, SineForce, check_int, check_real
from vibration.physics.numerics import simulate

__all__ = ["Explorer", "explorer", "live_explorer"]

#: Errors that bad input can raise while computing; shown in the readout, never raised.
INPUT_ERRORS = (ValueError, TypeError, ArithmeticError, RuntimeError)


@dataclass(frozen=True, kw_only=True)
class _Row:
    key: str  # key in Explorer.values
    label: str  # quantity, with symbol
    unit: str  # SI unit, "" for dimensionless numbers and words
    fmt: str = ".5g"  # format of the value: five significant figures unless told


_ROWS = (
    _Row(key="omega_n", label="natural frequency ω_n", unit="rad/s"),
    _Row(key="f_n", label="natural frequency f_n", unit="Hz"),
    _Row(key="omega", label="forcing frequency ω", unit="rad/s"),
    _Row(key="f", label="forcing frequency f", unit="Hz"),
    _Row(key="ratio", label="frequency ratio ω/ω_n", unit=""),
    _Row(key="zeta", label="damping ratio ζ", unit=""),
    _Row(key="regime", label="regime", unit="", fmt="s"),
    _Row(key="magnification", label="magnification |X|/(F0/k)", unit=""),
    _Row(key="amplitude", label="steady-state amplitude |X|", unit="m"),
    _Row(key="peak", label="peak |x| in the window", unit="m"),
    _Row(key="settling", label="2 % settling time", unit="s"),
    _Row(key="steady_reached", label="steady state reached in the window", unit="", fmt="s"),
    _Row(key="t_end", label="time window", unit="s"),
)
_RK45_ROWS = (
    _Row(key="rk45_max_error", label="RK45 max |x − x_exact|", unit="m", fmt=".3e"),
    _Row(key="rk45_nfev", label="RK45 right-hand-side evaluations", unit="", fmt="d"),
)


class _NoResponse(Exception):
    """Valid inputs whose response cannot be computed in floating point (overflow)."""


class Explorer(widgets.VBox):
    """Sliders, a readout table and one live figure of the forced oscillator.

    Build it with :func:`explorer` (the same class under the chapter's factory name) or
    :func:`live_explorer`. The child widgets are attributes, so code (and tests) can drive it
    as a user would: setting ``omega_slider.value`` or ``m_text.value`` runs :meth:`update`.

    Parameters
    ----------
    m, k, F0 : float
        The oscillator: mass (kg, > 0), stiffness (N/m, > 0) and force amplitude (N, >= 0).
    c : float
        Initial damping, N s/m (> 0); the log slider spans 0.01 to 20 N s/m.
    omega : float
        Initial forcing frequency, rad/s (> 0).
    t_end : float
        Time window, s (> 0).
    n_points : int
        Samples in ``[0, t_end]``.
    show_rk45 : bool
        Start with the paper's RK45 solution overlaid.

    Attributes
    ----------
    omega_slider : ipywidgets.FloatSlider
        Forcing frequency, rad/s; ``omega_hz`` shows it in Hz.
    c_slider : ipywidgets.FloatLogSlider
        Damping, N s/m.
    m_text, k_text, F0_text, t_end_text : ipywidgets.FloatText
        Mass (kg), stiffness (N/m), force amplitude (N), window (s).
    rk45_checkbox : ipywidgets.Checkbox
        Overlay the paper's RK45 solution.
    image : ipywidgets.Image
        PNG of :attr:`figure`, re-rendered on every update.
    readout : ipywidgets.HTML
        Table of the quantities in :attr:`values`, or the input error.
    figure : matplotlib.figure.Figure
        The one figure, reused by every update.
    values : dict
        Last valid readout: ``omega_n`` (rad/s), ``f_n`` (Hz), ``omega``
        (rad/s), ``f`` (Hz), ``ratio``, ``zeta``, ``regime``,
        ``magnification``, ``amplitude`` (m), ``peak`` (m), ``settling`` (s),
        ``steady_reached`` ("yes"/"no"), ``t_end`` (s) and, with the overlay,
        ``rk45_max_error`` (m) and ``rk45_nfev``.
    error : str or None
        Message of the last rejected input, None when the display is current.
    n_full_draws, n_blits : int
        How many updates redrew the whole figure and how many only blitted
        the moving artists.

    Raises
    ------
    ParameterError
        When a starting value is out of range (later, bad typed values are
        shown in the readout instead).

    Examples
    --------
    >>> ex = explorer()
    >>> ex.values["regime"], round(ex.values["amplitude"], 4)      # m
    ('underdamped', 2.2371)
    >>> ex.c_slider.value = 15.0
    >>> ex.values["regime"]
    'overdamped'
    >>> ex.m_text.value = 0.0
    >>> ex.error
    'm = 0.0 kg is out of range: allowed m > 0 kg, finite'
    """

    def __init__(
        self,
        m: float = 1.0,
        k: float = 20.0,
        F0: float = 5.0,
        c: float = 0.5,
        omega: float = 4.47,
        t_end: float = 50.0,
        n_points: int = N_POINTS,
        show_rk45: bool = False,
    ) -> None:
        osc = Oscillator(m=m, c=c, k=k)
        force = SineForce(F0=F0, omega=omega)
        check_real("c", c, low=0.0, low_open=True, unit="N s/m")
        check_real("omega", omega, low=0.0, low_open=True, unit="rad/s")
        t_end = check_real("t_end", t_end, low=0.0, low_open=True, unit="s")
        self.n_points = check_int("n_points", n_points, low=2, high=N_POINTS_MAX)
        self._start_state()
        self._build_sliders(osc, force)
        self._build_fields(osc, force, t_end, show_rk45)

        self.figure = self._build_figure()
        self._canvas = self.figure.canvas

        super().__init__(children=[widgets.HBox([self._controls(), self.readout]), self.image])
        self.add_class("vibration-explorer")

        for w in (self.omega_slider, self.c_slider, self.m_text, self.k_text, self.F0_text, self.t_end_text):
            w.observe(self._on_change, names="value")
        self.rk45_checkbox.observe(self._on_toggle, names="value")
        if not self.update():  # pragma: no cover - the inputs were validated above
            raise ParameterError(self.error)

    # ------------------------------------------------------------------ controls
    def _start_state(self) -> None:
        """No error, no readout yet, no draws counted, no cached background."""
        self.error: str | None = None
        self.values: dict = {}
        self.n_full_draws = 0
        self.n_blits = 0
        self._background = None
        self._bg_key = None
        self._dirty = True
        self._active = False

    def _build_sliders(self, osc: Oscillator, force: SineForce) -> None:
        """The forcing-frequency slider (with its Hz label) and the logarithmic damping slider (with its zeta label)."""
        top, step = omega_range(osc.natural_frequency, force.omega)
        slider = {"continuous_update": True, "style": {"description_width": "10.5em"}}
        self.omega_slider = widgets.FloatSlider(
            value=force.omega,
            min=step,
            max=top,
            step=step,
            description="forcing ω (rad/s)",
            readout_format=".3f",
            layout=widgets.Layout(width="36em"),
            **slider,
        )
        self.omega_hz = widgets.HTML(layout=widgets.Layout(width="9em"))
        lo = min(math.log10(C_MIN), math.floor(math.log10(osc.c)))
        hi = max(math.log10(C_MAX), math.log10(osc.c))
        self.c_slider = widgets.FloatLogSlider(
            value=osc.c,
            base=10.0,
            min=lo,
            max=hi,
            step=(hi - lo) / 400,
            description="damping c (N s/m)",
            readout_format=".3g",
            layout=widgets.Layout(width="36em"),
            **slider,
        )
        self.zeta_label = widgets.HTML(layout=widgets.Layout(width="9em"))

    def _build_fields(self, osc: Oscillator, force: SineForce, t_end: float, show_rk45: bool) -> None:
        """The typed values (m, k, F0, t_end), the RK45 checkbox, the readout and the figure's image."""
        small = widgets.Layout(width="13em")
        text_style = {"description_width": "5.5em"}
        self.m_text = widgets.FloatText(value=osc.m, description="m (kg)", style=text_style, layout=small)
        self.k_text = widgets.FloatText(value=osc.k, description="k (N/m)", style=text_style, layout=small)
        self.F0_text = widgets.FloatText(value=force.F0, description="F0 (N)", style=text_style, layout=small)
        self.t_end_text = widgets.FloatText(value=t_end, description="t_end (s)", style=text_style, layout=small)
        self.rk45_checkbox = widgets.Checkbox(
            value=bool(show_rk45),
            description="overlay the paper's RK45 (solve_ivp, SciPy defaults)",
            indent=False,
            layout=widgets.Layout(width="30em"),
        )
        self.readout = widgets.HTML(layout=widgets.Layout(min_width="24em"))
        self.readout.add_class("vibration-readout")
        self.image = widgets.Image(format="png", layout=widgets.Layout(max_width="100%", height="auto"))
        self.image.add_class("vibration-figure")

    def _controls(self) -> widgets.VBox:
        """The controls in rows: the two sliders with their labels, the typed values in pairs, the checkbox."""
        return widgets.VBox(
            [
                widgets.HBox([self.omega_slider, self.omega_hz]),
                widgets.HBox([self.c_slider, self.zeta_label]),
                widgets.HBox([self.m_text, self.k_text]),
                widgets.HBox([self.F0_text, self.t_end_text]),
                self.rk45_checkbox,
            ]
        )

    # ------------------------------------------------------------------ figure
    def _build_figure(self) -> Figure:
        """Create the figure and its (empty) artists once; :meth:`update` fills them."""
        fig, self._axes, self._art = build_figure()
        self._legend = None
        self._legend_rk45 = None
        return fig

    def _set_legend(self, rk45: bool) -> None:
        if self._legend is not None and self._legend_rk45 == rk45:
            return
        if self._legend is not None:
            self._legend.remove()
        handles = [
            Line2D([], [], **STYLE["curve"], label="exact closed form"),
            Line2D([], [], **STYLE["envelope"], label="± steady-state amplitude"),
            Line2D([], [], **STYLE["marker"], label=r"2 % settling time; $\omega_n$"),
            Line2D([], [], **STYLE["point"], label="operating point"),
        ]
        if rk45:
            handles.insert(1, Line2D([], [], **STYLE["rk45"], label="RK45, SciPy defaults"))
        self._legend = self.figure.legend(
            handles=handles,
            loc="upper left",
            bbox_to_anchor=(0.075, 1.0),
            ncols=len(handles) if len(handles) <= 4 else 3,
            frameon=False,
            fontsize=9,
            handlelength=2.2,
        )
        self._legend_rk45 = rk45
        self._dirty = True

    def _view_key(self) -> tuple:
        return tuple((ax.get_xlim(), ax.get_ylim()) for ax in self._axes.values())

    def _render(self, force_full: bool = False) -> bytes:
        """Draw the figure into its Agg buffer and return it as PNG bytes.

        Autoscales the y axes (round numbers). When no view limit moved, the
        cached background is restored and only the animated artists are
        drawn; otherwise the whole figure is drawn and the background cached.
        """
        with mpl.rc_context({"axes.autolimit_mode": "round_numbers"}):
            for ax in self._axes.values():
                ax.relim(visible_only=True)
                ax.autoscale_view(scalex=False)
        key = self._view_key()
        canvas = self._canvas
        if force_full or self._dirty or self._background is None or key != self._bg_key:
            canvas.draw()  # everything except the animated artists
            self._background = canvas.copy_from_bbox(self.figure.bbox)
            self._bg_key = key
            self._dirty = False
            self.n_full_draws += 1
        else:
            canvas.restore_region(self._background)
            self.n_blits += 1
        order = (
            "x_env_hi",
            "x_env_lo",
            "v_env_hi",
            "v_env_lo",
            "x_settle",
            "v_settle",
            "omega_n",
            "curve",
            "x",
            "v",
            "x_rk45",
            "v_rk45",
            "point",
        )
        for name in order:
            art = self._art[name]
            if art.get_visible():
                art.axes.draw_artist(art)
        return png_frame(canvas)

    # ------------------------------------------------------------------ update
    def _read(self):
        """Validated parameters from the controls (raises ParameterError)."""
        osc = Oscillator(m=self.m_text.value, c=self.c_slider.value, k=self.k_text.value)
        force = SineForce(F0=self.F0_text.value, omega=self.omega_slider.value)
        t_end = check_real("t_end", self.t_end_text.value, low=0.0, low_open=True, unit="s")
        return osc, force, t_end

    def _compute(self, osc: Oscillator, force: SineForce, t_end: float, rk45: bool) -> dict:
        """Responses and readout values from the package (raises on bad input)."""
        t = np.linspace(0.0, t_end, self.n_points)
        with np.errstate(over="ignore", invalid="ignore", under="ignore", divide="ignore"):
            resp = exact_response(osc, force, t)
            vals = readout(osc, force, t_end, n_points=self.n_points, response=resp).as_dict()
            ss = steady_state(osc, force)
            top, step = omega_range(vals["omega_n"], force.omega)
            grid = omega_grid(vals["omega_n"], osc.damping_ratio, top)
            curve = magnification(osc, grid)
            paper = simulate(osc, force, t_end, n_points=self.n_points) if rk45 else None
        if paper is not None:
            vals["rk45_max_error"] = float(np.max(np.abs(paper.x - resp.x)))
            vals["rk45_nfev"] = paper.nfev
        return {
            "vals": vals,
            "resp": resp,
            "ss": ss,
            "grid": grid,
            "curve": curve,
            "paper": paper,
            "top": top,
            "step": step,
        }

    def update(self, force_full: bool = False) -> bool:
        """Recompute from the controls and redraw the figure and the readout.

        Parameters
        ----------
        force_full : bool
            Redraw the whole figure even if no axis limit moved.

        Returns
        -------
        bool
            True when the display shows the controls' values; False when an
            input was rejected: the readout then shows the message (also in
            :attr:`error`) and the figure keeps the last valid state.
        """
        self._active = True
        try:
            osc, force, t_end = self._read()
            rk45 = bool(self.rk45_checkbox.value)
            try:
                res = self._compute(osc, force, t_end, rk45)
            except INPUT_ERRORS as exc:
                raise _NoResponse(
                    f"no finite response for m = {osc.m:g} kg, c = {osc.c:g} N s/m, k = {osc.k:g} N/m, "
                    f"F0 = {force.F0:g} N, omega = {force.omega:g} rad/s, t_end = {t_end:g} s "
                    f"({type(exc).__name__}: {exc})"
                ) from exc
        except (*INPUT_ERRORS, _NoResponse) as exc:
            self.error = str(exc)
            self.readout.value = self._readout_html()
            return False
        finally:
            self._active = False
        self.error = None
        vals, resp, ss = res["vals"], res["resp"], res["ss"]
        a = self._art
        ax = self._axes
        if ax["x"].get_xlim() != (0.0, t_end):
            ax["x"].set_xlim(0.0, t_end)
        a["x"].set_data(resp.t, resp.x)
        a["v"].set_data(resp.t, resp.v)
        for name, amp in (("x", ss.amplitude), ("v", ss.velocity_amplitude)):
            a[f"{name}_env_hi"].set_ydata([amp, amp])
            a[f"{name}_env_lo"].set_ydata([-amp, -amp])
            settle = a[f"{name}_settle"]
            inside = vals["settling"] <= t_end
            settle.set_visible(inside)
            if inside:
                settle.set_xdata([vals["settling"]] * 2)
        paper = res["paper"]
        for name in ("x", "v"):
            line = a[f"{name}_rk45"]
            line.set_visible(paper is not None)
            if paper is not None:
                line.set_data(paper.t, getattr(paper, name))
        self._set_legend(paper is not None)
        if ax["m"].get_xlim() != (0.0, res["top"]):
            ax["m"].set_xlim(0.0, res["top"])
        a["curve"].set_data(res["grid"], res["curve"])
        a["point"].set_data([force.omega], [ss.magnification])
        a["omega_n"].set_xdata([vals["omega_n"]] * 2)
        self._sync_omega_slider(res["top"], res["step"])
        if self.omega_slider.value != force.omega:  # the new bounds clamped it: show that value
            return self.update(force_full)
        self.values = vals
        self.omega_hz.value = f"f = {vals['f']:.4g} Hz"
        self.zeta_label.value = f"ζ = {vals['zeta']:.4g}"
        self.readout.value = self._readout_html()
        self.image.value = self._render(force_full)
        return True

    def _rebuild(self) -> bool:
        """Replace the figure by a new one and update it: the naive path that
        :func:`benchmark_updates` compares against."""
        self.figure = self._build_figure()
        self._canvas = self.figure.canvas
        self._background = None
        return self.update()

    def _sync_omega_slider(self, top: float, step: float) -> None:
        s = self.omega_slider  # its minimum stays: widening never moves the value
        if s.max == top and s.step == step:
            return
        self._active = True  # bounds may clamp the value: do not recurse
        try:
            s.step = step
            s.max = top
        finally:
            self._active = False

    def _on_change(self, change) -> None:
        if not self._active:
            self.update()

    def _on_toggle(self, change) -> None:
        self._dirty = True
        self._on_change(change)

    # ------------------------------------------------------------------ readout
    def _rows(self):
        rows = list(_ROWS)
        if "rk45_max_error" in self.values:
            rows += list(_RK45_ROWS)
        return [(r.label, format(self.values[r.key], r.fmt), r.unit) for r in rows]

    def _readout_html(self) -> str:
        parts = []
        if self.error is not None:
            parts.append(
                '<div class="vibration-error" style="color:#b00020;margin-bottom:0.4em">'
                f"<b>Input rejected:</b> {html.escape(self.error)}<br>"
                "The figure and the table show the last valid parameters.</div>"
            )
        if not self.values:
            return "".join(parts)
        pad = "padding:0.05em 0.6em 0.05em 0"
        cells = "".join(
            f"<tr><td style='text-align:left;{pad}'>{html.escape(q)}</td>"
            f"<td style='text-align:right;font-family:monospace;{pad}'>{html.escape(v)}</td>"
            f"<td style='text-align:left;{pad}'>{html.escape(u)}</td></tr>"
            for q, v, u in self._rows()
        )
        style = "opacity:0.45" if self.error is not None else ""
        parts.append(
            f"<table style='border-collapse:collapse;font-size:0.9em;line-height:1.35;{style}'>"
            f"<thead><tr><th style='text-align:left;{pad}'>quantity</th>"
            f"<th style='text-align:right;{pad}'>value</th><th style='text-align:left;{pad}'>unit</th></tr>"
            f"</thead><tbody>{cells}</tbody></table>"
        )
        return "".join(parts)

    def table(self) -> str:
        """The readout as a plain-text table at fixed precision (5 significant digits).

        Examples
        --------
        >>> print(explorer(omega=3.0).table())
        quantity                                 value  unit
        natural frequency ω_n                   4.4721  rad/s
        natural frequency f_n                  0.71176  Hz
        forcing frequency ω                          3  rad/s
        forcing frequency f                    0.47746  Hz
        frequency ratio ω/ω_n                  0.67082
        damping ratio ζ                       0.055902
        regime                             underdamped
        magnification |X|/(F0/k)                1.8015
        steady-state amplitude |X|             0.45038  m
        peak |x| in the window                  0.6129  m
        2 % settling time                       14.057  s
        steady state reached in the window         yes
        time window                                 50  s
        """
        rows = [("quantity", "value", "unit"), *self._rows()]
        wq = max(len(q) for q, _, _ in rows)
        wv = max(len(v) for _, v, _ in rows)
        return "\n".join(f"{q:<{wq}} {v:>{wv}}  {u}".rstrip() for q, v, u in rows)

    def close(self) -> None:
        """Close the explorer and every widget inside it (their comms are released)."""

        def walk(w):
            for child in getattr(w, "children", ()):
                yield from walk(child)
            yield w

        for w in list(walk(self))[:-1]:
            w.close()
        super().close()

    @property
    def widget(self) -> Explorer:
        """The container to display (the explorer itself)."""
        return self

    def png(self) -> bytes:
        """PNG bytes of the figure as currently shown."""
        return self.image.value

    def _repr_mimebundle_(self, **kwargs):
        """Widget view, plus for renderers without widget state (the HTML report) the
        static JavaScript slider panel at the same parameters, a PNG and a short text."""
        data = super()._repr_mimebundle_(**kwargs)
        if data is None:  # pragma: no cover - ipywidgets returns a bundle
            return None
        data["image/png"] = base64.b64encode(png_small(self._canvas)).decode("ascii")
        try:
            data["text/html"] = slider_panel_html(
                m=float(self.m_text.value),
                k=float(self.k_text.value),
                F0=float(self.F0_text.value),
                c=float(self.c_slider.value),
                omega=float(self.omega_slider.value),
                t_end=float(self.t_end_text.value),
            )
        except (TypeError, ValueError):  # a rejected value is being shown: keep the PNG only
            pass
        data["text/plain"] = (
            f"Explorer(m={self.m_text.value!r} kg, k={self.k_text.value!r} N/m, F0={self.F0_text.value!r} N, "
            f"c={self.c_slider.value:.4g} N s/m, omega={self.omega_slider.value!r} rad/s, "
            f"t_end={self.t_end_text.value!r} s)"
        )
        return data


#: The explorer's factory name: ``explorer(omega=3.0)`` builds an :class:`Explorer` (an ``ipywidgets.VBox``;
#: display it as the last expression of a cell).
explorer = Explorer


def live_explorer(study: ExploreStudy) -> Explorer:
    """The explorer started at a study's parameters: its mass, stiffness, force, window, starting
    forcing frequency and the damping its sliders can hold (:attr:`ExploreStudy.c_start`)."""
    p = study.params
    return explorer(m=p.m, k=p.k, F0=p.F0, c=study.c_start, omega=p.omega_res, t_end=p.t_end)
