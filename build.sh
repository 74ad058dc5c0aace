#!/usr/bin/env bash
# The two commands of README.md:
#   ./build.sh run [flags]   install what is missing, build, run sample 01 (a window when there is
#                            a display, otherwise an offscreen PNG whose path it prints)
#   ./build.sh test          install what is missing, build, run every test through ctest
set -euo pipefail
cd "$(dirname "$0")"

PACKAGES=(cmake g++ make pkg-config libglfw3-dev python3-glad libglm-dev libstb-dev
          libassimp-dev libosmesa6-dev libgtest-dev assimp-testmodels)

install_missing() {
    if ! command -v dpkg-query >/dev/null 2>&1; then
        echo "build.sh: not a Debian system; make sure these are installed: ${PACKAGES[*]}" >&2
        return 0
    fi
    local missing=() p
    for p in "${PACKAGES[@]}"; do
        dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
    done
    [ ${#missing[@]} -eq 0 ] && return 0
    local apt=(env DEBIAN_FRONTEND=noninteractive apt-get)
    if [ "$(id -u)" -ne 0 ]; then
        if command -v sudo >/dev/null 2>&1; then
            apt=(sudo env DEBIAN_FRONTEND=noninteractive apt-get)
        else
            echo "build.sh: missing Debian packages: ${missing[*]}" >&2
            echo "build.sh: not root and no sudo; as root run: apt-get install ${missing[*]}" >&2
            exit 1
        fi
    fi
    echo "build.sh: installing ${missing[*]}" >&2
    "${apt[@]}" update -q || echo "build.sh: apt-get update failed; trying the install anyway" >&2
    if ! "${apt[@]}" install -y -q --no-install-recommends "${missing[@]}"; then
        echo "build.sh: could not install: ${missing[*]}" >&2
        exit 1
    fi
}

build() {
    cmake --preset default >/dev/null
    cmake --build --preset default -j "$(nproc)"
}

case "${1:-}" in
    run)
        shift
        install_missing
        build
        exec build/release/bin/01_lighting "$@"
        ;;
    test)
        install_missing
        build
        ctest --preset default -j "$(nproc)"
        ;;
    *)
        echo "usage: ./build.sh run [sample flags] | ./build.sh test" >&2
        exit 2
        ;;
esac
