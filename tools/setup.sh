#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs the Debian packages sinew needs to build, test and check itself.
#
#   tools/setup.sh           the project's packages
#   tools/setup.sh --peers   also what bench/compare_peers.sh needs (Box2D, Chipmunk2D, C++)
#
# Idempotent: when every package is installed and the test locale exists it
# does nothing (no apt-get update) and says so. Needs root, or sudo for a
# normal user.
set -euo pipefail

# ---- The project's packages: add new dependencies here, one list. ----------
packages=(
    build-essential  # gcc, make, libc headers
    cmake            # >= 3.25 (CMakePresets.json version 6)
    pkg-config       # finds criterion, gsl, jansson, libpng, nlopt, cairo and gtk4
    libgsl-dev       # GNU Scientific Library
    libcriterion-dev # unit tests (tests/)
    libjansson-dev   # model files (musculo/)
    libcairo2-dev    # charts: PNG and SVG figures (tools/chart/), the viewer's drawing
    libpng-dev       # motor-pool profile images (musculo/: libmu reads PNGs with it, not with Cairo)
    libnlopt-dev     # static optimization (musculo/: NLopt's SLSQP solves each frame's activations)
    zlib1g-dev       # crc32 for the text chunks of PNG figures (tools/chart/)
    libgtk-4-dev     # the interactive viewer, `sinew view` (tools/viewer/): built only when present
    xvfb             # xvfb-run: the viewer's test runs it on a virtual X display
    xauth            # xvfb-run needs it for the display's authority file
    xdotool          # the viewer's input test types keys and moves the mouse on that display
    clang-format     # formatting check in tools/check.sh
    valgrind         # memory and cache profiling
    doxygen          # the API reference from the headers (cmake --build ... --target docs)
    g++              # the C++ example built against the installed library (tools/check_install.sh)
    clang            # clang and clang++: the examples and headers checked with a second compiler
    libclang-rt-14-dev # clang's libFuzzer and sanitizer runtimes: the fuzz targets (tools/fuzz.sh)
    binutils         # nm and readelf: what the shared libraries export
    locales          # de_DE.UTF-8, a decimal-comma locale the locale test runs under (generated below)
    python3          # the Python package python/sinew (ctypes over the shared librb and libmu)
    python3-numpy    # its readouts and run tables are numpy arrays
    python3-pytest   # its tests (python/tests: ctest's python test, tools/check_install.sh)
    python3-pandas   # optional for users (RunResult.dataframe()); the tests use it when present
    parallel         # GNU parallel: test_sweep runs `sinew sweep --emit parallel`'s job list with it
    slurmctld        # Slurm's controller, slurmd its node daemon and slurm-client sbatch/sinfo:
    slurmd           #   tests/slurm/sweep_on_slurm.sh starts a one-node cluster and runs a sweep's
    slurm-client     #   `sbatch --array` script on it
    munge            # munged: Slurm's authentication, started by that test with a key of its own
)
# ---- Only with --peers: the peer engines' benchmark harnesses. ------------
peer_packages=(
    libbox2d-dev    # Box2D 2.4.1
    libchipmunk-dev # Chipmunk2D 7.0.3
)
# ---------------------------------------------------------------------------

usage()
{
    sed -n '3,9s/^# \{0,1\}//p' "$0"
}

want=("${packages[@]}")
for arg in "$@"; do
    case "$arg" in
    --peers) want+=("${peer_packages[@]}") ;;
    -h | --help)
        usage
        exit 0
        ;;
    *)
        echo "setup.sh: unknown argument '$arg'" >&2
        usage >&2
        exit 2
        ;;
    esac
done

if ! command -v dpkg-query >/dev/null 2>&1 || ! command -v apt-get >/dev/null 2>&1; then
    echo "setup.sh: dpkg-query/apt-get not found: this script needs Debian or a derivative (Debian 12 is the reference)." >&2
    echo "setup.sh: install by hand: ${want[*]}" >&2
    exit 1
fi

missing=()
for pkg in "${want[@]}"; do
    status=$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)
    if [[ "$status" != "install ok installed" ]]; then
        missing+=("$pkg")
    fi
done

# The locale test (tests/test_locale.c) runs sinew under a locale whose
# decimal point is a comma; Debian ships the locales package with every
# locale commented out of /etc/locale.gen, so it is generated here.
test_locale=de_DE.UTF-8
have_test_locale()
{
    # `locale -a` spells it de_DE.utf8.
    locale -a 2>/dev/null | grep -qix 'de_DE\.utf-\{0,1\}8'
}

if ((${#missing[@]} == 0)) && have_test_locale; then
    echo "setup.sh: all packages present, locale $test_locale present"
    exit 0
fi

if ((EUID == 0)); then
    as_root=()
elif command -v sudo >/dev/null 2>&1; then
    as_root=(sudo)
else
    echo "setup.sh: need root to install packages or generate a locale, and sudo is not available." >&2
    echo "setup.sh: run as root: apt-get update && apt-get install -y --no-install-recommends ${missing[*]}" >&2
    echo "setup.sh: and generate $test_locale (uncomment it in /etc/locale.gen, run locale-gen)" >&2
    exit 1
fi

if ((${#missing[@]} > 0)); then
    echo "setup.sh: missing: ${missing[*]}"
    "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update
    "${as_root[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends "${missing[@]}"
    echo "setup.sh: installed: ${missing[*]}"
fi

if ! have_test_locale; then
    "${as_root[@]}" sed -i "s/^# *\($test_locale UTF-8\)/\1/" /etc/locale.gen
    if ! grep -qx "$test_locale UTF-8" /etc/locale.gen; then
        echo "$test_locale UTF-8" | "${as_root[@]}" tee -a /etc/locale.gen >/dev/null
    fi
    "${as_root[@]}" locale-gen
    have_test_locale || {
        echo "setup.sh: locale-gen did not make $test_locale" >&2
        exit 1
    }
    echo "setup.sh: generated locale $test_locale"
fi
