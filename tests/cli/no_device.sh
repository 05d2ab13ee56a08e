#!/bin/sh
# No silent skips (issue 12): each GPU test binary given here, run where the Vulkan loader
# finds no driver, must fail and say that no usable Vulkan device was found; with
# DEPTHSCOPE_ALLOW_NO_DEVICE=1 it must skip, saying the same. Both ways of naming the driver
# manifest are tried (VK_ICD_FILENAMES, and VK_DRIVER_FILES of newer loaders).
set -u
fail() { echo "FAIL: $*"; exit 1; }
for binary in "$@"; do
    for variable in VK_ICD_FILENAMES VK_DRIVER_FILES; do
        out=$(env "$variable=/nonexistent" "$binary" 2>&1)
        rc=$?
        [ "$rc" -ne 0 ] || fail "$binary with $variable=/nonexistent exited 0: $out"
        echo "$out" | grep -q "no usable Vulkan device found" ||
            fail "$binary with $variable=/nonexistent did not say why: $out"
        echo "$out" | grep -q "\[  SKIPPED \]" &&
            fail "$binary with $variable=/nonexistent reported a skip: $out"
        out=$(env "$variable=/nonexistent" DEPTHSCOPE_ALLOW_NO_DEVICE=1 "$binary" 2>&1)
        rc=$?
        [ "$rc" -eq 0 ] || fail "$binary with DEPTHSCOPE_ALLOW_NO_DEVICE=1 exited $rc: $out"
        echo "$out" | grep -q "\[  SKIPPED \] no usable Vulkan device found" ||
            fail "$binary with DEPTHSCOPE_ALLOW_NO_DEVICE=1 did not skip saying why: $out"
        echo "ok: $binary ($variable): $(echo "$out" | grep -m1 'no usable Vulkan device')"
    done
done
