"""The logger reader: the four real files, their digests, and every malformed case refused."""

from __future__ import annotations

import hashlib
from pathlib import Path

import numpy as np
import pytest

from vibration.physics.lab import LoggerRun, load_logger_runs
from vibration.physics.model import ParameterError

DATA = Path(__file__).resolve().parents[3] / "data" / "lab_oscillator"

# Digests of the files as published (source repository, folder 10-12-24-OS-2SB/, commit 450ede0...):
# the copies must be byte for byte the originals.
SHA256 = {
    "free_decay_no_magnet.csv": "bd7691cbda061e9ebacffb91b7daf57fcec91c46fb5d2ddf55a074513070a416",
    "free_decay_magnet.csv": "0b12b0919f6c65a24b47d4f691390e30c5efc9e66b924f531781504313eb400e",
    "driven_session1.csv": "a8ed98e378cf5e2574f6b46b13213c58d4a15f33b284180920f1275896c6ffe0",
    "driven_session2.csv": "83ff3a9c54d885a526636c0c23ff099ff43977b1bfc5a11dd72c35215648318c",
}
N_RUNS = {
    "free_decay_no_magnet.csv": 10,
    "free_decay_magnet.csv": 10,
    "driven_session1.csv": 30,
    "driven_session2.csv": 24,
}


@pytest.mark.parametrize("name", sorted(SHA256))
def test_copies_are_the_originals(name):
    assert hashlib.sha256((DATA / name).read_bytes()).hexdigest() == SHA256[name]


@pytest.mark.parametrize("name", sorted(N_RUNS))
def test_real_files_read(name):
    runs = load_logger_runs(DATA / name)
    assert [r.run for r in runs] == list(range(1, N_RUNS[name] + 1))
    for r in runs:
        assert isinstance(r, LoggerRun)
        assert r.n >= 150
        assert r.t.shape == r.angle.shape == r.drive_angle.shape == r.voltage.shape == r.current.shape
        assert r.t[0] == 0.0
        dt = np.diff(r.t)
        assert np.all(dt > 0)
        assert np.allclose(dt, 0.05, atol=1e-9)  # 20 Hz logger, 3 decimals in the file
        # the encoder counts whole degrees: every angle is a multiple of pi/180 to the file's 3 decimals
        steps = r.angle / (np.pi / 180)
        assert np.max(np.abs(steps - np.round(steps))) < 0.06
        assert not r.t.flags.writeable and not r.angle.flags.writeable
    if name.startswith("free_decay"):
        # motor off: the supply reads a few mV only and the drive does not turn
        for r in runs:
            assert np.max(np.abs(r.voltage)) < 0.05
            assert np.max(np.abs(r.drive_angle)) < 0.02
    else:
        # three consecutive runs per motor voltage; the settings differ by 5 mV or more (4.499 V and 4.507 V)
        volts = np.array([np.median(r.voltage) for r in runs]).reshape(-1, 3)
        assert np.all(np.ptp(volts, axis=1) < 0.003)
        settings = np.sort(volts.mean(axis=1))
        assert len(settings) == N_RUNS[name] // 3 and np.all(np.diff(settings) > 0.004)
        assert 1.9 < settings[0] and settings[-1] < 7.1


def test_str_and_path_agree_and_ragged_last_row_is_dropped():
    a = load_logger_runs(str(DATA / "free_decay_no_magnet.csv"))
    b = load_logger_runs(DATA / "free_decay_no_magnet.csv")
    assert [r.n for r in a] == [r.n for r in b]
    # run 4 has 200 time stamps but 199 angles: the last row is dropped from every column
    assert a[3].n == 199 and a[3].t[-1] == pytest.approx(9.9)


# ---------------------------------------------------------------- malformed files

HEADER = ["Time (s) Run #1", "Angle, Ch 1+2 (rad) Run #1", "Time (s) Run #2", "Angle, Ch 1+2 (rad) Run #2"]


def _num(x: float) -> str:
    return f"{x:.3f}".replace(".", ",")


def _table(n1=30, n2=25):
    rows = []
    for i in range(max(n1, n2)):
        row = []
        for n in (n1, n2):
            row += [_num(0.05 * i), _num(0.017 * (i % 5))] if i < n else ["", ""]
        rows.append(row)
    return [list(HEADER)] + rows


def _write(tmp_path, table, name="bad.csv") -> Path:
    p = tmp_path / name
    text = "\ufeff" + "".join(";".join(f'"{c}"' if "," in c and "Run #" in c else c for c in r) + "\r\n" for r in table)
    p.write_text(text, encoding="utf-8", newline="")
    return p


def test_good_synthetic_file(tmp_path):
    runs = load_logger_runs(_write(tmp_path, _table()))
    assert [r.n for r in runs] == [30, 25]
    assert runs[1].angle[3] == pytest.approx(0.051)
    assert runs[0].voltage is None and runs[0].current is None and runs[0].drive_angle is None


def test_exponent_and_derived_columns(tmp_path):
    table = _table()
    table[0] += ["Angular Velocity, Ch 1+2 (rad/s) Run #1", "Position, Ch 3+4 (m) Run #2"]
    for r in table[1:]:
        r += ["zz", ""]  # derived columns are skipped, whatever they hold
    table[1][1] = "-4,1667E-4"
    runs = load_logger_runs(_write(tmp_path, table))
    assert runs[0].angle[0] == pytest.approx(-4.1667e-4)


def _refused(tmp_path, table, *fragments):
    p = _write(tmp_path, table)
    with pytest.raises(ParameterError) as info:
        load_logger_runs(p)
    msg = str(info.value)
    assert "bad.csv" in msg
    for f in fragments:
        assert f in msg, msg
    return msg


def test_missing_time_column(tmp_path):
    table = _table()
    table[0][2] = "Angle, Ch 3+4 (rad) Run #2"
    _refused(tmp_path, table, "Time (s) Run #2", "no time column", "line 1")


def test_time_without_angle(tmp_path):
    table = _table()
    table[0][3] = "Output Voltage (V) Run #2"
    _refused(tmp_path, table, "Angle, Ch 1+2 (rad) Run #2", "no angle")


def test_text_in_number_cell(tmp_path):
    table = _table()
    table[7][1] = "abc"
    _refused(tmp_path, table, "data row 7", "line 8", "Angle, Ch 1+2 (rad) Run #1", "'abc'", "not a number")


@pytest.mark.parametrize("cell", ["0.017", "nan", "1,2,3", "inf"])
def test_other_non_numbers(tmp_path, cell):
    table = _table()
    table[4][3] = cell
    _refused(tmp_path, table, "data row 4", "Angle, Ch 1+2 (rad) Run #2")


@pytest.mark.parametrize("bad", ["0,100", "0,150"])  # equal to / less than the previous stamp
def test_non_increasing_time(tmp_path, bad):
    table = _table()
    table[5][0] = _num(0.20)
    table[6][0] = bad
    _refused(tmp_path, table, "data row 6", "Time (s) Run #1", "not increasing")


def test_too_few_samples(tmp_path):
    _refused(tmp_path, _table(n2=19), "run 2 has 19 samples", "at least 20", "Time (s) Run #2", "data row 20")


def test_unknown_header(tmp_path):
    table = _table()
    table[0][1] = "Angle, Ch 5+6 (rad) Run #1"
    _refused(tmp_path, table, "column 2", "'Angle, Ch 5+6 (rad) Run #1'", "unknown")
    table[0][1] = "Angle, Ch 1+2 (rad)"
    _refused(tmp_path, table, "unknown")


def test_repeated_header(tmp_path):
    table = _table()
    table[0][3] = "Angle, Ch 1+2 (rad) Run #1"
    _refused(tmp_path, table, "column 4", "repeated")


def test_empty_cell_in_the_middle(tmp_path):
    table = _table()
    table[10][1] = ""
    _refused(tmp_path, table, "data row 10", "Angle, Ch 1+2 (rad) Run #1", "empty cell in the middle")
    table = _table()
    table[10][0] = ""
    _refused(tmp_path, table, "data row 10", "Time (s) Run #1", "empty cell in the middle")


def test_angle_ending_early_is_refused_beyond_the_ragged_end(tmp_path):
    table = _table(n1=30)
    for i in range(27, 31):  # angle stops 4 rows before the time column
        table[i][1] = ""
    _refused(tmp_path, table, "data row 27", "Angle, Ch 1+2 (rad) Run #1", "empty cell in the middle")
    table = _table(n1=30)
    table[30][1] = ""  # the last row has a time but no angle: dropped
    assert load_logger_runs(_write(tmp_path, table, "ok.csv"))[0].n == 29


def test_value_after_the_run(tmp_path):
    table = _table(n1=30, n2=25)
    table[26][3] = "0,5"
    _refused(tmp_path, table, "data row 26", "Angle, Ch 1+2 (rad) Run #2", "after the last time stamp")
    table = _table(n1=30, n2=25)
    table[28][3] = "0,5"  # a gap, then a value: the gap is what is reported
    _refused(tmp_path, table, "data row 26", "Angle, Ch 1+2 (rad) Run #2", "empty cell in the middle")


def test_cell_under_empty_header_and_long_row(tmp_path):
    table = _table()
    table[0].append("")
    for r in table[1:]:
        r.append("")
    table[3][-1] = "1,0"
    _refused(tmp_path, table, "data row 3", "no header")
    table = _table()
    table[2].append("1,0")
    _refused(tmp_path, table, "data row 2", "cells")


def test_not_a_file_or_not_utf8(tmp_path):
    with pytest.raises(ParameterError, match="cannot be read"):
        load_logger_runs(tmp_path / "missing.csv")
    with pytest.raises(ParameterError, match="not a path"):
        load_logger_runs(3)
    p = tmp_path / "latin.csv"
    p.write_bytes("Time (s) Run #1;Angle (°)\n".encode("latin-1"))
    with pytest.raises(ParameterError, match="latin.csv.*not UTF-8"):
        load_logger_runs(p)
    e = tmp_path / "empty.csv"
    e.write_bytes(b"")
    with pytest.raises(ParameterError, match="empty"):
        load_logger_runs(e)
