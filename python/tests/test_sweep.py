# SPDX-License-Identifier: MIT
"""sinew.sweep: the table it returns is the one `sinew sweep` writes for
the same sweep file (but for the timing columns), its runs' files are the
same bytes, and a bad sweep file raises with the program's message.

The program is $SINEW_EXECUTABLE (ctest sets it to the
program just built)."""

import csv
import os
import subprocess

import numpy
import pytest

from sinew.sweep import SweepError, find_program, sweep

SWEEP = """{
  "model": "arm",
  "set": {"duration": 0.5},
  "grid": {"weight": [0, 1, 5], "activation.Biceps Long": [0, 1]}
}
"""

TIMING = ("wall_time_s", "real_time_factor")


def read_rows(path):
    with open(path, newline="", encoding="utf-8") as stream:
        return list(csv.reader(stream))


def test_sweep_returns_the_table_sinew_sweep_writes(tmp_path):
    (tmp_path / "arm_sweep.json").write_text(SWEEP)
    program = find_program()
    subprocess.run([program, "sweep", "arm_sweep.json", "--out", "by_c"], cwd=tmp_path, check=True,
                   capture_output=True)
    table = sweep(tmp_path / "arm_sweep.json", out=tmp_path / "by_python", jobs=2, dataframe=False)

    expected = read_rows(tmp_path / "by_c" / "summary.csv")
    header, rows = expected[0], expected[1:]
    assert list(table.dtype.names) == header
    assert len(table) == len(rows) == 6
    for row, record in zip(rows, table):
        for name, cell in zip(header, row):
            if name in TIMING:
                continue
            value = record[name]
            if isinstance(value, str):
                assert value == cell, name
            elif cell == "":
                assert numpy.isnan(value), name
            else:
                assert value == float(cell), name  # exact: both are the run's doubles
    assert set(table["status"]) == {"ok"}
    assert list(table["weight"]) == [0, 0, 1, 1, 5, 5]

    # The same runs wrote the same files.
    by_c = sorted(os.listdir(tmp_path / "by_c"))
    assert by_c == sorted(os.listdir(tmp_path / "by_python"))
    for name in by_c:
        if name.endswith(".csv") and name != "summary.csv" or name.endswith(".csv-metadata.json"):
            assert (tmp_path / "by_c" / name).read_bytes() == (tmp_path / "by_python" / name).read_bytes(), name


def test_a_second_sweep_runs_nothing(tmp_path):
    (tmp_path / "arm_sweep.json").write_text(SWEEP)
    sweep(tmp_path / "arm_sweep.json", out=tmp_path / "out", dataframe=False)
    summary = tmp_path / "out" / "arm_weight=1_activation.Biceps_Long=1.summary.json"
    before = summary.stat().st_mtime_ns
    again = sweep(tmp_path / "arm_sweep.json", out=tmp_path / "out", dataframe=False)
    assert summary.stat().st_mtime_ns == before
    assert len(again) == 6


def test_a_bad_sweep_file_raises_with_the_programs_message(tmp_path):
    (tmp_path / "bad.json").write_text('{"model": "arm", "grid": {"weight": [0, 7]}}')
    with pytest.raises(SweepError, match=r"\$\.grid\.weight\[1\]: expected one of the model's weights"):
        sweep(tmp_path / "bad.json", out=tmp_path / "out")
    assert not (tmp_path / "out").exists()
