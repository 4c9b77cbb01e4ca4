#!/bin/bash
# Authoring from motion as a user does it, with xdotool under Xvfb: `spt-editor MESH --scene
# SCENE --object NAME -o OUT.spt`, wait for the motion (the title loses " (loading motion)"),
# Shift+B builds under the root for it, Ctrl+S saves, and the saved file holds the built tree;
# Ctrl+Z, Ctrl+S saves the unsplit root again.
# usage: drive_motion.sh SPT_EDITOR SPT MESH SCENE OBJECT WORKDIR   (run under xvfb-run)
set -euo pipefail
editor=$1 spt=$2 mesh=$3 scene=$4 object=$5 work=$6
source "$(dirname "$0")/../xdotool_session.sh"
nodes_of() { "$spt" info "$1" | sed -n "s/^tree 'default': \([0-9]*\) nodes.*/\1/p"; }
wait_nodes() {
    for _ in $(seq 1 100); do [ "$(nodes_of "$1")" = "$2" ] && return 0; sleep 0.1; done
    return 1
}

# Few steps of the scene: the motion is the same kind, the test stays short.
"$editor" "$mesh" --scene "$scene" --object "$object" --motion-steps 60 -o "$work/out.spt" --autosave 0 &
pid=$!
# The title says "(opening)", then "(loading motion)"; without either the motion is in.
win=$(wait_window '^out\.spt\* - spt-editor$') || fail "the editor never showed the mesh with its motion loaded"
xdotool windowmove --sync "$win" 0 0 windowsize --sync "$win" 1280 860 windowfocus --sync "$win"
sleep 0.5
xdotool key --clearmodifiers shift+b
sleep 0.5
xdotool key --clearmodifiers ctrl+s
wait_file "$work/out.spt" || fail "Ctrl+S wrote nothing to $work/out.spt"
# The build may finish after the first save: save until the file holds it.
for _ in $(seq 1 50); do
    n=$(nodes_of "$work/out.spt")
    [ -n "$n" ] && [ "$n" -gt 1 ] && break
    sleep 0.2
    xdotool key --clearmodifiers ctrl+s
done
n=$(nodes_of "$work/out.spt")
[ -n "$n" ] && [ "$n" -gt 1 ] || fail "the saved file does not hold a tree built from the motion: $("$spt" info "$work/out.spt")"
echo "saved the tree built from the motion of $object: $("$spt" info "$work/out.spt" | grep "^tree")"
xdotool key --clearmodifiers ctrl+z
sleep 0.3
xdotool key --clearmodifiers ctrl+s
wait_nodes "$work/out.spt" 1 || fail "Ctrl+Z, Ctrl+S did not save the unbuilt root: $("$spt" info "$work/out.spt")"
echo "undid the build from motion"
xdotool key --clearmodifiers ctrl+q
for _ in $(seq 1 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
if kill -0 "$pid" 2>/dev/null; then kill "$pid"; fail "Ctrl+Q did not quit after saving"; fi
echo "ok"
