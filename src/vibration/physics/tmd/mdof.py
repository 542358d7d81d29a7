"""General linear MDOF structures: the record, modes, classical damping, frequency and time responses."""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.linalg as sla

from ..checks import check_array
from ..model import ParameterError, check_real
from ._limits import ENTRIES_MAX, ENTRY_MAX, ENTRY_MIN, N_DOF_MAX, SYM_TOL, WORK_MAX


class DampingNotClassical(ParameterError):
    """The damping matrix is not uncoupled by the undamped modes: modal damping ratios do not exist."""


@dataclass(frozen=True, kw_only=True)
class MDOFResponse:
    """Response of an :class:`MDOF` model on a time grid."""

    t: np.ndarray  # time, s, shape (n_t,)
    x: np.ndarray  # displacements, m, shape (n_t, n)
    v: np.ndarray  # velocities, m/s, shape (n_t, n)


def _matrix(name: str, A, n: int | None) -> np.ndarray:
    arr = check_array(name, A, ndim=(0, 2), max_size=N_DOF_MAX * N_DOF_MAX)
    if arr.ndim == 0 and n in (None, 1):
        arr = arr.reshape(1, 1)
    if arr.ndim != 2 or arr.shape[0] != arr.shape[1] or arr.shape[0] == 0:
        raise ParameterError(f"{name} has shape {arr.shape}: allowed a square matrix (n, n), 1 <= n <= {N_DOF_MAX}")
    if n is not None and arr.shape[0] != n:
        raise ParameterError(f"{name} has shape {arr.shape}: allowed ({n}, {n}), the shape of M")
    if arr.shape[0] > N_DOF_MAX:
        raise ParameterError(f"{name} has {arr.shape[0]} rows: allowed 1 <= n <= {N_DOF_MAX}")
    if not np.all(np.isfinite(arr)):
        raise ParameterError(f"{name} = {arr.tolist()!r} has non-finite entries: allowed finite entries")
    mag = np.abs(arr[arr != 0.0])
    if mag.size and not (mag.min() >= ENTRY_MIN and mag.max() <= ENTRY_MAX):
        bad = float(mag.min()) if mag.min() < ENTRY_MIN else float(mag.max())
        raise ParameterError(
            f"{name} has an entry of magnitude {bad!r}: allowed entries 0 or {ENTRY_MIN:g} <= |{name}_ij| <= "
            f"{ENTRY_MAX:g} (SI units)"
        )
    scale = float(np.max(np.abs(arr))) if arr.size else 0.0
    asym = float(np.max(np.abs(arr - arr.T)))
    if asym > SYM_TOL * scale:
        raise ParameterError(
            f"{name} is not symmetric (max |{name} - {name}ᵀ| = {asym:.3g}): allowed a symmetric matrix"
        )
    arr = 0.5 * (arr + arr.T)
    arr.setflags(write=False)
    return arr


def _positive_definite(name: str, A: np.ndarray, semi: bool = False) -> None:
    try:
        w = np.linalg.eigvalsh(A)
    except np.linalg.LinAlgError:
        raise ParameterError(
            f"{name}: its eigenvalues do not converge in floating point: allowed a symmetric matrix whose entries "
            f"span fewer than about 1e100"
        ) from None
    scale = max(float(np.max(np.abs(w))), np.finfo(float).tiny)
    ok = w.min() >= -SYM_TOL * scale if semi else w.min() > 0.0
    if not ok:
        what = "positive semi-definite" if semi else "positive definite"
        raise ParameterError(f"{name} has eigenvalue {w.min():.6g} (smallest): allowed a symmetric {what} matrix")


@dataclass(frozen=True, eq=False, kw_only=True)
class MDOF:
    """Linear structure M x'' + C x' + K x = F(t), SI units.

    Parameters
    ----------
    M : array_like
        Mass matrix, kg, symmetric positive definite (n, n).
    C : array_like
        Viscous damping matrix, N s/m, symmetric positive semi-definite (n, n).
    K : array_like
        Stiffness matrix, N/m, symmetric positive definite (n, n).

    Examples
    --------
    >>> s = MDOF(M=[[1.0, 0], [0, 1.0]], C=[[0.0, 0], [0, 0.0]], K=[[2.0, -1.0], [-1.0, 2.0]])
    >>> s.natural_frequencies.round(6).tolist()             # rad/s
    [1.0, 1.732051]
    >>> s.modal_damping_ratios.tolist()
    [0.0, 0.0]
    """

    M: np.ndarray  # mass matrix, kg
    C: np.ndarray  # damping matrix, N s/m
    K: np.ndarray  # stiffness matrix, N/m

    def __post_init__(self) -> None:
        M = _matrix("M", self.M, None)
        n = M.shape[0]
        C, K = _matrix("C", self.C, n), _matrix("K", self.K, n)
        _positive_definite("M", M)
        _positive_definite("K", K)
        _positive_definite("C", C, semi=True)
        object.__setattr__(self, "M", M)
        object.__setattr__(self, "C", C)
        object.__setattr__(self, "K", K)

    @property
    def n(self) -> int:
        """Number of degrees of freedom."""
        return self.M.shape[0]

    @cached_property
    def _eig(self):
        try:
            w2, phi = sla.eigh(self.K, self.M)  # phiᵀ M phi = I
        except (np.linalg.LinAlgError, ValueError):
            raise ParameterError(
                "M and K: the generalised eigenproblem K φ = ω² M φ does not converge in floating point: allowed "
                "M and K whose entries span fewer than about 1e100"
            ) from None
        w = np.sqrt(np.maximum(w2, 0.0))
        if self.is_classically_damped:  # rotate within repeated frequencies so that phiᵀ C phi is diagonal
            i = 0
            while i < len(w):
                j = i + 1
                while j < len(w) and w[j] - w[i] <= 1e-9 * max(w[j], 1e-300):
                    j += 1
                if j - i > 1:
                    block = phi[:, i:j].T @ self.C @ phi[:, i:j]
                    _, rot = np.linalg.eigh(0.5 * (block + block.T))
                    phi[:, i:j] = phi[:, i:j] @ rot
                i = j
        big = np.argmax(np.abs(phi), axis=0)  # sign: largest component of each mode positive
        phi = phi * np.sign(phi[big, np.arange(phi.shape[1])])
        w.setflags(write=False)
        phi.setflags(write=False)
        return w, phi

    @property
    def natural_frequencies(self) -> np.ndarray:
        """Undamped natural frequencies ω_i, rad/s, ascending."""
        return self._eig[0]

    @property
    def modes(self) -> np.ndarray:
        """Mass-normalised mode shapes as columns (Φᵀ M Φ = I, 1/sqrt(kg)); largest entry of each positive."""
        return self._eig[1]

    @cached_property
    def classical_mismatch(self) -> float:
        """Caughey and O'Kelly's test: ||C M⁻¹ K − K M⁻¹ C|| / (||C|| ||M⁻¹|| ||K||), 1 (0 when classical)."""
        Minv = np.linalg.inv(self.M)
        a = self.C @ Minv @ self.K
        norm = np.linalg.norm(self.C, 2) * np.linalg.norm(Minv, 2) * np.linalg.norm(self.K, 2)
        return 0.0 if norm == 0.0 else float(np.linalg.norm(a - a.T, 2) / norm)

    @property
    def is_classically_damped(self) -> bool:
        """Whether the undamped modes uncouple C (C M⁻¹ K = K M⁻¹ C to 1e-10 relative)."""
        return self.classical_mismatch <= SYM_TOL

    @property
    def damping_note(self) -> str:
        """One sentence saying whether modal damping ratios exist."""
        if self.is_classically_damped:
            return "The damping is classical: the undamped modes uncouple it, and each mode has a damping ratio."
        return (
            f"The damping is not classical (C M⁻¹K ≠ K M⁻¹C, relative mismatch {self.classical_mismatch:.2g}): "
            "the undamped modes do not uncouple it, so modal damping ratios do not exist; "
            "the complex poles give each mode's decay instead."
        )

    @property
    def modal_damping_ratios(self) -> np.ndarray:
        """ζ_i = (Φᵀ C Φ)_ii / (2 ω_i), 1; raises :class:`DampingNotClassical` when they do not exist."""
        if not self.is_classically_damped:
            raise DampingNotClassical(
                f"C: {self.damping_note} Allowed: C with C M⁻¹K = K M⁻¹C (e.g. Rayleigh or modal damping)"
            )
        w, phi = self._eig
        c = np.einsum("ij,ik,kj->j", phi, self.C, phi)
        with np.errstate(divide="ignore", invalid="ignore"):
            return np.where(w > 0.0, c / (2.0 * w), np.inf)

    @cached_property
    def state_matrix(self) -> np.ndarray:
        """First-order matrix A of z' = A z + [0; M⁻¹ F], z = [x; v], 1/s blocks."""
        n = self.n
        Minv = np.linalg.inv(self.M)
        A = np.zeros((2 * n, 2 * n))
        A[:n, n:] = np.eye(n)
        A[n:, :n] = -Minv @ self.K
        A[n:, n:] = -Minv @ self.C
        A.setflags(write=False)
        return A

    @property
    def poles(self) -> np.ndarray:
        """Eigenvalues λ of the state matrix, rad/s, sorted by |λ| (complex modes; exist for any damping)."""
        lam = np.linalg.eigvals(self.state_matrix)
        return lam[np.lexsort((lam.imag, np.abs(lam)))]

    def _load(self, load) -> np.ndarray:
        p = check_array("load", load, ndim=(0, 1, 2), max_size=N_DOF_MAX, unit="N").reshape(-1)
        if p.shape != (self.n,):
            raise ParameterError(f"load = {np.asarray(load).tolist()!r}: allowed {self.n} finite force amplitudes, N")
        return p

    def frf(self, omegas, load) -> np.ndarray:
        """Complex amplitudes X (m) of the steady response to ``load * sin(ω t)``.

        X = (K − ω² M + iω C)⁻¹ load, so that x(t) = Re X sin(ωt) + Im X cos(ωt)
        and |X| is the amplitude; with a unit load it is the receptance, m/N.

        Parameters
        ----------
        omegas : float or array_like
            Forcing frequencies, rad/s (>= 0).
        load : array_like
            Force amplitude on each degree of freedom, N, shape (n,).

        Returns
        -------
        numpy.ndarray
            Complex, shape (len(omegas), n), m; ``inf`` where K − ω² M + iω C is singular.

        Examples
        --------
        >>> s = MDOF(M=[[1.0]], C=[[0.5]], K=[[20.0]])
        >>> round(float(abs(s.frf([4.47], [5.0])[0, 0])), 4)     # the paper's resonance amplitude, m
        2.2371
        """
        p = self._load(load)
        w = np.atleast_1d(check_array("omegas", omegas, low=0.0, ndim=(0, 1), unit="rad/s"))
        if not w.size * self.n**3 <= WORK_MAX:
            raise ParameterError(
                f"omegas has {w.size} frequencies: with n = {self.n} degrees of freedom that is "
                f"{w.size * self.n**3:.3g} units of n³ work, allowed at most {WORK_MAX:g} "
                f"(len(omegas) <= {int(WORK_MAX // self.n**3)})"
            )
        out = np.empty((w.size, self.n), dtype=complex)
        for i in range(w.size):
            with np.errstate(over="ignore", invalid="ignore"):
                D = self.K - (w[i] * w[i]) * self.M + 1j * w[i] * self.C
            if not np.all(np.isfinite(D)):
                raise ParameterError(
                    f"omegas contains {w[i]!r} rad/s: the dynamic stiffness K - ω² M + iω C overflows there; "
                    "allowed frequencies at which it is finite"
                )
            try:
                out[i] = np.linalg.solve(D, p)
            except np.linalg.LinAlgError:
                out[i] = np.inf
        return out

    def response(self, t, load, omega, *, x0=None, v0=None, method="auto") -> MDOFResponse:
        """Exact response to ``load * sin(omega t)`` from x(0) = x0, v(0) = v0.

        "modal": steady state from the complex solve (:meth:`frf`) plus the free
        response exp(A t) z_h(0) by complex modal superposition of the state
        matrix A (its eigenvectors V, exp(A t) = V exp(Λ t) V⁻¹). "expm": the
        matrix exponential of the first-order system augmented with the two
        states of the harmonic load, valid also at an undamped resonance
        (secular growth). "auto" uses "modal" unless V is ill-conditioned
        (cond > 1e8, near-defective, e.g. critical damping) or the dynamic
        stiffness is near-singular (cond > 1e10), then "expm".

        Parameters
        ----------
        t : array_like
            Times, s (finite, >= 0, any order).
        load : array_like
            Force amplitudes, N, shape (n,).
        omega : float
            Forcing frequency, rad/s (>= 0).
        x0, v0 : array_like, optional
            Initial displacements (m) and velocities (m/s); rest by default.
        method : {"auto", "modal", "expm"}

        Returns
        -------
        MDOFResponse
            ``x`` (m) and ``v`` (m/s), shape (len(t), n).

        Examples
        --------
        >>> s = MDOF(M=[[1.0]], C=[[0.5]], K=[[20.0]])
        >>> r = s.response([0.0, 50.0], [5.0], 4.47)
        >>> round(float(r.x[0, 0]), 12), round(float(r.x[1, 0]), 4)
        (0.0, 2.009)
        """
        p, omega, t, z0 = self._response_inputs(t, load, omega, x0, v0, method)
        if method != "expm":
            with np.errstate(over="ignore", invalid="ignore"):
                D = self.K - omega * omega * self.M + 1j * omega * self.C
            if not np.all(np.isfinite(D)):
                raise ParameterError(
                    f"omega = {omega!r} rad/s: the dynamic stiffness K - ω² M + iω C overflows; allowed a smaller omega"
                )
            lam, V = np.linalg.eig(self.state_matrix)
            well = np.linalg.cond(V) <= 1e8 and np.linalg.cond(D) <= 1e10
            if well or method == "modal":
                return self._modal_response(t, p, omega, z0, D, lam, V)
        return self._expm_response(t, p, omega, z0)

    def _response_inputs(self, t, load, omega, x0, v0, method):
        """:meth:`response`'s arguments checked in its order: ``(load, omega, t, z0)``, ``z0 = [x0; v0]``."""
        p = self._load(load)
        omega = check_real("omega", omega, low=0.0, unit="rad/s")
        t = np.atleast_1d(check_array("t", t, low=0.0, ndim=(0, 1), unit="s"))
        n = self.n
        if not t.size * 2 * n <= ENTRIES_MAX:
            raise ParameterError(
                f"t has {t.size} samples: with n = {n} degrees of freedom the response has {t.size * 2 * n} entries, "
                f"allowed at most {ENTRIES_MAX} (memory)"
            )
        z0 = np.zeros(2 * n)
        if x0 is not None:
            z0[:n] = self._state("x0", x0)
        if v0 is not None:
            z0[n:] = self._state("v0", v0)
        if method not in ("auto", "modal", "expm"):
            raise ParameterError(f"method = {method!r} is not known: allowed 'auto', 'modal', 'expm'")
        return p, omega, t, z0

    def _modal_response(self, t, p, omega, z0, D, lam, V) -> MDOFResponse:
        """Steady state from the complex solve with the dynamic stiffness ``D`` plus the free response by complex
        modal superposition of the state matrix (eigenvalues ``lam``, eigenvectors ``V``)."""
        n = self.n
        try:
            with np.errstate(all="ignore"):  # a non-finite result is refused below
                X = np.linalg.solve(D, p)
                st, ct = np.sin(omega * t), np.cos(omega * t)
                xs = np.outer(st, X.real) + np.outer(ct, X.imag)
                vs = omega * (np.outer(ct, X.real) - np.outer(st, X.imag))
                zh0 = z0 - np.concatenate([X.imag, omega * X.real])
                q0 = np.linalg.solve(V, zh0.astype(complex))
                zh = ((np.exp(np.outer(t, lam)) * q0) @ V.T).real
                x, v = xs + zh[:, :n], vs + zh[:, n:]
        except np.linalg.LinAlgError:
            raise ParameterError(
                f"omega = {omega!r} rad/s is a natural frequency of the undamped model: the modal method has "
                "no steady state there; allowed method='expm' or 'auto' (secular growth)"
            ) from None
        return _finite_response(MDOFResponse(t=t, x=x, v=v))

    def _expm_response(self, t, p, omega, z0) -> MDOFResponse:
        """The matrix exponential of the first-order system augmented with the harmonic load's two states."""
        n = self.n
        Minv_p = np.linalg.solve(self.M, p)
        Aa = np.zeros((2 * n + 2, 2 * n + 2))
        Aa[: 2 * n, : 2 * n] = self.state_matrix
        Aa[n : 2 * n, 2 * n] = Minv_p  # load * s, with s = sin(ω t), c = cos(ω t)
        Aa[2 * n, 2 * n + 1] = omega  # s' = ω c
        Aa[2 * n + 1, 2 * n] = -omega  # c' = −ω s
        za = np.concatenate([z0, [0.0, 1.0]])
        if not t.size * (2 * n + 2) ** 3 <= WORK_MAX:
            raise ParameterError(
                f"t has {t.size} samples: the matrix exponential of size {2 * n + 2} at each is "
                f"{t.size * (2 * n + 2) ** 3:.3g} units of work, allowed at most {WORK_MAX:g} "
                f"(len(t) <= {int(WORK_MAX // (2 * n + 2) ** 3)} here)"
            )
        with np.errstate(all="ignore"):  # a non-finite result is refused below
            z = sla.expm(Aa[None] * t[:, None, None]) @ za
        return _finite_response(MDOFResponse(t=t, x=z[:, :n], v=z[:, n : 2 * n]))

    def _state(self, name: str, value) -> np.ndarray:
        a = check_array(name, value, ndim=(0, 1, 2), max_size=N_DOF_MAX).reshape(-1)
        if a.shape != (self.n,):
            raise ParameterError(f"{name} = {np.asarray(value).tolist()!r}: allowed {self.n} finite values")
        return a


def _finite_response(r: MDOFResponse) -> MDOFResponse:
    if not (np.all(np.isfinite(r.x)) and np.all(np.isfinite(r.v))):
        bad = float(r.t[~(np.all(np.isfinite(r.x), axis=1) & np.all(np.isfinite(r.v), axis=1))][0])
        raise ParameterError(
            f"t contains {bad!r} s: the response is not finite there (overflow, or a load at an undamped "
            "resonance the modal method cannot represent: use method='expm'); allowed times where it is finite"
        )
    return r
