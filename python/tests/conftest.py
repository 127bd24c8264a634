# SPDX-License-Identifier: MIT
"""Shared fixtures of the package's tests.

The tests import the package from this source tree (python/) unless
SINEW_PYTHON_INSTALLED=1 says to use the installed one, which must then
be on the path already (tools/check_install.sh runs them so). The
libraries come from SINEW_LIBRARY_DIR (a shared build) or the install.
"""
import os
import shutil
import sys

import pytest

if os.environ.get("SINEW_PYTHON_INSTALLED") != "1":
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir))

import sinew  # noqa: E402

REPOSITORY = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir))


@pytest.fixture(scope="session")
def sinew_program():
    """The sinew program to compare with: SINEW_EXECUTABLE (which must then
    exist: ctest and check_install.sh set it), else the one on PATH."""
    program = os.environ.get("SINEW_EXECUTABLE")
    if program and not os.access(program, os.X_OK):
        pytest.fail(f"SINEW_EXECUTABLE={program} is not an executable program")
    program = program or shutil.which("sinew")
    if not program:
        pytest.skip("no sinew program: set SINEW_EXECUTABLE to the one built with the libraries")
    return program


@pytest.fixture(scope="session")
def repository():
    """The source tree (its models/controls files)."""
    return REPOSITORY


@pytest.fixture
def world():
    with sinew.World(gravity=(0.0, -9.8)) as w:
        yield w
