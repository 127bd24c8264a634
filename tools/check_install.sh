#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# sinew as other people's programs get it: installed, moved, and built on.
#
#   tools/check_install.sh STATIC_BUILD_DIR
#
# STATIC_BUILD_DIR is a configured and built tree with the default static
# libraries (tools/check.sh passes build/release). The script, in a
# temporary folder that it removes at the end:
#
#   1. installs STATIC_BUILD_DIR to a prefix;
#   2. copies the source tree, builds it with BUILD_SHARED_LIBS=ON (libraries
#      and the sinew program) and installs it to another prefix;
#   3. deletes that copy of the sources and its build tree, moves the shared
#      install to a third prefix, and checks that nothing installed names
#      the deleted folders; then runs, from the moved prefix, `sinew
#      --version`, `sinew run arm`, `sinew experiment c1` and the installed
#      worm with its profile image (share/sinew, through SINEW_DATA_DIR);
#   4. runs the Python package's pytest suite (python/tests) against the
#      moved install: the package from P/lib/python3/dist-packages through
#      PYTHONPATH, SINEW_LIBRARY_DIR unset, so that it must find the libraries
#      it was installed with, and the moved sinew program to compare runs
#      with (needs a python3 with numpy and pytest: tools/setup.sh);
#   5. checks that the shared libraries export only the public API: every
#      dynamic symbol of librb.so starts with rb_, of libmu.so with mu_, and
#      each is declared RB_API/MU_API in an installed header (and the other
#      way round); and that libmu needs libpng, not Cairo;
#   6. compiles every installed public header alone as C17 and as C++17, with
#      gcc, g++, clang and clang++, warnings as errors;
#   7. builds the examples of docs/examples with sinew as a subproject
#      (add_subdirectory: the libraries only, no Criterion or GTK looked
#      for), and against both prefixes with gcc and with clang, through
#      find_package (CMake, the C++ example too) and through pkg-config
#      (make), and runs each one: each checks its own result (a rebound
#      height, a pendulum's period, a muscle flexing an elbow, the arm model
#      flexing) and exits non-zero when it is wrong.
#
# Prints one line per check and a closing "N passed, N failed"; exits 1 if
# anything failed, 2 on bad usage.
set -uo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
source_dir=$PWD

if (($# != 1)) || [[ ! -f "$1/CMakeCache.txt" ]]; then
    echo "usage: tools/check_install.sh STATIC_BUILD_DIR (a configured and built tree)" >&2
    exit 2
fi
static_build=$(cd "$1" && pwd)
# The version, as rb/version.h gives it ("0.2.0").
version=$(sed -n 's/^#define RB_VERSION_\(MAJOR\|MINOR\|PATCH\) \([0-9]*\)$/\2/p' engine/include/rb/version.h | paste -sd.)

work=$(mktemp -d /tmp/sinew-install-XXXXXX)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0
log=$work/log.txt

# Runs a check: its name, then the command; on failure shows the command's
# output (kept in $log).
check()
{
    local name=$1
    shift
    if "$@" >"$log" 2>&1; then
        echo "ok   $name"
        passed=$((passed + 1))
    else
        echo "FAIL $name"
        sed 's/^/     | /' "$log" | tail -n 40
        failed=$((failed + 1))
    fi
}

# ---- 1. The static install -------------------------------------------------
static_prefix=$work/static
check "install the static build" cmake --install "$static_build" --prefix "$static_prefix"

# ---- 2. A shared build from a copy of the sources --------------------------
copy=$work/source-copy
shared_build=$work/build-shared
shared_first=$work/shared-first
build_shared()
{
    mkdir -p "$copy" &&
        git ls-files -z --cached --others --exclude-standard | xargs -0 tar -cf - | tar -xf - -C "$copy" &&
        cmake -S "$copy" -B "$shared_build" -DBUILD_SHARED_LIBS=ON -DCMAKE_BUILD_TYPE=Release \
            "-DCMAKE_C_FLAGS_RELEASE=-O2 -DNDEBUG" -DCMAKE_INTERPROCEDURAL_OPTIMIZATION=ON -DSINEW_WERROR=ON \
            -DSINEW_BUILD_TESTS=OFF -DSINEW_BUILD_BENCHMARKS=OFF -DSINEW_BUILD_VIEWER=OFF -DSINEW_BUILD_DOCS=OFF &&
        cmake --build "$shared_build" -j2 &&
        cmake --install "$shared_build" --prefix "$shared_first"
}
check "build and install a copy of the sources with BUILD_SHARED_LIBS=ON" build_shared

# ---- 3. Moved, with its sources and build tree gone ------------------------
shared_prefix=$work/shared
relocate()
{
    rm -rf "$copy" "$shared_build" && mv "$shared_first" "$shared_prefix" &&
        if grep -rl -e "$copy" -e "$shared_build" -e "$shared_first" "$shared_prefix"; then
            echo "the files above name the deleted source, build or install folder"
            return 1
        fi
}
check "delete the copy's sources and build tree, move the install" relocate
run_moved()
(
    out=$work/moved-run
    mkdir -p "$out" && cd "$out" &&
        env -u SINEW_DATA_DIR "$shared_prefix/bin/sinew" --version | grep -qx "sinew $version" &&
        env -u SINEW_DATA_DIR "$shared_prefix/bin/sinew" run arm --duration 1 --out "$out" &&
        test -s "$out/arm.csv" &&
        env -u SINEW_DATA_DIR "$shared_prefix/bin/sinew" experiment c1 --out "$out" &&
        test -s "$out/c1_hill_curves.csv" && test -s "$out/c1_hill_curves.png" &&
        # The installed worm names its profile image beside it, in share/sinew.
        env -u SINEW_DATA_DIR "$shared_prefix/bin/sinew" check "$shared_prefix/share/sinew/worm.json" &&
        SINEW_DATA_DIR="$shared_prefix/share/sinew" "$shared_prefix/bin/sinew" run worm --duration 0.1 \
            --recruit "Torque Muscle=100" --out "$out" && grep -q 'Torque Muscle.exertion' "$out/worm.csv"
)
check "the moved install runs sinew --version, run arm, experiment c1 and its share/sinew worm" run_moved

# ---- 4. The Python package, from the moved install -------------------------
# The first python3 that imports numpy and pytest: the one on PATH, else
# Debian's own (a PATH may hold another Python without Debian's packages).
python_with_pytest()
{
    local candidate
    for candidate in "$(command -v python3)" /usr/bin/python3; do
        if [[ -x "$candidate" ]] && "$candidate" -c "import numpy, pytest" 2>/dev/null; then
            echo "$candidate"
            return 0
        fi
    done
    echo "no python3 imports numpy and pytest (tools/setup.sh installs python3-numpy and python3-pytest)" >&2
    return 1
}
python_moved()
(
    python=$(python_with_pytest) || exit 1
    packages=$shared_prefix/lib/python3/dist-packages
    cd "$work" &&
        # The package names the libraries of its own prefix.
        env -u SINEW_LIBRARY_DIR PYTHONPATH="$packages" PYTHONDONTWRITEBYTECODE=1 "$python" -c \
            'import sinew, sys; print(*sinew.library_paths); sys.exit(any(not p.startswith(sys.argv[1]) for p in sinew.library_paths))' \
            "$shared_prefix/lib/" &&
        env -u SINEW_LIBRARY_DIR -u SINEW_DATA_DIR PYTHONPATH="$packages" SINEW_PYTHON_INSTALLED=1 \
            SINEW_EXECUTABLE="$shared_prefix/bin/sinew" PYTHONDONTWRITEBYTECODE=1 \
            "$python" -m pytest -q -p no:cacheprovider "$source_dir/python/tests"
)
check "the moved install's Python package passes its pytest suite (python/tests)" python_moved

# ---- 5. Only the public API leaves the shared libraries --------------------
exports_match()
{
    local library=$1 prefix=$2 macro=$3 headers=$4
    local exported declared
    exported=$(nm -D --defined-only "$shared_prefix/lib/lib$library.so" | awk '{print $3}' | sort -u)
    declared=$(grep -ho "^$macro [^(]*[ *]\($prefix[a-z0-9_]*\)(" "$shared_prefix/include/$headers"/*.h |
        sed 's/.*[ *]\([a-z0-9_]*\)($/\1/' | sort -u)
    if grep -v "^$prefix" <<<"$exported"; then
        echo "lib$library.so exports the symbols above, which are not $prefix*"
        return 1
    fi
    if ! diff <(echo "$exported") <(echo "$declared"); then
        echo "lib$library.so's exports (<) differ from the $macro declarations of include/$headers (>)"
        return 1
    fi
    echo "$(wc -l <<<"$exported") symbols, all declared with $macro"
}
check "librb.so exports exactly the RB_API functions" exports_match rb rb_ RB_API rb
check "libmu.so exports exactly the MU_API functions" exports_match mu mu_ MU_API mu
check "librb.so and libmu.so carry their soname" \
    bash -c "readelf -d '$shared_prefix/lib/librb.so' | grep -q 'SONAME.*librb.so.0.2' &&
             readelf -d '$shared_prefix/lib/libmu.so' | grep -q 'SONAME.*libmu.so.0.2'"
# The muscle layer reads profile images with libpng; the drawing library
# (Cairo) is the tools' alone.
check "libmu.so needs libpng and not Cairo" \
    bash -c "readelf -d '$shared_prefix/lib/libmu.so' | grep -q 'NEEDED.*libpng' &&
             ! readelf -d '$shared_prefix/lib/libmu.so' | grep -q 'NEEDED.*cairo' &&
             ! grep -q cairo '$shared_prefix/lib/pkgconfig/sinew-mu.pc'"

# ---- 6. Each public header compiles alone as C17 and C++17 -----------------
headers_compile()
{
    local header source status=0
    for header in "$static_prefix"/include/rb/*.h "$static_prefix"/include/mu/*.h; do
        source=${header#"$static_prefix/include/"}
        printf '#include "%s"\ntypedef int header_compiles_alone;\n' "$source" >"$work/header.c"
        cp "$work/header.c" "$work/header.cpp"
        for compiler in "gcc -std=c17" "clang -std=c17"; do
            $compiler -Wall -Wextra -Wpedantic -Werror -I"$static_prefix/include" -c "$work/header.c" \
                -o /dev/null || { echo "$source: $compiler"; status=1; }
        done
        for compiler in "g++ -std=c++17" "clang++ -std=c++17"; do
            $compiler -Wall -Wextra -Wpedantic -Werror -I"$static_prefix/include" -c "$work/header.cpp" \
                -o /dev/null || { echo "$source: $compiler"; status=1; }
        done
    done
    return "$status"
}
check "every public header compiles alone as C17 and C++17 (gcc, g++, clang, clang++)" headers_compile

# ---- 7. The examples, built on each install with each compiler -------------
examples_cmake()
{
    local prefix=$1 cc=$2 cxx=$3 build=$work/examples-cmake-$4-$2
    cmake -S docs/examples -B "$build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_C_COMPILER="$cc" \
        -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Release &&
        cmake --build "$build" -j2 &&
        "$build/bouncing_ball" && "$build/pendulum" && "$build/muscle_bone" && "$build/arm_model"
}
examples_pkg_config()
{
    local prefix=$1 cc=$2 kind=$3 build=$work/examples-make-$3-$2 flags=
    if [[ "$kind" == static ]]; then
        flags=--static
    fi
    mkdir -p "$build" &&
        PKG_CONFIG_PATH="$prefix/lib/pkgconfig" make -C "$build" -f "$source_dir/docs/examples/Makefile" \
            CC="$cc" CFLAGS="-O2 -Wall -Wextra -Werror" PKG_CONFIG_FLAGS="$flags" &&
        LD_LIBRARY_PATH="$prefix/lib" "$build/bouncing_ball" &&
        LD_LIBRARY_PATH="$prefix/lib" "$build/pendulum" &&
        LD_LIBRARY_PATH="$prefix/lib" "$build/muscle_bone"
}
# As a subproject: only the two libraries are built, and nothing looks for
# Criterion, GTK or Doxygen.
examples_subproject()
{
    local build=$work/examples-subproject
    cmake -S docs/examples -B "$build" -DSINEW_SOURCE_DIR="$source_dir" -DCMAKE_BUILD_TYPE=Release &&
        if grep -iE "^(CRITERION|GTK4|DOXYGEN)" "$build/CMakeCache.txt"; then
            echo "the subproject looked for the above"
            return 1
        fi &&
        cmake --build "$build" -j2 &&
        if [[ -e "$build/sinew/tools" || -e "$build/sinew/tests" || -e "$build/sinew/bench" ]]; then
            echo "the subproject built its tools, tests or benchmarks"
            return 1
        fi &&
        "$build/bouncing_ball" && "$build/pendulum" && "$build/muscle_bone" && "$build/arm_model"
}
check "examples with sinew as a subproject (add_subdirectory): the libraries alone" examples_subproject

for kind in static shared; do
    prefix=$work/$kind
    for compilers in "gcc g++" "clang clang++"; do
        read -r cc cxx <<<"$compilers"
        check "examples on the $kind install, find_package, $cc and $cxx" examples_cmake "$prefix" "$cc" "$cxx" "$kind"
        check "examples on the $kind install, pkg-config, $cc" examples_pkg_config "$prefix" "$cc" "$kind"
    done
done

echo "install: ${passed} passed, ${failed} failed"
((failed == 0))
