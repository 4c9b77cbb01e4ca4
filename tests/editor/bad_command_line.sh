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
[[ $fail == 0 ]] && echo "every bad command line exited 2 with its reason"
exit $fail
