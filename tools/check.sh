#!/usr/bin/env bash
# The project's test command: everything CI checks, in one run.
#
#   1. tools/setup.sh (installs missing packages; does nothing when all present)
#   2. formatting: clang-format --dry-run --Werror over every *.c and *.h of
#      engine/ models/ tests/ bench/ tools/ musculo/
#   3. for the presets release and asan: configure with -DSINEW_WERROR=ON,
#      build, run ctest (output shown for failing tests)
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
for d in engine models tests bench tools musculo; do
    if [[ -d "$d" ]]; then
        dirs+=("$d")
    fi
done
sources=()
if ((${#dirs[@]})); then
    mapfile -d '' -t sources < <(find "${dirs[@]}" -type f \( -name '*.c' -o -name '*.h' \) -print0 | sort -z)
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

# ---- Build and test each preset ---------------------------------------------
# Sanitizer settings of the asan run (the asan test preset sets the same).
# LeakSanitizer suppressions, if any, may name only third-party internals.
asan_env=(
    ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
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

for p in "${presets[@]}"; do
    env_prefix=(env)
    if [[ "$p" == asan ]]; then
        env_prefix+=("${asan_env[@]}")
    fi
    step "$p" configure "${env_prefix[@]}" cmake --preset "$p" -DSINEW_WERROR=ON &&
        step "$p" build "${env_prefix[@]}" cmake --build --preset "$p" -j2 &&
        step "$p" test "${env_prefix[@]}" ctest --preset "$p" --output-on-failure &&
        summary+=("$p ok")
done

banner "summary"
summary_line=$(printf '%s, ' "${summary[@]}")
if ((failed)); then
    echo "check.sh: FAILED: ${summary_line%, }"
    exit 1
fi
echo "check.sh: all passed: ${summary_line%, }"
