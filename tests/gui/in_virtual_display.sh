#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Runs a command on a virtual X display (xvfb-run) and exits with the
# command's own status.
#
#   in_virtual_display.sh COMMAND [ARGUMENT...]
#
# xvfb-run's exit status is the command's unless its own clean-up fails:
# now and then it exits 5 after a command that passed (seen with the
# viewer exiting at once). The command's status is therefore written to a
# file inside the display's session and read back here; when there is
# none, the session never ran the command, and that is the failure.
set -euo pipefail

if (($# == 0)); then
    echo "usage: in_virtual_display.sh COMMAND [ARGUMENT...]" >&2
    exit 2
fi
status_file=$(mktemp)
trap 'rm -f "$status_file"' EXIT
: >"$status_file"
xvfb_status=0
xvfb-run -a -s "-screen 0 1600x1000x24" \
    bash -c '"$@"; echo $? >"$0"' "$status_file" "$@" || xvfb_status=$?
if [[ ! -s "$status_file" ]]; then
    echo "in_virtual_display.sh: the command did not run on the virtual display (xvfb-run exited $xvfb_status)" >&2
    exit 1
fi
exit "$(cat "$status_file")"
