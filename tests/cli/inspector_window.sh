#!/bin/bash
# The inspector in a real window under Xvfb (run by ctest through xvfb-run): N frames with
# validation on, a resize half-way (xdotool), exit 0; the layout and the settings persist, and
# a second run without --scene / --set starts from them; an unusable config folder only warns.
set -euo pipefail
exe="$1"
work="$2"
rm -rf "$work"
mkdir -p "$work"
export DEPTHSCOPE_CONFIG_DIR="$work/config"

"$exe" --frames 40 --scene edges --set exposure=2 --set render_scale=0.5 --validate \
    >"$work/run1.txt" 2>&1 &
pid=$!
# Resize once the window exists (the frames go on at the new size).
for _ in $(seq 1 100); do
    if id=$(xdotool search --name '^depthscope' 2>/dev/null | head -n1) && [[ -n "$id" ]]; then
        sleep 1
        xdotool windowsize "$id" 1000 600 || true
        break
    fi
    sleep 0.1
done
status=0
wait "$pid" || status=$?
cat "$work/run1.txt"
[[ $status -eq 0 ]] || { echo "FAIL: first run exited $status"; exit 1; }
grep -q '^depthscope: 40 frames (window 1000x600)' "$work/run1.txt" ||
    { echo "FAIL: no frame count, or the resize did not reach the window"; exit 1; }
grep -qx 'scene=edges' "$work/config/settings.ini" || { echo "FAIL: scene not saved"; exit 1; }
grep -qx 'exposure=2' "$work/config/settings.ini" || { echo "FAIL: exposure not saved"; exit 1; }
[[ -s "$work/config/imgui.ini" ]] || { echo "FAIL: no imgui.ini"; exit 1; }

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
echo "PASS"
