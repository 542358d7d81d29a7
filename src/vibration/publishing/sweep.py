"""Parameter sweeps: a chapter's study at every point of a grid, gathered into one labelled xarray Dataset.

Usage::

    python -m vibration.report sweep CHAPTER -g NAME START:STOP:N [-g NAME START:STOP:Nlog] [-g NAME V1,V2,...]
        [-p NAME VALUE] [--jobs N | --scheduler ADDRESS] [--resume] --out DIR

Each point runs the chapter's study (the pure function of its parameter record declared in the
chapter's ``keyresults.py``, not the notebook) as a task on a Dask cluster and returns the chapter's
key results; only the client writes ``DIR``. The whole grid is checked against the chapter's schema
before any task starts (the parameter is named when a value, or a combination with the fixed
values, is refused). A point whose study fails becomes NaN, its message in the ``error`` variable.

``DIR`` gets ``grid.json`` (what is swept) and ``points.jsonl`` (one line per finished point,
appended as points finish, so Ctrl-C or SIGTERM keeps them and ``--resume`` computes only the
missing ones, refusing a grid that differs from the stored one), then ``sweep.nc`` (netCDF, CF
units and long names), ``sweep.csv`` (long form: one row per point and result), a figure per key
result (a line for one swept parameter, a map for two) and ``summary.md``. The finished files are
written to temporary names and renamed, so none is ever half-written.

The Python API is :func:`sweep` (``vibration.sweep``).
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import itertools
import json
import math
import os
import signal
import subprocess
import sys
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..physics.model import ParameterError
from .cli import convert, protect_negative_values, terminate
from .engine import announce
from .registry import chapter_packages, project_root

#: Most points one sweep may have (a budget: a mistyped N cannot queue a billion tasks).
MAX_POINTS = 1_000_000
#: Version of the files in DIR (grid.json, points.jsonl): a resume refuses another.
FORMAT = 1


# ------------------------------------------------------------------------------ the grid


@dataclass(frozen=True, kw_only=True)
class Axis:
    """One swept parameter: its name and values (in its schema's unit), and whether they are log-spaced."""

    name: str
    values: tuple
    log: bool = False


@dataclass(frozen=True, kw_only=True)
class Grid:
    """A validated sweep: the chapter's package, its swept axes and its fixed values (all checked)."""

    chapter: str  # notebook stem, e.g. "09_duffing"
    package: str  # vibration.chapters.<package>
    axes: tuple[Axis, ...]
    fixed: dict  # parameter -> value, every parameter not swept (the schema's defaults where not given)

    @property
    def shape(self) -> tuple[int, ...]:
        return tuple(len(a.values) for a in self.axes)

    @property
    def size(self) -> int:
        return math.prod(self.shape)

    def points(self):
        """``(index, values)`` of every point, ``values`` a full parameter mapping, in C order."""
        for index in itertools.product(*(range(n) for n in self.shape)):
            yield index, self.fixed | {a.name: a.values[i] for a, i in zip(self.axes, index, strict=True)}

    def describe(self) -> dict:
        """The grid as JSON-able data (``grid.json``; a resume compares it)."""
        return {
            "format": FORMAT,
            "chapter": self.chapter,
            "axes": [{"name": a.name, "values": list(a.values), "log": a.log} for a in self.axes],
            "fixed": self.fixed,
        }


def _is_int(param) -> bool:
    return isinstance(param.default, int) and not isinstance(param.default, bool)


def parse_values(param, spec: str) -> Axis:
    """``START:STOP:N`` (linear), ``START:STOP:Nlog`` (geometric) or ``V1,V2,...`` for ``param`` (a schema Param).

    Examples
    --------
    >>> from vibration.presentation.schema import Param
    >>> w = Param(name="omega", symbol="ω", default=1.0, unit="rad/s", low=0.0, high=10.0, meaning="frequency")
    >>> parse_values(w, "1:2:3").values, parse_values(w, "1:4:3log").values, parse_values(w, "0.5, 2").values
    ((1.0, 1.5, 2.0), (1.0, 2.0, 4.0), (0.5, 2.0))
    >>> parse_values(Param(name="n", symbol="n", default=3, unit="", low=1, high=99, meaning="count"), "1:4:3").values
    Traceback (most recent call last):
    ...
    vibration.physics.model.ParameterError: n grid 1:4:3 gives 2.5, not an integer: allowed integer values on an \
integer grid (e.g. 1:5:3)
    """

    name, text = param.name, spec.strip()
    type_name = "int" if _is_int(param) else "float" if isinstance(param.default, float) else "str"
    if not text:
        raise ParameterError(f"{name} grid {spec!r} is empty: allowed START:STOP:N, START:STOP:Nlog or V1,V2,...")
    parts = text.split(":")
    if len(parts) == 3 and type_name != "str":
        start, stop = (convert(name, s, "float") for s in parts[:2])
        count, log = parts[2].strip(), parts[2].strip().lower().endswith("log")
        count = count[:-3] if log else count
        try:
            n = int(count)
        except ValueError:
            raise ParameterError(f"{name} grid {spec!r}: N = {count!r} is not an integer: allowed N >= 1") from None
        if n < 1:
            raise ParameterError(f"{name} grid {spec!r} is empty (N = {n}): allowed N >= 1")
        if n > MAX_POINTS:
            raise ParameterError(f"{name} grid {spec!r} has N = {n}: allowed N <= {MAX_POINTS}")
        if log:
            if not (start > 0 and stop > 0):
                raise ParameterError(
                    f"{name} grid {spec!r} is logarithmic from {start:g} to {stop:g}: allowed START > 0 and STOP > 0"
                )
            raw = np.geomspace(start, stop, n) if n > 1 else np.array([start])
        else:
            raw = np.linspace(start, stop, n) if n > 1 else np.array([start])
        if type_name == "int":
            if log:
                raw = np.round(raw)
            bad = [v for v in raw if abs(v - round(v)) > 1e-9 * max(1.0, abs(v))]
            if bad:
                raise ParameterError(
                    f"{name} grid {spec} gives {bad[0]:g}, not an integer: allowed integer values on an integer grid "
                    f"(e.g. {int(start)}:{int(start) + 2 * max(1, n - 1)}:{n})"
                )
            values = tuple(int(round(v)) for v in raw)
        else:
            values = tuple(float(v) for v in raw)
    else:
        values = tuple(convert(name, s, type_name) for s in text.split(",") if s.strip())
        if not values:
            raise ParameterError(f"{name} grid {spec!r} is empty: allowed START:STOP:N, START:STOP:Nlog or V1,V2,...")
        log = False
    if len(set(values)) != len(values):
        raise ParameterError(f"{name} grid {spec!r} repeats a value ({values}): allowed distinct values")
    return Axis(name=name, values=tuple(param.check(v) for v in values), log=log)


def _resolve(chapter: str) -> tuple[str, str]:
    """(notebook stem, package) of a chapter named by stem, number or topic, that declares key results."""

    packages = chapter_packages()
    found = None
    for stem, pkg in packages.items():
        num, _, rest = stem.partition("_")
        key = str(chapter)
        if key in (stem, rest, pkg) or (key.isdigit() and num.isdigit() and int(key) == int(num)):
            found = (stem, pkg)
            break
    swept = [s for s, p in packages.items() if _key_results(p) is not None]
    if found is None:
        raise ParameterError(f"chapter {chapter!r} does not exist: allowed {', '.join(swept)}")
    if _key_results(found[1]) is None:
        raise ParameterError(
            f"chapter {chapter!r} declares no key results (vibration.chapters.{found[1]}.keyresults): allowed "
            f"{', '.join(swept)}"
        )
    return found


def _key_results(package: str):
    try:
        module = importlib.import_module(f"vibration.chapters.{package}.keyresults")
    except ModuleNotFoundError as exc:
        if exc.name == f"vibration.chapters.{package}.keyresults":
            return None
        raise
    return module.KEY_RESULTS


def _schema(package: str):
    return importlib.import_module(f"vibration.chapters.{package}.params").SCHEMA


def make_grid(chapter: str, grid: Mapping[str, Sequence | str], params: Mapping | None = None) -> Grid:
    """Validate a sweep before anything runs: every value, and every point together with the fixed values.

    ``grid`` maps a parameter to its values (a sequence, or a ``START:STOP:N[log]`` / ``V1,V2`` string);
    ``params`` fixes others (typed values or strings). Raises :class:`ParameterError` naming the
    parameter: unknown, swept twice or also fixed, out of range, an empty grid, or a combination the
    schema's rules refuse.
    """

    stem, package = _resolve(chapter)
    schema = _schema(package)
    names = schema.names()
    if not grid:
        raise ParameterError("the grid is empty: allowed at least one -g NAME VALUES of " + ", ".join(names))
    axes = []
    for name, spec in grid.items():
        if name not in names:
            raise ParameterError(f"parameter {name!r} is not one of {stem}'s: allowed {', '.join(names)}")
        param = schema[name]
        if isinstance(spec, str):
            axes.append(parse_values(param, spec))
            continue
        values = tuple(np.asarray(spec).tolist()) if not isinstance(spec, (list, tuple)) else tuple(spec)
        if not values:
            raise ParameterError(f"{name} grid is empty: allowed one or more values")
        if len(set(values)) != len(values):
            raise ParameterError(f"{name} grid repeats a value ({values}): allowed distinct values")
        if _is_int(param):
            bad = [v for v in values if isinstance(v, bool) or float(v) != int(float(v))]
            if bad:
                raise ParameterError(f"{name} = {bad[0]!r} is not an integer: allowed an integer grid")
            values = tuple(int(v) for v in values)
        axes.append(Axis(name=name, values=tuple(param.check(v) for v in values)))
    fixed_in = {}
    for name, value in (params or {}).items():
        if name not in names:
            raise ParameterError(
                f"parameter {name!r} (value {value!r}) is not one of {stem}'s: allowed {', '.join(names)}"
            )
        if name in grid:
            raise ParameterError(f"parameter {name!r} is both swept and fixed: allowed one of -g {name} or -p {name}")
        param = schema[name]
        if isinstance(value, str) and not param.choices:
            value = convert(name, value, "int" if _is_int(param) else "float")
        fixed_in[name] = param.check(value)
    fixed = schema.defaults() | schema.check(fixed_in)
    for a in axes:
        fixed.pop(a.name)
    g = Grid(chapter=stem, package=package, axes=tuple(axes), fixed=fixed)
    if g.size > MAX_POINTS:
        raise ParameterError(f"the grid has {g.size} points: allowed at most {MAX_POINTS}")
    for _, values in g.points():  # the rules that tie parameters together, at every point
        schema.check({k: v for k, v in values.items() if k in {a.name for a in axes} | set(fixed_in)})
    return g


# ------------------------------------------------------------------------------ one point (a task)


@dataclass(frozen=True, kw_only=True)
class PointTask:
    """One point of a sweep, by value: the chapter's package and every parameter."""

    package: str
    index: tuple[int, ...]
    values: dict


def run_point(task: PointTask) -> dict:
    """The chapter's study at one point, on a worker: its key results, or NaN and the error's message."""

    announce(f"point {task.index}")
    keys = _key_results(task.package)
    params = importlib.import_module(f"vibration.chapters.{task.package}.params").Params
    start = time.perf_counter()
    try:
        study = keys.study(params(**task.values))
        values, error = keys.values(study), ""
    except Exception as exc:  # a failed point is data (NaN and its message), never the end of the sweep
        values = dict.fromkeys(keys.names(), math.nan)
        error = f"{type(exc).__name__}: {exc}".splitlines()[0][:500]
    return {"index": list(task.index), "values": values, "error": error, "elapsed_s": time.perf_counter() - start}


# ------------------------------------------------------------------------------ the sweep


class Store:
    """A sweep's folder: the grid, the points as they finish, and the finished files."""

    def __init__(self, folder: Path):
        self.folder = Path(folder)
        self.grid_file = self.folder / "grid.json"
        self.points_file = self.folder / "points.jsonl"

    def start(self, grid: Grid, resume: bool) -> dict[tuple, dict]:
        """Prepare the folder; on ``resume``, the points already done (refusing a different grid)."""
        self.folder.mkdir(parents=True, exist_ok=True)
        wanted = grid.describe()
        if resume:
            if not self.grid_file.is_file():
                raise ParameterError(f"--resume: {self.grid_file} does not exist: allowed a folder a sweep wrote")
            stored = json.loads(self.grid_file.read_text(encoding="utf-8"))
            if stored != json.loads(json.dumps(wanted)):
                diff = [k for k in wanted if stored.get(k) != json.loads(json.dumps(wanted[k]))]
                raise ParameterError(
                    f"--resume: the grid differs from the one stored in {self.grid_file} (in {', '.join(diff)}): "
                    "allowed the same chapter, axes and fixed values, or another --out"
                )
            return self.done()
        for name in ("points.jsonl", "grid.json", "sweep.nc", "sweep.csv", "summary.md"):
            (self.folder / name).unlink(missing_ok=True)
        _atomic_text(self.grid_file, json.dumps(wanted, indent=1))
        return {}

    def done(self) -> dict[tuple, dict]:
        out = {}
        if self.points_file.is_file():
            for line in self.points_file.read_text(encoding="utf-8").splitlines():
                try:
                    rec = json.loads(line)
                except ValueError:  # a line cut short by a kill: that point runs again
                    continue
                out[tuple(rec["index"])] = rec
        return out

    def add(self, rec: dict) -> None:
        with self.points_file.open("a", encoding="utf-8") as f:
            f.write(json.dumps(rec, allow_nan=True) + "\n")
            f.flush()
            os.fsync(f.fileno())


def _atomic_text(path: Path, text: str) -> None:
    tmp = path.with_name(f".{path.name}.part")
    tmp.write_text(text, encoding="utf-8")
    tmp.replace(path)


def _compute(grid: Grid, todo: list, client, on_point: Callable[[dict], None], progress) -> None:
    """Run the points of ``todo`` on ``client`` (None: serially, in this process), calling ``on_point`` as each ends."""
    tasks = [PointTask(package=grid.package, index=tuple(i), values=v) for i, v in todo]
    if client is None:
        for task in tasks:
            on_point(run_point(task))
            progress(1)
        return
    from distributed import as_completed

    token = f"{os.getpid()}-{time.time_ns()}"
    futures = [client.submit(run_point, t, key=f"point-{grid.chapter}-{t.index}-{token}", pure=False) for t in tasks]
    restarts = getattr(client, "restarts", None)
    try:
        for future in as_completed(futures):
            on_point(future.result())
            progress(1)
            if restarts is not None:
                for line in restarts.drain():
                    progress.write(line)
    finally:
        client.cancel(futures)


class _Progress:
    """A tqdm bar on stderr (or nothing)."""

    def __init__(self, total: int, done: int, show: bool):
        self.bar = None
        if show:
            from tqdm import tqdm

            self.bar = tqdm(total=total, initial=done, unit="point", file=sys.stderr, dynamic_ncols=True)

    def __call__(self, n: int) -> None:
        if self.bar is not None:
            self.bar.update(n)

    def write(self, line: str) -> None:
        if self.bar is not None:
            self.bar.write(line, file=sys.stderr)
        else:
            print(line, file=sys.stderr)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()


def sweep(
    chapter: str,
    grid: Mapping[str, Sequence | str],
    *,
    params: Mapping | None = None,
    client=None,
    jobs: int = 2,
    out: Path | str | None = None,
    resume: bool = False,
    progress: bool = False,
    serial: bool = False,
):
    """Run a chapter's study over a grid of parameters and gather its key results into an xarray Dataset.

    Parameters
    ----------
    chapter : str
        The chapter: notebook stem, number or topic (``"09"``, ``"duffing"``); it must declare key results.
    grid : mapping
        Swept parameter -> its values (in the schema's unit), or a ``"START:STOP:N"``, ``"START:STOP:Nlog"``
        or ``"V1,V2"`` string.
    params : mapping, optional
        Fixed values of other parameters (the rest keep the schema's defaults).
    client : distributed.Client, optional
        Where the points run; None: a LocalCluster of ``jobs`` single-threaded workers, started and closed here.
    out : path, optional
        A folder to write (``grid.json``, ``points.jsonl``, ``sweep.nc``, ``sweep.csv``, figures, ``summary.md``).
    resume : bool
        Compute only the points missing from ``out`` (whose grid must be the same).
    serial : bool
        Run the points one after the other in this process (no cluster; for comparisons).

    Returns
    -------
    xarray.Dataset
        One dimension per swept parameter, one variable per key result (CF ``units`` and ``long_name``),
        ``error`` (the message of a failed point, "" otherwise), fixed values, version and commit as attributes.

    Raises
    ------
    ParameterError
        A grid or fixed value the chapter's schema refuses (named), before any point runs.
    """
    g = make_grid(chapter, grid, params)
    store = Store(Path(out)) if out is not None else None
    done = store.start(g, resume) if store is not None else {}
    if resume and store is None:
        raise ParameterError("resume = True needs out: allowed a folder a sweep wrote")
    results = dict(done)
    todo = [(i, v) for i, v in g.points() if i not in done]

    def on_point(rec: dict) -> None:
        results[tuple(rec["index"])] = rec
        if store is not None:
            store.add(rec)

    bar = _Progress(g.size, len(done), progress)
    try:
        if todo:
            if serial:
                _compute(g, todo, None, on_point, bar)
            elif client is not None:
                _compute(g, todo, client, on_point, bar)
            else:
                from .engine import cluster

                with cluster(jobs) as local:
                    _compute(g, todo, local, on_point, bar)
    finally:
        bar.close()
    ds = dataset(g, results)
    if store is not None:
        write_outputs(ds, g, store.folder)
    return ds


# ------------------------------------------------------------------------------ the dataset and its files


def _cf_unit(unit: str) -> str:
    return unit if unit else "1"


def project_commit() -> str:
    """The project's git commit (``unknown`` outside a checkout), with ``+changes`` when the tree differs."""

    try:
        root = project_root()
        head = subprocess.run(["git", "rev-parse", "HEAD"], cwd=root, capture_output=True, text=True, timeout=10)
        if head.returncode:
            return "unknown"
        dirty = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no"], cwd=root,
                               capture_output=True, text=True, timeout=10)  # fmt: skip
        return head.stdout.strip() + ("+changes" if dirty.stdout.strip() else "")
    except (OSError, ParameterError, subprocess.SubprocessError):
        return "unknown"


def dataset(grid: Grid, results: Mapping[tuple, dict]):
    """The sweep's xarray Dataset from the points' records (missing points NaN with error "not computed")."""
    import xarray as xr

    import vibration

    schema, keys = _schema(grid.package), _key_results(grid.package)
    shape = grid.shape
    data = {r.name: np.full(shape, np.nan) for r in keys.results}
    errors = np.full(shape, "not computed", dtype=object)
    for index, rec in results.items():
        for name in data:
            data[name][index] = rec["values"].get(name, math.nan)
        errors[index] = rec.get("error", "")
    dims = tuple(a.name for a in grid.axes)
    coords = {}
    for a in grid.axes:
        p = schema[a.name]
        coords[a.name] = xr.Variable(
            a.name,
            np.asarray(a.values),
            attrs={
                "units": _cf_unit(p.unit),
                "long_name": p.meaning or p.name,
                "spacing": "logarithmic" if a.log else "as given",
            },  # fmt: skip
        )
    variables = {
        r.name: xr.Variable(dims, data[r.name], attrs={"units": _cf_unit(r.unit), "long_name": r.meaning})
        for r in keys.results
    }
    variables["error"] = xr.Variable(
        dims, errors.astype(str), attrs={"long_name": "error message of a failed point (empty when it succeeded)"}
    )
    attrs = {
        "Conventions": "CF-1.8",
        "title": f"sweep of chapter {grid.chapter}",
        "chapter": grid.chapter,
        "package_version": vibration.__version__,
        "commit": project_commit(),
        "fixed_parameters": ", ".join(grid.fixed),
    }
    for name, value in grid.fixed.items():
        attrs[f"param_{name}"] = int(value) if isinstance(value, bool) else value
        unit = schema[name].unit
        if unit:
            attrs[f"param_{name}_units"] = unit
    return xr.Dataset(variables, coords=coords, attrs=attrs)


def write_outputs(ds, grid: Grid, folder: Path) -> list[Path]:
    """``sweep.nc``, ``sweep.csv``, one figure per key result and ``summary.md`` in ``folder`` (each atomic)."""
    folder = Path(folder)
    written = []
    nc, tmp = folder / "sweep.nc", folder / ".sweep.nc.part"
    ds.to_netcdf(tmp, engine="h5netcdf")
    tmp.replace(nc)
    written.append(nc)
    written.append(_write_csv(ds, grid, folder / "sweep.csv"))
    written += _write_figures(ds, grid, folder)
    _atomic_text(folder / "summary.md", summary(ds, grid, [p.name for p in written if p.suffix == ".png"]))
    written.append(folder / "summary.md")
    return written


def _write_csv(ds, grid: Grid, path: Path) -> Path:
    import csv

    keys = _key_results(grid.package)
    tmp = path.with_name(f".{path.name}.part")
    dims = [a.name for a in grid.axes]
    with tmp.open("w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow([*dims, "result", "value", "unit", "error"])
        for index in itertools.product(*(range(n) for n in grid.shape)):
            coords = [a.values[i] for a, i in zip(grid.axes, index, strict=True)]
            error = str(ds["error"].values[index])
            for r in keys.results:
                value = float(ds[r.name].values[index])
                w.writerow([*coords, r.name, repr(value) if math.isfinite(value) else "nan", _cf_unit(r.unit), error])
    tmp.replace(path)
    return path


def _label(ds, name: str) -> str:
    attrs = ds[name].attrs
    unit = attrs.get("units", "")
    return f"{attrs.get('long_name', name)} ({unit})" if unit and unit != "1" else attrs.get("long_name", name)


def _write_figures(ds, grid: Grid, folder: Path) -> list[Path]:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    keys = _key_results(grid.package)
    out = []
    first = [a for a in grid.axes if len(a.values) > 1][:2] or list(grid.axes[:1])
    rest = {a.name: 0 for a in grid.axes if a not in first}
    for r in keys.results:
        da = ds[r.name].isel(rest) if rest else ds[r.name]
        fig, ax = plt.subplots(figsize=(6.0, 4.0), layout="constrained")
        if len(first) == 1:
            a = first[0]
            ax.plot(ds[a.name].values, da.values, "o-", ms=3, lw=1.0, color="k")
            ax.set_xlabel(_label(ds, a.name))
            ax.set_ylabel(_label(ds, r.name))
            if a.log:
                ax.set_xscale("log")
        else:
            ax_x, ax_y = first[1], first[0]  # rows: the first swept parameter, columns: the second
            mesh = ax.pcolormesh(ds[ax_x.name].values, ds[ax_y.name].values, da.transpose(ax_y.name, ax_x.name).values,
                                 shading="nearest", cmap="viridis")  # fmt: skip
            fig.colorbar(mesh, ax=ax, label=_label(ds, r.name))
            ax.set_xlabel(_label(ds, ax_x.name))
            ax.set_ylabel(_label(ds, ax_y.name))
            ax.set_xscale("log" if ax_x.log else "linear")
            ax.set_yscale("log" if ax_y.log else "linear")
        held = ", ".join(f"{k} = {ds[k].values[0]:g}" for k in rest)
        ax.set_title(f"{grid.chapter}: {r.name}" + (f" at {held}" if held else ""), fontsize=9)
        path, tmp = folder / f"{r.name}.png", folder / f".{r.name}.png.part"
        fig.savefig(tmp, format="png", dpi=110)
        plt.close(fig)
        tmp.replace(path)
        out.append(path)
    return out


def summary(ds, grid: Grid, figures: Sequence[str] = ()) -> str:
    """A short Markdown page: what was swept, the range of each result and where its extremes are, failures."""
    keys = _key_results(grid.package)
    errors = ds["error"].values
    failed = int(np.sum(errors != ""))
    missing = int(np.sum(errors == "not computed"))
    lines = [f"# Sweep of chapter {grid.chapter}", ""]
    lines.append(f"{grid.size} points; {failed - missing} failed, {missing} not computed.")
    lines.append("")
    lines.append("| swept | values | unit |")
    lines.append("| --- | --- | --- |")
    for a in grid.axes:
        vals = a.values
        shown = ", ".join(f"{v:g}" if isinstance(v, float) else str(v) for v in vals[:3])
        shown += f", ... {vals[-1]:g}" if len(vals) > 3 and isinstance(vals[-1], float) else ""
        lines.append(f"| {a.name} | {len(vals)} values: {shown}{' (log)' if a.log else ''} | "
                     f"{ds[a.name].attrs['units']} |")  # fmt: skip
    lines += ["", "| result | unit | smallest | at | largest | at |", "| --- | --- | --- | --- | --- | --- |"]
    for r in keys.results:
        v = ds[r.name].values
        if np.all(np.isnan(v)):
            lines.append(f"| {r.name} | {_cf_unit(r.unit)} | – | – | – | – |")
            continue
        lo, hi = np.unravel_index(np.nanargmin(v), v.shape), np.unravel_index(np.nanargmax(v), v.shape)

        def at(index) -> str:
            return ", ".join(f"{a.name} = {a.values[i]:g}" for a, i in zip(grid.axes, index, strict=True))

        lines.append(f"| {r.name} | {_cf_unit(r.unit)} | {v[lo]:.6g} | {at(lo)} | {v[hi]:.6g} | {at(hi)} |")
    lines += ["", "Fixed: " + ", ".join(f"{k} = {v}" for k, v in grid.fixed.items()) + "."]
    lines += [f"commit {ds.attrs['commit']}, vibration {ds.attrs['package_version']}."]
    lines += [""] + [f"![{f}]({f})" for f in figures]
    if failed - missing:
        first = next(str(e) for e in errors.flat if e not in ("", "not computed"))
        lines += ["", f"First failure: {first}"]
    return "\n".join(lines) + "\n"


# ------------------------------------------------------------------------------ the command


def main(argv: list[str] | None = None) -> int:
    """``python -m vibration.report sweep ...``: see the module's docstring."""

    parser = argparse.ArgumentParser(prog="python -m vibration.report sweep", description=__doc__.split("\n\n")[0])
    parser.add_argument("chapter", help="the chapter (stem, number or topic), one that declares key results")
    parser.add_argument("-g", "--grid", nargs=2, action="append", default=[], metavar=("NAME", "VALUES"),
                        help="a swept parameter: START:STOP:N, START:STOP:Nlog or V1,V2,...")  # fmt: skip
    parser.add_argument("-p", "--parameter", nargs=2, action="append", default=[], metavar=("NAME", "VALUE"),
                        help="a fixed parameter")  # fmt: skip
    parser.add_argument("--out", required=True, help="the sweep's folder")
    parser.add_argument("--jobs", type=int, default=2, help="workers of the local Dask cluster (default: 2)")
    parser.add_argument("--scheduler", metavar="ADDRESS", help="run on this Dask scheduler instead")
    parser.add_argument("--resume", action="store_true", help="compute only the points missing from --out")
    parser.add_argument("--no-progress", action="store_true", help="no progress bar")
    args = parser.parse_args(protect_negative_values(list(sys.argv[2:] if argv is None else argv)))
    previous = signal.signal(signal.SIGTERM, terminate)
    out = Path(args.out).resolve()
    grid = {}
    try:
        for name, spec in args.grid:
            if name in grid:
                raise ParameterError(f"parameter {name!r} is swept twice: allowed one -g {name}")
            grid[name] = spec.strip()
        params = dict((n, v.strip()) for n, v in args.parameter)
        start = time.perf_counter()
        with contextlib.ExitStack() as stack:
            client = None
            if args.scheduler:
                from .engine import cluster

                make_grid(args.chapter, grid, params)  # refused before connecting to anything
                client = stack.enter_context(cluster(args.jobs, args.scheduler))
            ds = sweep(args.chapter, grid, params=params, client=client, jobs=args.jobs, out=out,
                       resume=args.resume, progress=not args.no_progress)  # fmt: skip
        failed = int(np.sum(ds["error"].values != ""))
        print(f"sweep: {ds['error'].size} points ({failed} failed) in {time.perf_counter() - start:.1f} s -> "
              f"{out / 'sweep.nc'}")  # fmt: skip
    except ParameterError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        kept = len(Store(out).done()) if out.is_dir() else 0
        print(f"interrupted: {kept} finished points kept in {out}; --resume computes the rest", file=sys.stderr)
        return 130
    finally:
        signal.signal(signal.SIGTERM, previous)
    return 0


__all__ = ["Axis", "Grid", "make_grid", "sweep", "dataset", "write_outputs", "run_point"]
