"""A laboratory's folder of logger files described by a manifest, so that any Pohl wheel can be analysed.

The folder holds the logger files, a manifest ``runs.csv`` and optionally ``rig.csv``:

``runs.csv`` (comma-separated, UTF-8, header exactly ``file,kind,brake,brake_current_A,session,run``):

- ``file``: a logger file inside the folder (PASCO Capstone or CASSY Lab 2 CSV, detected from its header);
- ``kind``: ``free`` (a free decay) or ``driven``;
- ``brake``: a label of the brake setting ("off", "on", "400 mA", ...);
- ``brake_current_A``: the brake current (A), a number >= 0, or empty when not known;
- ``session``: a label of the session (settings are compared within a session);
- ``run``: the run number inside a multi-run file, or empty for every run of the file.

``rig.csv`` (header ``encoder_step_rad,max_angle_rad,description``, one row, each cell optional):
the angle sensor's step (rad), the largest angle the wheel can physically turn (rad), and a
description. Every refusal is a :class:`~vibration.physics.model.ParameterError` naming the file,
the row and the column.
"""

from __future__ import annotations

import csv
import io
import math
import os
from dataclasses import dataclass, field
from pathlib import Path

from vibration.physics.files import read_text_file
from vibration.physics.lab.cassy import is_cassy_header, load_cassy_runs
from vibration.physics.lab.logger import LoggerRun, load_logger_runs
from vibration.physics.model import ParameterError

MANIFEST = "runs.csv"
RIG = "rig.csv"
MANIFEST_HEADER = ("file", "kind", "brake", "brake_current_A", "session", "run")
RIG_HEADER = ("encoder_step_rad", "max_angle_rad", "description")
KINDS = ("free", "driven")
#: Largest number of manifest rows, and of manifest bytes.
MAX_MANIFEST_ROWS = 10_000
MAX_MANIFEST_BYTES = 5_000_000
#: Largest brake current (A) accepted.
MAX_CURRENT_A = 100.0


@dataclass(frozen=True, kw_only=True)
class Rig:
    """What the folder says about the rig (``None`` where ``rig.csv`` is absent or the cell empty).

    Attributes
    ----------
    encoder_step_rad : float or None
        The angle sensor's step (rad).
    max_angle_rad : float or None
        The largest angle the wheel can physically turn (rad).
    description : str
        Free text.
    """

    encoder_step_rad: float | None = None
    max_angle_rad: float | None = None
    description: str = ""


@dataclass(frozen=True, kw_only=True, eq=False)
class LabRun:
    """One run with its manifest row.

    Attributes
    ----------
    file : str
        The logger file (relative to the folder).
    row : int
        Manifest data row (1 = first row after the header).
    kind : str
        "free" or "driven".
    brake : str
        Brake setting label.
    brake_current_A : float or None
        Brake current (A).
    session : str
        Session label.
    run : int
        Run number inside the file.
    data : LoggerRun
        The samples.
    """

    file: str
    row: int
    kind: str
    brake: str
    brake_current_A: float | None
    session: str
    run: int
    data: LoggerRun = field(repr=False)

    @property
    def t(self):
        """Time stamps (s)."""
        return self.data.t

    @property
    def angle(self):
        """Wheel angle (rad)."""
        return self.data.angle


@dataclass(frozen=True, kw_only=True, eq=False)
class LabData:
    """Every run of a folder, with its manifest rows and rig facts.

    Attributes
    ----------
    folder : str
        The folder read.
    runs : tuple of LabRun
        In manifest order (a row with an empty ``run`` expands to every run of its file, by number).
    rig : Rig
        From ``rig.csv`` (all ``None`` without it).
    formats : dict
        File -> "PASCO Capstone" or "CASSY Lab 2".
    """

    folder: str
    runs: tuple
    rig: Rig
    formats: dict

    def select(self, *, kind=None, brake=None, session=None) -> list:
        """The runs of one kind, brake label and/or session."""
        return [
            r
            for r in self.runs
            if (kind is None or r.kind == kind)
            and (brake is None or r.brake == brake)
            and (session is None or r.session == session)
        ]

    @property
    def brakes(self) -> list:
        """Brake labels in order of first appearance."""
        return list(dict.fromkeys(r.brake for r in self.runs))

    @property
    def sessions(self) -> list:
        """Session labels in order of first appearance."""
        return list(dict.fromkeys(r.session for r in self.runs))

    def current(self, brake: str):
        """The brake current (A) of a brake label (the first given in the manifest), or None."""
        for r in self.runs:
            if r.brake == brake and r.brake_current_A is not None:
                return r.brake_current_A
        return None


def _read_csv(path: Path, label: str) -> list[list[str]]:
    _, text = read_text_file(path, "CSV file of a lab folder", max_bytes=MAX_MANIFEST_BYTES, label=label)
    rows = [r for r in csv.reader(io.StringIO(text, newline="")) if any(c.strip() for c in r)]
    if not rows:
        raise ParameterError(f"file {label!r} is empty: allowed a header row and data rows")
    return rows


def _where(file: str, row: int, column: str) -> str:
    return f"file {file!r}, row {row}, column {column!r}"


def _number(file, row, column, cell, *, low, high, unit):
    try:
        v = float(cell)
    except ValueError:
        raise ParameterError(
            f"{_where(file, row, column)}: cell = {cell!r} is not a number: allowed a number in {unit} with '.' as "
            "the decimal mark, or an empty cell"
        ) from None
    if not math.isfinite(v) or not low <= v <= high:
        raise ParameterError(
            f"{_where(file, row, column)}: cell = {cell!r} is out of range: allowed {low} to {high} {unit}"
        )
    return v


def _folder(folder) -> Path:
    if isinstance(folder, bytes) or not isinstance(folder, (str, os.PathLike)):
        raise ParameterError(f"folder = {folder!r} is not a path: allowed str or os.PathLike")
    p = Path(folder)
    if not p.is_dir():
        raise ParameterError(f"folder = {str(p)!r} is not a folder: allowed a folder with a manifest {MANIFEST}")
    if not (p / MANIFEST).is_file():
        raise ParameterError(
            f"folder = {str(p)!r} has no manifest {MANIFEST}: allowed a folder with {MANIFEST} "
            f"(header {','.join(MANIFEST_HEADER)})"
        )
    return p


def _rig(p: Path) -> Rig:
    path = p / RIG
    if not path.exists():
        return Rig()
    rows = _read_csv(path, RIG)
    header = tuple(c.strip() for c in rows[0])
    if header != RIG_HEADER:
        raise ParameterError(
            f"file {RIG!r}, row 0 (header): header = {','.join(header)!r} is out of range: allowed exactly "
            f"{','.join(RIG_HEADER)!r}"
        )
    if len(rows) != 2:
        raise ParameterError(f"file {RIG!r} has {len(rows) - 1} data rows: allowed exactly 1")
    r = rows[1] + [""] * 3
    if len(rows[1]) > 3:
        raise ParameterError(
            f"file {RIG!r}, row 1 has {len(rows[1])} cells: allowed at most 3 (quote a description with commas)"
        )
    vals = {}
    for j, col in enumerate(RIG_HEADER[:2]):
        c = r[j].strip()
        vals[col] = None if c == "" else _number(RIG, 1, col, c, low=1e-9, high=1e6, unit="rad")
    return Rig(encoder_step_rad=vals["encoder_step_rad"], max_angle_rad=vals["max_angle_rad"], description=r[2].strip())


def _load_file(path: Path, label: str, row: int) -> tuple[list[LoggerRun], str]:
    try:
        with path.open("rb") as fh:
            first = fh.read(65536).decode("utf-8-sig", errors="replace").split("\n", 1)[0]
    except OSError as exc:
        raise ParameterError(
            f"{_where(MANIFEST, row, 'file')}: {label!r} cannot be read: {exc.strerror or exc}"
        ) from None
    if "Run #" in first:
        return load_logger_runs(path), "PASCO Capstone"
    if is_cassy_header(first):
        return load_cassy_runs(path), "CASSY Lab 2"
    raise ParameterError(
        f"file {label!r}, header row (line 1) (listed in {MANIFEST}, row {row}, column 'file'): the header is neither "
        "a PASCO Capstone export ('Time (s) Run #1;...') nor a CASSY Lab 2 export ('Zeit t / s;...')"
    )


def _manifest_rows(p: Path) -> list[list[str]]:
    """The manifest's rows (header first), its header and its number of data rows checked."""
    rows = _read_csv(p / MANIFEST, MANIFEST)
    header = tuple(c.strip() for c in rows[0])
    if header != MANIFEST_HEADER:
        raise ParameterError(
            f"file {MANIFEST!r}, row 0 (header): header = {','.join(header)!r} is out of range: allowed exactly "
            f"{','.join(MANIFEST_HEADER)!r}"
        )
    if len(rows) - 1 > MAX_MANIFEST_ROWS:
        raise ParameterError(f"file {MANIFEST!r} has {len(rows) - 1} rows: allowed at most {MAX_MANIFEST_ROWS}")
    if len(rows) == 1:
        raise ParameterError(f"file {MANIFEST!r} has no data rows: allowed at least one run")
    return rows


def _manifest_file(p: Path, root: Path, i: int, fname: str) -> Path:
    """The logger file of manifest row ``i``, checked to be a file inside the folder."""
    if fname == "":
        raise ParameterError(f"{_where(MANIFEST, i, 'file')}: cell is empty: allowed the name of a logger file")
    fpath = (p / fname).resolve()
    if root not in fpath.parents or fname in (MANIFEST, RIG):
        raise ParameterError(
            f"{_where(MANIFEST, i, 'file')}: cell = {fname!r} is out of range: allowed a logger file inside the folder"
        )
    if not fpath.is_file():
        raise ParameterError(f"{_where(MANIFEST, i, 'file')}: cell = {fname!r} is not a file in the folder")
    return fpath


def _manifest_row(p: Path, root: Path, i: int, r: list[str]) -> tuple[dict, Path, float | None]:
    """Manifest data row ``i`` checked: its cells by column, its logger file's path and its brake current (A)."""
    if len(r) != len(MANIFEST_HEADER):
        raise ParameterError(
            f"file {MANIFEST!r}, row {i} has {len(r)} cells: allowed exactly {len(MANIFEST_HEADER)} "
            f"({','.join(MANIFEST_HEADER)})"
        )
    cell = dict(zip(MANIFEST_HEADER, (c.strip() for c in r), strict=True))
    fpath = _manifest_file(p, root, i, cell["file"])
    if cell["kind"] not in KINDS:
        raise ParameterError(f"{_where(MANIFEST, i, 'kind')}: cell = {cell['kind']!r} is out of range: allowed {KINDS}")
    for col in ("brake", "session"):
        if cell[col] == "":
            raise ParameterError(f"{_where(MANIFEST, i, col)}: cell is empty: allowed a label")
    cur = (
        None
        if cell["brake_current_A"] == ""
        else _number(MANIFEST, i, "brake_current_A", cell["brake_current_A"], low=0.0, high=MAX_CURRENT_A, unit="A")
    )
    return cell, fpath, cur


def _wanted_runs(c: str, available: dict, fname: str, i: int) -> list[int]:
    """The run numbers that the ``run`` cell ``c`` of manifest row ``i`` selects from a file's runs."""
    if c == "":
        return sorted(available)
    if not c.isdigit() or int(c) < 1:
        raise ParameterError(
            f"{_where(MANIFEST, i, 'run')}: cell = {c!r} is not a run number: allowed a positive integer or empty"
        )
    if int(c) not in available:
        raise ParameterError(
            f"{_where(MANIFEST, i, 'run')}: cell = {c!r} is out of range: file {fname!r} has runs {sorted(available)}"
        )
    return [int(c)]


def load_lab_data(folder) -> LabData:
    """Read a folder of logger files through its manifest.

    Parameters
    ----------
    folder : str or os.PathLike
        The folder (format in the module docstring).

    Returns
    -------
    LabData

    Raises
    ------
    ParameterError
        A missing or malformed manifest, rig file or logger file, naming the file, the row and the column.
    """
    p = _folder(folder)
    rows = _manifest_rows(p)
    cache: dict[str, list[LoggerRun]] = {}
    formats: dict[str, str] = {}
    seen: dict[tuple, int] = {}
    out: list[LabRun] = []
    root = p.resolve()
    for i, r in enumerate(rows[1:], start=1):
        cell, fpath, cur = _manifest_row(p, root, i, r)
        fname = cell["file"]
        if fname not in cache:
            cache[fname], formats[fname] = _load_file(fpath, fname, i)
        available = {lr.run: lr for lr in cache[fname]}
        for run in _wanted_runs(cell["run"], available, fname, i):
            key = (fname, run)
            if key in seen:
                raise ParameterError(
                    f"{_where(MANIFEST, i, 'run')}: run {run} of file {fname!r} is listed again (first in row "
                    f"{seen[key]})"
                )
            seen[key] = i
            out.append(
                LabRun(
                    file=fname,
                    row=i,
                    kind=cell["kind"],
                    brake=cell["brake"],
                    brake_current_A=cur,
                    session=cell["session"],
                    run=run,
                    data=available[run],
                )
            )
    return LabData(folder=str(p), runs=tuple(out), rig=_rig(p), formats=formats)


@dataclass(frozen=True, kw_only=True)
class LabCheck:
    """Summary of a valid folder (from :func:`check_lab_data`).

    Attributes
    ----------
    folder : str
        The folder.
    n_free, n_driven : int
        Free decays and driven runs.
    brakes : tuple of str
        Brake labels.
    sessions : tuple of str
        Session labels.
    formats : dict
        File -> format.
    rig : Rig
        The rig facts.
    warnings : tuple of str
        What the chapter will not be able to test with these data.
    """

    folder: str
    n_free: int
    n_driven: int
    brakes: tuple
    sessions: tuple
    formats: dict
    rig: Rig
    warnings: tuple

    def summary(self) -> str:
        """Plain-text summary, one line per fact."""
        lines = [
            f"{self.folder}: valid",
            f"  files: {len(self.formats)} ({', '.join(sorted(set(self.formats.values())))})",
            f"  runs: {self.n_free} free decays, {self.n_driven} driven",
            f"  brake settings: {', '.join(self.brakes)}",
            f"  sessions: {', '.join(self.sessions)}",
        ]
        lines += [f"  note: {w}" for w in self.warnings]
        return "\n".join(lines)


def check_lab_data(folder) -> LabCheck:
    """Validate a folder without analysing it: every file read, every manifest row checked.

    Parameters
    ----------
    folder : str or os.PathLike
        The folder.

    Returns
    -------
    LabCheck

    Raises
    ------
    ParameterError
        As :func:`load_lab_data`, and a folder without any free decay.
    """
    data = load_lab_data(folder)
    free = data.select(kind="free")
    driven = data.select(kind="driven")
    if not free:
        raise ParameterError(f"file {MANIFEST!r}, column 'kind': no row is 'free': allowed at least one free decay")
    warnings = []
    driven_brakes = sorted({r.brake for r in driven})
    if len(driven_brakes) < 2:
        warnings.append("driven runs at fewer than two brake settings: 'damping suppresses resonance' is not testable")
    if len({r.brake for r in free}) < 2:
        warnings.append("free decays at one brake setting only: the brake effect cannot be measured")
    for r in driven:
        if r.data.drive_angle is None:
            warnings.append(
                f"{r.file} run {r.run}: driven run without a drive signal (its frequency is read from the wheel)"
            )
    return LabCheck(
        folder=data.folder,
        n_free=len(free),
        n_driven=len(driven),
        brakes=tuple(data.brakes),
        sessions=tuple(data.sessions),
        formats=dict(data.formats),
        rig=data.rig,
        warnings=tuple(warnings),
    )
