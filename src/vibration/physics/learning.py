"""A learning controller measured against the optimum it should find (Part II).

The task
--------
:class:`OscillatorTask` is the paper's oscillator ``m x'' + c x' + k x = u + F0 sin(omega t)``
sampled every ``dt`` with an exact zero-order hold: the action is held constant over each
step and the state is propagated by the matrix exponential, not by an integrator. The
observation is the state ``s = [x, v]`` (m, m/s). Two modes:

* ``mode="force"``: the action is a force ``u`` (N) on the mass, bounded by ``|u| <= u_max``;
* ``mode="damping"`` (semi-active): the action is the damping coefficient ``c`` (N s/m) of the
  oscillator's damper, in ``[c_min, c_max]``; it replaces the passive ``c`` and is held over the
  step, so the damper force ``-c v(t)`` follows the velocity within the step. Its "control force"
  is that damper force, ``u = -c v``.

Cost
----
Step ``k`` starts at ``t_k = k dt`` in state ``s_k`` (the observation the action is chosen on)
and costs ``(q_x x_k**2 + q_v v_k**2 + r u_k**2) dt``; the gymnasium reward is its negative.
An episode is ``n_steps`` steps from ``s_0`` uniform in ``[-x0_max, x0_max] x [-v0_max, v0_max]``,
and the disturbance starts at phase 0 at ``t = 0``. The **episode cost** is the sum of the
step costs (``= -`` the episode's return); the **expected cost** is its mean over the
initial-state distribution. With the default weights (``q_x`` in 1/m², ``q_v`` in s²/m², ``r``
in 1/N²) every term is dimensionless and costs are in seconds.

Policies
--------
Every controller of the chapter is a *linear desired-force law* ``u_des = -K s`` with
``K = [K_x, K_v]`` (N/m, N s/m), realised by the mode's device:

* force mode: ``u = clip(-K s, -u_max, u_max)`` (``u = -K [x, v]``: positive ``K_x`` acts as a
  spring, positive ``K_v`` as a damper);
* damping mode: the damper can only produce ``-c v`` with ``c`` in ``[c_min, c_max]``, so the
  law is *clipped*: ``c = clip(K_v + K_x x / v, c_min, c_max)`` (``c = clip(K_v)`` at ``v = 0``).
  ``K = [0, c]`` is passive damping, ``K = [0, c_sky]`` clipped skyhook (on a damper anchored to
  the ground the skyhook force ``-c_sky v`` is a damper, so clipped skyhook is passive damping at
  ``clip(c_sky)``), and ``K = K_LQR`` the clipped-optimal law of Dyke et al. (1996).

The optimum and the learners
----------------------------
:func:`lqr_reference` solves the discrete algebraic Riccati equation for the sampled plant with
weights ``Q = dt diag(q_x, q_v)``, ``R = dt r`` (the same stage cost as the environment);
:func:`expected_cost` evaluates any linear force-mode law exactly (covariance recursion from the
uniform initial distribution plus the deterministic forced response), and certifies with
:func:`peak_force` that the bound ``u_max`` never binds. :func:`train` learns the two gains from
episodes only (model-free): basic random search with antithetic directions and top-``b``
selection (ARS V1-t, Mania et al. 2018) or CMA-ES (Hansen's ``cma`` package), every candidate of
an iteration scored on the same freshly drawn initial states (common random numbers).
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass, replace

import numpy as np
import scipy.linalg

from .duffing import _real_array
from .model import ParameterError, check_int, check_real

# Exported at the top level (``vibration.<name>``); the rest is in ``vibration.learn``.
__all__ = [
    "LQRReference",
    "LinearPolicy",
    "OscillatorTask",
    "PassiveOptimum",
    "Rollouts",
    "TrainingResult",
    "best_passive_damping",
    "lqr_reference",
    "resonance_task",
    "semi_active_task",
]

MODES = ("force", "damping")
METHODS = ("ars", "cma")

#: Work budgets: simulated steps (laws x episodes x steps) of one :func:`episode_costs` call and of one
#: :func:`train` run; recorded steps (episodes x steps, three float arrays) of one :func:`rollout` and of one
#: :func:`compare_controllers` (all controllers); initial states drawn at once.
MAX_EPISODE_STEPS = 300_000_000
MAX_RECORDED_STEPS = 10_000_000
MAX_STATES = 1_000_000


# ----------------------------------------------------------------------------- the task


@dataclass(frozen=True)
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


# ----------------------------------------------------------------------------- compiled rollouts


@functools.cache
def _kernel():
    """Compile (once per process, cached on disk) the batched episode loop; numba is imported lazily."""
    import numba

    @numba.njit(parallel=True, cache=True)
    def kernel(
        mode, a_d, b_d, d, sw, cw, m, k, dt, f0, om, qx, qv, r, u_max, c_min, c_max, gains, x0, rec, xs, vs, us
    ):  # pragma: no cover - compiled
        n_pol, n_ep, n = gains.shape[0], x0.shape[0], d.shape[0]
        costs = np.empty((n_pol, n_ep))
        for job in numba.prange(n_pol * n_ep):
            i, j = job // n_ep, job % n_ep
            kx, kv = gains[i, 0], gains[i, 1]
            x, v = x0[j, 0], x0[j, 1]
            acc = 0.0
            c_last = -1.0
            p00 = p01 = p10 = p11 = h_re = h_im = 0.0
            for step in range(n):
                if mode == 0:
                    u = -(kx * x + kv * v)
                    if u > u_max:
                        u = u_max
                    elif u < -u_max:
                        u = -u_max
                    xn = a_d[0, 0] * x + a_d[0, 1] * v + b_d[0] * u + d[step, 0]
                    vn = a_d[1, 0] * x + a_d[1, 1] * v + b_d[1] * u + d[step, 1]
                else:
                    cc = kv + kx * x / v if v != 0.0 else kv
                    if not cc >= c_min:  # also NaN
                        cc = c_min
                    elif cc > c_max:
                        cc = c_max
                    u = -cc * v
                    if cc != c_last:  # the transition matrix and forced response of this damping
                        c_last = cc
                        sg = -cc / (2.0 * m)
                        disc = sg * sg - k / m
                        z = disc * dt * dt
                        if abs(z) < 1e-3:
                            ch = 1.0 + z / 2.0 * (1.0 + z / 12.0 * (1.0 + z / 30.0 * (1.0 + z / 56.0)))
                            sh = dt * (1.0 + z / 6.0 * (1.0 + z / 20.0 * (1.0 + z / 42.0 * (1.0 + z / 72.0))))
                        elif disc < 0.0:
                            wd = np.sqrt(-disc)
                            ch = np.cos(wd * dt)
                            sh = np.sin(wd * dt) / wd
                        else:
                            q = np.sqrt(disc)
                            ch = np.cosh(q * dt)
                            sh = np.sinh(q * dt) / q
                        e = np.exp(sg * dt)
                        p00, p01 = e * (ch - sg * sh), e * sh
                        p10, p11 = -e * (k / m) * sh, e * (ch + sg * sh)
                        den_re, den_im = k - m * om * om, om * cc
                        den2 = den_re * den_re + den_im * den_im
                        h_re, h_im = f0 * den_re / den2, -f0 * den_im / den2
                    if f0 != 0.0:
                        s0, c0, s1, c1 = sw[step], cw[step], sw[step + 1], cw[step + 1]
                        xp0, vp0 = h_re * s0 + h_im * c0, om * (h_re * c0 - h_im * s0)
                        xp1, vp1 = h_re * s1 + h_im * c1, om * (h_re * c1 - h_im * s1)
                        xh, vh = x - xp0, v - vp0
                        xn = p00 * xh + p01 * vh + xp1
                        vn = p10 * xh + p11 * vh + vp1
                    else:
                        xn = p00 * x + p01 * v
                        vn = p10 * x + p11 * v
                if rec:
                    xs[i, j, step] = x
                    vs[i, j, step] = v
                    us[i, j, step] = u
                acc += (qx * x * x + qv * v * v + r * u * u) * dt
                x, v = xn, vn
                if not acc < np.inf:  # overflow (inf or nan): the law destabilises the plant
                    acc = np.inf
                    if rec:
                        for rest in range(step + 1, n):
                            xs[i, j, rest] = np.nan
                            vs[i, j, rest] = np.nan
                            us[i, j, rest] = np.nan
                    break
            costs[i, j] = acc
        return costs

    return kernel


def _run(task: OscillatorTask, gains: np.ndarray, x0: np.ndarray, record: bool):
    mode = MODES.index(task.mode)
    if mode == 0:
        a_d, b_d = _zoh(task.m, task.c, task.k, task.dt)
        d = _increments(task)
    else:
        a_d, b_d, d = np.eye(2), np.zeros(2), np.zeros((task.n_steps, 2))
    phase = task.omega * np.arange(task.n_steps + 1) * task.dt
    sw, cw = np.sin(phase), np.cos(phase)
    shape = (gains.shape[0], x0.shape[0], task.n_steps) if record else (0, 0, 0)
    xs, vs, us = np.empty(shape), np.empty(shape), np.empty(shape)
    costs = _kernel()(
        mode, a_d, b_d, d, sw, cw, task.m, task.k, task.dt, task.F0, task.omega, task.q_x, task.q_v, task.r,
        task.u_max, task.c_min, task.c_max, np.ascontiguousarray(gains, dtype=float),
        np.ascontiguousarray(x0, dtype=float), record, xs, vs, us,
    )  # fmt: skip
    return costs, xs, vs, us


def _check_states(x0) -> np.ndarray:
    s = _real_array("x0", x0, max_size=2 * MAX_STATES)
    if s.ndim == 1:
        s = s[None, :]
    if s.ndim != 2 or s.shape[1] != 2 or s.shape[0] < 1:
        raise ParameterError(f"x0 has shape {np.shape(x0)}: allowed finite [x (m), v (m/s)] rows, shape (n, 2)")
    return s


def _check_work(task: OscillatorTask, n_laws: int, n_states: int, limit: int, what: str) -> None:
    work = n_laws * n_states * task.n_steps
    if work > limit:
        raise ParameterError(
            f"{n_laws} laws x {n_states} initial states x n_steps = {task.n_steps} make {work} {what}: allowed at "
            f"most {limit}"
        )


def sample_initial_states(task: OscillatorTask | None, n: int, seed: int | np.random.Generator = 0) -> np.ndarray:
    """``n`` initial states uniform in the task's box, shape (n, 2) (m, m/s), seeded.

    Examples
    --------
    >>> s = sample_initial_states(None, 4, seed=1)
    >>> s.shape, bool(np.all(np.abs(s) <= 1.0))
    ((4, 2), True)
    """
    task = _check_task(task)
    n = check_int("n", n, low=1, high=MAX_STATES)
    rng = (
        seed
        if isinstance(seed, np.random.Generator)
        else np.random.default_rng(check_int("seed", seed, low=0, high=2**63 - 1))
    )
    return rng.uniform(-1.0, 1.0, size=(n, 2)) * np.array([task.x0_max, task.v0_max])


def episode_costs(task: OscillatorTask | None, gains, x0) -> np.ndarray:
    """Episode cost of every linear law on every initial state, shape (n_laws, n_states) (s).

    Runs the environment's dynamics (exact ZOH, force bound, clipped damping) in one compiled
    loop, in parallel over laws and episodes.

    Parameters
    ----------
    task : OscillatorTask or None
        The task (default task if None).
    gains : array_like, shape (2,) or (n_laws, 2)
        ``[K_x, K_v]`` of ``u_des = -K [x, v]``, N/m and N s/m.
    x0 : array_like, shape (2,) or (n_states, 2)
        Initial states ``[x, v]``, m and m/s.

    Returns
    -------
    numpy.ndarray
        Costs, s; ``inf`` for an episode whose state overflows (a law that destabilises the plant).

    Examples
    --------
    >>> ref = lqr_reference()
    >>> float(episode_costs(None, ref.gains, [1.0, 0.0])[0, 0]) == float(rollout(None, ref.gains, [1.0, 0.0]).cost[0])
    True
    """
    task = _check_task(task)
    g = _check_gain_rows(gains)
    states = _check_states(x0)
    _check_work(task, g.shape[0], states.shape[0], MAX_EPISODE_STEPS, "simulated steps")
    return _run(task, g, states, record=False)[0]


@dataclass(frozen=True)
class Rollouts:
    """Episodes of one linear law: sampled states and forces at the step starts, and costs.

    ``x``, ``v``, ``u`` have shape (n_episodes, n_steps): m, m/s, N (``u`` is the actuator force in
    force mode, the damper force ``-c v`` in damping mode); ``c`` is the damping applied (N s/m,
    damping mode; the passive ``c`` in force mode); ``cost`` the episode costs (s).
    """

    t: np.ndarray  # step start times, s
    x: np.ndarray  # displacement, m
    v: np.ndarray  # velocity, m/s
    u: np.ndarray  # control force, N
    cost: np.ndarray  # episode cost, s

    @property
    def peak_x(self) -> float:
        """Largest |x| over every episode and step, m."""
        return float(np.max(np.abs(self.x)))

    @property
    def rms_x(self) -> float:
        """Root mean square of x over every episode and step, m."""
        return float(np.sqrt(np.mean(self.x**2)))

    @property
    def rms_u(self) -> float:
        """Root mean square of the control force over every episode and step, N."""
        return float(np.sqrt(np.mean(self.u**2)))

    @property
    def peak_u(self) -> float:
        """Largest |u| over every episode and step, N."""
        return float(np.max(np.abs(self.u)))

    @property
    def mean_cost(self) -> float:
        """Mean episode cost, s."""
        return float(np.mean(self.cost))

    @property
    def cost_sem(self) -> float:
        """Standard error of the mean episode cost, s (0 with one episode)."""
        n = self.cost.size
        return float(np.std(self.cost, ddof=1) / math.sqrt(n)) if n > 1 else 0.0


def rollout(task: OscillatorTask | None, gains, x0) -> Rollouts:
    """Episodes of the linear law ``gains`` from the initial states ``x0``, with their trajectories.

    Parameters
    ----------
    task : OscillatorTask or None
        The task (default task if None).
    gains : array_like, shape (2,)
        ``[K_x, K_v]`` (N/m, N s/m) of ``u_des = -K [x, v]``.
    x0 : array_like, shape (2,) or (n, 2)
        Initial states, m and m/s.

    Examples
    --------
    >>> r = rollout(None, [0.0, 0.0], [1.0, 0.0])          # free decay from x = 1 m
    >>> r.x.shape, round(float(r.x[0, 0]), 3), round(r.mean_cost, 3)   # -, m, s
    ((1, 1000), 1.0, 20.868)
    """
    task = _check_task(task)
    g = _check_gains(gains)
    states = _check_states(x0)
    _check_work(task, 1, states.shape[0], MAX_RECORDED_STEPS, "recorded steps")
    costs, xs, vs, us = _run(task, g[None, :], states, record=True)
    if not (np.all(np.isfinite(costs)) and np.all(np.isfinite(xs)) and np.all(np.isfinite(vs))):
        raise ParameterError(
            f"gains = {g.tolist()!r} destabilise the plant: the state overflows (not finite) within "
            f"{task.n_steps} steps: allowed gains whose episodes stay finite"
        )
    return Rollouts(task.t, xs[0], vs[0], us[0], costs[0])


# ----------------------------------------------------------------------------- exact costs and the optimum


def _moments(task: OscillatorTask, g: np.ndarray) -> tuple[float, float]:
    """Exact expected cost (s) and exact largest |u| over the box (N) of the unclipped law g (force mode).

    The state is ``s_k = A_cl^k s_0 + mu_k`` with ``mu_k`` the forced response from rest; ``E s_0 = 0`` so
    ``E s_k s_k' = A_cl^k S_0 A_cl'^k + mu_k mu_k'``, and ``max |K s_k|`` over the box is
    ``|K A_cl^k| [x0_max, v0_max] + |K mu_k|``.
    """
    a_d, b_d = _zoh(task.m, task.c, task.k, task.dt)
    d = _increments(task)
    with np.errstate(over="ignore", invalid="ignore"):  # huge gains: inf weights, and the kernel returns inf
        acl = a_d - np.outer(b_d, g)
        w = task.state_weight + task.dt * task.r * np.outer(g, g)
    if not (np.all(np.isfinite(acl)) and np.all(np.isfinite(w))):
        return math.inf, math.inf
    return _moments_from(task, acl, w, d, g)


def peak_force(task: OscillatorTask | None, gains) -> float:
    """Largest ``|K s_k|`` of the unclipped law ``u = -K s`` over every step and every initial state of the box, N.

    Exact: ``s_k = A_cl^k s_0 + mu_k`` and the box is symmetric, so the largest value is
    ``|K A_cl^k| [x0_max, v0_max] + |K mu_k|``. When it is at most ``u_max`` the force bound never
    binds and :func:`expected_cost` is the law's exact expected cost. Force mode.

    Examples
    --------
    >>> ref = lqr_reference()
    >>> round(peak_force(None, ref.gains), 2)                 # N, from a corner of the box
    14.76
    """
    task = _check_task(task)
    _force_mode(task, "peak_force")
    g = _check_gains(gains)
    peak = _moments(task, g)[1]
    if not math.isfinite(peak):
        raise ParameterError(
            f"gains = {g.tolist()!r} destabilise the plant: the force overflows within {task.n_steps} steps: "
            "allowed gains whose force stays finite"
        )
    return peak


def _force_mode(task: OscillatorTask, what: str) -> None:
    if task.mode != "force":
        raise ParameterError(f"mode = {task.mode!r} is not supported by {what}: allowed mode = 'force'")


def expected_cost(task: OscillatorTask | None, gains) -> float:
    """Exact expected episode cost of the linear law ``u = -K [x, v]`` in force mode, s.

    The expected cost is the mean, over the initial states uniform in the task's box, of the
    episode's summed cost ``sum_{k=0}^{n_steps-1} (q_x x_k**2 + q_v v_k**2 + r u_k**2) dt``
    (the negative of the gymnasium return). Evaluated without sampling: the second moment
    of the state is propagated exactly (``E s_0 s_0' = diag(x0_max**2, v0_max**2) / 3``) and the
    disturbance's deterministic forced response is added.

    Parameters
    ----------
    task : OscillatorTask or None
        A force-mode task (default task if None).
    gains : array_like, shape (2,)
        ``[K_x, K_v]`` in N/m and N s/m, for ``u = -K_x x - K_v v``.

    Returns
    -------
    float
        The expected cost, s.

    Raises
    ------
    ParameterError
        If the force bound ``u_max`` could bind for some initial state (then the law is not
        linear on the task; use :func:`episode_costs` on sampled states), or in damping mode.

    Examples
    --------
    >>> round(expected_cost(None, lqr_reference().gains), 4)                  # s
    0.7663
    """
    task = _check_task(task)
    _force_mode(task, "expected_cost")
    g = _check_gains(gains)
    cost, peak = _moments(task, g)
    if not peak <= task.u_max:
        raise ParameterError(
            f"gains = {g.tolist()!r} is out of range: allowed gains whose largest force over the box "
            f"({peak:.4g} N) stays within u_max = {task.u_max:g} N; sample episodes instead"
        )
    return cost


def _passive_cost(task: OscillatorTask, c: float) -> float:
    """Exact expected cost of a constant damping c: total c (damping mode) or added c (force mode), s."""
    if task.mode == "force":
        return expected_cost(task, [0.0, c])
    sub = replace(task, mode="force", c=c)
    # a damper c is the plant with damping c and no actuator; its force -c v is costed like u
    a_d, _ = _zoh(sub.m, sub.c, sub.k, sub.dt)
    d = _increments(sub)
    w = task.state_weight + task.dt * task.r * np.diag([0.0, c * c])
    return _moments_from(task, a_d, w, d, np.array([0.0, c]))[0]


def _moments_from(task, acl, w, d, g):
    """Expected cost and largest |g s_k| over the box for ``s_{k+1} = acl s_k + d_k``, stage ``s'w s``."""
    total, peak = _moment_kernel()(
        np.ascontiguousarray(acl, dtype=float), np.ascontiguousarray(w, dtype=float), d,
        np.ascontiguousarray(g, dtype=float), task.x0_max, task.v0_max,
    )  # fmt: skip
    return float(total), float(peak)


@functools.cache
def _moment_kernel():
    """Compile (once per process, cached on disk) the exact moment recursion; numba is imported lazily."""
    import numba

    @numba.njit(cache=True)
    def kernel(acl, w, d, g, xb, vb):  # pragma: no cover - compiled
        a00, a01, a10, a11 = acl[0, 0], acl[0, 1], acl[1, 0], acl[1, 1]
        w00, w01, w11 = w[0, 0], w[0, 1], w[1, 1]
        s00, s01, s11 = xb * xb / 3.0, 0.0, vb * vb / 3.0  # E s s' of the uniform box
        mx = mv = 0.0  # forced response from rest
        kx, kv = g[0], g[1]  # row g A_cl^k
        total, peak = 0.0, 0.0
        for kk in range(d.shape[0]):
            total += w00 * (s00 + mx * mx) + 2.0 * w01 * (s01 + mx * mv) + w11 * (s11 + mv * mv)
            pk = abs(kx) * xb + abs(kv) * vb + abs(g[0] * mx + g[1] * mv)
            if pk > peak:
                peak = pk
            t00 = a00 * s00 + a01 * s01
            t01 = a00 * s01 + a01 * s11
            t10 = a10 * s00 + a11 * s01
            t11 = a10 * s01 + a11 * s11
            s00, s01, s11 = t00 * a00 + t01 * a01, t00 * a10 + t01 * a11, t10 * a10 + t11 * a11
            mx, mv = a00 * mx + a01 * mv + d[kk, 0], a10 * mx + a11 * mv + d[kk, 1]
            kx, kv = kx * a00 + kv * a10, kx * a01 + kv * a11
            if not np.isfinite(total):
                return np.inf, np.inf
        return total, peak

    return kernel


@dataclass(frozen=True)
class PassiveOptimum:
    """The best constant damping for a task and its exact expected cost.

    ``c`` is the damper's coefficient (N s/m): in damping mode the oscillator's whole damping, in
    force mode a damper added to the passive ``task.c`` (its force ``-c v`` is the control force).
    """

    c: float  # optimal damping, N s/m
    expected_cost: float  # exact expected cost, s
    at_bound: bool  # the optimum sits on c_min or c_max


def _largest_damper(task: OscillatorTask) -> float:
    """Largest added damping whose force stays within u_max for every initial state of the box, N s/m."""
    lo, hi = 0.0, task.u_max / task.v0_max if task.v0_max > 0.0 else 1e3 * task.c_max

    def peak(c):
        return _moments(task, np.array([0.0, c]))[1]  # inf when the damper destabilises the sampled loop

    while peak(hi) <= task.u_max and hi < 1e12:
        lo, hi = hi, 2.0 * hi
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if peak(mid) <= task.u_max else (lo, mid)
    return lo


def best_passive_damping(task: OscillatorTask | None = None) -> PassiveOptimum:
    """Best constant damping: the semi-active damper held fixed, or a damper added to the plant.

    Damping mode: the best constant ``c`` in ``[c_min, c_max]``. Force mode: the best damper
    added in parallel to the plant's ``c``, ``u = -c_add v``, among those whose force stays
    within ``u_max`` for every initial state (the actuator's force budget). Exact expected cost of
    each constant damping; a 121-point geometric grid, then a bounded Brent search around the
    best grid point.

    Examples
    --------
    >>> opt = best_passive_damping(semi_active_task(F0=0.0))
    >>> round(opt.c, 2), round(opt.expected_cost, 4)                     # N s/m, s
    (9.17, 0.803)
    """
    import scipy.optimize

    task = _check_task(task)
    if task.mode == "damping":
        lo, hi = task.c_min, task.c_max
    else:
        lo, hi = 0.0, _largest_damper(task)
    grid = np.concatenate([[lo], np.geomspace(max(lo, 1e-3 * hi), hi, 120)])
    grid = np.unique(grid)
    costs = np.array([_passive_cost(task, float(c)) for c in grid])
    i = int(np.argmin(costs))
    a, b = grid[max(i - 1, 0)], grid[min(i + 1, grid.size - 1)]
    res = scipy.optimize.minimize_scalar(
        lambda c: _passive_cost(task, float(c)), bounds=(a, b), method="bounded", options={"xatol": 1e-9 * hi}
    )
    c, cost = (float(res.x), float(res.fun)) if res.fun <= costs[i] else (float(grid[i]), float(costs[i]))
    return PassiveOptimum(c, cost, bool(c <= lo + 1e-6 * hi or c >= hi * (1 - 1e-6)))


@dataclass(frozen=True)
class LQRReference:
    """Discrete-time LQR of the sampled task: gains, Riccati solution, exact expected cost.

    ``gains = [K_x, K_v]`` (N/m, N s/m) for ``u = -K [x, v]``; ``P`` solves the discrete algebraic
    Riccati equation with ``Q = dt diag(q_x, q_v)`` and ``R = dt r``, so ``s' P s`` is the optimal
    infinite-horizon cost from ``s`` (s); ``expected_cost`` is the exact mean episode cost of the
    task with these gains (n_steps steps, the disturbance included); ``infinite_horizon_cost`` is
    ``trace(P E[s_0 s_0'])`` (no disturbance); ``poles`` are the closed-loop eigenvalues (z-plane).
    """

    gains: np.ndarray  # [K_x (N/m), K_v (N s/m)]
    P: np.ndarray  # Riccati solution, s (SI units of the state)
    expected_cost: float  # exact expected episode cost, s
    infinite_horizon_cost: float  # trace(P E s0 s0'), s
    poles: np.ndarray  # closed-loop eigenvalues of A_d - B_d K, 1
    peak_force: float  # largest |u| over the box and the episode, N


def lqr_reference(task: OscillatorTask | None = None) -> LQRReference:
    """Discrete-time LQR gains and expected cost of the task (force mode), from the Riccati equation.

    The stage cost of the environment, ``(q_x x**2 + q_v v**2 + r u**2) dt`` on the sampled state
    and the held force, is ``s'Q s + u'R u`` with ``Q = dt diag(q_x, q_v)``, ``R = dt r``: exactly
    the discrete LQR problem of the ZOH plant ``(A_d, B_d)``. Its stationary optimal law is
    ``u = -K s``, ``K = (R + B_d' P B_d)^-1 B_d' P A_d`` (:func:`scipy.linalg.solve_discrete_are`).
    For an episode of ``n_steps`` steps the exact optimum varies with time near the end of the
    episode; with the default task the stationary gains lose less than 1e-12 of the cost to it.
    A disturbance does not change the gains (LQR does not know it), only the expected cost.

    Parameters
    ----------
    task : OscillatorTask, optional
        A force-mode task; the default task if omitted.

    Returns
    -------
    LQRReference

    Examples
    --------
    >>> ref = lqr_reference()
    >>> np.round(ref.gains, 4)                                 # N/m, N s/m
    array([1.2977, 9.2676])
    >>> round(ref.expected_cost, 4), round(ref.infinite_horizon_cost, 4)   # s, s
    (0.7663, 0.7663)
    """
    task = _check_task(task)
    _force_mode(task, "lqr_reference")
    a_d, b_d = zoh(task)
    b = b_d[:, None]
    q, r = task.state_weight, np.array([[task.dt * task.r]])
    try:
        p = scipy.linalg.solve_discrete_are(a_d, b, q, r)
        k = np.linalg.solve(r + b.T @ p @ b, b.T @ p @ a_d).ravel()
    except (ValueError, np.linalg.LinAlgError) as exc:
        raise ParameterError(
            f"the Riccati equation of the task has no stabilising solution ({exc}): allowed a task whose weights "
            f"q_x = {task.q_x!r}, q_v = {task.q_v!r}, r = {task.r!r} and plant make it solvable"
        ) from None
    if not (np.all(np.isfinite(p)) and np.all(np.isfinite(k))):
        raise ParameterError("the Riccati solution of the task is not finite: allowed a better scaled task")
    cost, peak = _moments(task, k)
    return LQRReference(
        gains=k,
        P=p,
        expected_cost=cost,
        infinite_horizon_cost=float(np.trace(p @ task.initial_covariance)),
        poles=np.linalg.eigvals(a_d - b @ k[None, :]),
        peak_force=peak,
    )


# ----------------------------------------------------------------------------- policies and learning


@dataclass(frozen=True)
class LinearPolicy:
    """A linear desired-force law ``u_des = -K [x, v]`` realised by the task's device.

    ``gains = [K_x, K_v]``: K_x in N/m, K_v in N s/m; the sign convention is ``u = -K [x, v]``
    (positive gains act as a spring and a damper). Calling the policy on an observation
    ``[x, v]`` (m, m/s) returns the environment's action: the force ``clip(-K s, -u_max, u_max)``
    (N) in force mode, the damping ``clip(K_v + K_x x / v, c_min, c_max)`` (N s/m) in damping mode.

    Examples
    --------
    >>> pol = LinearPolicy([1.0, 2.0], OscillatorTask())
    >>> pol(np.array([0.5, -1.0]))                    # N
    array([1.5])
    >>> LinearPolicy([1.0, 2.0], semi_active_task())(np.array([0.5, -1.0]))   # N s/m
    array([1.5])
    """

    gains: np.ndarray  # [K_x (N/m), K_v (N s/m)]
    task: OscillatorTask

    def __post_init__(self) -> None:
        object.__setattr__(self, "gains", _check_gains(self.gains))
        object.__setattr__(self, "task", _check_task(self.task))

    def __call__(self, observation) -> np.ndarray:
        obs = _real_array("observation", observation, max_size=2)
        if obs.size != 2:
            raise ParameterError(f"observation = {observation!r:.60} is not [x, v]: allowed two finite numbers")
        x, v = (float(z) for z in obs.reshape(2))
        kx, kv = (float(z) for z in self.gains)
        t = self.task
        if t.mode == "force":
            return np.array([min(max(-(kx * x + kv * v), -t.u_max), t.u_max)])
        c = kv + kx * x / v if v != 0.0 else kv
        c = t.c_min if not c >= t.c_min else min(c, t.c_max)
        return np.array([c])


@dataclass(frozen=True)
class TrainingResult:
    """What :func:`train` learned, and how it got there.

    ``policy.gains`` (= ``gains``) are ``[K_x (N/m), K_v (N s/m)]`` for ``u_des = -K [x, v]``.
    ``curve_cost[i]`` is the expected cost (s) of the learner's current gains ``curve_gains[i]``
    after ``curve_episodes[i]`` training episodes (index 0: the initial gains): exact
    (:func:`expected_cost`) where ``curve_exact[i]``, else the mean over ``n_eval`` fixed
    evaluation episodes drawn from a seed stream separate from training's.
    """

    policy: LinearPolicy
    method: str  # "ars" or "cma"
    seed: int
    curve_episodes: np.ndarray  # training episodes used so far, 1
    curve_gains: np.ndarray  # (n, 2): K_x (N/m), K_v (N s/m)
    curve_cost: np.ndarray  # expected cost, s
    curve_exact: np.ndarray  # bool: exact (True) or sampled (False)

    @property
    def gains(self) -> np.ndarray:
        """Learned ``[K_x, K_v]``, N/m and N s/m, for ``u_des = -K [x, v]``."""
        return self.policy.gains

    @property
    def episodes(self) -> int:
        """Training episodes used, 1."""
        return int(self.curve_episodes[-1])

    @property
    def expected_cost(self) -> float:
        """Expected cost of the learned gains as in the curve's last point, s."""
        return float(self.curve_cost[-1])


def _finite_costs(costs: np.ndarray, cand: np.ndarray) -> np.ndarray:
    """The candidates' mean costs, or :class:`ParameterError` when one of them overflowed (inf)."""
    bad = np.flatnonzero(~np.isfinite(costs))
    if bad.size:
        raise ParameterError(
            f"the learner's candidate gains {cand[bad[0]].tolist()!r} destabilise the plant (the episode cost "
            "overflows): allowed smaller initial_gains, noise, step or sigma0"
        )
    return costs


def _curve_point(task, g, eval_states):
    if task.mode == "force":
        cost, peak = _moments(task, g)
        if peak <= task.u_max:
            return cost, True
    return float(episode_costs(task, g, eval_states).mean()), False


#: Default hyper-parameters per method (tuned on the default task; see the chapter).
DEFAULTS = {
    "ars": {"iterations": 100, "n_episodes": 4, "n_directions": 4, "top": 2, "step": 0.5, "noise": 0.5},
    "cma": {"iterations": 40, "n_episodes": 4, "popsize": 6, "sigma0": 3.0},
}


def train(
    task: OscillatorTask | None = None,
    seed: int = 0,
    method: str = "ars",
    *,
    iterations: int | None = None,
    n_episodes: int | None = None,
    initial_gains=(0.0, 0.0),
    n_eval: int = 64,
    **options,
) -> TrainingResult:
    """Learn the two gains of a linear law from episodes of the task (model-free, seeded).

    Each iteration draws ``n_episodes`` fresh initial states and scores every candidate gain
    vector of the iteration on those same states (common random numbers), by running the
    environment's dynamics; the learner never sees the model. Methods:

    * ``"ars"``: basic random search, Mania, Guy and Recht (2018), "Simple random search provides a
      competitive approach to reinforcement learning", algorithm V1-t: ``n_directions``
      antithetic Gaussian perturbations of size ``noise`` (gain units), the ``top`` best kept,
      step ``step / (top sigma_R) sum (R+ - R-) delta`` with ``sigma_R`` the standard deviation of
      the kept returns.
    * ``"cma"``: CMA-ES (Hansen, ``cma`` package) from ``initial_gains`` with step ``sigma0``
      and population ``popsize``; the learner's gains are the distribution mean.

    Parameters
    ----------
    task : OscillatorTask, optional
        Task to learn (default task if omitted).
    seed : int
        Seed of every random draw (initial states, directions, CMA-ES sampling), >= 0.
    method : {"ars", "cma"}
        The learner.
    iterations : int, optional
        Iterations (ARS) or generations (CMA-ES); default 120 (ARS), 60 (CMA-ES).
    n_episodes : int, optional
        Initial states per iteration, shared by its candidates; default 4.
    initial_gains : array_like, shape (2,)
        Starting ``[K_x, K_v]``, N/m and N s/m (default: no control).
    n_eval : int
        Fixed evaluation episodes for the learning curve where the cost is not exact.
    **options
        ``n_directions``, ``top``, ``step``, ``noise`` (ARS) or ``popsize``, ``sigma0`` (CMA-ES).

    Returns
    -------
    TrainingResult
        ``.policy.gains`` are ``[K_x, K_v]`` for ``u_des = -K [x, v]``.

    Examples
    --------
    >>> res = train(seed=0)
    >>> ref = lqr_reference()
    >>> bool(res.expected_cost < 1.001 * ref.expected_cost), res.episodes          # -, 1
    (True, 3200)
    """
    task = _check_task(task)
    seed = check_int("seed", seed, low=0, high=2**32 - 2)
    if not isinstance(method, str) or method not in METHODS:
        raise ParameterError(f"method = {method!r:.60} is not a learner: allowed one of {METHODS}")
    opts = dict(DEFAULTS[method])
    unknown = set(options) - set(opts) - {"iterations", "n_episodes"}
    if unknown:
        raise ParameterError(f"options = {sorted(unknown)!r} are not options of {method}: allowed {sorted(opts)}")
    opts.update(options)
    iters = check_int("iterations", opts["iterations"] if iterations is None else iterations, low=1, high=100_000)
    n_ep = check_int("n_episodes", opts["n_episodes"] if n_episodes is None else n_episodes, low=1, high=100_000)
    n_eval = check_int("n_eval", n_eval, low=1, high=1_000_000)
    theta = _check_gains(initial_gains).copy()
    if method == "ars":
        per_iteration = 2 * check_int("n_directions", opts["n_directions"], low=1, high=10_000)
    else:
        per_iteration = check_int("popsize", opts["popsize"], low=2, high=10_000)
    # every iteration simulates its candidates, and a curve point that is not exact its n_eval episodes
    work = (iters * (per_iteration * n_ep + n_eval) + n_eval) * task.n_steps
    if work > MAX_EPISODE_STEPS:
        raise ParameterError(
            f"iterations = {iters}, n_episodes = {n_ep}, n_eval = {n_eval} with {per_iteration} candidates per "
            f"iteration and n_steps = {task.n_steps} make up to {work} simulated steps: allowed at most "
            f"{MAX_EPISODE_STEPS}"
        )
    train_seq, eval_seq, algo_seq = np.random.SeedSequence([seed, 14]).spawn(3)
    states_rng = np.random.default_rng(train_seq)
    eval_states = sample_initial_states(task, n_eval, np.random.default_rng(eval_seq))
    episodes, gains_hist, costs, exact = [0], [theta.copy()], [], []
    c0, e0 = _curve_point(task, theta, eval_states)
    costs.append(c0)
    exact.append(e0)

    if method == "ars":
        n_dir = check_int("n_directions", opts["n_directions"], low=1, high=10_000)
        top = check_int("top", opts["top"], low=1, high=n_dir)
        step = check_real("step", opts["step"], low=0.0, low_open=True, unit="N/m")
        noise = check_real("noise", opts["noise"], low=0.0, low_open=True, unit="N/m")
        rng = np.random.default_rng(algo_seq)
        for _ in range(iters):
            delta = rng.standard_normal((n_dir, 2))
            cand = np.concatenate([theta + noise * delta, theta - noise * delta])
            states = sample_initial_states(task, n_ep, states_rng)
            ret = -_finite_costs(episode_costs(task, cand, states).mean(axis=1), cand)
            r_plus, r_minus = ret[:n_dir], ret[n_dir:]
            best = np.argsort(-np.maximum(r_plus, r_minus), kind="stable")[:top]
            sigma = float(np.std(np.concatenate([r_plus[best], r_minus[best]])))
            if sigma > 0.0:
                theta = theta + step / (top * sigma) * ((r_plus[best] - r_minus[best]) @ delta[best])
            episodes.append(episodes[-1] + 2 * n_dir * n_ep)
            gains_hist.append(theta.copy())
            c, e = _curve_point(task, theta, eval_states)
            costs.append(c)
            exact.append(e)
    else:
        import cma

        popsize = check_int("popsize", opts["popsize"], low=2, high=10_000)
        sigma0 = check_real("sigma0", opts["sigma0"], low=0.0, low_open=True, unit="N/m")
        es = cma.CMAEvolutionStrategy(
            theta,
            sigma0,
            {"seed": int(algo_seq.generate_state(1)[0]) % (2**31 - 1) + 1, "popsize": popsize, "verbose": -9,
             "tolfun": 0.0, "tolx": 0.0, "tolfunhist": 0.0, "tolflatfitness": 10**9, "tolstagnation": 10**9,
             "maxiter": 10**9, "CMA_diagonal": False},
        )  # fmt: skip
        for _ in range(iters):
            cand = np.asarray(es.ask(), dtype=float)
            states = sample_initial_states(task, n_ep, states_rng)
            es.tell(list(cand), list(_finite_costs(episode_costs(task, cand, states).mean(axis=1), cand)))
            theta = np.asarray(es.mean, dtype=float).copy()
            episodes.append(episodes[-1] + popsize * n_ep)
            gains_hist.append(theta.copy())
            c, e = _curve_point(task, theta, eval_states)
            costs.append(c)
            exact.append(e)
    return TrainingResult(
        policy=LinearPolicy(theta, task),
        method=method,
        seed=seed,
        curve_episodes=np.array(episodes),
        curve_gains=np.array(gains_hist),
        curve_cost=np.array(costs),
        curve_exact=np.array(exact),
    )


# ----------------------------------------------------------------------------- comparisons and checks


@dataclass(frozen=True)
class Comparison:
    """Controllers of one task rolled out on the same seeded episodes.

    ``names[i]`` has gains ``gains[i]`` (``[K_x, K_v]``, N/m and N s/m) and episodes ``runs[i]``;
    ``exact[i]`` is its exact expected cost (s) when the law is linear on the task (force mode,
    bound never reached, or a constant damping), else ``nan``.
    """

    task: OscillatorTask
    names: tuple[str, ...]
    gains: tuple[np.ndarray, ...]
    runs: tuple[Rollouts, ...]
    exact: tuple[float, ...]
    seed: int

    def paired_gain(self, i: int, j: int) -> tuple[float, float]:
        """Mean cost of controller j minus controller i on the same episodes, and its standard error, s."""
        diff = self.runs[j].cost - self.runs[i].cost
        return float(diff.mean()), float(diff.std(ddof=1) / math.sqrt(diff.size)) if diff.size > 1 else 0.0


def compare_controllers(task: OscillatorTask, controllers: dict, n_episodes: int = 1000, seed: int = 0) -> Comparison:
    """Roll every controller (name -> gains) out on the same ``n_episodes`` seeded initial states.

    Examples
    --------
    >>> cmp = compare_controllers(OscillatorTask(), {"LQR": lqr_reference().gains}, n_episodes=8)
    >>> cmp.names, round(cmp.exact[0], 4)                                    # -, s
    (('LQR',), 0.7663)
    """
    task = _check_task(task)
    n_episodes = check_int("n_episodes", n_episodes, low=2, high=MAX_STATES)
    seed = check_int("seed", seed, low=0, high=2**32 - 2)
    if not isinstance(controllers, dict) or not controllers:
        raise ParameterError(f"controllers = {controllers!r:.60} is not a dict: allowed a non-empty {{name: gains}}")
    _check_work(task, len(controllers), n_episodes, MAX_RECORDED_STEPS, "recorded steps")
    states = sample_initial_states(task, n_episodes, np.random.default_rng(np.random.SeedSequence([seed, 14, 1])))
    names, gains, runs, exact = [], [], [], []
    for name, g in controllers.items():
        g = _check_gains(g)
        names.append(str(name))
        gains.append(g)
        runs.append(rollout(task, g, states))
        ex = math.nan
        if task.mode == "force":
            cost, peak = _moments(task, g)
            ex = cost if peak <= task.u_max else math.nan
        elif g[0] == 0.0 and task.c_min <= g[1] <= task.c_max:
            ex = _passive_cost(task, float(g[1]))
        exact.append(ex)
    return Comparison(task, tuple(names), tuple(gains), tuple(runs), tuple(exact), seed)


def verification(task: OscillatorTask, gains) -> dict[str, float]:
    """Residuals of the chapter's numbers against independent methods (all relative, 1).

    * ``lqr_vs_control``: LQR gains against python-control's ``dlqr``;
    * ``riccati``: residual of the discrete Riccati equation, relative to ``|P|``;
    * ``cost_vs_cubature``: exact expected cost of ``gains`` against the 2 x 2 Gauss-Legendre
      cubature of the environment's episode costs (exact for a cost quadratic in ``s_0``);
    * ``env_vs_loop``: one episode of the gymnasium-side step (scipy ``expm``) against the compiled
      loop (closed-form exponential), largest displacement difference relative to ``x0_max``.

    Examples
    --------
    >>> chk = verification(OscillatorTask(), lqr_reference().gains)
    >>> all(v < 1e-9 for v in chk.values())
    True
    """
    import control

    task = replace(_check_task(task), mode="force")
    g = _check_gains(gains)
    ref = lqr_reference(task)
    a_d, b_d = zoh(task)
    k_ctrl = np.ravel(control.dlqr(a_d, b_d[:, None], task.state_weight, task.dt * task.r)[0])
    b = b_d[:, None]
    pa = ref.P @ a_d
    resid = a_d.T @ pa - ref.P - pa.T @ b @ b.T @ pa / (task.dt * task.r + b.T @ ref.P @ b) + task.state_weight
    nodes = np.array([-1.0, 1.0]) / math.sqrt(3.0)
    xs, vs = np.meshgrid(nodes * task.x0_max, nodes * task.v0_max, indexing="ij")
    cub = float(episode_costs(task, g, np.column_stack([xs.ravel(), vs.ravel()])).mean())
    cost, peak = _moments(task, g)
    # one episode with the step map of the environment: expm-based ZOH, force held
    s = np.array([task.x0_max, -task.v0_max])
    d = _increments(task)
    xs_env = np.empty(task.n_steps)
    for i in range(task.n_steps):
        xs_env[i] = s[0]
        u = min(max(-(g[0] * s[0] + g[1] * s[1]), -task.u_max), task.u_max)
        s = a_d @ s + b_d * u + d[i]
    loop = rollout(task, g, [task.x0_max, -task.v0_max]).x[0]
    return {
        "lqr_vs_control": float(np.max(np.abs(ref.gains - k_ctrl)) / np.max(np.abs(k_ctrl))),
        "riccati": float(np.max(np.abs(resid)) / np.max(np.abs(ref.P))),
        "cost_vs_cubature": abs(cost - cub) / cub if peak <= task.u_max else math.nan,
        "env_vs_loop": float(np.max(np.abs(xs_env - loop)) / max(task.x0_max, 1e-300)),
    }
