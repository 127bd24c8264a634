#!/bin/bash
# SPDX-License-Identifier: MIT
# bench_engine's command line: every bad value of --grid (the joint grid's
# side, 2 .. 1000) is refused with exit status 2 and a message naming the
# option and the value, before any scene runs; a good one builds a grid of
# that side (bodies = side²) and reports its worst gap.
# Usage: bench_engine_options.sh BENCH_ENGINE
set -u
bench=$1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

for value in 0 1 -3 1001 nan inf 12x 2.5 1e9 ""; do
    out=$("$bench" --scene joint_grid --quick --grid "$value" 2>&1 >/dev/null)
    status=$?
    [ "$status" -eq 2 ] || fail "--grid '$value': exit status $status, expected 2"
    grep -q -- "--grid" <<<"$out" || fail "--grid '$value': the message does not name --grid: $out"
done
out=$("$bench" --scene joint_grid --quick --grid 2>&1 >/dev/null)
[ $? -eq 2 ] || fail "--grid without a value: expected exit status 2"
grep -q "needs a value" <<<"$out" || fail "--grid without a value: $out"

csv=$(mktemp)
trap 'rm -f "$csv"' EXIT
out=$("$bench" --scene joint_grid --quick --grid 5 --csv "$csv")
[ $? -eq 0 ] || fail "--grid 5: bench_engine failed: $out"
grep -q "bodies=25 " <<<"$out" || fail "--grid 5: not a 5 x 5 grid: $out"
gap=$(grep -o 'max_joint_gap=[^ ]*' <<<"$out" | cut -d= -f2)
awk -v g="$gap" 'BEGIN { exit !(g > 0 && g < 0.05) }' || fail "--grid 5: worst gap '$gap' not in (0, 0.05) m"

[ "$failures" -eq 0 ] && echo "bench_engine options: all passed"
exit $((failures > 0))
