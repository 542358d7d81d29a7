"""Benchmarks, reported as ratios of medians measured side by side in one run.

``python -m vibration.bench [--quick] [--skip-report]`` (``make bench``). Nothing here asserts
a time: the tables are for reading. Targets (from the issues):

* ``exact_response`` on 5001 points: >= 200x faster than RK45 at SciPy's defaults and
  >= 3000x faster than RK45 at rtol 1e-9 (issue 15; was 50x and 1000x), with its cost
  per sample reported against one ``np.exp`` over the grid;
* ``peak_displacement_map`` 200 x 200 x 5001: >= 1000x faster than the per-cell
  ``solve_ivp`` loop a user would write;
* slider update with 5001 samples: <= 30 ms median, against rebuilding the figure (chapter 5's bench);
* ``make report``: <= 2x the time papermill needs for as many empty notebooks (cold), a run with
  nothing changed at most 0.1 of the cold one (it only checks), one edited chapter module at most 0.5
  (that chapter alone runs);
* a 2-D sweep on a two-worker ``LocalCluster``: >= 1.8x faster than the same points run serially
  (cluster start and compilation excluded), and Dask's overhead per point (issue 31).
"""

from __future__ import annotations

import argparse
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from ...physics.exact import exact_response
from ...physics.frequency import peak_displacement_map
from ...physics.model import Oscillator, SineForce
from ...physics.numerics import simulate
from ..presentation.timing import median_time, table
from .registry import chapter_packages


def bench_exact(quick: bool) -> None:
    """Closed form against the paper's integrator on the resonance scenario, and its cost per sample.

    The floor is one ``numpy.exp`` over the same grid: the least any closed form
    that evaluates an exponential per sample can cost. On a uniform grid
    ``exact_response`` forms its exponentials from about sqrt(n) anchors and
    offsets in a compiled kernel, so it can come within a few floors.
    """
    osc, force = Oscillator(m=1.0, c=0.5, k=20.0), SineForce(F0=5.0, omega=4.47)
    t = np.linspace(0.0, 50.0, 5001)
    t_general = t.copy()
    t_general[1] *= 1.0 + 1e-9  # not uniform any more: the pointwise path
    k = 1 if quick else 3
    t_exact = median_time(lambda: exact_response(osc, force, t), 200 * k)
    t_floor = median_time(lambda: np.exp(t), 200 * k)
    t_general = median_time(lambda: exact_response(osc, force, t_general), 50 * k)
    t_rk = median_time(lambda: simulate(osc, force, 50.0, n_points=5001), 7 * k)
    t_rk9 = median_time(lambda: simulate(osc, force, 50.0, n_points=5001, rtol=1e-9, atol=1e-12), 3 * k)
    t_dop = median_time(
        lambda: simulate(osc, force, 50.0, n_points=5001, method="DOP853", rtol=1e-9, atol=1e-12), 3 * k
    )
    table(
        "exact_response on 5001 uniform points (block products of exact anchors) vs solve_ivp",
        [
            ("exact_response", t_exact, None, ""),
            ("RK45, SciPy defaults (the paper's method)", t_rk, t_rk / t_exact, ">= 200x"),
            ("RK45, rtol 1e-9, atol 1e-12", t_rk9, t_rk9 / t_exact, ">= 3000x"),
            ("DOP853, rtol 1e-9, atol 1e-12", t_dop, t_dop / t_exact, ""),
        ],
    )
    n = t.size
    print(
        f"  cost per sample: exact_response {t_exact / n * 1e9:.1f} ns (uniform grid), "
        f"{t_general / n * 1e9:.1f} ns (pointwise path, arbitrary t); "
        f"floor, one np.exp over the grid: {t_floor / n * 1e9:.2f} ns; "
        f"ratio {t_exact / t_floor:.2f} floors (pointwise {t_general / t_floor:.2f})"
    )


def bench_map(quick: bool) -> None:
    """Design map against the per-cell loops, the loops timed on a random sample of cells."""
    m, k, F0 = 1.0, 20.0, 5.0
    omegas = np.linspace(0.05, 10.0, 200)
    dampings = np.geomspace(0.01, 20.0, 200)
    t_map = median_time(lambda: peak_displacement_map(m, k, F0, omegas=omegas, dampings=dampings), 3 if quick else 5)
    rng = np.random.default_rng(0)
    cells = [(dampings[i], omegas[j]) for i, j in rng.integers(0, 200, size=(20 if quick else 60, 2))]
    t = np.linspace(0.0, 50.0, 5001)

    def loop_ivp():
        for c, w in cells:
            np.max(np.abs(simulate(Oscillator(m=m, c=c, k=k), SineForce(F0=F0, omega=w), 50.0, n_points=5001).x))

    def loop_exact():
        for c, w in cells:
            np.max(np.abs(exact_response(Oscillator(m=m, c=c, k=k), SineForce(F0=F0, omega=w), t).x))

    scale = omegas.size * dampings.size / len(cells)
    t_ivp = median_time(loop_ivp, 1 if quick else 3) * scale
    t_naive = median_time(loop_exact, 3) * scale
    table(
        f"peak_displacement_map 200 x 200 x 5001 (loops timed on {len(cells)} random cells, scaled x{scale:.0f})",
        [
            ("peak_displacement_map", t_map, None, ""),
            ("per-cell solve_ivp loop (RK45 defaults)", t_ivp, t_ivp / t_map, ">= 1000x"),
            ("per-cell exact_response loop (naive closed form)", t_naive, t_naive / t_map, "(short of it)"),
        ],
    )


def bench_report() -> None:
    """The whole report against papermill on as many empty notebooks (same kernel, sequential)."""
    import nbformat
    import papermill

    from .report import KERNEL_ARGS, discover, kernel_name

    chapters = discover()
    kernel = kernel_name()
    with tempfile.TemporaryDirectory() as tmp:
        empty = Path(tmp) / "empty.ipynb"
        nb = nbformat.v4.new_notebook()
        nb.cells = [nbformat.v4.new_code_cell("x = 1")]
        nb.metadata["kernelspec"] = {"name": kernel, "display_name": kernel, "language": "python"}
        nbformat.write(nb, empty)

        def empties():
            for i in range(len(chapters)):
                papermill.execute_notebook(
                    str(empty),
                    str(Path(tmp) / f"out{i}.ipynb"),
                    kernel_name=kernel,
                    progress_bar=False,
                    extra_arguments=KERNEL_ARGS,
                )

        def empties_cli():
            exe = Path(sys.executable).parent / "papermill"
            for i in range(len(chapters)):
                out = str(Path(tmp) / f"cli{i}.ipynb")
                subprocess.run(
                    [str(exe), str(empty), out, "-k", kernel, "--no-progress-bar"], check=True, capture_output=True
                )

        t_empty = median_time(empties, 1)
        t_cli = median_time(empties_cli, 1)

        def report() -> tuple[float, str]:
            start = time.perf_counter()
            done = subprocess.run(
                [sys.executable, "-m", "vibration.report", "--out", str(Path(tmp) / "report")],
                check=True,
                capture_output=True,
                text=True,
            )
            return time.perf_counter() - start, done.stdout

        t_report, _ = report()  # cold: an empty cache, every chapter executes (longest first)
        t_warm, _ = report()  # warm: nothing changed: the runner only checks
        t_edit, log = one_edit(report)  # one chapter module edited: that chapter runs, the book is rebuilt
    ran = sum(1 for line in log.splitlines() if " done in " in line)
    n = len(chapters)
    table(
        f"report: {n} chapters, papermill + book (HTML and PDF), vs papermill on {n} empty notebooks",
        [
            ("papermill API in one process, empty notebooks", t_empty, None, ""),
            ("papermill command, once per empty notebook", t_cli, None, ""),
            ("python -m vibration.report (2 workers, cold), vs the API", t_report, t_report / t_empty, "<= 2x"),
            ("python -m vibration.report (2 workers, cold), vs the command", t_report, t_report / t_cli, "<= 2x"),
            ("again, nothing changed (warm), vs cold", t_warm, t_warm / t_report, "<= 0.1"),
            (f"one chapter module edited ({ran} chapter ran), vs cold", t_edit, t_edit / t_report, "<= 0.5"),
        ],
    )


#: The module edited by the one-edit build (imported by chapter 5 alone): a comment is appended, then removed.
EDITED = Path(__file__).resolve().parents[1] / "chapters" / "explore" / "tables.py"


def one_edit(build):
    """``build()`` after appending a comment to :data:`EDITED`, which is restored afterwards whatever happens."""
    original = EDITED.read_bytes()
    try:
        EDITED.write_bytes(original + b"\n# an edit timed by make bench (removed when the build ends)\n")
        return build()
    finally:
        EDITED.write_bytes(original)


def _noop(x):
    return x


def _warm_worker() -> None:
    """Compile the chapter 9 study's kernels in a worker (compilation is not what the sweep bench measures)."""
    from ..chapters.duffing.study import chaos_study

    chaos_study(n_lyapunov=100)


def bench_sweep(quick: bool) -> None:
    """A 2-D sweep of chapter 9 on a two-worker LocalCluster against the same points run one after the other.

    Cluster start and numba compilation are excluded: the cluster is started and each worker (and this
    process) has compiled the kernels before the clocks start. Dask's overhead per point is timed on a
    task that does nothing.
    """
    from .engine import cluster
    from .sweep import sweep

    grid = {"F0_ueda": "4:10:4" if quick else "4:10:12", "c_ueda": "0.05,0.1"}
    params = {"n_lyapunov": 300 if quick else 600}
    n = 8 if quick else 24
    warm = {"F0_ueda": "7", "c_ueda": "0.05"}  # one point first: the sweep's own first-call costs are not timed
    _warm_worker()
    sweep("09", warm, params=params, serial=True)
    start = time.perf_counter()
    serial = sweep("09", grid, params=params, serial=True)
    t_serial = time.perf_counter() - start
    with cluster(2) as client:
        client.run(_warm_worker)
        sweep("09", {**warm, "c_ueda": "0.05,0.1"}, params=params, client=client)
        start = time.perf_counter()
        local = sweep("09", grid, params=params, client=client)
        t_cluster = time.perf_counter() - start
        k = 200
        start = time.perf_counter()
        client.gather(client.map(_noop, range(k), pure=False))
        t_noop = (time.perf_counter() - start) / k
    same = bool(np.array_equal(serial["lyapunov"].values, local["lyapunov"].values))
    table(
        f"sweep of chapter 9, {n} points of F0_ueda x c_ueda ({params['n_lyapunov']} periods each), identical: {same}",
        [
            ("serial, in this process", t_serial, None, ""),
            ("LocalCluster, 2 single-threaded workers", t_cluster, t_serial / t_cluster, ">= 1.8x faster"),
            (
                f"Dask overhead per point (a task doing nothing), {100 * t_noop / (t_serial / n):.2g} % of a point",
                t_noop,
                None,
                "",
            ),  # fmt: skip
        ],
    )


def bench_chapters(quick: bool) -> None:
    """Every chapter package's ``bench.run(quick, ...)``, in report order (found, not listed: a new chapter's
    benchmark runs with no edit here). ``run`` may accept ``median_time`` and ``table``, this module's helpers."""
    import importlib
    import inspect

    helpers = {"median_time": median_time, "table": table}
    for pkg in chapter_packages().values():
        try:
            module = importlib.import_module(f"vibration.book.chapters.{pkg}.bench")
        except ModuleNotFoundError as exc:
            if exc.name == f"vibration.book.chapters.{pkg}.bench":
                continue  # a chapter without a benchmark
            raise
        if hasattr(module, "run"):
            accepted = inspect.signature(module.run).parameters
            module.run(quick, **{k: v for k, v in helpers.items() if k in accepted})


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m vibration.bench")
    parser.add_argument("--quick", action="store_true", help="fewer repeats")
    parser.add_argument("--skip-report", action="store_true", help="do not time the whole report")
    parser.add_argument("--skip-sweep", action="store_true", help="do not time the sweep on a local cluster")
    args = parser.parse_args(argv)
    print("vibration benchmarks: medians of repeated runs, ratios measured side by side in this run")
    bench_exact(args.quick)
    bench_map(args.quick)
    bench_chapters(args.quick)
    if not args.skip_sweep:
        bench_sweep(args.quick)
    if not args.skip_report:
        bench_report()
    return 0


if __name__ == "__main__":
    sys.exit(main())
