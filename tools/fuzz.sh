#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds the fuzz targets of fuzz/ with clang (libFuzzer, AddressSanitizer,
# UndefinedBehaviorSanitizer) and runs each: first its regression corpus
# fuzz/regressions/<target>/ (every input that ever failed: each must pass),
# then a fuzzing session of a bounded time.
#
#   tools/fuzz.sh [--seconds N] [--seed N] [--build DIR] [TARGET...]
#
#   --seconds N  fuzz each target for N s (default 60; 0 only replays)
#   --seed N     libFuzzer's random seed (default 1, so that a run is reproducible;
#                0 picks one at random)
#   --build DIR  the build folder (default build/fuzz); the working corpora
#                grow in DIR/corpus/<target>, failing inputs land in
#                DIR/artifacts/<target>
#   TARGET       fuzz_model, fuzz_control_file, fuzz_csv_chart, fuzz_pool_profile,
#                fuzz_sweep_plan
#                (default: all)
#
# The last line reads "fuzz: N passed, N failed", counting each replayed
# input and each session; the exit status is non-zero when anything failed.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

usage()
{
    sed -n '3,20s/^# \{0,1\}//p' "$0"
}

all_targets=(fuzz_model fuzz_control_file fuzz_csv_chart fuzz_pool_profile fuzz_sweep_plan)
seconds=60
seed=1
build=build/fuzz
targets=()
while (($#)); do
    case "$1" in
    --seconds | --seed | --build)
        if (($# < 2)); then
            echo "fuzz.sh: $1 needs a value" >&2
            exit 2
        fi
        case "$1" in
        --seconds) seconds=$2 ;;
        --seed) seed=$2 ;;
        --build) build=$2 ;;
        esac
        shift 2
        ;;
    -h | --help)
        usage
        exit 0
        ;;
    fuzz_model | fuzz_control_file | fuzz_csv_chart | fuzz_pool_profile | fuzz_sweep_plan)
        targets+=("$1")
        shift
        ;;
    *)
        echo "fuzz.sh: unknown argument '$1'" >&2
        usage >&2
        exit 2
        ;;
    esac
done
for value in "$seconds" "$seed"; do
    if [[ ! "$value" =~ ^[0-9]+$ ]]; then
        echo "fuzz.sh: '$value' is not a whole number" >&2
        exit 2
    fi
done
if ((${#targets[@]} == 0)); then
    targets=("${all_targets[@]}")
fi

# ---- What each target reads ---------------------------------------------------
# Seeds: the inputs the project already has, so that fuzzing starts from
# files that get deep into each parser. Largest input: a few times the
# largest seed, so that inputs stay quick while structure can still grow.
seeds()
{
    case "$1" in
    fuzz_model) printf '%s\n' models/*.json tests/data/bad_models/*.json tests/data/models/*.json ;;
    fuzz_control_file) printf '%s\n' models/controls/* fuzz/seeds/control_file/* ;;
    fuzz_csv_chart) printf '%s\n' models/data/hill-curves.csv fuzz/seeds/csv_chart/* ;;
    fuzz_pool_profile) printf '%s\n' models/worm-pool.png fuzz/seeds/pool_profile/* ;;
    fuzz_sweep_plan) printf '%s\n' fuzz/seeds/sweep_plan/* ;;
    esac
}
declare -A max_len=([fuzz_model]=32768 [fuzz_control_file]=4096 [fuzz_csv_chart]=16384 [fuzz_pool_profile]=8192 [fuzz_sweep_plan]=4096)

# ---- Build --------------------------------------------------------------------
# Debug keeps the assertions; -O1 as the asan preset, for speed.
printf '==== fuzz: building the targets in %s\n' "$build"
if ! cmake -S . -B "$build" -DCMAKE_C_COMPILER=clang -DCMAKE_BUILD_TYPE=Debug -DCMAKE_C_FLAGS_DEBUG="-O1 -g" \
    -DSINEW_BUILD_FUZZERS=ON -DSINEW_WERROR=ON -DSINEW_BUILD_TESTS=OFF -DSINEW_BUILD_BENCHMARKS=OFF \
    -DSINEW_BUILD_VIEWER=OFF -DSINEW_BUILD_DOCS=OFF -DSINEW_INSTALL=OFF >/dev/null ||
    ! cmake --build "$build" -j2 --target "${targets[@]}"; then
    echo "fuzz: the build failed"
    echo "fuzz: 0 passed, 1 failed"
    exit 1
fi

# The sanitizers' settings of the asan preset; libFuzzer reports leaks itself.
export ASAN_OPTIONS=abort_on_error=1
export LSAN_OPTIONS=suppressions=$PWD/tools/lsan.supp
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

passed=0
failed=0
# An input over this many seconds is a hang (libFuzzer reports it as a timeout).
timeout_s=10

# Says how to reproduce a failing input and keep it as a regression.
explain()
{
    local target=$1 input=$2
    echo "fuzz: $target failed on $input"
    echo "  reproduce: $build/fuzz/$target $input"
    echo "  once fixed, keep it: cp $input fuzz/regressions/$target/<what-it-does> (a name saying what the input does)"
}

for target in "${targets[@]}"; do
    binary=$build/fuzz/$target
    options=(-timeout="$timeout_s" -max_len="${max_len[$target]}" -rss_limit_mb=2048)
    # A target's dictionary: the words of its format, for the mutations.
    if [[ -f fuzz/$target.dict ]]; then
        options+=(-dict="fuzz/$target.dict")
    fi

    # ---- Replay every input that ever failed --------------------------------
    regressions=()
    if [[ -d fuzz/regressions/$target ]]; then
        mapfile -t regressions < <(find "fuzz/regressions/$target" -type f | sort)
    fi
    printf '\n==== fuzz: %s: replaying %d regression inputs\n' "$target" "${#regressions[@]}"
    for input in "${regressions[@]}"; do
        # With a file argument libFuzzer runs that input once instead of fuzzing.
        if "$binary" "${options[@]}" "$input" >"$build/replay.log" 2>&1; then
            passed=$((passed + 1))
        else
            cat "$build/replay.log"
            explain "$target" "$input"
            failed=$((failed + 1))
        fi
    done

    # ---- Fuzz -----------------------------------------------------------------
    if ((seconds == 0)); then
        continue
    fi
    corpus=$build/corpus/$target
    artifacts=$build/artifacts/$target
    mkdir -p "$corpus" "$artifacts"
    while IFS= read -r seed_file; do
        cp -n "$seed_file" "$corpus/"
    done < <(seeds "$target")
    printf '\n==== fuzz: %s: %d s from %d inputs (seed %d)\n' "$target" "$seconds" \
        "$(find "$corpus" -type f | wc -l)" "$seed"
    before=$(find "$artifacts" -type f | sort)
    log=$build/$target.log
    if "$binary" "${options[@]}" -seed="$seed" -max_total_time="$seconds" -print_final_stats=1 \
        -artifact_prefix="$artifacts/" "$corpus" >"$log" 2>&1; then
        grep -E '^(Done|stat::number_of_executed_units|stat::peak_rss_mb)' "$log" || true
        passed=$((passed + 1))
    else
        tail -n 60 "$log" # the sanitizer's or libFuzzer's report and the stack
        new=$(comm -13 <(echo "$before") <(find "$artifacts" -type f | sort))
        explain "$target" "${new:-"(no input saved: see $log)"}"
        failed=$((failed + 1))
    fi
done

echo "fuzz: $passed passed, $failed failed"
((failed == 0))
