#!/bin/bash
# The inspector in a real window under Xvfb (run by ctest through xvfb-run): N frames with
# validation on, a resize half-way (xdotool), exit 0; the layout and the settings persist, and
# a second run without --scene / --set starts from them; an unusable config folder only warns.
# Captures (issue 13): F12 (a real key press) writes a capture that replays bit-identically;
# `view --capture DIR` opens a capture with its settings over the saved ones (which it leaves
# as they were), and F12 there captures the same frame again. The live inspector (issue 14): a
# real drag with validation on both devices.
set -euo pipefail
exe="$1"
work="$2"
rm -rf "$work"
mkdir -p "$work"
export DEPTHSCOPE_CONFIG_DIR="$work/config"

source "$(dirname "$0")/window_helpers.sh"
wait_for_display || exit 1

"$exe" --frames 40 --scene edges --set exposure=2 --set render_scale=0.5 --validate \
    >"$work/run1.txt" 2>&1 &
pid=$!
# Resize once the window exists (the frames go on at the new size).
if id=$(window_of "$pid"); then
    sleep 1
    xdotool windowsize "$id" 1000 600 || true
fi
status=0
wait "$pid" || status=$?
cat "$work/run1.txt"
[[ $status -eq 0 ]] || { echo "FAIL: first run exited $status"; exit 1; }
grep -q '^depthscope: 40 frames (window 1000x600)' "$work/run1.txt" ||
    { echo "FAIL: no frame count, or the resize did not reach the window"; exit 1; }
grep -qx 'scene=edges' "$work/config/settings.ini" || { echo "FAIL: scene not saved"; exit 1; }
grep -qx 'exposure=2' "$work/config/settings.ini" || { echo "FAIL: exposure not saved"; exit 1; }
[[ -s "$work/config/imgui.ini" ]] || { echo "FAIL: no imgui.ini"; exit 1; }
# The workspace's entry (open tabs; split sizes once dragged), kept by the explicit save.
grep -q '^tab_left=Settings$' "$work/config/imgui.ini" ||
    { cat "$work/config/imgui.ini"; echo "FAIL: no workspace entry in imgui.ini"; exit 1; }

"$exe" --frames 3 --validate >"$work/run2.txt" 2>&1 || { cat "$work/run2.txt"; exit 1; }
cat "$work/run2.txt"
grep -q "inspector: edges" "$work/run2.txt" || { echo "FAIL: saved scene not used"; exit 1; }
grep -q "exposure=2" "$work/run2.txt" || { echo "FAIL: saved settings not used"; exit 1; }
# An unusable config folder costs persistence, not the session: one warning, exit 0.
DEPTHSCOPE_CONFIG_DIR=/proc/depthscope-nope "$exe" --frames 2 --scene edges >"$work/run3.txt" 2>&1 ||
    { cat "$work/run3.txt"; echo "FAIL: an unusable config folder ended the inspector"; exit 1; }
cat "$work/run3.txt"
grep -q "depthscope: warning: /proc/depthscope-nope" "$work/run3.txt" ||
    { echo "FAIL: no warning about the config folder"; exit 1; }

# Once the window of process $1 shows, F12 (a real key press and release: the window's key
# callback keeps it until the inspector's next frame, however short).
press_f12() {
    local id
    id=$(window_of "$1") || return 1
    xdotool windowfocus --sync "$id" 2>/dev/null || true
    xdotool key F12
}

# F12: a capture of the inspector's frame into $DEPTHSCOPE_CAPTURE_DIR, its path printed.
export DEPTHSCOPE_CAPTURE_DIR="$work/captures"
"$exe" --frames 30 --scene edges --size 640x400 --validate >"$work/run4.txt" 2>&1 &
pid=$!
press_f12 "$pid"
status=0
wait "$pid" || status=$?
cat "$work/run4.txt"
[[ $status -eq 0 ]] || { echo "FAIL: the F12 run exited $status"; exit 1; }
shot=$(sed -n 's/^depthscope: wrote //p' "$work/run4.txt")
[[ -n "$shot" && "$(dirname "$shot")" == "$work/captures" ]] || { echo "FAIL: F12 wrote nothing"; exit 1; }
[[ -s "$shot/final.png" && -s "$shot/report.json" && -s "$shot/resources/final.exr" ]] ||
    { echo "FAIL: $shot is not a whole capture"; ls -R "$shot"; exit 1; }
"$exe" replay "$shot" --out "$work/replayed" --resources none >"$work/replay.txt" 2>&1 ||
    { cat "$work/replay.txt"; exit 1; }
grep -q "final.png is bit-identical" "$work/replay.txt" || { cat "$work/replay.txt"; echo "FAIL: replay"; exit 1; }

# view --capture: a capture with exposure=3 opens with exposure=3 over the saved exposure=2 and
# render_scale=0.5, at the capture's size; settings.ini stays as the first run left it.
"$exe" capture --scene edges --size 160x90 --set exposure=3 --out "$work/exposure3" >/dev/null
cp "$work/config/settings.ini" "$work/settings.before"
rm -rf "$work/captures"
"$exe" view --capture "$work/exposure3" --frames 30 --size 640x400 --validate >"$work/run5.txt" 2>&1 &
pid=$!
press_f12 "$pid"
status=0
wait "$pid" || status=$?
cat "$work/run5.txt"
[[ $status -eq 0 ]] || { echo "FAIL: view --capture exited $status"; exit 1; }
grep -qx "depthscope: inspector: edges, exposure=3" "$work/run5.txt" ||
    { echo "FAIL: the capture's settings did not win"; exit 1; }
grep -qx "depthscope: inspector: capture $work/exposure3 (160x90)" "$work/run5.txt" ||
    { echo "FAIL: the capture was not opened"; exit 1; }
cmp -s "$work/settings.before" "$work/config/settings.ini" ||
    { echo "FAIL: a capture's session changed settings.ini"; exit 1; }
# F12 in that session: the same frame (scene, camera, settings, size) bit for bit.
again=$(sed -n 's/^depthscope: wrote //p' "$work/run5.txt")
[[ -n "$again" ]] || { echo "FAIL: F12 in view --capture wrote nothing"; exit 1; }
cmp "$work/exposure3/final.png" "$again/final.png" ||
    { echo "FAIL: view --capture does not show the captured frame"; exit 1; }

# The live inspector (issue 14): a real left drag orbits the camera while the UI goes on (scene
# frames on the render thread, smaller while moving, the full size after); validation on the
# renderer's and the UI's device stays silent (exit 0, not 3).
"$exe" --frames 300 --scene edges --size 800x500 --validate >"$work/run6.txt" 2>&1 &
pid=$!
if id=$(window_of "$pid"); then
    xdotool mousemove --window "$id" 400 200 mousedown 1
    for _ in $(seq 1 20); do xdotool mousemove_relative 6 1; sleep 0.03; done
    xdotool mouseup 1
fi
status=0
wait "$pid" || status=$?
cat "$work/run6.txt"
[[ $status -eq 0 ]] || { echo "FAIL: the drag run exited $status"; exit 1; }
posted=$(sed -n 's/^depthscope: 300 frames .*scene frames: \([0-9]*\) posted.*/\1/p' "$work/run6.txt")
[[ -n "$posted" ]] || { echo "FAIL: no frame count"; exit 1; }
# Without input: the first frame and the one at the viewer's size once laid out. The drag adds
# frames while moving (each superseding the last) and the full size after it stopped.
((posted >= 4)) || { echo "FAIL: $posted scene frames posted: the drag moved nothing"; exit 1; }
echo "PASS"
