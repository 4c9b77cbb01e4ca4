#!/bin/bash
# The viewer as a user drives it, with xdotool under Xvfb: `spt-viewer SCENE --size 320x240`,
# Right 40 times, Ctrl+E and a file name typed into the dialog; the exported PNG equals
# `spt render --frame 40` of the same view and size (and differs from frame 0: the box has
# fallen). Then Left 10 times, Ctrl+E: frame 30. Ctrl+Q quits.
# usage: drive_viewer.sh SPT_VIEWER SPT PNG_SAME SCENES_DIR WORKDIR   (run under xvfb-run)
set -euo pipefail
viewer=$1 spt=$2 png_same=$3 scenes=$4 work=$5
source "$(dirname "$0")/../xdotool_session.sh"

# The bundled box-on-the-floor scene, its .spt models beside it.
cp "$scenes"/box_settle.json "$scenes"/slab.spt "$scenes"/crate.spt "$work"/
scene=$work/box_settle.json

# Exports the frame shown through Ctrl+E and the file dialog to $1.
export_shown() {
    xdotool windowfocus --sync "$win" key --clearmodifiers ctrl+e
    dialog=$(wait_window '^Export frame$') || fail "Ctrl+E opened no export dialog"
    xdotool windowfocus --sync "$dialog"
    sleep 0.5
    xdotool key --clearmodifiers ctrl+a
    xdotool type --delay 20 "$1"
    xdotool key --clearmodifiers Return
    wait_file "$1" || fail "the export dialog wrote nothing to $1"
    sleep 0.3
}

"$viewer" "$scene" --size 320x240 &
pid=$!
win=$(wait_window '^box_settle\.json - spt-viewer$') || fail "the viewer never showed the scene"
xdotool windowmove --sync "$win" 0 0 windowfocus --sync "$win"
sleep 1
xdotool key --clearmodifiers --delay 30 --repeat 40 Right
sleep 0.3
export_shown "$work/shown40.png"
for k in 0 30 40; do
    "$spt" render "$scene" --frame $k --view camera --size 320x240 -o "$work/render$k.png"
done
"$png_same" "$work/shown40.png" "$work/render40.png" || fail "frame 40 as shown differs from spt render --frame 40"
if "$png_same" "$work/shown40.png" "$work/render0.png" > /dev/null; then
    fail "after Right x40 the viewer still shows the initial state"
fi
xdotool windowfocus --sync "$win" key --clearmodifiers --delay 30 --repeat 10 Left
sleep 0.3
export_shown "$work/shown30.png"
"$png_same" "$work/shown30.png" "$work/render30.png" || fail "frame 30 after Left x10 differs from spt render --frame 30"
echo "Right x40 and Left x10 showed frames 40 and 30 as spt render draws them"
xdotool windowfocus --sync "$win" key --clearmodifiers ctrl+q
for _ in $(seq 1 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
if kill -0 "$pid" 2>/dev/null; then kill "$pid"; fail "Ctrl+Q did not quit"; fi
