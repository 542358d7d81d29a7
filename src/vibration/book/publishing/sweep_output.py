"""A sweep's results: the labelled xarray Dataset (CF units and long names) and the files written from it,
``sweep.nc``, ``sweep.csv``, a figure per key result and ``summary.md``, each written atomically."""

from __future__ import annotations

import itertools
import math
import subprocess
from collections.abc import Mapping, Sequence
from pathlib import Path

import numpy as np

from ...physics.model import ParameterError
from .registry import project_root
from .sweep_grid import Grid, chapter_key_results, chapter_schema

__all__ = ["atomic_text", "dataset", "project_commit", "summary", "write_outputs"]


def atomic_text(path: Path, text: str) -> None:
    tmp = path.with_name(f".{path.name}.part")
    tmp.write_text(text, encoding="utf-8")
    tmp.replace(path)


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

    schema, keys = chapter_schema(grid.package), chapter_key_results(grid.package)
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
    atomic_text(folder / "summary.md", summary(ds, grid, [p.name for p in written if p.suffix == ".png"]))
    written.append(folder / "summary.md")
    return written


def _write_csv(ds, grid: Grid, path: Path) -> Path:
    import csv

    keys = chapter_key_results(grid.package)
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

    keys = chapter_key_results(grid.package)
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
    keys = chapter_key_results(grid.package)
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
