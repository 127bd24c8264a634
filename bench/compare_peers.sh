#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Compares sinew's engine with the peer engines Debian packages, Box2D 2.4.1
# and Chipmunk2D 7.0.3, and with Box2D v3 when its harness is at hand, on the
# peer harnesses' scenes (docs/benchmarks.md), as ratios measured in one
# session on this machine.
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
# Box2D runs 8 velocity / 3 position iterations, Chipmunk 10 iterations,
# Box2D v3 its defaults (4 substeps); its harness, built outside the project
# from Box2D v3's source (the peers folder's build_box2d3.sh), comes in an
# SSE2 and an AVX2 variant, box2d3_bench_sse2 and box2d3_bench_avx2, and
# each one found runs as an engine of its own. Box2D v3 reports the grid's
# worst gap over every step, the others none.
#
# Each repetition runs, for each scene, sinew, Box2D, Chipmunk and Box2D v3
# one after the other, so that a change in the machine's load touches all
# the engines alike. The tables give, per engine and scene, the median over
# repetitions of each run's median ms per step, and the ratios of sinew's
# to each peer's (below 1: sinew is faster); the other figures come from
# the last repetition (every engine is deterministic).
#
# usage: bench/compare_peers.sh [--runs R] [--scenes LIST] [--out FILE] [--build-dir DIR] [--peers DIR]
#                                [--box2d3 PATH] [--solver NAME] [--substeps N] [--vel N] [--pos N]
#   --runs R       repetitions, 1 .. 100 (default 3)
#   --scenes LIST  comma-separated, of pyramid20, pyramid100, joint_grid,
#                  chain_hang, chain_swing (default all five)
#   --out FILE     CSV of the tables, one row per scene, empty fields where a
#                  figure does not apply (default compare_peers.csv); written
#                  to a temporary name and renamed
#   --build-dir D  sinew's build directory (default build/release)
#   --peers DIR    the peer harnesses' folder (default $SINEW_PEERS; one of the two is needed)
#   --box2d3 PATH  Box2D v3's harness: box2d3_bench_sse2 or box2d3_bench_avx2, or
#                  a folder holding either or both (default: those in the peers
#                  folder, if any; without them Box2D v3 is left out)
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
box2d3_path=""
# Box2D v3's harnesses found, and the engine name of each ("box2d3_sse2").
box2d3_harnesses=()
box2d3_engines=()
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
        --runs | --scenes | --out | --build-dir | --peers | --box2d3)
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
                --box2d3) box2d3_path=$2 ;;
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

# Adds Box2D v3's harness `program` if it is one (named box2d3_bench_sse2 or
# box2d3_bench_avx2 and executable); returns 1 otherwise.
add_box2d3() {
    local program=$1 name
    name=$(basename "$program")
    [[ -f "$program" && -x "$program" && "$name" =~ ^box2d3_bench_(sse2|avx2)$ ]] || return 1
    box2d3_harnesses+=("$program")
    box2d3_engines+=("box2d3_${BASH_REMATCH[1]}")
}
if [[ -n "$box2d3_path" ]]; then
    if [[ -d "$box2d3_path" ]]; then
        add_box2d3 "$box2d3_path/box2d3_bench_sse2" || true
        add_box2d3 "$box2d3_path/box2d3_bench_avx2" || true
        if ((${#box2d3_harnesses[@]} == 0)); then
            echo "compare_peers.sh: --box2d3: no executable box2d3_bench_sse2 or box2d3_bench_avx2 in $box2d3_path" >&2
            exit 1
        fi
    elif ! add_box2d3 "$box2d3_path"; then
        echo "compare_peers.sh: --box2d3: $box2d3_path is not an executable box2d3_bench_sse2 or" \
            "box2d3_bench_avx2 (or a folder holding one)" >&2
        exit 1
    fi
else
    add_box2d3 "$peers_dir/box2d3_bench_sse2" || true
    add_box2d3 "$peers_dir/box2d3_bench_avx2" || true
fi

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

# Records one peer line: the pyramid's moved boxes, the chain's gaps (and
# Box2D v3's worst gap over the grid's steps, with its gap at the end).
record_peer() {
    local engine=$1 scene=$2 line=$3 worst final
    worst=$(field "$line" peak_sep_0_5s)
    final=$(field "$line" max_sep_5s)
    if [[ "$scene" == joint_grid ]]; then
        worst=$(field "$line" peak_sep_all_steps)
        final=$(field "$line" max_sep_end)
    fi
    record "$engine" "$scene" "$(field "$line" median_ms)" "$(field "$line" lateral_gt_0.25)" "$worst" "$final"
}

# One run of each Box2D v3 harness found, with the arguments given (the
# scene and its protocol).
run_box2d3() {
    local scene=$1 v
    shift
    for v in "${!box2d3_harnesses[@]}"; do
        record_peer "${box2d3_engines[v]}" "$scene" "$("${box2d3_harnesses[v]}" "$@" | grep '^engine=')"
    done
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
                run_box2d3 "$scene" pyramid --base "$base"
                ;;
            joint_grid)
                run_sinew_joints joint_grid "$grid_warmup" "$grid_steps"
                record_peer box2d "$scene" "$("$peers_dir/box2d24_bench" joint_grid --vel 8 --pos 3 \
                    --warmup "$grid_warmup" --steps "$grid_steps")"
                record_peer chipmunk "$scene" "$("$peers_dir/chipmunk_bench" joint_grid --iters 10 \
                    --warmup "$grid_warmup" --steps "$grid_steps" | grep '^engine=')"
                run_box2d3 "$scene" joint_grid --warmup "$grid_warmup" --steps "$grid_steps"
                ;;
            chain_hang | chain_swing)
                layout=${scene#chain_}
                run_sinew_joints "$scene" 0 "$chain_steps"
                record_peer box2d "$scene" "$("$peers_dir/box2d24_bench" chain --layout "$layout" --vel 8 --pos 3 \
                    --warmup 0 --steps "$chain_steps")"
                record_peer chipmunk "$scene" "$("$peers_dir/chipmunk_bench" chain --layout "$layout" --iters 10 \
                    --warmup 0 --steps "$chain_steps" | grep '^engine=')"
                run_box2d3 "$scene" chain --layout "$layout" --warmup 0 --steps "$chain_steps"
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
# Every engine's columns are in the CSV, empty for a Box2D v3 variant not run.
all_engines=(sinew box2d chipmunk box2d3_sse2 box2d3_avx2)
engines=(sinew box2d chipmunk ${box2d3_engines[@]+"${box2d3_engines[@]}"})
ran() {
    local e
    for e in "${engines[@]}"; do
        [[ "$e" == "$1" ]] && return 0
    done
    return 1
}
{
    printf 'host,scene,runs'
    for engine in "${all_engines[@]}"; do printf ',%s_ms' "$engine"; done
    for engine in "${all_engines[@]:1}"; do printf ',sinew_over_%s' "$engine"; done
    for figure in moved worst_gap_m final_gap_m; do
        for engine in "${all_engines[@]}"; do printf ',%s_%s' "$engine" "$figure"; done
    done
    printf '\n'
    for scene in "${scenes[@]}"; do
        s=$(median_of sinew "$scene")
        printf '%s,%s,%d,%s' "$host" "$scene" "$runs" "$(awk -v v="$s" 'BEGIN { printf "%.4f", v }')"
        for engine in "${all_engines[@]:1}"; do
            ran "$engine" && printf ',%s' "$(awk -v v="$(median_of "$engine" "$scene")" 'BEGIN { printf "%.4f", v }')" ||
                printf ','
        done
        for engine in "${all_engines[@]:1}"; do
            ran "$engine" && printf ',%s' "$(awk -v s="$s" -v v="$(median_of "$engine" "$scene")" \
                'BEGIN { printf "%.3f", s / v }')" || printf ','
        done
        for column in 4 5 6; do
            for engine in "${all_engines[@]}"; do
                printf ',%s' "$(last_of "$engine" "$scene" "$column")"
            done
        done
        printf '\n'
    done
} >"$csv_tmp"
mv "$csv_tmp" "$out"

echo
echo "median of $runs runs, ms per step on $host (Box2D: 8 vel / 3 pos; Chipmunk: 10 iterations;" \
    "Box2D v3: 4 substeps; sinew pyramid: ${sinew_pyramid_settings:-not run};" \
    "sinew joints: ${sinew_joint_settings:-not run})"
# The table shows the engines that ran, each column found by its name.
awk -F, -v shown="${engines[*]}" 'function show(v) { return v == "" ? "-" : v }
    function figures(name,   i, out) {
        out = ""
        for (i = 1; i <= n; ++i) out = out (i > 1 ? "/" : "") show($(col[e[i] "_" name]))
        return out
    }
    BEGIN { n = split(shown, e, " ") }
    NR == 1 {
        for (i = 1; i <= NF; ++i) col[$i] = i
        printf "%-11s", "scene"
        for (i = 1; i <= n; ++i) printf " %11s", e[i]
        for (i = 2; i <= n; ++i) printf " %11s", "s/" e[i]
        printf "   moved, worst gap m, gap at end m (in that order of engines)\n"
        next
    }
    {
        printf "%-11s", $2
        for (i = 1; i <= n; ++i) printf " %11.4f", $(col[e[i] "_ms"])
        for (i = 2; i <= n; ++i) printf " %11.3f", $(col["sinew_over_" e[i]])
        printf "   %s  %s  %s\n", figures("moved"), figures("worst_gap_m"), figures("final_gap_m")
    }' "$out"
echo "csv: $out"
