# SPDX-License-Identifier: MIT
"""The experiments of ``sinew experiment`` from Python:
``sinew.experiment("p1", dynamics="fast")``.

The experiments (the muscle's validation: twitches, relaxation,
isometric and isotonic holds, summation, the Hill curves, recruitment, and
the round trip of inverse dynamics and static optimization) are part of
the ``sinew`` program, not of the libraries, so this module runs the
program, found as :func:`sinew.sweep` finds it, and reads what it wrote.
"""

import os
import re

from . import _program

__all__ = ["ExperimentResult", "experiment", "experiments"]


class ExperimentResult:
    """What an experiment wrote and printed.

    table: its CSV as a numpy structured array (columns named as the CSV's,
        with their units: ``time_s``, ``...force_N``, ...).
    csv, figure: the paths of its CSV and of its PNG figure.
    report: the lines of figures it printed.
    """

    def __init__(self, table, csv, figure, report):
        self.table = table
        self.csv = csv
        self.figure = figure
        self.report = report

    def dataframe(self):
        """The table as a pandas DataFrame (needs pandas)."""
        import pandas  # optional: only for this

        return pandas.DataFrame(self.table)


def experiments(program=None):
    """The experiments the program offers: {NAME: (STEM, what it shows)},
    read from ``sinew experiment --help``."""
    found = _program.find_program(program)
    text = _program.run_program(found, ["experiment", "--help"])
    listing = text[text.index("experiments (NAME") :].splitlines()[1:]
    offered = {}
    for line in listing:
        match = re.match(r"\s+(\S+)\s+(\S+)\s+(.*)", line)
        if match:
            offered[match.group(1)] = (match.group(2), match.group(3).strip())
    return offered


def experiment(name, out=".", pulse_width=None, dynamics=None, program=None):
    """Runs the experiment ``name`` (``sinew experiment NAME``) and returns
    an ExperimentResult.

    out: the folder of its files (default the current one, as the program's).
    pulse_width: s, the width of the pulses of the experiments that give
        pulses (``--pulse-width``).
    dynamics: the muscle's activation dynamics for p1: "first_order",
        "fast" or "slow" (``--dynamics``).
    program: the ``sinew`` program (default: as sinew.sweep finds it).

    Raises sinew.ProgramError with the program's message for an unknown
    experiment or a bad option.
    """
    found = _program.find_program(program)
    offered = experiments(found)
    if name not in offered:
        raise _program.ProgramError(f"no experiment is called {name!r}; expected one of {', '.join(offered)}")
    arguments = ["experiment", name, "--out", os.fspath(out)]
    if pulse_width is not None:
        arguments += ["--pulse-width", repr(float(pulse_width))]
    if dynamics is not None:
        arguments += ["--dynamics", str(dynamics)]
    report = _program.run_program(found, arguments)
    stem = offered[name][0]
    csv_path = os.path.join(os.fspath(out), stem + ".csv")
    return ExperimentResult(
        _program.read_table(csv_path), csv_path, os.path.join(os.fspath(out), stem + ".png"), report.splitlines()
    )
