"""Reader for the teaching-lab logger's CSV exports (one column group per run).

The format, as the logger software writes it: UTF-8 with a byte-order mark, ``;`` as the
separator, ``,`` as the decimal mark (exponent notation such as ``-4,1667E-4`` allowed), one
header row, then one row per sample. Every header cell is ``<quantity> Run #<n>``; the
quantities kept are

======================================  ==================  ===========================
header quantity                         :class:`LoggerRun`  unit
======================================  ==================  ===========================
``Time (s)``                            ``t``               s
``Angle, Ch 1+2 (rad)``                 ``angle``           rad (the oscillating wheel)
``Angle, Ch 3+4 (rad)``                 ``drive_angle``     rad (the drive)
``Output Voltage (V)``                  ``voltage``         V (motor supply)
``Output Current (A)``                  ``current``         A (motor current)
======================================  ==================  ===========================

The logger's derived columns (``Angular Velocity``, ``Angular Acceleration``, ``Position``,
``Velocity``, ``Acceleration`` of channel 1+2 or 3+4) are recognised and skipped on purpose:
they are finite differences of the quantised angle and carry no information of their own. Any
other header is refused. Runs may have different lengths: a run ends at the first empty time
cell and every later cell of its kept columns must be empty too. The logger sometimes writes a
run's last time stamp (with voltage and current) but no angle: a kept column may stop up to
:data:`MAX_RAGGED_END` rows before its run's time column, and those last rows are then dropped
from the whole run (they are checked to be numbers first). A longer gap is an error. Every refusal is a
:class:`~vibration.physics.model.ParameterError` naming the file, the data row (1 = first row
after the header; the file line is given too) and the column.
"""

from __future__ import annotations

import csv
import io
import math
import re
from dataclasses import dataclass

import numpy as np

from vibration.physics.files import read_text_file
from vibration.physics.model import ParameterError

#: Largest file the reader accepts (bytes).
MAX_FILE_BYTES = 200_000_000
#: Largest number of data rows and of columns.
MAX_ROWS = 2_000_000
MAX_COLUMNS = 10_000
#: Fewest samples a run may have.
MIN_SAMPLES = 20
#: Largest number of rows at the end of a run in which a column may be empty while the time
#: column goes on (the logger sometimes writes a last time stamp without an angle); such rows
#: are dropped from every column of the run.
MAX_RAGGED_END = 2
#: Largest |value| of a number cell.
MAX_ABS_VALUE = 1e9

_KEPT = {
    "Time (s)": "t",
    "Angle, Ch 1+2 (rad)": "angle",
    "Angle, Ch 3+4 (rad)": "drive_angle",
    "Output Voltage (V)": "voltage",
    "Output Current (A)": "current",
}
_DERIVED = re.compile(
    r"(Angular Velocity, Ch (1\+2|3\+4) \(rad/s\))|(Angular Acceleration, Ch (1\+2|3\+4) \(rad/s²\))"
    r"|(Position, Ch (1\+2|3\+4) \(m\))|(Velocity, Ch (1\+2|3\+4) \(m/s\))|(Acceleration, Ch (1\+2|3\+4) \(m/s²\))"
)
_HEADER = re.compile(r"(?P<quantity>.+?) Run #(?P<run>[0-9]{1,6})")
_NUMBER = re.compile(r"[+-]?[0-9]+(,[0-9]+)?([eE][+-]?[0-9]{1,3})?")


@dataclass(frozen=True, eq=False, kw_only=True)
class LoggerRun:
    """One run of a logger export, in SI units.

    Attributes
    ----------
    run : int
        Run number from the header (``Run #n``).
    t : numpy.ndarray
        Time stamps (s), strictly increasing, read-only.
    angle : numpy.ndarray
        Angle of the oscillating wheel, channel 1+2 (rad), read-only.
    drive_angle, voltage, current : numpy.ndarray or None
        Angle of the drive, channel 3+4 (rad); motor supply voltage (V); motor current (A).
        ``None`` when the file has no such column for this run.
    drive_unit : str
        Unit of ``drive_angle``: "rad" (an encoder on the drive) or "V" (the exciter's signal of a
        logger that records it as a voltage).
    """

    run: int
    t: np.ndarray
    angle: np.ndarray
    drive_angle: np.ndarray | None
    voltage: np.ndarray | None
    current: np.ndarray | None
    drive_unit: str = "rad"

    @property
    def n(self) -> int:
        """Number of samples."""
        return int(self.t.size)

    @property
    def duration(self) -> float:
        """Time from the first to the last sample (s)."""
        return float(self.t[-1] - self.t[0])

    def __repr__(self) -> str:
        extra = [k for k in ("drive_angle", "voltage", "current") if getattr(self, k) is not None]
        return f"LoggerRun(run={self.run}, n={self.n}, t=[{self.t[0]:g} .. {self.t[-1]:g}] s, with {extra})"


def _frozen(a: list[float]) -> np.ndarray:
    arr = np.asarray(a, dtype=float)
    arr.flags.writeable = False
    return arr


def _where(file: str, row: int, column: str) -> str:
    return f"file {file!r}, data row {row} (line {row + 1}), column {column!r}"


def _parse_number(cell: str, file: str, row: int, column: str) -> float:
    s = cell.strip()
    if not _NUMBER.fullmatch(s):
        raise ParameterError(
            f"{_where(file, row, column)}: cell = {cell!r} is not a number: allowed a decimal number "
            "with ',' as the decimal mark (optionally with an exponent, e.g. -4,1667E-4)"
        )
    v = float(s.replace(",", "."))
    if not math.isfinite(v) or abs(v) > MAX_ABS_VALUE:
        raise ParameterError(f"{_where(file, row, column)}: cell = {cell!r} is out of range: allowed |value| <= 1e9")
    return v


def load_logger_runs(path) -> list[LoggerRun]:
    """Read every run of a logger CSV export.

    Parameters
    ----------
    path : str or os.PathLike
        The CSV file (format in the module docstring).

    Returns
    -------
    list of LoggerRun
        Sorted by run number. Times in s, angles in rad, voltage in V, current in A.

    Raises
    ------
    ParameterError
        For a file that cannot be read or is malformed, naming the file, the data row and the
        column: unknown or duplicated header, a run without a time or an angle column, text in a
        number cell, an empty cell inside a run, a value after a run's end, time not strictly
        increasing, fewer than 20 samples, more than 2 000 000 rows or 200 MB.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> text = "\\ufeffTime (s) Run #1;Angle, Ch 1+2 (rad) Run #1\\r\\n"
    >>> text += "".join(f"{0.05 * i:.3f};{0.017 * (i % 3):.3f}\\r\\n".replace(".", ",") for i in range(25))
    >>> with tempfile.TemporaryDirectory() as d:
    ...     p = pathlib.Path(d) / "runs.csv"
    ...     _ = p.write_text(text, encoding="utf-8")
    ...     runs = load_logger_runs(p)
    >>> runs[0].run, runs[0].n, float(runs[0].t[-1]), runs[0].drive_angle is None
    (1, 25, 1.2, True)
    """
    name, text = read_text_file(path, "logger CSV file", max_bytes=MAX_FILE_BYTES)
    rows = list(csv.reader(io.StringIO(text, newline=""), delimiter=";"))
    if not rows:
        raise ParameterError(f"file {name!r} is empty: allowed a header row and data rows")
    header = rows[0]
    data = rows[1:]
    while data and all(c.strip() == "" for c in data[-1]):
        data.pop()
    if len(header) > MAX_COLUMNS:
        raise ParameterError(f"file {name!r} has {len(header)} columns: allowed at most {MAX_COLUMNS}")
    if len(data) > MAX_ROWS:
        raise ParameterError(f"file {name!r} has {len(data)} data rows: allowed at most {MAX_ROWS}")
    columns, unnamed = _header_columns(name, header)
    _check_cells_outside_runs(name, header, data, unnamed)
    return [_read_run(name, header, data, run, columns[run]) for run in sorted(columns)]


def _cell(data: list[list[str]], i: int, j: int) -> str:
    """Data row i, column j, stripped (``""`` past a short row's end)."""
    r = data[i]
    return r[j].strip() if j < len(r) else ""


def _header_columns(name: str, header: list[str]) -> tuple[dict[int, dict[str, int]], list[int]]:
    """The header read: each run's kept fields and their column indices, and the columns without a header."""
    columns: dict[int, dict[str, int]] = {}
    unnamed: list[int] = []
    for j, cell in enumerate(header):
        h = cell.strip()
        if h == "":
            unnamed.append(j)
            continue
        m = _HEADER.fullmatch(h)
        quantity = m.group("quantity") if m else None
        if m is None or (quantity not in _KEPT and not _DERIVED.fullmatch(quantity)):
            raise ParameterError(
                f"file {name!r}, header row (line 1), column {j + 1}: header = {cell!r} is unknown: allowed "
                f"'<quantity> Run #<n>' with quantity one of {sorted(_KEPT)} or a derived velocity, "
                "acceleration or position of channel 1+2 or 3+4"
            )
        if quantity not in _KEPT:
            continue  # derived by the logger from the angle: skipped on purpose
        run = int(m.group("run"))
        field = _KEPT[quantity]
        group = columns.setdefault(run, {})
        if field in group:
            raise ParameterError(f"file {name!r}, header row (line 1), column {j + 1}: header = {h!r} is repeated")
        group[field] = j
    if not columns:
        raise ParameterError(f"file {name!r} has no run columns: allowed headers such as 'Time (s) Run #1'")
    return columns, unnamed


def _check_cells_outside_runs(name: str, header: list[str], data: list[list[str]], unnamed: list[int]) -> None:
    """No row longer than the header, and nothing under an empty header."""
    ncol = len(header)
    for i, r in enumerate(data, start=1):
        if len(r) > ncol:
            raise ParameterError(
                f"file {name!r}, data row {i} (line {i + 1}) has {len(r)} cells: allowed at most {ncol} (the header's)"
            )
    for j in unnamed:
        for i in range(len(data)):
            if _cell(data, i, j) != "":
                raise ParameterError(
                    f"{_where(name, i + 1, f'column {j + 1} (no header)')}: cell = {_cell(data, i, j)!r} is under an "
                    "empty header: allowed only empty cells there"
                )


def _run_lengths(name: str, header: list[str], data: list[list[str]], run: int, group: dict[str, int]) -> dict:
    """Each field's number of samples in one run: filled from the first row, empty after, none past the time's."""
    lengths: dict[str, int] = {}
    for field, j in group.items():
        cname = header[j].strip()
        length = 0
        while length < len(data) and _cell(data, length, j) != "":
            length += 1
        for i in range(length, len(data)):
            if _cell(data, i, j) != "":
                raise ParameterError(
                    f"{_where(name, length + 1, cname)}: empty cell in the middle of run {run} (data continue at "
                    f"data row {i + 1}): allowed empty cells only after a run's last sample"
                )
        lengths[field] = length
    nt = lengths["t"]
    for field, j in group.items():
        cname = header[j].strip()
        if lengths[field] > nt:
            raise ParameterError(
                f"{_where(name, nt + 1, cname)}: cell = {_cell(data, nt, j)!r} after the last time stamp of run {run} "
                f"(data row {nt}): allowed only empty cells there"
            )
        if lengths[field] < nt - MAX_RAGGED_END:
            raise ParameterError(
                f"{_where(name, lengths[field] + 1, cname)}: empty cell in the middle of run {run} (its time "
                f"column goes on to data row {nt}): allowed a number in every row that has a time, except "
                f"in the last {MAX_RAGGED_END} rows"
            )
    return lengths


def _read_run(name: str, header: list[str], data: list[list[str]], run: int, group: dict[str, int]) -> LoggerRun:
    """One run's columns checked, parsed and cut to their common length, with time strictly increasing."""
    if "t" not in group:
        present = ", ".join(header[j].strip() for j in group.values())
        raise ParameterError(
            f"file {name!r}, header row (line 1), column 'Time (s) Run #{run}' is missing: run {run} has "
            f"{present} but no time column"
        )
    if "angle" not in group:
        raise ParameterError(
            f"file {name!r}, header row (line 1), column 'Angle, Ch 1+2 (rad) Run #{run}' is missing: run "
            f"{run} has a time column but no angle of the wheel"
        )
    tname = header[group["t"]].strip()
    lengths = _run_lengths(name, header, data, run, group)
    n = min(lengths.values())
    if n < MIN_SAMPLES:
        raise ParameterError(f"{_where(name, n + 1, tname)}: run {run} has {n} samples: allowed at least {MIN_SAMPLES}")
    values: dict[str, list[float]] = {}
    for field in ("t", "angle", "drive_angle", "voltage", "current"):
        if field not in group:
            continue
        j = group[field]
        cname = header[j].strip()
        col = [_parse_number(_cell(data, i, j), name, i + 1, cname) for i in range(lengths[field])]
        values[field] = col[:n]
    t = values["t"]
    for i in range(1, n):
        if not t[i] > t[i - 1]:
            raise ParameterError(
                f"{_where(name, i + 1, tname)}: time = {t[i]!r} s after {t[i - 1]!r} s is not increasing: "
                "allowed strictly increasing time stamps"
            )
    return LoggerRun(
        run=run,
        t=_frozen(t),
        angle=_frozen(values["angle"]),
        drive_angle=_frozen(values["drive_angle"]) if "drive_angle" in values else None,
        voltage=_frozen(values["voltage"]) if "voltage" in values else None,
        current=_frozen(values["current"]) if "current" in values else None,
    )
