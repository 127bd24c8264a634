#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The project's test command: everything CI checks, in one run.
#
#   1. tools/setup.sh (installs missing packages; does nothing when all present)
#   2. formatting: clang-format --dry-run --Werror over every *.c, *.h and *.cpp of
#      engine/ models/ tests/ bench/ tools/ musculo/ fuzz/ docs/examples/ python/
#   3. licence: an SPDX line in every source, script and build file
#   4. for the presets release and asan: configure with -DSINEW_WERROR=ON,
#      build, run ctest (output shown for failing tests)
#   5. the release build installed, built shared, moved, and used by the
#      examples of docs/examples with gcc and clang and by the Python
#      package's tests (tools/check_install.sh)
#   6. fuzzing: the fuzz targets of fuzz/ built with clang's libFuzzer and the
#      sanitizers, every input that ever failed replayed, then each target
#      fuzzed for 60 s (tools/fuzz.sh, build/fuzz)
#
# Every stage runs even when an earlier one failed, so one run reports
# everything; the last line sums up, and the exit status is non-zero when
# anything failed.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

clang_format=${CLANG_FORMAT:-clang-format}
presets=(release asan)
failed=0
summary=()

banner()
{
    printf '\n==== %s\n' "$*"
}

banner "setup"
tools/setup.sh

# ---- Formatting -------------------------------------------------------------
banner "format ($("$clang_format" --version | sed 's/.*version \([0-9.]*\).*/clang-format \1/'))"
dirs=()
for d in engine models tests bench tools musculo fuzz docs/examples python; do
    if [[ -d "$d" ]]; then
        dirs+=("$d")
    fi
done
sources=()
if ((${#dirs[@]})); then
    mapfile -d '' -t sources < <(find "${dirs[@]}" -type f \( -name '*.c' -o -name '*.h' -o -name '*.cpp' \) -print0 | sort -z)
fi
unformatted=()
for f in "${sources[@]}"; do
    if ! "$clang_format" --dry-run --Werror "$f" >/dev/null 2>&1; then
        unformatted+=("$f")
    fi
done
if ((${#unformatted[@]})); then
    echo "not formatted (${#unformatted[@]} of ${#sources[@]} files):"
    printf '  %s\n' "${unformatted[@]}"
    echo "fix with: clang-format -i ${unformatted[*]}"
    summary+=("format FAIL (${#unformatted[@]} files)")
    failed=1
else
    echo "${#sources[@]} files formatted"
    summary+=("format ok")
fi

# ---- Licence lines ----------------------------------------------------------
# Every source, header, script and build file says its licence (LICENSE: MIT)
# in an SPDX line.
banner "licence lines"
unlicensed=()
while IFS= read -r -d '' f; do
    if ! grep -q 'SPDX-License-Identifier: MIT' "$f"; then
        unlicensed+=("$f")
    fi
done < <(git ls-files -z --cached --others --exclude-standard -- '*.c' '*.h' '*.cpp' '*.sh' '*.cmake' '*.in' '*.py' \
    '*CMakeLists.txt' '*Makefile' .ci/run)
if ((${#unlicensed[@]})); then
    echo "no 'SPDX-License-Identifier: MIT' line in:"
    printf '  %s\n' "${unlicensed[@]}"
    summary+=("licence FAIL (${#unlicensed[@]} files)")
    failed=1
else
    echo "every source, script and build file has its SPDX line"
    summary+=("licence ok")
fi

# ---- Build and test each preset ---------------------------------------------
# Sanitizer settings of the asan run (the asan test preset sets the same).
# LeakSanitizer suppressions (tools/lsan.supp) may name only third-party internals.
asan_env=(
    ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
    LSAN_OPTIONS=suppressions=$PWD/tools/lsan.supp
    UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
)

# Runs one step of a preset; on failure records "<preset> FAIL (<step>)".
step()
{
    local preset=$1 name=$2
    shift 2
    banner "$preset: $name"
    if "$@"; then
        return 0
    fi
    summary+=("$preset FAIL ($name)")
    failed=1
    return 1
}

# Runs ctest for a preset and adds its counts to the totals; ctest's own
# summary line reads "N% tests passed, F tests failed out of T".
tests_passed=0
tests_failed=0
run_ctest()
{
    local preset=$1 log status total failures
    shift
    log=$(mktemp)
    status=0
    "$@" ctest --preset "$preset" --output-on-failure 2>&1 | tee "$log" || status=$?
    total=$(sed -n 's/.*tests failed out of \([0-9]*\).*/\1/p' "$log" | tail -n 1)
    failures=$(sed -n 's/.* \([0-9]*\) tests failed out of.*/\1/p' "$log" | tail -n 1)
    rm -f "$log"
    if [[ -n "$total" && -n "$failures" ]]; then
        tests_passed=$((tests_passed + total - failures))
        tests_failed=$((tests_failed + failures))
    else
        tests_failed=$((tests_failed + 1))
    fi
    return "$status"
}

for p in "${presets[@]}"; do
    env_prefix=(env)
    if [[ "$p" == asan ]]; then
        env_prefix+=("${asan_env[@]}")
    fi
    step "$p" configure "${env_prefix[@]}" cmake --preset "$p" -DSINEW_WERROR=ON &&
        step "$p" build "${env_prefix[@]}" cmake --build --preset "$p" -j2 &&
        step "$p" test run_ctest "$p" "${env_prefix[@]}" &&
        summary+=("$p ok")
done

# Runs a stage whose script ends with "NAME: N passed, N failed": records
# "NAME ok" or "NAME FAIL", and adds its counts to the closing line's (one
# failure when it printed none).
counted_stage()
{
    local name=$1 log counts passed_here failed_here
    shift
    log=$(mktemp)
    if "$@" 2>&1 | tee "$log"; then
        summary+=("$name ok")
    else
        summary+=("$name FAIL")
        failed=1
    fi
    counts=$(sed -n "s/^$name: \([0-9]*\) passed, \([0-9]*\) failed$/\1 \2/p" "$log")
    rm -f "$log"
    if [[ -n "$counts" ]]; then
        read -r passed_here failed_here <<<"$counts"
        tests_passed=$((tests_passed + passed_here))
        tests_failed=$((tests_failed + failed_here))
    else
        tests_failed=$((tests_failed + 1))
    fi
}

# ---- The installed library, as other programs use it ------------------------
# On the release build: installed, built as shared libraries too, moved, and
# built on by the examples of docs/examples (tools/check_install.sh).
if [[ " ${summary[*]} " == *" release ok"* ]]; then
    banner "install: consumers, relocation, exported symbols, headers"
    counted_stage install tools/check_install.sh build/release
else
    summary+=("install skipped (release failed)")
    failed=1
fi

# ---- Fuzzing ------------------------------------------------------------------
# The regression corpora, then a fixed-seed session per target (tools/fuzz.sh).
banner "fuzz: regressions, then 60 s per target"
counted_stage fuzz tools/fuzz.sh --seconds 60

banner "summary"
summary_line=$(printf '%s, ' "${summary[@]}")
if ((failed)); then
    echo "check.sh: FAILED: ${summary_line%, }"
else
    echo "check.sh: all passed: ${summary_line%, }"
fi
# The closing line, counted over both presets' test programs, the install
# checks and the fuzzing.
echo "tests: ${tests_passed} passed, ${tests_failed} failed"
exit "$failed"
