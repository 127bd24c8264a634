# SPDX-License-Identifier: MIT
"""Finds and loads librb and libmu, the two shared libraries of sinew.

Where from, first found wins:

1. the folder named by the environment variable ``SINEW_LIBRARY_DIR`` (a
   build tree's: ``build/shared/engine`` holds librb, ``build/shared/musculo``
   libmu, so the variable may name the build folder itself, which is
   searched one level down too);
2. the folder the package was installed with: ``cmake --install`` writes
   ``_paths.py`` beside this file with the path from the package to the
   installed ``lib`` folder, relative, so that a moved prefix still works;
3. the dynamic linker's own search (``LD_LIBRARY_PATH``, ``ldconfig``).

librb is loaded first, by its full path: libmu names it by its soname
(``librb.so.0.2``), which the dynamic linker then finds already loaded.
"""
import ctypes
import os

from . import _api

# The soname's version, as the build writes it (CMakeLists.txt: SOVERSION is
# MAJOR.MINOR): a package of 0.2 loads 0.2 libraries and no other.
SOVERSION = "0.2"


class LibraryNotFound(ImportError):
    """Neither SINEW_LIBRARY_DIR, the install nor the linker gave librb and libmu."""


def _candidates(folder):
    """The folders under ``folder`` where a library may be: itself, and for
    a build tree its engine/ and musculo/ subfolders."""
    return [folder, os.path.join(folder, "engine"), os.path.join(folder, "musculo")]


def _find_in(folders, name):
    for folder in folders:
        for file in (f"lib{name}.so.{SOVERSION}", f"lib{name}.so"):
            path = os.path.join(folder, file)
            if os.path.exists(path):
                return path
    return None


def _installed_dir():
    try:
        from . import _paths  # written by cmake --install
    except ImportError:
        return None
    return os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), _paths.LIBRARY_DIR))


def _locate():
    """The paths (or sonames) of librb and libmu, and the places looked in."""
    tried = []
    env = os.environ.get("SINEW_LIBRARY_DIR")
    if env:
        folders = _candidates(os.path.abspath(env))
        rb, mu = _find_in(folders, "rb"), _find_in(folders, "mu")
        if rb and mu:
            return rb, mu, tried
        tried.append(f"SINEW_LIBRARY_DIR={env} (and its engine/ and musculo/)")
    installed = _installed_dir()
    if installed:
        rb, mu = _find_in([installed], "rb"), _find_in([installed], "mu")
        if rb and mu:
            return rb, mu, tried
        tried.append(f"the install's library folder {installed}")
    tried.append("the dynamic linker's search path")
    return f"librb.so.{SOVERSION}", f"libmu.so.{SOVERSION}", tried


def load():
    """Loads the two libraries and declares their functions (_api.py)."""
    rb_path, mu_path, tried = _locate()
    try:
        rb = ctypes.CDLL(rb_path, mode=ctypes.RTLD_GLOBAL)
        mu = ctypes.CDLL(mu_path, mode=ctypes.RTLD_GLOBAL)
    except OSError as error:
        where = "; ".join(tried)
        raise LibraryNotFound(
            f"sinew: cannot load librb and libmu ({error}); looked in {where}. "
            "Set SINEW_LIBRARY_DIR to the folder of librb.so and libmu.so "
            "(a shared build: cmake -DBUILD_SHARED_LIBS=ON)"
        ) from None
    _api.declare(rb, mu)
    return rb, mu


rb, mu = load()
