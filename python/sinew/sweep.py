# SPDX-License-Identifier: MIT
"""Parameter sweeps from Python: ``sinew.sweep(...)``.

The sweep is the one ``sinew sweep`` expands (docs/sweeps.md): this module
asks the ``sinew`` program for the run list (``sinew sweep FILE --emit
list``), runs the runs that are not complete on a pool of worker processes
(concurrent.futures), each exactly as the program's own pool and the GNU
parallel job list run it (``sinew run ARGS`` in the output folder, its
messages in NAME.log), then has the program gather the summary table
(``sinew sweep FILE --gather``) and reads it. So the names, the files and
the table are the same, byte for byte but for the timing columns, whether
a sweep was run from Python, by ``sinew sweep``, GNU parallel or Slurm.

It needs only the ``sinew`` program and numpy (pandas when installed):
found through the ``program`` argument, else the environment variable
``SINEW_EXECUTABLE``, else the program installed with the package, else
``sinew`` on the PATH.
"""

import concurrent.futures
import json
import os
import subprocess

from . import _program
from ._program import ProgramError

__all__ = ["SweepError", "sweep", "find_program"]

# The summary's columns that hold text; every other column is a number
# (NaN where a run has none).
_TEXT_COLUMNS = {"run", "status", "message", "variant_name", "failure", "warnings"}


class SweepError(ProgramError):
    """``sinew sweep`` refused the sweep file or could not run it; the
    message is the program's."""


def find_program(program=None):
    """The path of the ``sinew`` program: ``program`` when given, else
    ``$SINEW_EXECUTABLE``, else the one installed with the package, else
    ``sinew`` on the PATH."""
    return _program.find_program(program, SweepError)


def _sinew(program, arguments, runs_may_fail=False):
    """Runs ``sinew ARGUMENTS`` and returns its stdout; SweepError with its
    message when it fails. With runs_may_fail, exit status 1 after the
    table was written (some runs failed) is not a failure."""

    def succeeded(done):
        gathered = runs_may_fail and done.returncode == 1 and done.stdout.startswith("summary")
        return done.returncode == 0 or gathered

    return _program.run_program(program, arguments, SweepError, succeeded=succeeded)


def _run_one(program, out, name, arguments):
    """One run, as a line of the job list runs it: in the output folder,
    stdout dropped, stderr in NAME.log. Returns (name, exit status)."""
    with open(os.path.join(out, name + ".log"), "w", encoding="utf-8") as log:
        status = subprocess.run(
            [program, "run", *arguments], cwd=out, stdout=subprocess.DEVNULL, stderr=log, check=False
        ).returncode
    return name, status


def sweep(sweep_file, out=None, jobs=None, program=None, yes=False, dataframe=True):
    """Runs the sweep of ``sweep_file`` and returns its summary table.

    sweep_file: a sweep file (JSON; docs/sweeps.md).
    out: the output folder (default: the file's "out", else its stem in
        the current folder), as ``sinew sweep --out``.
    jobs: runs at a time (default: the cores).
    program: the ``sinew`` program (default: find_program's).
    yes: allow more than 1000 runs, as ``--yes``.
    dataframe: return a pandas DataFrame when pandas is importable.

    Runs already complete are not run again; a run that fails is a row
    with status "failed" and its message. The table has a row per run in
    the sweep's order: its name, the varied parameters, status, message,
    and the run's figures (peak forces in N, angles in degrees, ...; the
    last two columns, wall_time_s and real_time_factor, are the only ones
    that depend on the machine). A numpy structured array, or a DataFrame.
    Raises SweepError, with the program's message, for a bad sweep file.
    """
    program = find_program(program)
    options = (["--out", os.fspath(out)] if out is not None else []) + (["--yes"] if yes else [])
    listing = json.loads(_sinew(program, ["sweep", os.fspath(sweep_file), "--emit", "list", *options]))
    folder = listing["out"]
    todo = [run for run in listing["runs"] if not run["complete"]]
    with concurrent.futures.ProcessPoolExecutor(max_workers=jobs or os.cpu_count() or 1) as pool:
        futures = [pool.submit(_run_one, listing["program"], folder, run["name"], run["arguments"]) for run in todo]
        for future in concurrent.futures.as_completed(futures):
            future.result()
    _sinew(program, ["sweep", os.fspath(sweep_file), "--out", folder, "--gather"], runs_may_fail=True)
    table = _program.read_table(os.path.join(folder, "summary.csv"), _TEXT_COLUMNS)
    if dataframe:
        try:
            import pandas  # optional: the DataFrame when it is there
        except ImportError:
            return table
        return pandas.DataFrame(table)
    return table
