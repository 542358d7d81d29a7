"""Run the report's chapters with papermill and build them into a book (HTML and PDF).

Usage::

    python -m vibration.report [CHAPTER ...] [-p NAME VALUE ...] [--out DIR]
    python -m vibration.report --list
    python -m vibration.report --in-place      # re-execute notebooks/ (nbval references)

Chapters are the notebooks in ``notebooks/`` (``01_reproduction`` may be given
as ``01``, ``1`` or ``reproduction``). ``-p NAME VALUE`` applies to every
selected chapter that declares NAME; unknown names, values of the wrong type
and values out of range are refused before any kernel starts. Output goes to
``DIR/report`` (HTML, ``index.html``), ``DIR/tables`` (CSV) and
``DIR/notebooks`` (executed copies); it is built in a temporary folder and
moved into place only when every chapter succeeded.
"""

from __future__ import annotations

import argparse
import math
import multiprocessing
import os
import queue
import re
import shutil
import signal
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from ..physics.model import N_POINTS_MAX, ParameterError, check_int, check_real
from ..presentation.tables import TABLES_ENV

KERNEL = "vibration"

#: Allowed ranges of the chapters' parameters: name -> (low, low_open, high, unit).
#: A notebook may declare other names; those are only type-checked here.
PARAMETER_RULES: dict[str, tuple[float | None, bool, float | None, str]] = {
    "m": (1e-3, False, 1e3, "kg"),
    "k": (1e-3, False, 1e6, "N/m"),
    "F0": (0.0, True, 1e4, "N"),
    "t_end": (0.0, True, 1e3, "s"),
    "omega_ref": (0.0, True, 1e3, "rad/s"),
    "omega_res": (0.0, True, 1e3, "rad/s"),
    "c_low": (-1e4, False, 1e4, "N s/m"),
    "c_nominal": (-1e4, False, 1e4, "N s/m"),
    "c_high": (-1e4, False, 1e4, "N s/m"),
    "n_points": (2, False, 200_001, ""),
    "n_omega": (2, False, 2000, ""),
    "n_damping": (2, False, 2000, ""),
    "omega_max": (0.0, True, 1e3, "rad/s"),
    "c_min": (1e-3, False, 1e4, "N s/m"),
    "c_max": (1e-3, False, 1e4, "N s/m"),
    # chapter 06, stability and damping as a design choice
    "c_unstable": (-1e4, False, 0.0, "N s/m"),
    "t_growth": (0.0, True, 2000.0, "s"),
    "isolation_ratio": (1.4142135623730951, True, 100.0, ""),
    "S0": (0.0, True, 1e6, "N² s/rad"),
    "n_paths": (2, False, 5000, ""),
    "seed": (0, False, 2**31 - 1, ""),
    # chapter 09, Duffing oscillator
    "k3_hard": (0.0, True, 1e3, "N/m³"),
    "k3_soft": (-1e3, False, 0.0, "N/m³"),
    "omega_sweep_min": (0.0, True, 1e3, "rad/s"),
    "omega_sweep_max": (0.0, True, 1e3, "rad/s"),
    "n_sweep": (10, False, 400, ""),
    "c_ueda": (0.0, True, 10.0, "N s/m"),
    "F0_ueda": (0.0, True, 100.0, "N"),
    "F0_ueda_periodic": (0.0, True, 100.0, "N"),
    "n_lyapunov": (100, False, 100_000, ""),
    # chapter 10, digital twin
    "F_rms": (0.0, True, 1e4, "N"),
    "f_max": (0.2, False, 1e3, "Hz"),
    "t_record": (0.0, True, 1e4, "s"),
    "noise": (0.0, True, 10.0, ""),
    "runs": (10, False, 500, ""),  # about 65 ms per identification: 500 runs take ~35 s
    "sweep_runs": (5, False, 100, ""),
    "assumption_runs": (10, False, 100, ""),
    "force_noise": (0.0, True, 1.0, ""),
    "colour": (0.0, True, 0.99, ""),
    "cubic": (0.0, True, 1.0, ""),
    "t_monitor": (0.0, True, 1e4, "s"),
    "decline_rate": (0.0, False, 1.0, "1/s"),
    "drop": (0.0, False, 0.9, ""),
    "detect_runs": (5, False, 300, ""),
    "threshold": (0.0, True, 1e6, ""),
    # chapter 11, learning controller (dt also chapter 10's sampling step)
    "dt": (0.0, True, 1.0, "s"),
    "n_steps": (1, False, 3000, ""),
    "r_weight": (0.0, True, 1e6, "1/N²"),
    "u_max": (0.0, True, 1e4, "N"),
    "c_semi_min": (0.0, False, 1e4, "N s/m"),
    "c_semi_max": (0.0, True, 1e4, "N s/m"),
    "n_eval": (2, False, 20_000, ""),
    "n_seeds": (10, False, 30, ""),
    # chapter 07, control ("u_max" is also chapter 11's actuator bound; "n_sweep" also chapter 9's)
    "kp": (0.0, False, 1e4, "N/m"),
    "kd": (0.0, False, 1e3, "N s/m"),
    "pid_kp": (0.0, True, 1e4, "N/m"),
    "pid_ki": (0.0, True, 1e5, "N/(m s)"),
    "pid_kd": (0.0, False, 1e3, "N s/m"),
    "x_ref": (-10.0, False, 10.0, "m"),
    "q_x": (0.0, False, 1e8, "1/m²"),
    "q_v": (0.0, False, 1e8, "s²/m²"),
    "r_lqr": (1e-9, False, 1e4, "1/N²"),
    "c_flutter": (-1e3, False, 0.0, "N s/m"),
    "c_sky": (0.0, False, 1e3, "N s/m"),
    "c_sa_min": (0.0, False, 1e3, "N s/m"),
    "c_sa_max": (0.0, False, 1e4, "N s/m"),
    "f_mr": (0.0, True, 1e3, "N"),
    "move": (-10.0, False, 10.0, "m"),
    "freq_error": (-0.9, False, 2.0, ""),
    # chapter 08, tuned mass dampers
    "mu": (0.0, True, 1.0, ""),
    "mistuning": (0.0, False, 0.5, ""),
    "n_storeys": (1, False, 30, ""),
    "storey_mass": (1e-3, False, 1e9, "kg"),
    "storey_stiffness": (1e-3, False, 1e12, "N/m"),
    "zeta_building": (0.0, False, 0.99, ""),
    "mu_building": (0.0, True, 1.0, ""),
}
#: Most forcing or natural periods the window may hold (the paper's holds 36).
MAX_PERIODS = 1000
#: Largest growth exponent (-c / 2m) t_end of negative damping (e^50 ~ 5e21 stays finite in every table).
MAX_GROWTH = 50.0
#: Largest (c / m) t_end, the stiffness the paper's explicit RK45 is asked to cross (the paper's: 750).
MAX_STIFFNESS = 1e6
assert PARAMETER_RULES["n_points"][2] <= N_POINTS_MAX


def chapter_schemas() -> dict:
    """The parameter schemas of the chapter packages (``vibration.chapters.<name>.params.SCHEMA``), by notebook."""
    import importlib
    import pkgutil

    from .. import chapters

    out = {}
    for info in pkgutil.iter_modules(chapters.__path__):
        if info.ispkg:
            schema = importlib.import_module(f"{chapters.__name__}.{info.name}.params").SCHEMA
            out[schema.notebook] = schema
    return out


def project_root() -> Path:
    """The project folder (holding ``notebooks/``): ``$VIBRATION_ROOT`` or the source checkout."""
    env = os.environ.get("VIBRATION_ROOT")
    return Path(env) if env else Path(__file__).resolve().parents[3]


@dataclass(frozen=True)
class Chapter:
    """One notebook of the report."""

    path: Path  # source notebook
    params: dict  # papermill's inspection: name -> {inferred_type_name, default, help}

    @property
    def name(self) -> str:
        """File stem, e.g. ``01_reproduction``."""
        return self.path.stem

    def matches(self, key: str) -> bool:
        """Whether ``key`` names this chapter (stem, number or stem without number)."""
        num, _, rest = self.name.partition("_")
        return key in (self.name, rest) or (key.isdigit() and num.isdigit() and int(key) == int(num))


def discover(root: Path | None = None) -> list[Chapter]:
    """All chapters in ``notebooks/``, sorted by file name."""
    import papermill

    folder = (root or project_root()) / "notebooks"
    paths = sorted(p for p in folder.glob("*.ipynb") if not p.name.startswith("."))
    return [Chapter(p, papermill.inspect_notebook(str(p))) for p in paths]


def select(chapters: list[Chapter], keys: list[str]) -> list[Chapter]:
    """The chapters named by ``keys`` (all when empty), in report order."""
    if not keys:
        return chapters
    chosen = []
    for key in keys:
        hits = [c for c in chapters if c.matches(key)]
        if not hits:
            names = ", ".join(c.name for c in chapters)
            raise ParameterError(f"chapter {key!r} does not exist: allowed {names}")
        chosen += [c for c in hits if c not in chosen]
    return [c for c in chapters if c in chosen]


def _convert(name: str, text: str, type_name: str):
    """Parse ``text`` as the declared type of parameter ``name``."""
    text = text.strip()
    if type_name == "int":
        try:
            return int(text)
        except ValueError:
            raise ParameterError(f"{name} = {text!r} is not an integer: allowed an integer") from None
    if type_name == "float":
        try:
            value = float(text)
        except ValueError:
            raise ParameterError(f"{name} = {text!r} is not a number: allowed a real number") from None
        if not math.isfinite(value):
            raise ParameterError(f"{name} = {text!r} is not finite: allowed a finite real number")
        return value
    if type_name == "bool":
        low = text.lower()
        if low not in ("true", "false", "1", "0"):
            raise ParameterError(f"{name} = {text!r} is not a boolean: allowed true or false")
        return low in ("true", "1")
    if len(text) >= 2 and text[0] == text[-1] and text[0] in "'\"":  # a quoted literal, as notebooks write them
        return text[1:-1]
    return text


def check_parameters(chapters: list[Chapter], pairs: list[tuple[str, str]]) -> dict[str, object]:
    """Validate ``-p NAME VALUE`` pairs against the chapters' declarations and the rules.

    Returns the typed values. Raises :class:`ParameterError` naming the
    parameter, its value and what is allowed.
    """
    schemas = chapter_schemas()
    declared: dict[str, str] = {}
    for ch in chapters:
        for name, info in ch.params.items():
            declared.setdefault(name, info.get("inferred_type_name") or "str")
    values: dict[str, object] = {}
    for name, text in pairs:
        if name not in declared:
            allowed = ", ".join(sorted(declared))
            raise ParameterError(
                f"parameter {name!r} (value {text!r}) is not declared by any chapter run: allowed {allowed}"
            )
        value = _convert(name, text, declared[name])
        for schema in (schemas[ch.name] for ch in chapters if ch.name in schemas and name in ch.params):
            schema.check({name: value})  # the chapter package's own range: one source per chapter
        if name in PARAMETER_RULES:
            low, low_open, high, unit = PARAMETER_RULES[name]
            if declared[name] == "int":
                check_int(name, value, low=int(low), high=int(high))
            else:
                check_real(name, value, low=low, low_open=low_open, high=high, unit=unit)
        values[name] = value
    _check_together(chapters, values)
    for ch in chapters:
        if ch.name in schemas:  # the chapter's rules that tie several of its parameters together
            schemas[ch.name].check({k: v for k, v in values.items() if k in ch.params})
    return values


#: Pairs of parameters that bound a range: (lower, upper, unit); the upper must exceed the lower.
ORDERED = (
    ("c_min", "c_max", "N s/m"),
    ("c_sa_min", "c_sa_max", "N s/m"),
    ("c_semi_min", "c_semi_max", "N s/m"),
    ("omega_sweep_min", "omega_sweep_max", "rad/s"),
)
#: Fewest samples an identification record may hold (t_record / dt).
MIN_RECORD_SAMPLES = 200


def _check_together(chapters: list[Chapter], values: dict) -> None:
    """Limits that involve several parameters, on the values each chapter would use (its defaults and ``-p``)."""
    for ch in chapters:
        _check_chapter_together({**_defaults(ch), **{k: v for k, v in values.items() if k in ch.params}})


def _check_chapter_together(p: dict) -> None:
    get = p.get
    for low, high, unit in ORDERED:
        if low in p and high in p and not p[high] > p[low]:
            raise ParameterError(f"{high} = {p[high]!r} {unit} must exceed {low} = {p[low]!r} {unit}")
    f_max, dt, t_record = get("f_max"), get("dt"), get("t_record")
    if f_max is not None and dt is not None and not f_max < 0.5 / dt:
        raise ParameterError(
            f"f_max = {f_max!r} Hz is not below the Nyquist frequency 1/(2 dt) = {0.5 / dt:.4g} Hz of dt = {dt!r} s: "
            f"allowed f_max < {0.5 / dt:.4g} Hz"
        )
    if t_record is not None and dt is not None and t_record / dt < MIN_RECORD_SAMPLES:
        raise ParameterError(
            f"t_record = {t_record!r} s holds {t_record / dt:.3g} samples of dt = {dt!r} s: allowed at least "
            f"{MIN_RECORD_SAMPLES} samples (t_record >= {MIN_RECORD_SAMPLES * dt:.4g} s)"
        )
    m, k, t_end = get("m"), get("k"), get("t_end")
    if None in (m, k, t_end):
        return
    if all(n in p for n in ("pid_kp", "pid_ki", "pid_kd", "c_nominal")):  # chapter 7's PID loop, before a kernel
        from ..physics.control import pid_work_check
        from ..physics.model import Oscillator

        try:
            pid_work_check(Oscillator(m, p["c_nominal"], k), p["pid_kp"], p["pid_ki"], p["pid_kd"], t_end,
                           get("omega_res") or 0.0)  # fmt: skip
        except ParameterError as exc:
            gains = f"pid_kp = {p['pid_kp']!r}, pid_ki = {p['pid_ki']!r}, pid_kd = {p['pid_kd']!r}"
            raise ParameterError(f"{gains} with m = {m!r} kg, k = {k!r} N/m: {exc}") from None
    fastest = max([math.sqrt(k / m)] + [w for w in map(get, ("omega_ref", "omega_res", "omega_max")) if w])
    periods = fastest * t_end / (2 * math.pi)
    if periods > MAX_PERIODS:
        raise ParameterError(
            f"t_end = {t_end!r} s holds {periods:.0f} periods of the fastest frequency ({fastest:.4g} rad/s, "
            f"from m = {m!r} kg, k = {k!r} N/m and the forcing): allowed at most {MAX_PERIODS}"
        )
    dampings = [x for x in map(get, ("c_low", "c_nominal", "c_high")) if x is not None]
    for name in ("c_low", "c_nominal", "c_high"):
        c = get(name)
        if c is not None and c < 0 and -c / (2 * m) * t_end > MAX_GROWTH:
            raise ParameterError(
                f"{name} = {c!r} N s/m with m = {m!r} kg over t_end = {t_end!r} s: the negative damping grows the "
                f"response like exp({-c / (2 * m) * t_end:.3g}): allowed (-c/2m) t_end at most {MAX_GROWTH:g}"
            )
    c = max([abs(x) for x in dampings] or [0.0])  # the ones RK45 meets
    if c / m * t_end > MAX_STIFFNESS:
        raise ParameterError(
            f"c = {c!r} N s/m with m = {m!r} kg over t_end = {t_end!r} s: (c/m) t_end = {c / m * t_end:.3g} "
            f"is out of range: allowed at most {MAX_STIFFNESS:g} (the paper's explicit RK45 would crawl)"
        )


def _defaults(ch: Chapter) -> dict:
    """The chapter's numeric defaults, as papermill read them from its parameters cell."""
    import ast

    out = {}
    for name, info in ch.params.items():
        try:
            value = ast.literal_eval(info.get("default", ""))
        except (ValueError, SyntaxError):
            continue
        if isinstance(value, int | float) and not isinstance(value, bool):
            out[name] = value
    return out


def kernel_name() -> str:
    """The project's kernel if installed (``make setup`` installs it), else ``python3``."""
    from jupyter_client.kernelspec import KernelSpecManager

    return KERNEL if KERNEL in KernelSpecManager().find_kernel_specs() else "python3"


#: Kernel arguments: the runner's output carries no kernel log lines, such as the warning
#: that the kernel talks over TCP on the loopback interface, or the "KeyboardInterrupt caught"
#: an idle kernel logs at ERROR when its client interrupts it before every shutdown. A cell's
#: error still reaches the runner through papermill.
KERNEL_ARGS = ["--IPKernelApp.log_level=CRITICAL"]
#: Longest a single cell may run, s: a last resort that a run within the parameters' ranges never meets
#: (the longest cell of the default run takes about 10 s). A cell that exceeds it fails its chapter,
#: naming the chapter and the cell; a kernel message that never arrives becomes this failure, not a hang.
CELL_TIMEOUT_S = 180


class CellTimeout(RuntimeError):
    """A chapter's cell ran longer than :data:`CELL_TIMEOUT_S`."""


def _execute(
    source: Path, output: Path, params: dict, kernel: str, tables: str | None, cell_timeout: float = CELL_TIMEOUT_S
) -> float:
    """Execute one notebook with papermill; runs in its own process. Returns the seconds it took.

    One process per notebook: jupyter clients sharing a process can lose a kernel
    message, and papermill's ``cwd`` changes the working directory of the whole
    process. SIGTERM (the pool's terminate) kills this process's kernel too: jupyter
    starts kernels in a session of their own, where a stopped runner would leave them
    computing.
    """
    import logging

    import papermill

    signal.signal(signal.SIGTERM, _kill_children_and_exit)
    for name in ("papermill", "traitlets", "nbclient"):
        logging.getLogger(name).setLevel(logging.ERROR)
    if tables is None:  # the kernel inherits the environment (a forked worker may predate this run)
        os.environ.pop(TABLES_ENV, None)
    else:
        os.environ[TABLES_ENV] = tables
    start = time.perf_counter()
    try:
        papermill.execute_notebook(
            str(source),
            str(output),
            parameters=params,
            kernel_name=kernel,
            cwd=str(source.parent),
            progress_bar=False,
            log_output=False,
            execution_timeout=cell_timeout,
            extra_arguments=KERNEL_ARGS,
        )
    except TimeoutError as exc:
        raise CellTimeout(
            f"{_cell_preview(str(exc))} ran longer than the runner's limit of {cell_timeout:g} s"
        ) from None
    return time.perf_counter() - start


def _cell_preview(message: str) -> str:
    """The timed-out cell's first line, from nbclient's message (which quotes the cell between dashed lines,
    a long cell as the list of its first and last lines).

    >>> _cell_preview("A cell timed out.\\n-------------------\\nstudy = run(a)\\nx = 1\\n-------------------\\n")
    'the cell starting "study = run(a)"'
    >>> _cell_preview("A cell timed out.\\n-------------------\\n['import numba', '']\\n...\\n-------------------\\n")
    'the cell starting "import numba"'
    """
    import ast

    parts = message.split("-------------------\n")
    lines = parts[1].strip().splitlines() if len(parts) > 2 else []
    if lines and lines[0].startswith("["):
        try:
            lines = [ln for ln in ast.literal_eval(lines[0]) if ln.strip()]
        except (ValueError, SyntaxError):
            pass
    return f'the cell starting "{lines[0]}"' if lines else "a cell the message does not quote"


def _kill_children_and_exit(signum, frame):
    """SIGTERM in a pool worker: kill the kernel (and anything else it started), then exit."""
    import psutil

    children = psutil.Process().children(recursive=True)
    for child in children:
        try:
            child.kill()
        except psutil.NoSuchProcess:
            pass
    psutil.wait_procs(children, timeout=5)
    os._exit(143)


def notebook_pool(jobs: int = 2):
    """A pool that runs each notebook in its own process, forked from a server that imported papermill once.

    Leaving its ``with`` block terminates what still runs (a failed chapter, Ctrl-C, SIGTERM): each worker
    kills its kernel on the way out.
    """
    ctx = multiprocessing.get_context("forkserver")
    ctx.set_forkserver_preload(["papermill", __name__])
    return ctx.Pool(processes=max(1, jobs), maxtasksperchild=1)


def execute_notebooks(runs: list[tuple[Path, Path, dict]], jobs: int = 2, kernel: str | None = None) -> list[float]:
    """Execute ``(source, output, parameters)`` runs with papermill, ``jobs`` at a time; seconds each, in order."""
    kernel = kernel or kernel_name()
    with notebook_pool(jobs) as pool:
        pending = [
            pool.apply_async(_execute, (Path(src), Path(out), dict(params), kernel, None)) for src, out, params in runs
        ]
        return [p.get() for p in pending]


def chapter_parameters(ch: Chapter, values: dict) -> list:
    """The chapter's declared parameters with the values this run used (for the book)."""
    import ast

    from ..physics.paper import paper_defaults
    from .book import Parameter, differs, split_help

    paper = paper_defaults()
    out = []
    for name, info in ch.params.items():
        try:
            default = ast.literal_eval(info.get("default", ""))
        except (ValueError, SyntaxError):
            default = info.get("default")
        meaning, unit = split_help(info.get("help", ""))
        is_paper = name in paper and not differs(default, paper[name])
        out.append(Parameter(name, values.get(name, default), default, meaning, unit, is_paper))
    return out


def _plural(n: int, word: str) -> str:
    return f"{n} {word}" if n == 1 else f"{n} {word}s"


def run(
    chapters: list[Chapter],
    values: dict,
    out: Path,
    jobs: int = 2,
    log=print,
    pdf: bool = True,
    cell_timeout: float = CELL_TIMEOUT_S,
    cache: bool = True,
) -> list[dict]:
    """Execute ``chapters`` with papermill and build the book into ``out`` (replaced only on success).

    A chapter whose notebook, parameter values, imported modules, data and environment are those of a
    cached run (``out/cache``) is not executed again; the runner says which chapters ran and why.
    """
    import logging

    import grimp
    import nbformat

    from .book import ChapterPage
    from .book import build as build_book
    from .cache import ChapterCache

    out = out.resolve()  # kernels run in notebooks/: every path they get must be absolute
    out.mkdir(parents=True, exist_ok=True)
    work = Path(tempfile.mkdtemp(prefix=".report-", dir=out))
    for name in ("papermill", "traitlets", "nbclient", "sphinx"):
        logging.getLogger(name).setLevel(logging.ERROR)
    store = ChapterCache(out / "cache")
    try:
        for sub in ("notebooks", "report", "tables", "tables-of"):
            (work / sub).mkdir()
        kernel = kernel_name()
        total = len(chapters)
        t0 = time.perf_counter()
        graph = grimp.build_graph("vibration", cache_dir=None)
        results, manifests, todo = {}, {}, []
        for ch in chapters:
            params = {k: v for k, v in values.items() if k in ch.params}
            manifests[ch.name] = _manifest(ch, params, graph)
            found = store.lookup(ch.name, manifests[ch.name]) if cache else None
            if found is not None and found.hit:
                store.restore(ch.name, work / "notebooks" / ch.path.name, work / "tables")
                results[ch.name] = {"executed": work / "notebooks" / ch.path.name, "elapsed_s": found.elapsed_s}
                log(f"[cached] {ch.name}: nothing it depends on changed")
            else:
                why = _why(found.reasons) if found is not None else "the cache is off"
                todo.append((ch, params, why))
        finished: queue.Queue = queue.Queue()  # (chapter, seconds or None, exception or None)
        with notebook_pool(jobs) as pool:
            for ch, params, why in todo:
                (work / "tables-of" / ch.name).mkdir()
                args = (ch.path, work / "notebooks" / ch.path.name, params)
                pool.apply_async(
                    _execute,
                    (*args, kernel, str(work / "tables-of" / ch.name), cell_timeout),
                    callback=lambda res, ch=ch: finished.put((ch, res, None)),
                    error_callback=lambda exc, ch=ch: finished.put((ch, None, exc)),
                )
                log(f"[start] {ch.name}: {why}")
            for _ in todo:
                ch, res, exc = finished.get()
                if exc is not None:  # a chapter failed: report it, keep the old tree (the pool stops the others)
                    raise RuntimeError(f"chapter {ch.name} failed: {_short(exc)}") from exc
                executed, tables = work / "notebooks" / ch.path.name, work / "tables-of" / ch.name
                for path in tables.iterdir():
                    shutil.copy2(path, work / "tables" / path.name)
                store.store(ch.name, manifests[ch.name], executed, tables, res)
                results[ch.name] = {"executed": executed, "elapsed_s": res}
                log(f"[{len(results)}/{total}] {ch.name} done in {res:.1f} s")
        t_run = time.perf_counter() - t0
        pages = [
            ChapterPage(
                ch.name,
                nbformat.read(results[ch.name]["executed"], as_version=4),
                chapter_parameters(ch, values),
                results[ch.name]["elapsed_s"],
            )
            for ch in chapters
        ]
        t1 = time.perf_counter()
        info = build_book(pages, work / "report", work / "book", pdf=pdf)
        shutil.rmtree(work / "book", ignore_errors=True)
        pdf_text = f", PDF {_plural(info['pdf_pages'], 'page')}" if "pdf_pages" in info else ""
        log(f"book: built in {time.perf_counter() - t1:.1f} s{pdf_text}")
        for sub in ("notebooks", "report", "tables"):
            target = out / sub
            if target.exists():
                target.rename(work / f"old-{sub}")
            (work / sub).rename(target)
        ran = len(todo)
        log(
            f"report: {_plural(ran, 'chapter')} executed and {total - ran} reused from the cache in {t_run:.1f} s, "
            f"{time.perf_counter() - t0:.1f} s in all -> {out / 'report' / 'index.html'}"
        )
        return [{"name": p.name, "title": p.title, "elapsed_s": p.elapsed_s} for p in pages]
    finally:
        shutil.rmtree(work, ignore_errors=True)


def _manifest(ch: Chapter, params: dict, graph) -> dict[str, str]:
    from .cache import manifest

    return manifest(ch.path, params, ch.path.parent.parent, graph)


def _why(reasons: tuple[str, ...]) -> str:
    """The first reasons a chapter runs again, e.g. "src/vibration/presentation/tmd.py changed"."""
    shown = ", ".join(reasons[:3])
    return shown + (f" and {len(reasons) - 3} more" if len(reasons) > 3 else "")


def book_from_sources(chapters: list[Chapter], out: Path, pdf: bool = True) -> dict:
    """Build the book from the committed notebooks as they are (their stored outputs), no kernel.

    For checking the publishing stack quickly (tests, previews); ``make report`` executes.
    """
    import nbformat

    from .book import ChapterPage
    from .book import build as build_book

    out = Path(out).resolve()
    out.parent.mkdir(parents=True, exist_ok=True)
    work = Path(tempfile.mkdtemp(prefix=".book-", dir=out.parent))
    try:
        pages = [
            ChapterPage(ch.name, nbformat.read(ch.path, as_version=4), chapter_parameters(ch, {})) for ch in chapters
        ]
        return build_book(pages, out, work, pdf=pdf)
    finally:
        shutil.rmtree(work, ignore_errors=True)


def _short(exc: Exception) -> str:
    """``Name: message`` of the error a chapter raised (papermill keeps both)."""
    name, value = getattr(exc, "ename", None), getattr(exc, "evalue", None)
    if name:
        return f"{name}: {value}"
    lines = [ln for ln in str(exc).splitlines() if ln.strip()]
    return lines[-1].strip() if lines else type(exc).__name__


def execute_in_place(chapters: list[Chapter], log=print) -> None:
    """Re-execute the source notebooks and store their outputs (the nbval references).

    Uses nbclient directly, so no papermill timestamps enter the committed files.
    """
    import nbformat
    from nbclient import NotebookClient

    kernel = kernel_name()
    for ch in chapters:
        start = time.perf_counter()
        nb = nbformat.read(ch.path, as_version=4)
        NotebookClient(
            nb,
            kernel_name=kernel,
            timeout=CELL_TIMEOUT_S,
            extra_arguments=KERNEL_ARGS,
            record_timing=False,
            resources={"metadata": {"path": str(ch.path.parent)}},
        ).execute()
        nb.metadata.pop("widgets", None)
        for cell in nb.cells:
            cell.metadata.pop("execution", None)
        nbformat.write(nb, ch.path)
        log(f"{ch.name} re-executed in {time.perf_counter() - start:.1f} s")


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m vibration.report", description=__doc__.split("\n\n")[0])
    parser.add_argument("chapters", nargs="*", help="chapters to run (default: all)")
    parser.add_argument(
        "-p",
        "--parameter",
        nargs=2,
        action="append",
        default=[],
        metavar=("NAME", "VALUE"),
        help="set a parameter in every chapter that declares it",
    )
    parser.add_argument("--out", default="build", help="output folder (default: build)")
    parser.add_argument("--jobs", type=int, default=2, help="chapters run at once (default: 2)")
    parser.add_argument("--no-pdf", action="store_true", help="skip the PDF (faster previews)")
    parser.add_argument(
        "--no-cache", action="store_true", help="execute every chapter, even those whose inputs did not change"
    )
    parser.add_argument("--list", action="store_true", help="list chapters and their parameters")
    parser.add_argument(
        "--new-chapter", metavar="NN_topic", help="write a new chapter from the template (package, notebook, test)"
    )
    parser.add_argument("--in-place", action="store_true", help="re-execute notebooks/ in place (no parameters)")
    args = parser.parse_args(_protect_negative_values(sys.argv[1:] if argv is None else list(argv)))
    previous = signal.signal(signal.SIGTERM, _terminate)
    try:
        if args.new_chapter:
            from .template import new_chapter

            for path in new_chapter(args.new_chapter, project_root()):
                print(f"wrote {path.relative_to(project_root())}")
            return 0
        chapters = select(discover(), args.chapters)
        if args.list:
            for ch in chapters:
                print(ch.name)
                for name, info in ch.params.items():
                    print(f"  {name}: {info['inferred_type_name']} = {info['default']}  # {info['help']}")
            return 0
        if args.in_place:
            if args.parameter:
                raise ParameterError("--in-place re-executes the references with their defaults: -p is not allowed")
            execute_in_place(chapters)
            return 0
        values = check_parameters(chapters, [tuple(p) for p in args.parameter])
        run(chapters, values, Path(args.out).resolve(), jobs=args.jobs, pdf=not args.no_pdf, cache=not args.no_cache)
    except ParameterError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    except RuntimeError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("interrupted: the previous output was left as it was", file=sys.stderr)
        return 130
    finally:
        signal.signal(signal.SIGTERM, previous)
    return 0


def _protect_negative_values(argv: list[str]) -> list[str]:
    """``-p c_low -2e4``: argparse would read ``-2e4`` as an option; a leading space keeps it a value.

    Examples
    --------
    >>> _protect_negative_values(["-p", "c_low", "-2e4", "01"])
    ['-p', 'c_low', ' -2e4', '01']
    >>> _protect_negative_values(["-p", "m", "--no-pdf"])  # a missing value stays missing
    ['-p', 'm', '--no-pdf']
    """
    out = list(argv)
    for i in range(2, len(out)):
        if out[i - 2] in ("-p", "--parameter") and _NEGATIVE.match(out[i]):
            out[i] = " " + out[i]
    return out


#: A negative number (``-2``, ``-2.5e4``, ``-.5``, ``-inf``): an option such as ``--no-pdf`` is not one.
_NEGATIVE = re.compile(r"^-(\d|\.\d|inf|nan)", re.IGNORECASE)


def _terminate(signum, frame):
    """SIGTERM ends the run like Ctrl-C, so the temporary folder is removed."""
    raise KeyboardInterrupt


if __name__ == "__main__":
    sys.exit(main())
