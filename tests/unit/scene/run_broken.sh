#!/usr/bin/env bash
# Runs ds_import_check (importer built with ASan + UBSan) over every deliberately broken glTF
# file and every glTF 1.0 file of assimp-testmodels, plus a few valid files as a control.
# Fails when a run crashes, hangs (10 s), prints a sanitizer report or more than one line, or
# exits with anything but 1 for a broken file (0 for a valid one).
# Usage: run_broken.sh PATH/TO/ds_import_check MODELS_ROOT   (exit 77: models not installed)
set -uo pipefail

check="$1"
root="$2"
[[ -d "$root/glTF2" && -d "$root/glTF" ]] || { echo "skip: $root not installed"; exit 77; }

# Directories whose every .gltf/.glb must be rejected with InputError (see the per-file table in
# test_broken_files.cpp for why each one is broken).
broken_dirs=(glTF2/IndexOutOfRange glTF2/MissingBin glTF2/SchemaFailures glTF2/wrongTypes
             glTF2/BoxWithInfinites-glTF-Binary glTF2/RecursiveNodes glTF2/TestNoRootNode
             glTF2/IncorrectVertexArrays glTF2/draco glTF)
valid_files=(glTF2/BoxTextured-glTF/BoxTextured.gltf
             glTF2/BoxTextured-glTF-Binary/BoxTextured.glb
             glTF2/BoxTextured-glTF-Embedded/BoxTextured.gltf
             glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb
             glTF2/cameras/Cameras.gltf
             glTF2/glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_14.gltf
             glTF2/textureTransform/TextureTransformTest.gltf)

# Sanitizer exit codes distinct from the importer's 1; leaks are reports too.
export ASAN_OPTIONS=exitcode=86:detect_leaks=1:abort_on_error=0
export UBSAN_OPTIONS=halt_on_error=1:exitcode=87:print_stacktrace=1

failures=0
runs=0
run_one() {  # FILE EXPECTED_RC EXPECTED_PREFIX
    local file="$1" want_rc="$2" want_prefix="$3" out rc lines
    out=$(timeout 10 "$check" "$file" 2>&1)
    rc=$?
    lines=$(printf '%s\n' "$out" | wc -l)
    runs=$((runs + 1))
    local why=""
    if ((rc == 124)); then why="hang (killed after 10 s)"
    elif ((rc >= 128)); then why="crashed (signal $((rc - 128)))"
    elif grep -qE 'AddressSanitizer|LeakSanitizer|runtime error:' <<<"$out"; then why="sanitizer report"
    elif ((rc != want_rc)); then why="exit code $rc, expected $want_rc"
    elif ((lines != 1)); then why="$lines lines of output, expected 1"
    elif [[ "$out" != "$want_prefix"* ]]; then why="output does not start with '$want_prefix'"
    fi
    if [[ -n "$why" ]]; then
        failures=$((failures + 1))
        echo "FAIL $file: $why"
        printf '%s\n' "$out" | head -40 | sed 's/^/    /'
    else
        echo "ok   $file -> $out"
    fi
}

cd "$root" || exit 1
broken=0
while IFS= read -r -d '' file; do
    broken=$((broken + 1))
    run_one "$file" 1 "depthscope: error: $file: "
done < <(find "${broken_dirs[@]}" -type f \( -name '*.gltf' -o -name '*.glb' \) -print0 | sort -z)
for file in "${valid_files[@]}"; do run_one "$file" 0 "ok: $file: "; done

# Guard against a silently empty run (renamed folders in a future package version).
if ((broken < 20)); then
    echo "FAIL: only $broken broken files found under $root"
    failures=$((failures + 1))
fi
echo "$runs runs, $failures failures"
((failures == 0))
