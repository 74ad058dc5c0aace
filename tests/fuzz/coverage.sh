#!/usr/bin/env bash
# The lines of each reader that a fuzz target's corpus reaches, counted by gcov in the sanitizer
# build (the asan preset, with gcov's line counts, file by file): each target's replay program
# (replay_main.cpp) runs over its kept inputs and the corpus a campaign left in
# build/fuzz/corpus/TARGET (tests/fuzz/campaign.sh), alone, and gcov counts the lines of the
# files that hold its reader. Prints one line a target and source file:
#   TARGET  FILE  lines run / lines  (percent)
# usage: tests/fuzz/coverage.sh [TARGET...]   (default: every target; build/release first)
set -euo pipefail

source_dir=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$source_dir/../.." && pwd)
build=$root/build/fuzz-coverage
cd "$root"

# The files that hold each target's reader (what it is there to fuzz).
declare -A readers=(
    [hdr]="common/files/image.cpp"
    [png]="common/files/image.cpp"
    [ktx]="common/files/ktx.cpp"
    [ibl_cache]="common/files/ktx.cpp"
    [gltf_json]="common/files/gltf_file.cpp"
    [model]="common/gltf/model_assimp.cpp common/gltf/model.cpp common/files/gltf_file.cpp"
    [model_pack]="common/gltf/model_pack.cpp"
    [material_folder]="common/files/material_folder.cpp"
    [options]="common/app/options.cpp"
    [panel_script]="common/app/panel_script.cpp"
    [shader_source]="common/gl/shader.cpp"
)
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(hdr png ktx ibl_cache gltf_json model model_pack
                                     material_folder options panel_script shader_source)

cmake --preset asan -B "$build" -DCMAKE_UNITY_BUILD=OFF -DCMAKE_DISABLE_PRECOMPILE_HEADERS=ON \
      -DCMAKE_C_FLAGS=--coverage -DCMAKE_CXX_FLAGS=--coverage \
      -DCMAKE_EXE_LINKER_FLAGS=--coverage -DPBR_FUZZ_REPLAY=ON >/dev/null
cmake --build "$build" -j "$(nproc)" --target "${targets[@]/#/fuzz_replay_}" >/dev/null

export ASAN_OPTIONS=detect_leaks=0  # what is counted here is lines; the fuzz build finds leaks
for target in "${targets[@]}"; do
    find "$build" -name '*.gcda' -delete
    inputs=()
    for dir in "$source_dir/regressions/$target" "$source_dir/seeds/$target" \
               "$root/build/fuzz/seeds/$target" "$root/build/fuzz/corpus/$target"; do
        [ -d "$dir" ] && inputs+=("$dir")
    done
    "$build/tests/fuzz/fuzz_replay_$target" "${inputs[@]}" >/dev/null 2>&1 ||
        echo "$target: the replay failed (a finding: run it alone)" >&2
    for file in ${readers[$target]}; do
        object=$(find "$build/common" -name "$(basename "$file").gcda" | head -n 1)
        [ -n "$object" ] || { echo "$target  $file  not run"; continue; }
        # -o names the object: CMake's notes are shader.cpp.gcno, not the shader.gcno that gcov
        # looks for in a folder
        summary=$(cd "$(dirname "$object")" &&
                  gcov -n -o "$(basename "$object" .gcda).o" "$root/$file" 2>/dev/null |
                  grep -A1 "^File '$root/$file'" | tail -n 1)
        # "Lines executed:81.25% of 160"
        percent=$(sed -E 's/.*:([0-9.]+)% of ([0-9]+)/\1/' <<<"$summary")
        total=$(sed -E 's/.*:([0-9.]+)% of ([0-9]+)/\2/' <<<"$summary")
        run=$(awk -v p="$percent" -v t="$total" 'BEGIN { printf "%d", p * t / 100 + 0.5 }')
        printf '%-16s %-32s %5d / %-5d (%s %%)\n' "$target" "$file" "$run" "$total" "$percent"
    done
done
