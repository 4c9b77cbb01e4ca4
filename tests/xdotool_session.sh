# Sourced by the scripts that drive a built Qt app with xdotool under Xvfb: a clean work
# folder $work with the app's settings and data in it, and waits. Needs $work set.
rm -rf "$work"
mkdir -p "$work"
export XDG_CONFIG_HOME=$work/config XDG_DATA_HOME=$work/data QT_QPA_PLATFORM=xcb
fail() { echo "FAIL: $*" >&2; exit 1; }

# Prints the id of the first window whose title matches the regular expression $1.
wait_window() {
    for _ in $(seq 1 1200); do
        id=$(xdotool search --name "$1" 2>/dev/null | head -1 || true)
        if [ -n "$id" ]; then echo "$id"; return 0; fi
        sleep 0.1
    done
    return 1
}
# Waits until file $1 exists and is not empty.
wait_file() { for _ in $(seq 1 600); do [ -s "$1" ] && return 0; sleep 0.1; done; return 1; }
