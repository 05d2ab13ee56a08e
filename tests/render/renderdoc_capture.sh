#!/usr/bin/env bash
# Under a real `renderdoccmd capture`, `capture --renderdoc` must leave an .rdc in the capture
# folder whose frame holds the forward pass (its debug label) and its draws.
set -euo pipefail
exe="$1"
work="$2/renderdoc"
rm -rf "$work" && mkdir -p "$work"
renderdoccmd capture -w "$exe" capture --renderdoc --scene atrium --size 320x180 \
    --out "$work/cap" >"$work/log" 2>&1 || { cat "$work/log"; exit 1; }
rdc=$(ls "$work"/cap/*.rdc 2>/dev/null | head -1)
[[ -n "$rdc" ]] || { echo "no .rdc in $work/cap"; cat "$work/log"; exit 1; }
[[ -f "$work/cap/final.png" && -f "$work/cap/report.json" ]] || { echo "capture incomplete"; exit 1; }
renderdoccmd convert -f "$rdc" -o "$work/frame.xml" -c xml >/dev/null
grep -q '<string name="pLabelName"[^>]*>forward</string>' "$work/frame.xml" ||
    { echo "no 'forward' debug label in the capture"; exit 1; }
draws=$(grep -c 'name="vkCmdDrawIndexed"' "$work/frame.xml")
(( draws > 0 )) || { echo "no draws in the capture"; exit 1; }
# The forward pass's depth state (dynamic state, set inside its label): EQUAL, writes off.
forward=$(awk '/pLabelName[^>]*>forward</{f=1} /pLabelName[^>]*>skybox</{f=0} f' "$work/frame.xml")
grep -q 'name="depthCompareOp"[^>]*string="VK_COMPARE_OP_EQUAL"' <<<"$forward" ||
    { echo "forward: depth compare is not EQUAL"; exit 1; }
grep -q '<uint name="depthWriteEnable"[^>]*>0</uint>' <<<"$forward" ||
    { echo "forward: depth writes are not off"; exit 1; }
if grep -q '<uint name="depthWriteEnable"[^>]*>1</uint>' <<<"$forward"; then
    echo "forward: depth writes switched on"; exit 1
fi
echo "renderdoc: $rdc: forward has depth compare EQUAL, writes off; $draws indexed draws"
