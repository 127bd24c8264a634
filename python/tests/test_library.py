# SPDX-License-Identifier: MIT
"""Where the package loads its libraries from (sinew/_lib.py)."""
import os
import subprocess
import sys

import pytest

import sinew
from sinew._program import find_program

PACKAGE_PARENT = os.path.dirname(os.path.dirname(os.path.abspath(sinew.__file__)))


def loaded_from(environment):
    """The library paths a fresh interpreter loads under ``environment``."""
    result = subprocess.run(
        [sys.executable, "-c", "import sinew; print(*sinew.library_paths, sep='\\n')"],
        env=dict(environment, PYTHONPATH=PACKAGE_PARENT, PYTHONDONTWRITEBYTECODE="1"),
        capture_output=True,
        text=True,
    )
    return result


def test_sinew_library_dir_comes_first(tmp_path):
    """Copies of the libraries in another folder are loaded from there."""
    for path in sinew.library_paths:
        os.symlink(os.path.realpath(path), tmp_path / os.path.basename(path))
    result = loaded_from(dict(os.environ, SINEW_LIBRARY_DIR=str(tmp_path)))
    assert result.returncode == 0, result.stderr
    assert result.stdout.split() == [str(tmp_path / os.path.basename(p)) for p in sinew.library_paths]


def test_missing_libraries_say_where_they_were_looked_for(tmp_path):
    environment = {k: v for k, v in os.environ.items() if k != "LD_LIBRARY_PATH"}
    environment["SINEW_LIBRARY_DIR"] = str(tmp_path)
    result = loaded_from(environment)
    if result.returncode == 0:
        # An installed package falls back to the libraries it was installed with.
        assert os.path.exists(os.path.join(os.path.dirname(sinew.__file__), "_paths.py"))
    else:
        assert f"looked in SINEW_LIBRARY_DIR={tmp_path}" in result.stderr
        assert "LibraryNotFound" in result.stderr


@pytest.mark.skipif(
    os.environ.get("SINEW_PYTHON_INSTALLED") != "1", reason="only an installed package has a program beside it"
)
def test_the_installed_package_finds_the_program_installed_with_it(monkeypatch):
    """Without SINEW_EXECUTABLE or a sinew on the PATH, sweeps and
    experiments run the program of the package's own prefix (check_install.sh
    names that one in SINEW_EXECUTABLE)."""
    expected = os.environ["SINEW_EXECUTABLE"]
    monkeypatch.delenv("SINEW_EXECUTABLE")
    monkeypatch.setenv("PATH", "/nonexistent")
    assert os.path.samefile(find_program(), expected)
