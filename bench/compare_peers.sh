#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Compares sinew's engine with the peer engines Debian packages, Box2D 2.4.1
# and Chipmunk2D 7.0.3, on the peer harnesses' scenes (docs/benchmarks.md), as ratios
# measured in one session on this machine.
#
# Scenes and protocols (dt = 1/60 s, gravity (0, -10)):
#   pyramid20, pyramid100  60 warm-up and 300 timed steps; sinew through
#       bench_engine (engine defaults). Figure: boxes moved > 0.25 m sideways.
#   joint_grid  100 x 100, 60 warm-up and 60 timed steps (Chipmunk blows up
#       after 2-3 s, so all three stop at 2 s); sinew through bench_solver
#       --single (engine defaults). The peers print no gap for the grid.
#   chain_hang, chain_swing  40 links and a 100:1 box, 300 steps, every one
#       timed (the peers with --warmup 0 --steps 300); sinew through
#       bench_solver --single. Figures: the worst joint gap over 0-5 s and
#       the gap at 5 s (m), which the peers compute the same way.
# Box2D runs 8 velocity / 3 position iterations, Chipmunk 10 iterations.
#
# Each repetition runs, for each scene, sinew, Box2D and Chipmunk one after
# the other, so that a change in the machine's load touches all three
# engines alike. The tables give, per engine and scene, the median over
# repetitions of each run's median ms per step, and the ratios
# sinew/Box2D and sinew/Chipmunk (below 1: sinew is faster); the other
# figures come from the last repetition (every engine is deterministic).
#
# usage: bench/compare_peers.sh [--runs R] [--scenes LIST] [--out FILE] [--build-dir DIR] [--peers DIR]
#                                [--solver NAME] [--substeps N] [--vel N] [--pos N]
#   --runs R       repetitions, 1 .. 100 (default 3)
#   --scenes LIST  comma-separated, of pyramid20, pyramid100, joint_grid,
#                  chain_hang, chain_swing (default all five)
#   --out FILE     CSV of the tables, one row per scene, empty fields where a
#                  figure does not apply (default compare_peers.csv); written
#                  to a temporary name and renamed
#   --build-dir D  sinew's build directory (default build/release)
#   --peers DIR    the peer harnesses' folder (default $SINEW_PEERS; one of the two is needed)
#   --solver NAME  sinew's solver: baumgarte, ngs or soft_step (default the engine's)
#   --substeps N, --vel N, --pos N
#                  sinew's substeps (1 .. 1000), velocity passes (1 .. 1000) and
#                  position or relax passes (0 .. 1000), default the engine's;
#                  e.g. Box2D v3's budget: --solver soft_step --substeps 4 --vel 1 --pos 1
# Exit status: 0 success, 1 failure, 2 bad command line.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
all_scenes=(pyramid20 pyramid100 joint_grid chain_hang chain_swing)
runs=3
scenes=("${all_scenes[@]}")
out=compare_peers.csv
build_dir="$root/build/release"
peers_dir=${SINEW_PEERS:-}
# Sinew's settings when given, for bench_engine (pyramids) and bench_solver (joints).
engine_settings=()
solver_settings=()

# bench_solver's protocol for the joint scenes, given to the peers too.
grid_warmup=60
grid_steps=60
chain_steps=300

usage() {
    sed -n 's/^# \{0,1\}//; /^usage:/,/^Exit status/p' "${BASH_SOURCE[0]}"
}

bad_usage() {
    echo "compare_peers.sh: $1" >&2
    usage >&2
    exit 2
}

# Sets `scenes` from a comma-separated list, refusing unknown names and
# keeping the order of all_scenes.
parse_scenes() {
    local list=$1 name known s wanted=()
    IFS=, read -r -a wanted <<<"$list"
    ((${#wanted[@]})) || bad_usage "--scenes expects a comma-separated list of ${all_scenes[*]}, got \"$list\""
    for name in "${wanted[@]}"; do
        known=no
        for s in "${all_scenes[@]}"; do
            [[ "$name" == "$s" ]] && known=yes
        done
        [[ $known == yes ]] || bad_usage "--scenes: unknown scene \"$name\" (expected ${all_scenes[*]})"
    done
    scenes=()
    for s in "${all_scenes[@]}"; do
        for name in "${wanted[@]}"; do
            if [[ "$name" == "$s" ]]; then
                scenes+=("$s")
                break
            fi
        done
    done
}

while [[ $# -gt 0 ]]; do
    case "$1" in
        --help | -h)
            usage
            exit 0
            ;;
        --solver)
            [[ $# -ge 2 ]] || bad_usage "--solver needs a value"
            case "$2" in
                baumgarte | ngs | soft_step) ;;
                *) bad_usage "--solver expects baumgarte, ngs or soft_step, got \"$2\"" ;;
            esac
            engine_settings+=(--solver "$2")
            solver_settings+=(--method "$2")
            shift 2
            ;;
        --substeps | --vel | --pos)
            [[ $# -ge 2 ]] || bad_usage "$1 needs a value"
            lowest=1
            [[ "$1" == --pos ]] && lowest=0
            if ! [[ "$2" =~ ^[0-9]{1,4}$ ]] || ((10#$2 < lowest || 10#$2 > 1000)); then
                bad_usage "$1 expects an integer from $lowest to 1000, got \"$2\""
            fi
            engine_settings+=("$1" "$((10#$2))")
            solver_settings+=("$1" "$((10#$2))")
            shift 2
            ;;
        --runs | --scenes | --out | --build-dir | --peers)
            [[ $# -ge 2 && -n "$2" ]] || bad_usage "$1 needs a value"
            case "$1" in
                --runs)
                    if ! [[ "$2" =~ ^[0-9]{1,3}$ ]] || ((10#$2 < 1 || 10#$2 > 100)); then
                        bad_usage "--runs expects an integer from 1 to 100, got \"$2\""
                    fi
                    runs=$((10#$2))
                    ;;
                --scenes) parse_scenes "$2" ;;
                --out) out=$2 ;;
                --build-dir) build_dir=$2 ;;
                --peers) peers_dir=$2 ;;
            esac
            shift 2
            ;;
        *)
            bad_usage "unknown argument \"$1\""
            ;;
    esac
done

# The peers link the Debian packages; without them there is nothing to compare.
for package in libbox2d-dev libchipmunk-dev; do
    if [[ "$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null)" != "install ok installed" ]]; then
        echo "compare_peers.sh: $package is not installed; run tools/setup.sh --peers first" >&2
        exit 1
    fi
done
if [[ -z "$peers_dir" ]]; then
    echo "compare_peers.sh: where are the peer harnesses? give --peers DIR or set SINEW_PEERS" >&2
    exit 2
fi
if [[ ! -f "$peers_dir/Makefile" ]]; then
    echo "compare_peers.sh: no peer harnesses in $peers_dir (give --peers DIR)" >&2
    exit 1
fi
make -s -C "$peers_dir" >&2

for program in bench_engine bench_solver; do
    if [[ ! -x "$build_dir/bench/$program" ]]; then
        echo "compare_peers.sh: $build_dir/bench/$program not found; build first:" >&2
        echo "  cmake --preset release && cmake --build --preset release" >&2
        exit 1
    fi
done

work=$(mktemp -d)
csv_tmp="$out.tmp.$$"
trap 'rm -rf "$work" "$csv_tmp"' EXIT

# The value of `key=value` in a peer's or bench_engine's line, or NA.
field() {
    local value
    value=$(grep -o " $2=[^ ]*" <<<" $1" | head -n 1 | cut -d= -f2)
    echo "${value:-NA}"
}

# The value of column `name` in the first data row of a CSV file, or NA.
csv_field() {
    awk -F, -v name="$2" 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == name) c = i; next }
        NR == 2 { v = c ? $c : ""; print (v == "" ? "NA" : v); exit }' "$1"
}

# Appends "engine scene median_ms moved worst_gap final_gap" (NA where a
# figure does not apply).
record() {
    local engine=$1 scene=$2 median=$3 moved=$4 worst=$5 final=$6
    if [[ "$median" == NA ]]; then
        echo "compare_peers.sh: no median_ms from $engine on $scene" >&2
        exit 1
    fi
    echo "$engine $scene $median $moved $worst $final" >>"$work/samples"
}

# Records one peer line: the pyramid's moved boxes, the chain's gaps.
record_peer() {
    local engine=$1 scene=$2 line=$3
    record "$engine" "$scene" "$(field "$line" median_ms)" "$(field "$line" lateral_gt_0.25)" \
        "$(field "$line" peak_sep_0_5s)" "$(field "$line" max_sep_5s)"
}

# One run of sinew on a joint scene through bench_solver at the engine's
# default settings (or those given); checks that it ran the protocol the
# peers are given.
run_sinew_joints() {
    local scene=$1 warmup=$2 steps=$3 csv="$work/bench_solver.csv"
    "$build_dir/bench/bench_solver" --scene "$scene" --single --runs 1 --csv "$csv" \
        ${solver_settings[@]+"${solver_settings[@]}"} >/dev/null
    if [[ "$(csv_field "$csv" warmup_steps)" != "$warmup" || "$(csv_field "$csv" timed_steps)" != "$steps" ]]; then
        echo "compare_peers.sh: warning: sinew's $scene ran $(csv_field "$csv" warmup_steps) warm-up and" \
            "$(csv_field "$csv" timed_steps) timed steps, the peers $warmup and $steps" \
            "(diverged=$(csv_field "$csv" diverged))" >&2
    fi
    record sinew "$scene" "$(csv_field "$csv" median_ms)" NA "$(csv_field "$csv" worst_gap_m)" \
        "$(csv_field "$csv" final_gap_m)"
    sinew_joint_settings="$(csv_field "$csv" correction), $(csv_field "$csv" velocity_iterations) vel /"
    sinew_joint_settings+=" $(csv_field "$csv" position_iterations) pos / $(csv_field "$csv" substeps) substeps"
}

sinew_pyramid_settings=""
sinew_joint_settings=""
for ((r = 1; r <= runs; ++r)); do
    for scene in "${scenes[@]}"; do
        echo "repetition $r/$runs, $scene" >&2
        case "$scene" in
            pyramid20 | pyramid100)
                base=${scene#pyramid}
                line=$("$build_dir/bench/bench_engine" --scene "$scene" --runs 1 --csv "$work/bench_engine.csv" \
                    ${engine_settings[@]+"${engine_settings[@]}"} | grep '^engine=')
                record sinew "$scene" "$(field "$line" median_ms)" "$(field "$line" lateral_gt_0.25)" NA NA
                sinew_pyramid_settings="$(field "$line" solver), $(field "$line" vel_iters) vel / $(field "$line" pos_iters) pos"
                sinew_pyramid_settings+=" / $(field "$line" relax_iters) relax / $(field "$line" substeps) substeps"
                record_peer box2d "$scene" "$("$peers_dir/box2d24_bench" pyramid --base "$base" --vel 8 --pos 3)"
                record_peer chipmunk "$scene" \
                    "$("$peers_dir/chipmunk_bench" pyramid --base "$base" --iters 10 | grep '^engine=')"
                ;;
            joint_grid)
                run_sinew_joints joint_grid "$grid_warmup" "$grid_steps"
                record_peer box2d "$scene" "$("$peers_dir/box2d24_bench" joint_grid --vel 8 --pos 3 \
                    --warmup "$grid_warmup" --steps "$grid_steps")"
                record_peer chipmunk "$scene" "$("$peers_dir/chipmunk_bench" joint_grid --iters 10 \
                    --warmup "$grid_warmup" --steps "$grid_steps" | grep '^engine=')"
                ;;
            chain_hang | chain_swing)
                layout=${scene#chain_}
                run_sinew_joints "$scene" 0 "$chain_steps"
                record_peer box2d "$scene" "$("$peers_dir/box2d24_bench" chain --layout "$layout" --vel 8 --pos 3 \
                    --warmup 0 --steps "$chain_steps")"
                record_peer chipmunk "$scene" "$("$peers_dir/chipmunk_bench" chain --layout "$layout" --iters 10 \
                    --warmup 0 --steps "$chain_steps" | grep '^engine=')"
                ;;
        esac
    done
done

# Median of the samples of one engine and scene (mean of the middle two when
# the count is even).
median_of() {
    awk -v e="$1" -v s="$2" '$1 == e && $2 == s { print $3 }' "$work/samples" | sort -g |
        awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}

# Column `column` (4 moved, 5 worst gap, 6 final gap) of the last
# repetition, empty when it does not apply.
last_of() {
    awk -v e="$1" -v s="$2" -v c="$3" '$1 == e && $2 == s { v = $c } END { print (v == "NA" ? "" : v) }' \
        "$work/samples"
}

host=$(hostname)
{
    echo "host,scene,runs,sinew_ms,box2d_ms,chipmunk_ms,sinew_over_box2d,sinew_over_chipmunk,sinew_moved,box2d_moved,chipmunk_moved,sinew_worst_gap_m,box2d_worst_gap_m,chipmunk_worst_gap_m,sinew_final_gap_m,box2d_final_gap_m,chipmunk_final_gap_m"
    for scene in "${scenes[@]}"; do
        s=$(median_of sinew "$scene")
        b=$(median_of box2d "$scene")
        c=$(median_of chipmunk "$scene")
        printf '%s,%s,%d,' "$host" "$scene" "$runs"
        awk -v s="$s" -v b="$b" -v c="$c" 'BEGIN { printf "%.4f,%.4f,%.4f,%.3f,%.3f", s, b, c, s / b, s / c }'
        for column in 4 5 6; do
            for engine in sinew box2d chipmunk; do
                printf ',%s' "$(last_of "$engine" "$scene" "$column")"
            done
        done
        printf '\n'
    done
} >"$csv_tmp"
mv "$csv_tmp" "$out"

echo
echo "median of $runs runs, ms per step on $host (Box2D: 8 vel / 3 pos; Chipmunk: 10 iterations;" \
    "sinew pyramid: ${sinew_pyramid_settings:-not run}; sinew joints: ${sinew_joint_settings:-not run})"
awk -F, 'function show(v) { return v == "" ? "-" : v }
    NR == 1 {
        printf "%-11s %9s %9s %9s %8s %8s   %-24s %-30s %s\n", "scene", "sinew", "box2d", "chipmunk", "s/box2d",
            "s/chipm", "moved (s/b/c)", "worst gap m (s/b/c)", "gap at end m (s/b/c)"
        next
    }
    {
        printf "%-11s %9.4f %9.4f %9.4f %8.3f %8.3f   %-24s %-30s %s\n", $2, $4, $5, $6, $7, $8,
            show($9) "/" show($10) "/" show($11), show($12) "/" show($13) "/" show($14),
            show($15) "/" show($16) "/" show($17)
    }' "$out"
echo "csv: $out"
