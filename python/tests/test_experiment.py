# SPDX-License-Identifier: MIT
"""sinew.experiment: runs ``sinew experiment NAME`` and returns its table,
the same numbers as its CSV read on its own, with the Hill curves' defining
point; an unknown experiment or a bad option raises with a message."""

import csv
import math

import pytest

import sinew


def test_the_listing_names_every_experiment(sinew_program):
    offered = sinew.experiments(program=sinew_program)
    assert {"e1", "e2", "e3.1", "e3.2", "e4", "c1", "p1", "r1", "loop"} <= set(offered)
    assert offered["c1"][0] == "c1_hill_curves"


def test_the_hill_curves_come_back_as_their_csv(sinew_program, tmp_path):
    result = sinew.experiment("c1", out=tmp_path, program=sinew_program)
    assert result.csv == str(tmp_path / "c1_hill_curves.csv")
    assert (tmp_path / "c1_hill_curves.png").exists() and result.figure.endswith(".png")
    with open(result.csv, newline="", encoding="utf-8") as stream:
        rows = list(csv.DictReader(stream))
    assert len(result.table) == len(rows)
    for name in rows[0]:
        assert [float(row[name]) for row in rows] == list(result.table[name]), name
    # Normalized curves: the analytic active force-length curve is 1 at the
    # rest length.
    at_rest = [i for i, length in enumerate(result.table["normalized_length"]) if length == 1.0]
    assert at_rest, "no row at the rest length"
    assert result.table["active_force_length.seed003"][at_rest[0]] == pytest.approx(1.0, abs=1e-9)
    assert any("isometric peak 5.00 N" in line for line in result.report)


def test_an_unknown_experiment_raises(sinew_program, tmp_path):
    with pytest.raises(sinew.ProgramError, match="no experiment is called 'e9'"):
        sinew.experiment("e9", out=tmp_path, program=sinew_program)


def test_a_bad_option_raises_with_the_programs_message(sinew_program, tmp_path):
    with pytest.raises(sinew.ProgramError, match="--pulse-width"):
        sinew.experiment("e1", out=tmp_path, pulse_width=math.inf, program=sinew_program)
    assert not list(tmp_path.iterdir())
