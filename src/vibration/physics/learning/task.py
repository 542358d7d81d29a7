"""The task: the oscillator with its actuator, cost and episodes, and its exact zero-order-hold step."""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
import scipy.linalg

from ..duffing import _real_array
from ..model import ParameterError, check_int, check_real

MODES = ("force", "damping")
METHODS = ("ars", "cma")

#: Work budgets: simulated steps (laws x episodes x steps) of one :func:`episode_costs` call and of one
#: :func:`train` run; recorded steps (episodes x steps, three float arrays) of one :func:`rollout` and of one
#: :func:`compare_controllers` (all controllers); initial states drawn at once.
MAX_EPISODE_STEPS = 300_000_000
MAX_RECORDED_STEPS = 10_000_000
MAX_STATES = 1_000_000


# ----------------------------------------------------------------------------- the task


@dataclass(frozen=True, kw_only=True)
class OscillatorTask:
    """The control task: plant, sampling, initial states, cost, disturbance and actuator.

    Defaults are the issue's task: the paper's oscillator with c = 0.5 N s/m, dt = 0.01 s,
    1000 steps (10 s), initial state uniform in [-1, 1] m x [-1, 1] m/s, stage cost
    ``(x**2 + v**2 + 0.01 u**2) dt``, force bounded by 50 N (the optimum needs at most
    14.8 N, see :func:`peak_force`), no disturbance.

    Examples
    --------
    >>> task = OscillatorTask()
    >>> task.mode, task.n_steps * task.dt                # -, s
    ('force', 10.0)
    >>> OscillatorTask(dt=0.0)
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: dt = 0.0 s is out of range: allowed dt > 0 s, dt <= 1 s, finite
    """

    m: float = 1.0  # mass, kg
    c: float = 0.5  # passive viscous damping, N s/m (replaced by the action in damping mode)
    k: float = 20.0  # stiffness, N/m
    dt: float = 0.01  # sampling period (zero-order hold), s
    n_steps: int = 1000  # steps per episode, 1
    x0_max: float = 1.0  # initial displacement uniform in [-x0_max, x0_max], m
    v0_max: float = 1.0  # initial velocity uniform in [-v0_max, v0_max], m/s
    q_x: float = 1.0  # displacement weight, 1/m^2
    q_v: float = 1.0  # velocity weight, s^2/m^2
    r: float = 0.01  # force weight, 1/N^2
    u_max: float = 50.0  # force bound of the actuator (force mode), N
    F0: float = 0.0  # disturbance amplitude, N (0: no disturbance)
    omega: float = 4.47  # disturbance angular frequency, rad/s
    mode: str = "force"  # "force" (active) or "damping" (semi-active)
    c_min: float = 0.1  # smallest damping of the semi-active damper, N s/m
    c_max: float = 15.0  # largest damping of the semi-active damper, N s/m

    def __post_init__(self) -> None:
        pos = {"low": 0.0, "low_open": True}
        s = object.__setattr__
        s(self, "m", check_real("m", self.m, **pos, unit="kg"))
        s(self, "c", check_real("c", self.c, low=0.0, unit="N s/m"))
        s(self, "k", check_real("k", self.k, **pos, unit="N/m"))
        s(self, "dt", check_real("dt", self.dt, **pos, high=1.0, unit="s"))
        s(self, "n_steps", check_int("n_steps", self.n_steps, low=1, high=100_000))
        s(self, "x0_max", check_real("x0_max", self.x0_max, low=0.0, unit="m"))
        s(self, "v0_max", check_real("v0_max", self.v0_max, low=0.0, unit="m/s"))
        s(self, "q_x", check_real("q_x", self.q_x, low=0.0, unit="1/m^2"))
        s(self, "q_v", check_real("q_v", self.q_v, low=0.0, unit="s^2/m^2"))
        s(self, "r", check_real("r", self.r, **pos, unit="1/N^2"))
        s(self, "u_max", check_real("u_max", self.u_max, **pos, unit="N"))
        s(self, "F0", check_real("F0", self.F0, low=0.0, unit="N"))
        s(self, "omega", check_real("omega", self.omega, low=0.0, unit="rad/s"))
        if not isinstance(self.mode, str) or self.mode not in MODES:
            raise ParameterError(f"mode = {self.mode!r} is not a mode: allowed one of {MODES}")
        s(self, "c_min", check_real("c_min", self.c_min, low=0.0, unit="N s/m"))
        s(self, "c_max", check_real("c_max", self.c_max, low=self.c_min, low_open=True, unit="N s/m"))
        if self.dt * math.sqrt(self.k / self.m) > 10.0 or self.dt * max(self.c, self.c_max) / self.m > 700.0:
            wn_dt, c_dt = self.dt * math.sqrt(self.k / self.m), self.dt * max(self.c, self.c_max) / self.m
            raise ParameterError(
                f"dt = {self.dt!r} s is out of range: allowed dt sqrt(k/m) <= 10 and dt c/m <= 700 "
                f"(here {wn_dt:.3g} and {c_dt:.3g})"
            )
        if self.F0 > 0.0:
            c_low = self.c if self.mode == "force" else self.c_min
            if abs(complex(self.k - self.m * self.omega**2, self.omega * c_low)) <= 1e-9 * self.k:
                raise ParameterError(
                    f"omega = {self.omega!r} rad/s is out of range: allowed omega != sqrt(k/m) when the damping "
                    f"can be 0 (undamped resonance has no bounded forced response)"
                )

    @property
    def t(self) -> np.ndarray:
        """Start times of the steps ``k dt``, k = 0 .. n_steps - 1, s."""
        return np.arange(self.n_steps) * self.dt

    @property
    def initial_covariance(self) -> np.ndarray:
        """Second moment of the uniform initial state, ``diag(x0_max**2, v0_max**2) / 3`` (m², m²/s²)."""
        return np.diag([self.x0_max**2 / 3.0, self.v0_max**2 / 3.0])

    @property
    def state_weight(self) -> np.ndarray:
        """``Q = dt diag(q_x, q_v)`` of the discrete cost ``sum s'Q s + u'R u``."""
        return self.dt * np.diag([self.q_x, self.q_v])


def resonance_task(F0: float = 5.0, omega: float = 4.47, **fields) -> OscillatorTask:
    """The default task with the paper's resonance force ``F0 sin(omega t)`` on the mass.

    Examples
    --------
    >>> resonance_task().F0, resonance_task().omega                      # N, rad/s
    (5.0, 4.47)
    """
    return OscillatorTask(F0=F0, omega=omega, **fields)


def semi_active_task(F0: float = 5.0, omega: float = 4.47, **fields) -> OscillatorTask:
    """The semi-active task: the action is the damping in [c_min, c_max], under the resonance force.

    Examples
    --------
    >>> t = semi_active_task()
    >>> t.mode, t.c_min, t.c_max                                           # -, N s/m, N s/m
    ('damping', 0.1, 15.0)
    """
    return OscillatorTask(F0=F0, omega=omega, mode="damping", **fields)


def _check_task(task) -> OscillatorTask:
    if task is None:
        return OscillatorTask()
    if not isinstance(task, OscillatorTask):
        raise ParameterError(f"task = {task!r} is not an OscillatorTask: allowed OscillatorTask(...) or None")
    return task


def _check_gains(gains) -> np.ndarray:
    try:
        g = _real_array("gains", gains, max_size=2)
    except ParameterError:
        g = None
    if g is None or g.shape != (2,):
        raise ParameterError(f"gains = {gains!r:.80} is not two finite numbers: allowed [K_x (N/m), K_v (N s/m)]")
    return g


def _check_gain_rows(gains) -> np.ndarray:
    """Gains as an (n, 2) array of finite numbers, n >= 1."""
    g = _real_array("gains", gains, max_size=2 * MAX_STATES)
    if g.ndim == 1:
        return _check_gains(g)[None, :]
    if g.ndim != 2 or g.shape[1] != 2:
        raise ParameterError(f"gains has shape {g.shape}: allowed finite [K_x, K_v] rows, shape (2,) or (n, 2)")
    return g


# ----------------------------------------------------------------------------- exact discretisation


def zoh(task: OscillatorTask | None = None, c: float | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Exact zero-order-hold matrices ``(A_d, B_d)`` of ``s' = A s + B u``, ``s = [x, v]``.

    ``A_d = exp(A dt)``, ``B_d = int_0^dt exp(A t) dt B`` from one matrix exponential of the
    augmented matrix ``[[A, B], [0, 0]] dt`` (Van Loan).

    Parameters
    ----------
    task : OscillatorTask, optional
        Plant and ``dt`` (s); the default task if omitted.
    c : float, optional
        Damping to use instead of ``task.c``, N s/m.

    Returns
    -------
    A_d : ndarray, shape (2, 2)
        State transition over one step (1, s; 1/s, 1).
    B_d : ndarray, shape (2,)
        Response to a unit force held over one step (m/N, m/(N s)).

    Examples
    --------
    >>> A_d, B_d = zoh()
    >>> np.round(A_d, 5)
    array([[ 0.999  ,  0.00997],
           [-0.19943,  0.99402]])
    """
    task = _check_task(task)
    cc = task.c if c is None else check_real("c", c, low=0.0, high=700.0 * task.m / task.dt, unit="N s/m")
    a_d, b_d = _zoh(task.m, cc, task.k, task.dt)
    return a_d.copy(), b_d.copy()


@functools.lru_cache(maxsize=256)
def _zoh(m: float, c: float, k: float, dt: float) -> tuple[np.ndarray, np.ndarray]:
    a = np.array([[0.0, 1.0, 0.0], [-k / m, -c / m, 1.0 / m], [0.0, 0.0, 0.0]])
    e = scipy.linalg.expm(a * dt)
    a_d, b_d = e[:2, :2].copy(), e[:2, 2].copy()
    a_d.flags.writeable = b_d.flags.writeable = False
    return a_d, b_d


def _particular(task: OscillatorTask, c: float, t: np.ndarray) -> np.ndarray:
    """Steady forced response ``[x_p, v_p]`` (m, m/s) to ``F0 sin(omega t)`` with damping c, shape (len(t), 2)."""
    h = task.F0 / complex(task.k - task.m * task.omega**2, task.omega * c)
    st, ct = np.sin(task.omega * t), np.cos(task.omega * t)
    return np.column_stack([h.real * st + h.imag * ct, task.omega * (h.real * ct - h.imag * st)])


def disturbance_increments(task: OscillatorTask | None = None) -> np.ndarray:
    """Exact state increments of the disturbance over each step, shape (n_steps, 2) (m, m/s).

    With the force held at u over step k, ``s_{k+1} = A_d s_k + B_d u + d_k``. The forced
    particular solution ``p(t)`` solves the ODE, so ``d_k = p(t_{k+1}) - A_d p(t_k)``; zero when
    ``F0 = 0``. Force mode only (the plant's own ``c``).

    Examples
    --------
    >>> d = disturbance_increments(resonance_task())
    >>> d.shape, bool(np.all(d[0] == 0.0) or abs(d[0, 1]) < 0.01)        # first step: about F0 t^2
    ((1000, 2), True)
    """
    return _increments(_check_task(task)).copy()


@functools.lru_cache(maxsize=64)
def _increments(task: OscillatorTask) -> np.ndarray:
    if task.F0 == 0.0:
        d = np.zeros((task.n_steps, 2))
    else:
        a_d, _ = _zoh(task.m, task.c, task.k, task.dt)
        tt = np.arange(task.n_steps + 1) * task.dt
        p = _particular(task, task.c, tt)
        d = p[1:] - p[:-1] @ a_d.T
    d.flags.writeable = False
    return d
