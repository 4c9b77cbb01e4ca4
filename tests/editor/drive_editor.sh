#!/bin/bash
# The editor as a user drives it, with xdotool under Xvfb: `spt-editor MESH -o OUT.spt`,
# a drag in the top view, S, Ctrl+S, and the saved file holds the split (and its recipe
# replays with `spt convert --recipe`); Ctrl+Z and Ctrl+Shift+Z, each saved. Then a second
# split, a recovery file, SIGKILL, and the next start recovers the edit.
# usage: drive_editor.sh SPT_EDITOR SPT MESH WORKDIR   (run under xvfb-run)
set -euo pipefail
editor=$1 spt=$2 mesh=$3 work=$4
source "$(dirname "$0")/../xdotool_session.sh"
nodes_of() { "$spt" info "$1" | sed -n "s/^tree 'default': \([0-9]*\) nodes.*/\1/p"; }

# A left drag in window coordinates from ($1, $2) to ($3, $4).
drag() {
    xdotool mousemove --window "$win" "$1" "$2" mousedown 1 sleep 0.2 \
        mousemove --window "$win" $(( ($1 + $3) / 2 )) $(( ($2 + $4) / 2 )) sleep 0.1 \
        mousemove --window "$win" "$3" "$4" sleep 0.2 mouseup 1 sleep 0.3
}

"$editor" "$mesh" -o "$work/out.spt" --autosave 1 &
pid=$!
# The title loses " (opening)" once the mesh is converted; a converted mesh is unsaved (*).
win=$(wait_window '^out\.spt\* - spt-editor$') || fail "the editor never showed the converted mesh"
xdotool windowmove --sync "$win" 0 0 windowsize --sync "$win" 1280 860 windowfocus --sync "$win"
sleep 1
# The top view fills the upper left of the grid (about 0-460 x 50-435 at this size); the
# torus lies across its middle. The rectangle takes the torus's left half.
drag 20 60 205 430
xdotool key --clearmodifiers s
sleep 0.3
xdotool key --clearmodifiers ctrl+s
wait_file "$work/out.spt" || fail "Ctrl+S wrote nothing to $work/out.spt"
[ "$(nodes_of "$work/out.spt")" = 3 ] || fail "the saved file does not hold the split: $("$spt" info "$work/out.spt")"
echo "saved the split: $("$spt" info "$work/out.spt" | grep "^tree")"
# The split's recipe replays through the command line.
"$spt" convert "$mesh" --recipe "$work/out.spt" -o "$work/replayed.spt" 2> "$work/replay.log" || fail "spt convert --recipe failed: $(cat "$work/replay.log")"
grep -q "1 of 1 splits replayed" "$work/replay.log" || fail "the recipe did not replay: $(cat "$work/replay.log")"
[ "$(nodes_of "$work/replayed.spt")" = 3 ] || fail "the replayed file does not hold the split"

# Undo and redo from the keyboard, each saved and read back.
wait_nodes() {
    for _ in $(seq 1 50); do [ "$(nodes_of "$1")" = "$2" ] && return 0; sleep 0.1; done
    return 1
}
xdotool key --clearmodifiers ctrl+z
sleep 0.3
xdotool key --clearmodifiers ctrl+s
wait_nodes "$work/out.spt" 1 || fail "Ctrl+Z, Ctrl+S did not save the unsplit tree: $("$spt" info "$work/out.spt")"
xdotool key --clearmodifiers ctrl+shift+z
sleep 0.3
xdotool key --clearmodifiers ctrl+s
wait_nodes "$work/out.spt" 3 || fail "Ctrl+Shift+Z, Ctrl+S did not save the split again: $("$spt" info "$work/out.spt")"
echo "undid and redid the split from the keyboard"

# A second split (the right child is current now), left unsaved; the recovery file follows.
drag 250 60 280 430
xdotool key --clearmodifiers s
recovery=$(ls -d "$XDG_DATA_HOME"/*/*/recovery 2>/dev/null | head -1 || true)
for _ in $(seq 1 50); do
    recovery=$(ls -d "$XDG_DATA_HOME"/*/*/recovery 2>/dev/null | head -1 || true)
    if [ -n "$recovery" ] && [ -s "$recovery/editor-$pid.spt" ] && [ "$(nodes_of "$recovery/editor-$pid.spt")" = 5 ]; then break; fi
    sleep 0.1
done
[ "$(nodes_of "$recovery/editor-$pid.spt" 2>/dev/null)" = 5 ] || fail "no recovery file with the second split"
kill -KILL "$pid"
wait "$pid" 2>/dev/null || true

"$editor" -o "$work/recovered.spt" --autosave 1 &
pid=$!
ask=$(wait_window '^Recover unsaved work$') || fail "the next start did not offer the recovery file"
xdotool windowfocus --sync "$ask" key --clearmodifiers Return
win=$(wait_window '^recovered\.spt\* - spt-editor$') || fail "the recovered document did not open"
xdotool windowfocus --sync "$win"
sleep 0.5
xdotool key --clearmodifiers ctrl+s
wait_file "$work/recovered.spt" || fail "Ctrl+S wrote nothing after recovery"
[ "$(nodes_of "$work/recovered.spt")" = 5 ] || fail "the recovered file lacks the second split: $("$spt" info "$work/recovered.spt")"
echo "recovered after SIGKILL: $("$spt" info "$work/recovered.spt" | grep "^tree")"
xdotool key --clearmodifiers ctrl+q
for _ in $(seq 1 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
if kill -0 "$pid" 2>/dev/null; then kill "$pid"; fail "Ctrl+Q did not quit after saving"; fi
[ -z "$(ls "$recovery" 2>/dev/null)" ] || fail "recovery files left after a clean quit: $(ls "$recovery")"
echo "ok"
