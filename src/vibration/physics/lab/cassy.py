"""Reader for Leybold CASSY Lab 2 CSV exports (one run per file), German or English interface.

The German export: UTF-8 with a byte-order mark, ``;`` as the separator, ``,`` as the decimal mark,
one header row of "quantity symbol / unit" names, then one row per sample (10 Hz is usual):

=====================================  ===================  ===========================
header (German / English)              :class:`LoggerRun`   unit
=====================================  ===================  ===========================
``Zeit t / s`` / ``Time t / s``        ``t``                s
``Weg &b_A1 / rad`` (``Winkel``,       ``angle``            rad (the wheel)
``Angle``, ``Distance``, ``Path``)
``Spannung U_B1 / V`` / ``Voltage``    ``drive_angle``      V (the exciter's signal;
                                                            ``drive_unit`` "V")
=====================================  ===================  ===========================

Derived columns (``Frequenz``/``Frequency``, ``FFT``, ``zeitliche Ableitung``/``Time derivative``,
``Ableitung``/``Derivative``) are skipped on purpose. The English export uses ``.`` as the decimal
mark and ``;``, a tab or ``,`` as the separator; the separator is read from the header row and the
decimal mark from the data. Every refusal is a :class:`~vibration.physics.model.ParameterError` naming
the file, the data row (the file line too) and the column.
"""

from __future__ import annotations

import csv
import io
import math
import re

import numpy as np

from vibration.physics.files import read_text_file
from vibration.physics.lab.logger import MAX_FILE_BYTES, MAX_RAGGED_END, MAX_ROWS, MIN_SAMPLES, LoggerRun
from vibration.physics.model import ParameterError

_HEADER = re.compile(r"(?P<quantity>.+?)\s+(?P<symbol>\S+)\s*/\s*(?P<unit>\S.*)")
_TIME = {"zeit", "time"}
_ANGLE = {"weg", "winkel", "angle", "distance", "path", "displacement", "rotation angle", "drehwinkel"}
_VOLT = {"spannung", "voltage"}
_DERIVED = {"frequenz", "frequency", "fft", "zeitliche ableitung", "time derivative", "ableitung", "derivative"}
_NUM = {
    ",": re.compile(r"[+-]?[0-9]+(,[0-9]*)?([eE][+-]?[0-9]{1,3})?"),
    ".": re.compile(r"[+-]?[0-9]+(\.[0-9]*)?([eE][+-]?[0-9]{1,3})?"),
}
#: Header rows recognised as a CASSY export (the first row's cells look like "quantity symbol / unit").
HEADER_PATTERN = _HEADER


def is_cassy_header(line: str) -> bool:
    """Whether the first line of a file looks like a CASSY Lab 2 header (a time column "Zeit t / s" or "Time t / s")."""
    for sep in (";", "\t", ","):
        cells = [c.strip().strip('"') for c in line.lstrip("\ufeff").split(sep)]
        for c in cells:
            m = _HEADER.fullmatch(c)
            if m and m.group("quantity").strip().lower() in _TIME and m.group("unit").strip() == "s":
                return True
    return False


def _where(file: str, row: int, column: str) -> str:
    return f"file {file!r}, data row {row} (line {row + 1}), column {column!r}"


def load_cassy_runs(path) -> list[LoggerRun]:
    """Read a CASSY Lab 2 CSV export (one run).

    Parameters
    ----------
    path : str or os.PathLike
        The CASSY CSV file (format in the module docstring).

    Returns
    -------
    list of LoggerRun
        One run (number 1): time (s), wheel angle (rad), the exciter's signal as ``drive_angle`` (V,
        ``drive_unit`` "V") when the file has it.

    Raises
    ------
    ParameterError
        A file that cannot be read or is malformed, naming the file, the data row and the column.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> rows = [f"{0.1 * i:.1f};{0.5 * (i % 4):.2f};0,00".replace(".", ",") for i in range(25)]
    >>> text = "\\ufeffZeit t / s;Weg &b_A1 / rad;Spannung U_B1 / V\\r\\n" + "\\r\\n".join(rows)
    >>> with tempfile.TemporaryDirectory() as d:
    ...     p = pathlib.Path(d) / "run.csv"
    ...     _ = p.write_text(text, encoding="utf-8")
    ...     runs = load_cassy_runs(p)
    >>> runs[0].n, float(runs[0].t[-1]), runs[0].drive_unit
    (25, 2.4, 'V')
    """
    name, text = read_text_file(path, "CASSY Lab 2 CSV file", max_bytes=MAX_FILE_BYTES)
    first = text.split("\n", 1)[0]
    sep = ";" if ";" in first else ("\t" if "\t" in first else ",")
    rows = list(csv.reader(io.StringIO(text, newline=""), delimiter=sep))
    if not rows or not any(c.strip() for c in rows[0]):
        raise ParameterError(f"file {name!r} is empty: allowed a header row and data rows")
    header = [c.strip() for c in rows[0]]
    data = rows[1:]
    while data and all(c.strip() == "" for c in data[-1]):
        data.pop()
    if len(data) > MAX_ROWS:
        raise ParameterError(f"file {name!r} has {len(data)} data rows: allowed at most {MAX_ROWS}")
    cols = _header_columns(name, header)
    decimal = _decimal_mark(sep, data)
    values = {k: _column(name, header[j], data, j, decimal) for k, j in cols.items()}
    n = _common_length(name, header, cols, values)

    def frozen(a):
        arr = np.asarray(a[:n], dtype=float)
        arr.flags.writeable = False
        return arr

    return [
        LoggerRun(
            run=1,
            t=frozen(values["t"]),
            angle=frozen(values["angle"]),
            drive_angle=frozen(values["drive"]) if "drive" in values else None,
            voltage=None,
            current=None,
            drive_unit="V",
        )
    ]


def _header_columns(name: str, header: list[str]) -> dict[str, int]:
    """The columns kept (time ``t``, wheel ``angle``, ``drive`` voltage) and their indices; derived ones skipped."""
    cols: dict[str, int] = {}
    for j, h in enumerate(header):
        m = _HEADER.fullmatch(h)
        if m is None:
            raise ParameterError(
                f"file {name!r}, header row (line 1), column {j + 1}: header = {h!r} is unknown: allowed "
                "'quantity symbol / unit' such as 'Zeit t / s', 'Weg &b_A1 / rad', 'Spannung U_B1 / V'"
            )
        q, unit = m.group("quantity").strip().lower(), m.group("unit").strip()
        if q in _DERIVED:
            continue
        if q in _TIME and unit == "s":
            key = "t"
        elif q in _ANGLE and unit == "rad":
            key = "angle"
        elif q in _VOLT and unit == "V":
            key = "drive"
        else:
            raise ParameterError(
                f"file {name!r}, header row (line 1), column {j + 1}: header = {h!r} is unknown: allowed a time "
                "(s), a wheel angle (rad), a voltage (V) or a derived column (frequency, FFT, time derivative)"
            )
        if key in cols:
            raise ParameterError(f"file {name!r}, header row (line 1), column {j + 1}: header = {h!r} is repeated")
        cols[key] = j
    for key, label in (("t", "a time column 'Zeit t / s'"), ("angle", "a wheel angle column 'Weg &b_A1 / rad'")):
        if key not in cols:
            raise ParameterError(f"file {name!r}, header row (line 1): {label} is missing")
    return cols


def _decimal_mark(sep: str, data: list[list[str]]) -> str:
    """The decimal mark: a comma where the separator is not one and the first 50 rows hold a comma."""
    if sep != ",":
        for r in data[:50]:
            if any("," in c for c in r):
                return ","
    return "."


def _column(name: str, cname: str, data: list[list[str]], j: int, decimal: str) -> list[float]:
    """Column j's numbers from the first data row to its first empty cell, after which all must be empty."""
    pattern = _NUM[decimal]
    vals: list[float] = []
    ended = None
    for i, r in enumerate(data, start=1):
        c = r[j].strip() if j < len(r) else ""
        if c == "":
            if ended is None:
                ended = i
            continue
        if ended is not None:
            raise ParameterError(
                f"{_where(name, ended, cname)}: empty cell in the middle of the run (data continue at data row "
                f"{i}): allowed empty cells only after the last sample"
            )
        if not pattern.fullmatch(c):
            raise ParameterError(
                f"{_where(name, i, cname)}: cell = {c!r} is not a number: allowed a decimal number with "
                f"{decimal!r} as the decimal mark"
            )
        v = float(c.replace(",", "."))
        if not math.isfinite(v) or abs(v) > 1e9:
            raise ParameterError(f"{_where(name, i, cname)}: cell = {c!r} is out of range: allowed |value| <= 1e9")
        vals.append(v)
    return vals


def _common_length(name: str, header: list[str], cols: dict[str, int], values: dict[str, list[float]]) -> int:
    """The run's number of samples: no value past the last time, at most a ragged end, times increasing."""
    nt = len(values["t"])
    for k, v in values.items():
        if len(v) > nt:
            raise ParameterError(
                f"{_where(name, nt + 1, header[cols[k]])}: a value after the last time stamp: allowed only empty cells"
            )
        if len(v) < nt - MAX_RAGGED_END:
            raise ParameterError(
                f"{_where(name, len(v) + 1, header[cols[k]])}: empty cell while the time column goes on to data row "
                f"{nt}: allowed a number in every row that has a time"
            )
    n = min(len(v) for v in values.values())
    if n < MIN_SAMPLES:
        raise ParameterError(
            f"{_where(name, n + 1, header[cols['t']])}: the run has {n} samples: allowed at least {MIN_SAMPLES}"
        )
    t = np.asarray(values["t"][:n])
    bad = np.nonzero(~(np.diff(t) > 0))[0]
    if bad.size:
        i = int(bad[0]) + 2
        raise ParameterError(
            f"{_where(name, i, header[cols['t']])}: time = {t[i - 1]!r} s after {t[i - 2]!r} s is not increasing: "
            "allowed strictly increasing time stamps"
        )
    return n
