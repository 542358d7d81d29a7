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

The Python API is :func:`sweep` (``vibration.sweep``). The grid is :mod:`~vibration.book.publishing.sweep_grid`,
the Dataset and its files :mod:`~vibration.book.publishing.sweep_output`; this module runs the points.
"""

from __future__ import annotations

import argparse
import contextlib
import importlib
import json
import math
import os
import signal
import sys
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ...physics.model import ParameterError
from .cli import protect_negative_values, terminate
from .engine import announce
from .sweep_grid import FORMAT as FORMAT  # the grid and the files, importable from here as before
from .sweep_grid import MAX_POINTS as MAX_POINTS
from .sweep_grid import Axis, Grid, chapter_key_results, make_grid
from .sweep_grid import parse_values as parse_values
from .sweep_output import atomic_text, dataset, write_outputs
from .sweep_output import project_commit as project_commit
from .sweep_output import summary as summary

__all__ = ["Axis", "Grid", "make_grid", "sweep", "dataset", "write_outputs", "run_point"]


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
    keys = chapter_key_results(task.package)
    params = importlib.import_module(f"vibration.book.chapters.{task.package}.params").Params
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
        atomic_text(self.grid_file, json.dumps(wanted, indent=1))
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
