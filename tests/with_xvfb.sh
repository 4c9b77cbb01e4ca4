#!/bin/bash
# Runs a command under an Xvfb server of its own. The server picks a free display itself
# (-displayfd), so tests that ctest starts at the same moment never race for one display
# (xvfb-run -a can hand two of them the same number; one then finds no server).
# -noreset: a script that kills its app and starts it again would otherwise find the server
# resetting (the last client left) and fail to connect.
# usage: with_xvfb.sh WxHxDEPTH COMMAND [ARG...]
set -uo pipefail
screen=$1
shift
tmp=$(mktemp -d)
Xvfb -displayfd 3 -screen 0 "$screen" -nolisten tcp -noreset 3>"$tmp/display" 2>"$tmp/xvfb.log" &
xvfb=$!
trap 'kill "$xvfb" 2>/dev/null; wait "$xvfb" 2>/dev/null; rm -rf "$tmp"' EXIT
for _ in $(seq 1 600); do
    [ -s "$tmp/display" ] && break
    kill -0 "$xvfb" 2>/dev/null || { echo "with_xvfb.sh: Xvfb did not start:" >&2; cat "$tmp/xvfb.log" >&2; exit 1; }
    sleep 0.1
done
[ -s "$tmp/display" ] || { echo "with_xvfb.sh: Xvfb gave no display in 60 s" >&2; exit 1; }
export DISPLAY=":$(head -1 "$tmp/display")"
"$@"
