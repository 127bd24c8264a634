#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The viewer's mouse and keys, end to end: runs `sinew view arm` with a
# script that stops at each step (wait-for FILE) while xdotool moves the
# mouse and types on the display, then reads what the viewer printed
# (status, locate) to check that
#   - the wheel zooms about the cursor (the hand under it stays put),
#   - a right click resets the view,
#   - dragging the background pans by the drag,
#   - dragging the hand pulls it up with a mouse joint, and letting go ends it,
#   - space steps one frame when paused (the pulse), P plays,
#   - an Export button's file chooser writes the graph's CSV, and a path
#     that cannot be written is shown in the window,
#   - Up recruits 20 neurons of the worm's motor pool per press.
#
#   tests/gui/in_virtual_display.sh bash tests/gui/viewer_input.sh build/release/tools/sinew
#
# Registered in tests/CMakeLists.txt when the viewer, xvfb-run and xdotool
# are all there. Exit status 0 when every check holds; each failure is one
# line "viewer_input: ..." on stderr.
set -euo pipefail

sinew=${1:?usage: viewer_input.sh PATH_TO_SINEW}
dir=$(mktemp -d)
pid=
cleanup()
{
    if [[ -n "$pid" ]]; then
        kill "$pid" 2>/dev/null || true
    fi
    rm -rf "$dir"
}
trap cleanup EXIT

failures=0
fail()
{
    echo "viewer_input: $*" >&2
    failures=$((failures + 1))
}
die()
{
    echo "viewer_input: $*" >&2
    echo "--- viewer stdout:" >&2
    cat "$dir/out.txt" >&2 || true
    echo "--- viewer stderr:" >&2
    cat "$dir/err.txt" >&2 || true
    exit 1
}

cat >"$dir/script.txt" <<SCRIPT
play 120
status
locate Hand
print ready
wait-for $dir/zoom
status
locate Hand
print zoomed
wait-for $dir/reset
status
print reset
wait-for $dir/pan
status
locate Hand
print panned
wait-for $dir/grab
play 90
status
locate Hand
print dragged
wait-for $dir/release
status
print released
wait-for $dir/pulse
status
print pulsed
wait-for $dir/play
status
locate export-activation
print exporting
wait-for $dir/exported
print exporting-again
wait-for $dir/refused
status
model worm
print worm
wait-for $dir/recruit
status
quit
SCRIPT

GSK_RENDERER=cairo GDK_DEBUG=gl-disable "$sinew" view arm --script "$dir/script.txt" >"$dir/out.txt" 2>"$dir/err.txt" &
pid=$!

# Waits (up to 2 minutes) until the viewer prints the line $1.
await()
{
    for _ in $(seq 1200); do
        if grep -qxs "$1" "$dir/out.txt"; then
            return 0
        fi
        kill -0 "$pid" 2>/dev/null || die "the viewer exited before printing \"$1\""
        sleep 0.1
    done
    die "the viewer did not print \"$1\" within 2 minutes"
}

# Lets the script go on past `wait-for NAME`, then waits for its next marker.
go()
{
    touch "$dir/$1"
    await "$2"
}

# A field of the last status line: status_field NAME.
status_field()
{
    grep '^status ' "$dir/out.txt" | tail -n 1 | tr ' ' '\n' | sed -n "s/^$1=//p"
}
# The last "locate Hand X Y": prints "X Y".
hand()
{
    grep '^locate Hand ' "$dir/out.txt" | tail -n 1 | cut -d ' ' -f 3,4
}
# Whether the awk expression $1 holds.
holds()
{
    awk "BEGIN { exit !($1) }"
}

await ready
window=$(timeout 60 xdotool search --sync --onlyvisible --name '^sinew view$' | head -n 1) || true
[[ -n "$window" ]] || die "no window named \"sinew view\""
IFS=, read -r canvas_x canvas_y canvas_w canvas_h <<<"$(status_field canvas)"
scale0=$(status_field scale)
centre0=$(status_field centre)
read -r hand_x hand_y <<<"$(hand)"

# Two notches of the wheel over the hand: zoom in about it.
xdotool mousemove --window "$window" "$hand_x" "$hand_y" click 4 click 4
go zoom zoomed
scale1=$(status_field scale)
holds "$scale1 > 1.25 * $scale0" || fail "the wheel did not zoom in: scale $scale0 -> $scale1"
read -r x y <<<"$(hand)"
holds "($x - $hand_x)^2 + ($y - $hand_y)^2 <= 4" || fail "the hand moved from ($hand_x, $hand_y) to ($x, $y) while zooming about it"

# A right click resets the view.
xdotool click 3
go reset reset
[[ "$(status_field scale)" == "$scale0" && "$(status_field centre)" == "$centre0" ]] ||
    fail "a right click did not reset the view: scale $(status_field scale), centre $(status_field centre)"

# Drag the background (the canvas's lower right corner) by (-100, -60) px.
bx=$((canvas_x + canvas_w - 30))
by=$((canvas_y + canvas_h - 30))
xdotool mousemove --window "$window" "$bx" "$by" mousedown 1
xdotool mousemove --window "$window" $((bx - 50)) $((by - 30))
xdotool mousemove --window "$window" $((bx - 100)) $((by - 60)) mouseup 1
go pan panned
read -r x y <<<"$(hand)"
holds "($x - ($hand_x - 100))^2 + ($y - ($hand_y - 60))^2 <= 9" ||
    fail "panning by (-100, -60) moved the hand from ($hand_x, $hand_y) to ($x, $y)"
[[ "$(status_field dragging)" == 0 ]] || fail "dragging the background grabbed a body"

# Grab the hand and hold it 80 px higher while 90 frames play.
hand_x=$x
hand_y=$y
xdotool mousemove --window "$window" "$hand_x" "$hand_y" mousedown 1
xdotool mousemove --window "$window" "$hand_x" $((hand_y - 40))
xdotool mousemove --window "$window" "$hand_x" $((hand_y - 80))
go grab dragged
[[ "$(status_field dragging)" == 1 ]] || fail "dragging the hand did not grab it"
read -r x y <<<"$(hand)"
holds "$y < $hand_y - 40" || fail "the mouse joint did not lift the hand: from y $hand_y to $y (target $((hand_y - 80)))"
xdotool mouseup 1
go release released
[[ "$(status_field dragging)" == 0 ]] || fail "letting go of the mouse did not end the drag"

# Paused, space pulses and steps one frame; P plays.
frame=$(status_field frame)
xdotool key space
go pulse pulsed
[[ "$(status_field frame)" == $((frame + 1)) ]] || fail "space stepped from frame $frame to $(status_field frame), expected one frame"
[[ "$(status_field playing)" == 0 ]] || fail "the viewer plays before P is pressed"
xdotool key p
go play exporting
grep '^status ' "$dir/out.txt" | tail -n 1 | grep -q ' playing=1 ' || fail "P did not start playing"

# Export the activation graph through its button and file chooser: once to
# a file, once where no file can be made.
read -r button_x button_y <<<"$(grep '^locate export-activation ' "$dir/out.txt" | tail -n 1 | cut -d ' ' -f 3,4)"
export_to()
{
    xdotool mousemove --window "$window" "$button_x" "$button_y" click 1
    local dialog
    dialog=$(timeout 60 xdotool search --sync --onlyvisible --name '^Export graph as CSV$' | head -n 1) || true
    [[ -n "$dialog" ]] || die "the Export button opened no file chooser"
    xdotool windowfocus --sync "$dialog"
    xdotool key --clearmodifiers ctrl+a
    xdotool type --delay 10 "$1"
    xdotool key Return
}
# Waits (up to 30 s) until the file $1 holds the text $2.
await_text()
{
    for _ in $(seq 300); do
        if grep -qsF "$2" "$1"; then
            return 0
        fi
        sleep 0.1
    done
    return 1
}
export_to "$dir/activation.csv"
await_text "$dir/activation.csv" "time_s,Biceps Short.activation," ||
    fail "the Export button did not write the activation CSV"
go exported exporting-again
export_to /proc/sinew-viewer-input.csv
await_text "$dir/err.txt" "/proc/sinew-viewer-input.csv" || fail "exporting to /proc gave no error"
go refused worm
grep '^status ' "$dir/out.txt" | tail -n 1 | grep -q 'message=".*/proc/sinew-viewer-input.csv' ||
    fail "the window does not show the export's error: $(grep '^status ' "$dir/out.txt" | tail -n 1)"

# The worm: Up twice recruits 40 neurons.
xdotool key Up Up
touch "$dir/recruit"
wait "$pid" || die "the viewer exited with status $?"
pid=
[[ "$(status_field recruited)" == 40 ]] || fail "two presses of Up recruited $(status_field recruited) neurons, expected 40"

if ((failures > 0)); then
    die "$failures check(s) failed"
fi
echo "viewer_input: all checks passed"
