# Sourced by the real-window tests (inspector_window.sh, present_window.sh) under xvfb-run.

# xvfb-run may hand over before its server takes connections (seen once in a clean-clone CI
# run, both cores busy: "X11: Failed to open display :99"): wait for it, at most 30 s. (The
# server runs with -noreset, so these probes leaving cannot reset it under the next client.)
wait_for_display() {
    for _ in $(seq 1 300); do
        xdotool getdisplaygeometry >/dev/null 2>&1 && return 0
        sleep 0.1
    done
    echo "FAIL: display $DISPLAY never came up"
    return 1
}

# The id of process $1's window, once it shows (at most 30 s).
window_of() {
    local id
    for _ in $(seq 1 300); do
        if id=$(xdotool search --onlyvisible --pid "$1" --name '^depthscope' 2>/dev/null |
            head -n1) && [[ -n "$id" ]]; then
            echo "$id"
            return 0
        fi
        sleep 0.1
    done
    echo "FAIL: process $1 shows no window" >&2
    return 1
}
