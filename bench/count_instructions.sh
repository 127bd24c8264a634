#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Instructions per step of one bench_engine scene, counted by callgrind:
# repeatable where times are not (pyramid20 at the engine's defaults; the
# peer harnesses count Box2D 2.4.1 at 4.12 M and Chipmunk at 3.41 M, see
# docs/benchmarks.md).
#
# Method: bench_engine runs the scene twice under
# `valgrind --tool=callgrind`, once for SHORT_STEPS and once for
# LONG_STEPS steps (no warm-up, one run). Building the scene, the first
# steps and the report cost the same in both, so the difference divided
# by LONG_STEPS - SHORT_STEPS is the mean over steps 161 .. 260, after the
# contacts have formed and the warm starts have settled (the scene is
# deterministic, so both runs take the same first 160 steps). It includes
# bench_engine's own work per step: reading the clock and the step's
# profile, a few thousand instructions.
#
# usage: bench/count_instructions.sh [--scene NAME] [--solver NAME] [--substeps N] [--vel N] [--pos N]
#                                     [--build-dir DIR]
#   --scene NAME   a bench_engine scene (default pyramid20)
#   --solver NAME, --substeps N, --vel N, --pos N
#                  passed to bench_engine, which checks them (default the engine's)
#   --build-dir D  sinew's build directory (default build/release)
# Prints one line: scene, settings and instructions_per_step.
# Exit status: 0 success, 1 failure, 2 bad command line.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
SHORT_STEPS=160
LONG_STEPS=260
scene=pyramid20
settings=()
build_dir="$root/build/release"

usage() {
    sed -n 's/^# \{0,1\}//; /^usage:/,/^Exit status/p' "${BASH_SOURCE[0]}"
}

bad_usage() {
    echo "count_instructions.sh: $1" >&2
    usage >&2
    exit 2
}

while [[ $# -gt 0 ]]; do
    case "$1" in
        --help | -h)
            usage
            exit 0
            ;;
        --scene | --solver | --substeps | --vel | --pos | --build-dir)
            [[ $# -ge 2 && -n "$2" ]] || bad_usage "$1 needs a value"
            case "$1" in
                --scene) scene=$2 ;;
                --build-dir) build_dir=$2 ;;
                *) settings+=("$1" "$2") ;;
            esac
            shift 2
            ;;
        *)
            bad_usage "unknown argument \"$1\""
            ;;
    esac
done

engine="$build_dir/bench/bench_engine"
[[ -x "$engine" ]] || {
    echo "count_instructions.sh: $engine is missing: build the release preset first" >&2
    exit 1
}
command -v valgrind >/dev/null || {
    echo "count_instructions.sh: valgrind is missing (tools/setup.sh installs it)" >&2
    exit 1
}
# bench_engine's CSV goes to a scratch directory, removed on exit.
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
csv="$scratch/bench_engine.csv"

# bench_engine checks the scene and the settings: a bad one ends here with
# its message and exit status 2, before any slow run.
"$engine" --scene "$scene" --runs 1 --warmup 0 --steps 1 --csv "$csv" "${settings[@]}" >/dev/null || exit $?

# The instructions callgrind counted in a run of `steps` steps.
count() {
    local steps=$1 log
    log=$(valgrind --tool=callgrind --callgrind-out-file=/dev/null \
        "$engine" --scene "$scene" --runs 1 --warmup 0 --steps "$steps" --csv "$csv" "${settings[@]}" 2>&1 >/dev/null) || {
        echo "count_instructions.sh: bench_engine failed under valgrind:" >&2
        echo "$log" >&2
        exit 1
    }
    local refs
    refs=$(sed -n 's/.*Collected : *\([0-9][0-9,]*\).*/\1/p' <<<"$log" | tr -d ,)
    [[ -n "$refs" ]] || {
        echo "count_instructions.sh: no instruction count in valgrind's output:" >&2
        echo "$log" >&2
        exit 1
    }
    echo "$refs"
}

short=$(count "$SHORT_STEPS")
long=$(count "$LONG_STEPS")
per_step=$(((long - short) / (LONG_STEPS - SHORT_STEPS)))
echo "scene=$scene settings=${settings[*]:-defaults} steps=$((SHORT_STEPS + 1))..$LONG_STEPS instructions_per_step=$per_step"
