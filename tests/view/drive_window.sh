#!/usr/bin/env bash
# Drives a window program with real X input events (xdotool), for tests/view/iblkit_view_window_test.
#
#   drive_window.sh LOG EVENTS PROGRAM [ARGUMENTS...]
#
# Under the current X display (xvfb-run gives one): starts PROGRAM with its stdout and stderr in
# LOG, waits (20 s at most) for its window to be mapped, then runs each line of the file EVENTS as
# an xdotool command, %W standing for the window's id; a line "shots N" instead waits (20 s at
# most) until LOG has N "iblkit-view: wrote" lines, the screenshots the P key writes. Then it
# presses Esc and waits (10 s at most) for the program to exit. The program is killed whatever
# happens. Exit status: the program's; 124 when something timed out; 125 when xdotool failed.
set -u
log=$1 events=$2
shift 2

"$@" >"$log" 2>&1 &
program=$!
trap 'kill "$program" 2>/dev/null; wait "$program" 2>/dev/null' EXIT

fail() {
  echo "drive_window: $1" >&2
  exit "$2"
}

window=$(timeout 20 xdotool search --sync --onlyvisible --pid "$program" 2>/dev/null | head -n 1)
[ -n "$window" ] || fail "no window of $1 within 20 s (its output: $(tr '\n' ' ' <"$log"))" 124
# No window manager: the keyboard follows the pointer once the window has the focus.
xdotool windowfocus "$window" mousemove --window "$window" 1 1 || fail "cannot focus window $window" 125

while IFS= read -r line || [ -n "$line" ]; do
  [ -n "$line" ] || continue
  if [[ $line == shots\ * ]]; then
    wanted=${line#shots }
    for _ in $(seq 200); do
      [ "$(grep -c 'iblkit-view: wrote' "$log")" -ge "$wanted" ] && break
      kill -0 "$program" 2>/dev/null || fail "$1 exited before screenshot $wanted: $(tr '\n' ' ' <"$log")" 1
      sleep 0.1
    done
    [ "$(grep -c 'iblkit-view: wrote' "$log")" -ge "$wanted" ] || fail "no screenshot $wanted within 20 s" 124
    continue
  fi
  # shellcheck disable=SC2086  # the line is an xdotool command line, split into its words
  timeout 10 xdotool ${line//%W/$window} || fail "xdotool $line failed" 125
done <"$events"

xdotool key Escape 2>/dev/null
for _ in $(seq 100); do
  if ! kill -0 "$program" 2>/dev/null; then
    wait "$program"
    exit $?
  fi
  sleep 0.1
done
fail "$1 still running 10 s after Esc" 124
