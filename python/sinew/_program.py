# SPDX-License-Identifier: MIT
"""The ``sinew`` program, for what lives in it rather than in the
libraries (the sweeps' pool and gathering, the experiments): where it is,
running it, and reading the CSV tables it writes."""

import csv
import os
import shutil
import subprocess

import numpy


class ProgramError(RuntimeError):
    """The ``sinew`` program was not found, or refused what it was asked;
    the message is the program's."""


def _installed_program():
    """The ``sinew`` program installed with the package, or None (a package
    used from the source tree has no _paths.py)."""
    try:
        from . import _paths  # written by cmake --install
    except ImportError:
        return None
    folder = os.path.join(os.path.dirname(os.path.abspath(__file__)), _paths.PROGRAM_DIR)
    path = os.path.normpath(os.path.join(folder, "sinew"))
    return path if os.access(path, os.X_OK) else None


def find_program(program=None, error=ProgramError):
    """The path of the ``sinew`` program: ``program`` when given, else
    ``$SINEW_EXECUTABLE``, else the one installed with the package, else
    ``sinew`` on the PATH; ``error`` (a ProgramError class) when none is."""
    found = program or os.environ.get("SINEW_EXECUTABLE") or _installed_program() or shutil.which("sinew")
    if not found:
        raise error("the sinew program was not found: give program=..., set SINEW_EXECUTABLE or put it on the PATH")
    return found


def run_program(program, arguments, error=ProgramError, cwd=None, succeeded=None):
    """Runs ``sinew ARGUMENTS`` and returns its stdout; ``error`` with the
    program's message when it failed: when its exit status is not 0, or
    when ``succeeded(completed_process)`` says so."""
    done = subprocess.run([program, *arguments], capture_output=True, text=True, check=False, cwd=cwd)
    if not (succeeded(done) if succeeded else done.returncode == 0):
        raise error(done.stderr.strip() or f"{program} {' '.join(arguments)}: exit status {done.returncode}")
    return done.stdout


def _is_number(cell):
    if cell == "":
        return True
    try:
        float(cell)
    except ValueError:
        return False
    return True


def read_table(path, text_columns=()):
    """A CSV with a header row as a numpy structured array: the columns in
    ``text_columns``, and any holding a cell that is not a number, as str;
    the others as float64 (NaN for an empty cell)."""
    with open(path, newline="", encoding="utf-8") as stream:
        rows = list(csv.reader(stream))
    header, body = rows[0], rows[1:]
    columns = []
    for index, name in enumerate(header):
        cells = [row[index] for row in body]
        if name in text_columns or not all(_is_number(cell) for cell in cells):
            width = max([len(cell) for cell in cells] + [1])
            columns.append((name, f"U{width}", cells))
        else:
            columns.append((name, "f8", [float(cell) if cell else numpy.nan for cell in cells]))
    table = numpy.empty(len(body), dtype=[(name, kind) for name, kind, _ in columns])
    for name, _, values in columns:
        table[name] = values
    return table
