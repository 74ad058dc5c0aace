#!/usr/bin/env bash
# The two commands of README.md:
#   ./build.sh run [flags]   install what is missing, build, run sample 01 (a window when there is
#                            a display, otherwise an offscreen PNG whose path it prints)
#   ./build.sh test          install what is missing, build, run every test through ctest: in the
#                            Release build (the web samples in headless Chromium included), then
#                            in the AddressSanitizer + UBSan build those that run every line of
#                            ours (tests/sanitizers/release_only.txt names the others), then the
#                            fuzz targets of our readers (clang's libFuzzer, tests/fuzz)
# and two more:
#   ./build.sh web           install what is missing, build the samples for the browser into
#                            build/web (open build/web/index.html)
#   ./build.sh windows       install what is missing, cross-build every sample for 64-bit
#                            Windows into build/windows/bin (MinGW-w64; docs/building.md)
set -euo pipefail

usage() {
    cat <<'USAGE'
usage: ./build.sh run [sample flags]   install what is missing, build, run sample 01: a window
                                       when there is a display, else an offscreen PNG and its path
       ./build.sh test                 install what is missing, build, run every test (Release,
                                       the web samples in headless Chromium), then under
                                       AddressSanitizer + UBSan those that run every line of ours,
                                       then each fuzz target for a bounded number of inputs
       ./build.sh web                  install what is missing (emscripten, Chromium), build the
                                       web samples into build/web: open build/web/index.html
       ./build.sh windows              install what is missing (MinGW-w64, Wine), build every
                                       sample for Windows into build/windows/bin (.exe)
       ./build.sh -h | --help          this help
Flags after "run" go to the sample (./build.sh run --help lists them); relative paths in them
are taken from the folder you run build.sh in.
USAGE
}

case "${1:-}" in
    -h | --help) usage; exit 0 ;;
    run | test | web | windows) ;;
    "") usage >&2; echo "build.sh: error: say run, test, web or windows" >&2; exit 2 ;;
    *) usage >&2; echo "build.sh: error: unknown argument '$1'" >&2; exit 2 ;;
esac
if [ "$1" != run ] && [ $# -gt 1 ]; then
    usage >&2; echo "build.sh: error: $1 takes no arguments ('$2')" >&2; exit 2
fi

caller_dir="$PWD"  # the sample runs here, so its relative paths mean what the caller meant
repo_dir="$(cd "$(dirname "$0")" && pwd)"
cd "$repo_dir"

PACKAGES=(cmake g++ make pkg-config libglfw3-dev python3-glad libglm-dev libstb-dev
          libassimp-dev libegl-dev libegl-mesa0 libgtest-dev assimp-testmodels libimgui-dev)
# OSMesa is gone from Mesa 25.1 on; where the distribution still has it, it is the first
# headless backend (always software, so it matches the goldens). EGL does without it.
OPTIONAL_PACKAGES=(libosmesa6-dev)
# The web build and its tests: emscripten (its GLFW and libc++ are built in; nothing is
# downloaded) and a headless Chromium with a software WebGL 2 (SwiftShader). About 1.1 GB.
WEB_PACKAGES=(emscripten chromium-headless-shell)
# The fuzz targets of our readers (tests/fuzz, the fuzz preset): Debian's clang with libFuzzer and
# the sanitizers' runtime. About 50 MB to download.
FUZZ_PACKAGES=(clang-19 libfuzzer-19-dev libclang-rt-19-dev)
# The Windows build (cmake/mingw-w64.cmake, scripts/windows_deps.sh) and its tests under Wine on
# Xvfb: Debian's MinGW-w64, zlib for it, the header-only libraries the cross-built Assimp needs,
# dpkg-dev for apt-get source, and Wine. About 200 MB to download.
WINDOWS_PACKAGES=(g++-mingw-w64-x86-64-posix libz-mingw-w64-dev libutfcpp-dev rapidjson-dev
                  dpkg-dev patch pkg-config wine wine64 xvfb)

is_installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }

# The apt-get to install with, in APT: as root, or through sudo. Returns 1 when neither can be.
apt_command() {
    if [ "$(id -u)" -eq 0 ]; then
        APT=(env DEBIAN_FRONTEND=noninteractive apt-get)
    elif command -v sudo >/dev/null 2>&1; then
        APT=(sudo env DEBIAN_FRONTEND=noninteractive apt-get)
    else
        return 1
    fi
}

install_missing() {
    if ! command -v dpkg-query >/dev/null 2>&1; then
        echo "build.sh: not a Debian system; make sure these are installed: ${PACKAGES[*]} ${OPTIONAL_PACKAGES[*]}" >&2
        return 0
    fi
    local missing=() optional=() p
    for p in "${PACKAGES[@]}"; do is_installed "$p" || missing+=("$p"); done
    for p in "${OPTIONAL_PACKAGES[@]}"; do is_installed "$p" || optional+=("$p"); done
    [ ${#missing[@]} -eq 0 ] && [ ${#optional[@]} -eq 0 ] && return 0
    if ! apt_command; then
        [ ${#missing[@]} -eq 0 ] && return 0  # only optional packages missing: build without them
        echo "build.sh: missing Debian packages: ${missing[*]}" >&2
        echo "build.sh: not root and no sudo; as root run: apt-get install ${missing[*]}" >&2
        exit 1
    fi
    "${APT[@]}" update -q || echo "build.sh: apt-get update failed; trying the install anyway" >&2
    for p in "${optional[@]}"; do
        if apt-cache show "$p" >/dev/null 2>&1; then
            missing+=("$p")
        else
            echo "build.sh: $p is not available here; building without it" >&2
        fi
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    echo "build.sh: installing ${missing[*]}" >&2
    if ! "${APT[@]}" install -y -q --no-install-recommends "${missing[@]}"; then
        echo "build.sh: could not install: ${missing[*]}" >&2
        exit 1
    fi
}

# A build's own packages (install_extra WHAT PACKAGE...): installed where missing. Returns 1,
# saying why, where they cannot be had.
install_extra() {
    local what="$1" missing=() p
    shift
    for p in "$@"; do is_installed "$p" || missing+=("$p"); done
    [ ${#missing[@]} -eq 0 ] && return 0
    if ! apt_command; then
        echo "build.sh: not root and no sudo; as root run: apt-get install --no-install-recommends ${missing[*]}" >&2
        return 1
    fi
    echo "build.sh: installing ${missing[*]} ($what)" >&2
    if ! "${APT[@]}" install -y -q --no-install-recommends "${missing[@]}"; then
        "${APT[@]}" update -q || true
        if ! "${APT[@]}" install -y -q --no-install-recommends "${missing[@]}"; then
            echo "build.sh: could not install: ${missing[*]}" >&2
            return 1
        fi
    fi
}

# The web build's packages (see WEB_PACKAGES). Returns 1, saying why, where they cannot be had.
install_web() {
    if ! command -v dpkg-query >/dev/null 2>&1; then
        if command -v em++ >/dev/null 2>&1 &&
           { command -v chromium-headless-shell || command -v chromium; } >/dev/null 2>&1; then
            return 0
        fi
        echo "build.sh: not a Debian system and no em++ or Chromium on PATH: no web build" >&2
        return 1
    fi
    install_extra "the web build" "${WEB_PACKAGES[@]}"
}

# The fuzz build's packages (see FUZZ_PACKAGES). Returns 1, saying why, where they cannot be had.
install_fuzz() {
    if ! command -v dpkg-query >/dev/null 2>&1; then
        command -v clang++-19 >/dev/null 2>&1 && return 0
        echo "build.sh: not a Debian system and no clang++-19 on PATH: no fuzz build" >&2
        return 1
    fi
    install_extra "the fuzz build" "${FUZZ_PACKAGES[@]}"
}

# The Windows build's packages (see WINDOWS_PACKAGES); Debian only (its source packages are what
# the libraries are built from). Returns 1, saying why, where they cannot be had.
install_windows() {
    if ! command -v dpkg-query >/dev/null 2>&1; then
        echo "build.sh: not a Debian system: no Windows build (docs/building.md says how on Windows)" >&2
        return 1
    fi
    install_extra "the Windows build" "${WINDOWS_PACKAGES[@]}"
}

# Every sample for 64-bit Windows (the windows preset), into build/windows/bin, with the assets
# the Release build baked; the libraries from scripts/windows_deps.sh, built once and cached.
build_windows() {
    local deps cache=build/windows/CMakeCache.txt stamp=build/windows/pbr-windows-deps.txt
    deps=$(scripts/windows_deps.sh) || return 1
    # A build configured against another prefix (older libraries, another cache folder) keeps the
    # paths it found there: configured afresh
    if [ -f "$cache" ] && [ "$(cat "$stamp" 2>/dev/null)" != "$deps" ]; then
        rm -f "$cache"
    fi
    PBR_WINDOWS_DEPS="$deps" build windows
    echo "$deps" >"$stamp.tmp" && mv -f "$stamp.tmp" "$stamp"
}

# The samples for the browser (cmake/Web.cmake), into build/web, with the assets the Release
# build baked.
build_web() {
    emcmake cmake -S . -B build/web -DCMAKE_BUILD_TYPE=Release -DCMAKE_UNITY_BUILD=ON \
          -DPBR_BAKED_RESOURCES="$repo_dir/build/release/resources" >/dev/null
    cmake --build build/web -j "$(nproc)"
}

# Khronos' glTF validator, for the test of our own glTF asset, and Khronos' glTF Sample Viewer
# (WebGL 2, run in headless Chromium), the reference of the khronos tests for 07 and 08: one npm
# call into build/node-tools. On Debian a missing npm is installed with apt-get; elsewhere, or
# where the registry cannot be reached, the tests that need them are skipped, saying so.
NODE_TOOLS=(gltf-validator@2.0.0-dev.3.10 @khronosgroup/gltf-viewer@1.1.0)
install_gltf_validator() {
    [ -d build/node-tools/node_modules/gltf-validator ] &&
        [ -f build/node-tools/node_modules/@khronosgroup/gltf-viewer/dist/gltf-viewer.module.js ] && return 0
    if ! command -v npm >/dev/null 2>&1 && command -v dpkg-query >/dev/null 2>&1 && apt_command; then
        echo "build.sh: installing npm (Khronos' glTF validator and Sample Viewer)" >&2
        "${APT[@]}" install -y -q --no-install-recommends npm >&2 ||
            { "${APT[@]}" update -q && "${APT[@]}" install -y -q --no-install-recommends npm >&2; } ||
            echo "build.sh: could not install npm" >&2
    fi
    command -v npm >/dev/null 2>&1 || {
        echo "build.sh: no npm; the glTF validator and Khronos viewer tests will be skipped" >&2
        return 0
    }
    mkdir -p build/node-tools
    if ! npm install --no-audit --no-fund --loglevel=error --prefix build/node-tools "${NODE_TOOLS[@]}" >&2; then
        # On Debian the registry is part of the platform: the reference tests must run there
        if command -v dpkg-query >/dev/null 2>&1; then
            echo "build.sh: could not install ${NODE_TOOLS[*]} with npm" >&2
            exit 1
        fi
        echo "build.sh: could not install ${NODE_TOOLS[*]}; their tests will be skipped" >&2
    fi
}

# A build of the test command that needs packages of its own (optional_build INSTALL-STATUS
# STAGE LABEL FUNCTION): made where they were installed; skipped, saying so, only where they
# cannot be had at all (not Debian); on Debian a failed install fails the command (CI never
# skips the LABEL tests).
optional_build() {
    if [ "$1" -eq 0 ]; then
        timed "$2" "$4"
    elif command -v dpkg-query >/dev/null 2>&1; then
        exit 1
    else
        echo "build.sh: no $2 here: the $3 tests will be skipped" >&2
    fi
}

# Runs a stage of the test command and keeps how long it took, for the summary at the end, with
# how busy the cores were (Linux: /proc/stat's user and system time against all of it; niced
# work, a fuzzing campaign beside, is not counted): a stage well under 100% has cores to share.
stage_times=""
cpu_ticks() {  # prints "BUSY ALL": the machine's CPU time so far, in ticks
    [ -r /proc/stat ] || { echo "0 0"; return; }
    local _cpu user nice system idle iowait irq softirq steal _rest
    read -r _cpu user nice system idle iowait irq softirq steal _rest </proc/stat
    echo "$((user + system + irq + softirq)) $((user + nice + system + idle + iowait + irq + softirq + steal))"
}
timed() {  # timed NAME COMMAND...
    local name="$1" start=$SECONDS busy0 all0 busy1 all1 busy=""
    shift
    read -r busy0 all0 < <(cpu_ticks)
    "$@"
    read -r busy1 all1 < <(cpu_ticks)
    [ "$all1" -le "$all0" ] || busy=" ($((100 * (busy1 - busy0) / (all1 - all0)))% busy)"
    stage_times+=" $name $((SECONDS - start))$busy,"
}

build() {  # build PRESET [CMAKE ARGUMENTS...]
    local preset="$1"
    shift
    cmake --preset "$preset" "$@" >/dev/null
    cmake --build --preset "$preset" -j "$(nproc)"
}

# The user's checkout path decides nothing: the sanitizer build is configured, built and tested
# from a copy of the source tree at a path of over 150 characters with spaces and a non-ASCII
# letter in it (the build and the data paths compiled into the samples live under it too).
LONG_CHECKOUT="build/a checkout path of more than 150 characters, with spaces and a non-ASCII"
LONG_CHECKOUT+=" letter, ü, in it, as a user may have - the tests must pass from any checkout/src"
copy_to_long_checkout() {
    local copy="$repo_dir/$LONG_CHECKOUT"
    [ "${#copy}" -ge 150 ] || { echo "build.sh: $copy is not long enough" >&2; exit 1; }
    mkdir -p "$copy/build/release"
    # the source as it is now (files deleted here go there too; the copy's build/ stays, and the
    # files keep their times, so that its build is incremental)
    find "$copy" -mindepth 1 -maxdepth 1 ! -name build -exec rm -rf {} +
    tar -C "$repo_dir" --exclude=./build --exclude=./.git -cf - . | tar -C "$copy" -xf -
    # the assets the Release build baked, where the asan preset looks for them, and the glTF
    # validator the resources tests run
    ln -sfn "$repo_dir/build/release/resources" "$copy/build/release/resources"
    [ ! -d "$repo_dir/build/node-tools" ] || ln -sfn "$repo_dir/build/node-tools" "$copy/build/node-tools"
    echo "build.sh: the sanitizer build, from $copy" >&2
}

# A windowed-only configuration (no OSMesa, no EGL: what macOS and Windows have) must configure,
# build and run: --help works, and without a display the sample says what is missing. Built in
# a folder of its own with the assets the Release build baked (nothing is baked twice) and
# without the tools, which the Release build has built already. Only common/'s context layer
# compiles differently there, so one sample stands for all: 07 links every layer of common/, the
# ibl/ and gltf/ ones and Assimp as found without pkg-config included. Built unoptimized (Debug):
# what is checked is that it builds and runs, and -O0 compiles in two thirds of the time.
check_windowed_build() {
    echo "build.sh: the windowed-only configuration (no OSMesa, no EGL)" >&2
    cmake --preset windowed -B build/windowed-check -DPBR_BUILD_TOOLS=OFF -DCMAKE_BUILD_TYPE=Debug \
          -DPBR_BAKED_RESOURCES="$repo_dir/build/release/resources" >/dev/null
    cmake --build build/windowed-check -j "$(nproc)" --target 07_gltf_metallic_roughness
    local sample=build/windowed-check/bin/07_gltf_metallic_roughness output status=0
    "$sample" --help >/dev/null || { echo "build.sh: $sample --help failed" >&2; exit 1; }
    output=$(env -u DISPLAY -u WAYLAND_DISPLAY "$sample" 2>&1) || status=$?
    if [ "$status" -ne 1 ] || ! grep -q "no offscreen backend" <<<"$output"; then
        echo "build.sh: $sample without a display should fail naming the missing backend; it said: $output" >&2
        exit 1
    fi
    echo "build.sh: windowed-only build: ok ($output)" >&2
}

case "${1:-}" in
    run)
        shift
        install_missing
        build default
        cd "$caller_dir"
        exec "$repo_dir/build/release/bin/01_lighting" "$@"
        ;;
    windows)
        install_missing
        install_windows || exit 1
        # the assets the samples read, baked by the native build (host tools)
        cmake --preset default >/dev/null
        cmake --build --preset default -j "$(nproc)" --target materials models environments ibl_maps
        build_windows
        echo "build.sh: the Windows samples are in $repo_dir/build/windows/bin; they read the" \
             "shaders and assets of this checkout (PBR_SHADER_DIR, PBR_RESOURCE_DIR move them)." \
             "Under Wine (a window on a display of its own, and its picture with --output):" \
             "tests/windows/run_wine.sh build/wine build/windows/bin/01_lighting.exe --frames 10" >&2
        ;;
    web)
        install_missing
        install_web || exit 1
        build default
        build_web
        echo "build.sh: the web samples are in $repo_dir/build/web: open index.html there, or" \
             "serve the folder (python3 -m http.server -d build/web) and open http://localhost:8000" >&2
        ;;
    test)
        timed "install" install_missing
        # The web, Windows and fuzz packages and the node tools (npm) download and unpack (disk
        # and network) while the Release build compiles (the cores); their output is shown when
        # an install fails. One after the other: apt takes one install at a time.
        mkdir -p build
        # (record_install NAME FUNCTION: its output in build/NAME-install.log, 0 or 1 in
        # build/NAME-install.status; in a subshell, since an install may exit)
        record_install() {
            if ("$2") >"build/$1-install.log" 2>&1; then echo 0; else echo 1; fi \
                >"build/$1-install.status"
        }
        # On Debian, first one apt-get for them all: dpkg's triggers (man-db, ldconfig) then run
        # once, not once a build (43 CPU-s against 55, one sitting, 2026-12-08); each build's own
        # install then finds its packages there, or installs them alone and says why it could not.
        { if command -v dpkg-query >/dev/null 2>&1; then
              extra=("${WEB_PACKAGES[@]}" "${WINDOWS_PACKAGES[@]}" "${FUZZ_PACKAGES[@]}")
              command -v npm >/dev/null 2>&1 || extra+=(npm)
              (install_extra "the web, Windows and fuzz builds" "${extra[@]}") \
                  >build/extra-install.log 2>&1 || true
          fi
          record_install web install_web
          record_install windows install_windows
          record_install node-tools install_gltf_validator
          record_install fuzz install_fuzz; } &
        install_pid=$!
        timed "Release build" build default
        # The web tests are skipped, saying so, only where the web build cannot be made at all;
        # on Debian a failed install fails the command (CI never skips them).
        start=$SECONDS
        wait "$install_pid"
        web_status=$(cat build/web-install.status)
        [ "$web_status" -eq 0 ] || cat build/web-install.log >&2
        windows_status=$(cat build/windows-install.status)
        [ "$windows_status" -eq 0 ] || cat build/windows-install.log >&2
        # (the node tools' install says why their tests will be skipped, where they will be)
        if [ "$(cat build/node-tools-install.status)" -ne 0 ]; then
            cat build/node-tools-install.log >&2
            exit 1
        fi
        grep "^build.sh: " build/node-tools-install.log >&2 || true
        stage_times+=" web, Windows, node tools and fuzz install (its wait after the build) $((SECONDS - start)),"
        # The fuzz build (clang) runs beside the web build, whose links leave a core idle.
        # Skipped, saying so, only where clang cannot be had at all; on Debian a failed install
        # fails the command.
        fuzz_build_pid=""
        if [ "$(cat build/fuzz-install.status)" -eq 0 ]; then
            build fuzz >build/fuzz-build.log 2>&1 &
            fuzz_build_pid=$!
        elif command -v dpkg-query >/dev/null 2>&1; then
            cat build/fuzz-install.log >&2
            exit 1
        else
            cat build/fuzz-install.log >&2
            echo "build.sh: no fuzz build here: the fuzz tests are skipped" >&2
        fi
        optional_build "$web_status" "web build" web build_web
        # every sample for Windows, run under Wine by the windows tests
        optional_build "$windows_status" "Windows build" windows build_windows
        if [ -n "$fuzz_build_pid" ]; then
            start=$SECONDS
            wait "$fuzz_build_pid" || { cat build/fuzz-build.log >&2; exit 1; }
            stage_times+=" fuzz build (its wait after the web build) $((SECONDS - start)),"
        fi
        timed "Release tests" ctest --preset default -j "$(nproc)"
        echo "build.sh: under AddressSanitizer + UndefinedBehaviorSanitizer, the tests that run every line of ours" >&2
        copy_to_long_checkout
        cd "$repo_dir/$LONG_CHECKOUT"
        # (its test programs are the Release build's, compiled, linked with its instrumented
        # common/: tests/CMakeLists.txt, PBR_TEST_OBJECTS_FROM)
        timed "sanitizer build" build asan -DPBR_TEST_OBJECTS_FROM="$repo_dir/build/release"
        timed "sanitizer tests" ctest --preset asan -j "$(nproc)"
        cd "$repo_dir"
        # Each fuzz target of our readers (clang, libFuzzer, ASan + UBSan): the kept inputs, then
        # a bounded number of new ones from a fixed seed (tests/fuzz/CMakeLists.txt).
        if [ -n "$fuzz_build_pid" ]; then
            timed "fuzz tests" ctest --preset fuzz -j "$(nproc)"
        fi
        # The Windows build is a windowed-only one (no OSMesa, no EGL), built and run whole;
        # without it, one sample of such a build here
        [ "$windows_status" -eq 0 ] || timed "windowed-only build" check_windowed_build
        echo "build.sh: all tests passed; seconds taken:${stage_times%,}" >&2
        ;;
esac
