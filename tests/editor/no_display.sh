#!/usr/bin/env bash
# spt-editor and spt-viewer where no window system can be reached: --help still answers (exit 0),
# and a start says why and exits 3 instead of Qt's abort and core dump.
# usage: no_display.sh SPT_EDITOR SPT_VIEWER MESH
set -u
fail=0
check() { # name want_code want_text command...
    local name=$1 code_want=$2 want=$3
    shift 3
    local out code
    out=$("$@" 2>&1 < /dev/null)
    code=$?
    if [[ $code != "$code_want" || $out != *"$want"* ]]; then
        echo "FAIL: $name: exit $code, '$out' (want exit $code_want and '$want')"
        fail=1
    fi
}
for app in "$1" "$2"; do
    name=$(basename "$app")
    check "$name --help, no DISPLAY" 0 "sage: $name" env -u DISPLAY -u WAYLAND_DISPLAY QT_QPA_PLATFORM=xcb "$app" --help
    check "$name -h, no DISPLAY" 0 "sage: $name" env -u DISPLAY -u WAYLAND_DISPLAY "$app" -h
    check "$name, no DISPLAY" 3 "$name: cannot open a window: Qt's platform plugin 'xcb' could not start; DISPLAY is not set" \
        env -u DISPLAY -u WAYLAND_DISPLAY QT_QPA_PLATFORM=xcb "$app" "$3"
    check "$name, a display nobody serves" 3 "DISPLAY is :97" env DISPLAY=:97 QT_QPA_PLATFORM=xcb "$app" "$3"
    check "$name, an unknown platform" 3 "Qt's platform plugin 'no-such-platform' could not start" \
        env -u DISPLAY QT_QPA_PLATFORM=no-such-platform "$app"
done
[[ $fail == 0 ]] && echo "with no window system both apps answered --help and exited 3 with the reason"
exit $fail
