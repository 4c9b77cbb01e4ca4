#!/usr/bin/env bash
# spt-editor with a bad command line: exit 2 and a message naming the problem, before any window.
# usage: bad_command_line.sh SPT_EDITOR
set -u
editor=$1
fail=0
expect_2() {
    local want=$1
    shift
    local out code
    out=$("$editor" "$@" 2>&1)
    code=$?
    if [[ $code != 2 || $out != *"$want"* ]]; then
        echo "FAIL: spt-editor $*: exit $code, '$out' (want exit 2 and '$want')"
        fail=1
    fi
}
# The recovery timer counts milliseconds in an int: more than a day would overflow it.
expect_2 "--autosave 3000000: expected a whole number of seconds from 0 to 86400" --autosave 3000000
expect_2 "--autosave -1: expected" --autosave -1
expect_2 "--autosave 1.5: expected" --autosave 1.5
expect_2 "--autosave nan: expected" --autosave nan
expect_2 "one FILE at most" a.obj b.obj
expect_2 "Unknown option 'bogus'" --bogus a.obj
expect_2 "Missing value after '--mesh'" a.spt --mesh
# A motion (--scene, --object): the scene must be readable and hold the object, before any window.
here=$(cd "$(dirname "$0")/../.." && pwd)
walking=$here/resources/scenes/walking.json
expect_2 "no_such_scene.json: cannot open the scene" a.spt --scene no_such_scene.json --object walker
expect_2 "--object nobody: $walking has no object of that name; it has 'floor', 'walker'" \
    figure_walk.spt --scene "$walking" --object nobody
expect_2 "--object and --motion-steps need --scene" a.spt --object walker
expect_2 "--scene needs FILE" --scene "$walking" --object walker
expect_2 "--motion-steps -3: expected" figure_walk.spt --scene "$walking" --motion-steps -3
[[ $fail == 0 ]] && echo "every bad command line exited 2 with its reason"
exit $fail
