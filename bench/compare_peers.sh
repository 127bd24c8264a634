#!/usr/bin/env bash
# Compares sinew's engine with the peer engines Debian packages, Box2D 2.4.1
# and Chipmunk2D 7.0.3, on the pyramid of shared/peers/README.md (base 20 and
# 100), as ratios measured in one session on this machine.
#
# Each repetition runs, for each base, sinew's bench_engine (one run of 60
# warm-up and 300 timed steps), box2d24_bench (8 velocity / 3 position
# iterations) and chipmunk_bench (10 iterations) one after the other, so that
# a change in the machine's load touches all three engines alike. The table
# gives, per engine and base, the median over repetitions of each run's
# median ms per step, and the ratios sinew/Box2D and sinew/Chipmunk (below 1:
# sinew is faster).
#
# usage: bench/compare_peers.sh [--runs R] [--out FILE] [--build-dir DIR] [--peers DIR]
#   --runs R       repetitions, 1 .. 100 (default 3)
#   --out FILE     CSV of the table (default compare_peers.csv), written to a
#                  temporary name and renamed
#   --build-dir D  sinew's build directory (default build/release)
#   --peers DIR    the peer harnesses (default ../shared/peers)
# Exit status: 0 success, 1 failure, 2 bad command line.
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
runs=3
out=compare_peers.csv
build_dir="$root/build/release"
peers_dir="$root/../shared/peers"

usage() {
    sed -n 's/^# \{0,1\}//; /^usage:/,/^Exit status/p' "${BASH_SOURCE[0]}"
}

bad_usage() {
    echo "compare_peers.sh: $1" >&2
    usage >&2
    exit 2
}

while [[ $# -gt 0 ]]; do
    case "$1" in
        --help | -h)
            usage
            exit 0
            ;;
        --runs | --out | --build-dir | --peers)
            [[ $# -ge 2 && -n "$2" ]] || bad_usage "$1 needs a value"
            case "$1" in
                --runs)
                    if ! [[ "$2" =~ ^[0-9]{1,3}$ ]] || ((10#$2 < 1 || 10#$2 > 100)); then
                        bad_usage "--runs expects an integer from 1 to 100, got \"$2\""
                    fi
                    runs=$((10#$2))
                    ;;
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
if [[ ! -f "$peers_dir/Makefile" ]]; then
    echo "compare_peers.sh: no peer harnesses in $peers_dir (give --peers DIR)" >&2
    exit 1
fi
make -s -C "$peers_dir" >&2

bench="$build_dir/bench/bench_engine"
if [[ ! -x "$bench" ]]; then
    echo "compare_peers.sh: $bench not found; build first:" >&2
    echo "  cmake --preset release && cmake --build --preset release" >&2
    exit 1
fi

work=$(mktemp -d)
csv_tmp="$out.tmp.$$"
trap 'rm -rf "$work" "$csv_tmp"' EXIT

# Appends "engine base median_ms moved_boxes" for one benchmark line.
record() {
    local engine=$1 base=$2 line=$3 median moved
    median=$(grep -o 'median_ms=[0-9.e+-]*' <<<"$line" | cut -d= -f2)
    moved=$(grep -o 'lateral_gt_0.25=[0-9]*' <<<"$line" | cut -d= -f2)
    if [[ -z "$median" ]]; then
        echo "compare_peers.sh: no median_ms in the output of $engine: $line" >&2
        exit 1
    fi
    echo "$engine $base $median ${moved:-NA}" >>"$work/samples"
}

sinew_settings=""
for ((r = 1; r <= runs; ++r)); do
    for base in 20 100; do
        echo "repetition $r/$runs, pyramid base $base" >&2
        line=$("$bench" --scene "pyramid$base" --runs 1 --csv "$work/bench_engine.csv" | grep '^engine=')
        record sinew "$base" "$line"
        sinew_settings=$(grep -o 'vel_iters=[0-9]* pos_iters=[0-9]* substeps=[0-9]*' <<<"$line")
        record box2d "$base" "$("$peers_dir/box2d24_bench" pyramid --base "$base" --vel 8 --pos 3)"
        record chipmunk "$base" "$("$peers_dir/chipmunk_bench" pyramid --base "$base" --iters 10 | grep '^engine=')"
    done
done

# Median of the samples of one engine and base (mean of the middle two when
# the count is even).
median_of() {
    awk -v e="$1" -v b="$2" '$1 == e && $2 == b { print $3 }' "$work/samples" | sort -g |
        awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2]; else print (v[NR / 2] + v[NR / 2 + 1]) / 2 }'
}

# Boxes moved > 0.25 m sideways in the last repetition.
moved_of() {
    awk -v e="$1" -v b="$2" '$1 == e && $2 == b { m = $4 } END { print m }' "$work/samples"
}

host=$(hostname)
{
    echo "host,base,runs,sinew_ms,box2d_ms,chipmunk_ms,sinew_over_box2d,sinew_over_chipmunk,sinew_moved,box2d_moved,chipmunk_moved"
    for base in 20 100; do
        s=$(median_of sinew "$base")
        b=$(median_of box2d "$base")
        c=$(median_of chipmunk "$base")
        awk -v h="$host" -v base="$base" -v r="$runs" -v s="$s" -v b="$b" -v c="$c" \
            -v ms="$(moved_of sinew "$base")" -v mb="$(moved_of box2d "$base")" -v mc="$(moved_of chipmunk "$base")" \
            'BEGIN { printf "%s,%d,%d,%.4f,%.4f,%.4f,%.3f,%.3f,%s,%s,%s\n", h, base, r, s, b, c, s / b, s / c, ms, mb, mc }'
    done
} >"$csv_tmp"
mv "$csv_tmp" "$out"

echo
echo "pyramid, median of $runs runs, ms per step on $host (sinew: $sinew_settings; Box2D: 8 vel / 3 pos; Chipmunk: 10 iterations)"
awk -F, 'NR == 1 {
        printf "%-6s %10s %10s %12s %12s %15s   %s\n", "base", "sinew", "box2d", "chipmunk", "sinew/box2d", "sinew/chipmunk", "moved > 0.25 m (sinew/box2d/chipmunk)"
        next
    }
    { printf "%-6s %10.4f %10.4f %12.4f %12.3f %15.3f   %s/%s/%s\n", $2, $4, $5, $6, $7, $8, $9, $10, $11 }' "$out"
echo "csv: $out"
