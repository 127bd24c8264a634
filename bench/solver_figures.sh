#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The solver benchmark's figures (docs/benchmarks.md, "Accuracy against
# cost"): bench_solver sweeps each solver's velocity iterations, position
# (or relax) passes and substeps on the swinging 100:1 chain, the
# pendulum and the joint grid; `sinew plot` then draws, for each scene,
# the error against the median ms per step, one curve per solver through
# its front (the settings no cheaper one beats; the others as rings), on
# logarithmic axes:
#   solver_chain_swing.png  the chain's worst joint gap (m)
#   solver_pendulum.png     the pendulum's largest energy drift |E - E0|/E0
#   solver_joint_grid.png   the joint grid's worst joint gap (m)
# Settings that diverged are left out (a log axis shows no infinity).
#
# usage: bench/solver_figures.sh [--runs N] [--build-dir DIR] [--out DIR] [--from DIR]
#   --runs N       repetitions of each setting; a time is the median over them (default 5)
#   --build-dir D  sinew's build directory (default build/release): bench/bench_solver, tools/sinew
#   --out DIR      where the figures go (default docs/figures)
#   --from DIR     draw from the CSVs an earlier run left in DIR instead of measuring
# The CSVs (bench_solver_SCENE.csv) go to BUILD_DIR/bench/solver_figures/.
# Exit status: 0 success, 1 failure, 2 bad command line.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
runs=5
build_dir="$root/build/release"
out="$root/docs/figures"
from=""

usage() {
    sed -n 's/^# \{0,1\}//; /^usage:/,/^Exit status/p' "${BASH_SOURCE[0]}"
}

bad_usage() {
    echo "solver_figures.sh: $1" >&2
    usage >&2
    exit 2
}

while [[ $# -gt 0 ]]; do
    case "$1" in
    --runs | --build-dir | --out | --from)
        [[ $# -ge 2 ]] || bad_usage "$1 needs a value"
        case "$1" in
        --runs) runs=$2 ;;
        --build-dir) build_dir=$2 ;;
        --out) out=$2 ;;
        --from) from=$2 ;;
        esac
        shift 2
        ;;
    --help | -h)
        usage
        exit 0
        ;;
    *) bad_usage "unknown argument \"$1\"" ;;
    esac
done
[[ "$runs" =~ ^[1-9][0-9]*$ ]] || bad_usage "--runs expects a whole number above 0, got \"$runs\""

bench="$build_dir/bench/bench_solver"
sinew="$build_dir/tools/sinew"
for program in "$bench" "$sinew"; do
    if [[ ! -x "$program" ]]; then
        echo "solver_figures.sh: $program is missing; build it first (cmake --build --preset release)" >&2
        exit 1
    fi
done
if [[ ! -d "$out" ]]; then
    echo "solver_figures.sh: --out $out: no such folder" >&2
    exit 1
fi

csv_dir=${from:-"$build_dir/bench/solver_figures"}
scenes=(chain_swing pendulum joint_grid)
if [[ -z "$from" ]]; then
    mkdir -p "$csv_dir"
    for scene in "${scenes[@]}"; do
        echo "bench_solver --scene $scene --runs $runs"
        "$bench" --scene "$scene" --runs "$runs" --csv "$csv_dir/bench_solver_$scene.csv" >/dev/null
    done
fi

# The runs behind the times, as the CSVs say (--from may hold another count).
runs=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "runs") c = i } NR == 2 { print $c; exit }' \
    "$csv_dir/bench_solver_chain_swing.csv")

# scene, column along y, its axis's label, the title
plot() {
    local scene=$1 column=$2 label=$3 title=$4
    "$sinew" plot "$csv_dir/bench_solver_$scene.csv" --where diverged=no --x median_ms --y "$column" \
        --group correction --front --log-x --log-y --x-label "time per step (ms, median of $runs runs)" \
        --y-label "$label" --title "$title" --out "$out/solver_$scene.png"
}
plot chain_swing worst_gap_m "worst joint gap (m)" "Chain of 40 links and a 100:1 box, swinging, 5 s"
plot pendulum energy_drift_max "largest energy drift |E - E0| / E0" "Pendulum, 1 m, released at 90°, 20 s"
plot joint_grid worst_gap_m "worst joint gap (m)" "Joint grid, 100 x 100 bodies, 2 s"
