#!/usr/bin/env bash
# scripts/windows_deps.sh: the libraries of the Windows build (cmake/mingw-w64.cmake), made with
# Debian's MinGW-w64 from Debian's own source packages, pinned below, into a prefix outside the
# checkout that is kept between runs, keyed by the versions, the compiler and this script:
#
#     scripts/windows_deps.sh          prints the prefix (building it first where it is missing)
#
# The sources come from Debian's archive through apt-get source, with apt's lists kept in a folder
# of the cache (the system's own sources, as deb-src; nothing in /etc is touched), and are built
# with Debian's patches applied but one (below). Header-only libraries (glm, stb, utfcpp,
# rapidjson) are Debian's arch-independent packages, copied from the host. Needs the packages
# build.sh windows installs (WINDOWS_PACKAGES there). Logs in the prefix's build folder; on
# failure, the log's last lines and exit 1.
set -euo pipefail

# Debian 12's versions of the libraries the native build uses (libglfw3-dev, libassimp-dev,
# libimgui-dev, libminizip-dev for Assimp's zip reading)
SOURCES=(glfw3=3.3.8-1 assimp=5.2.5~ds0-1 imgui=1.86+ds-1 minizip=1.1-8+deb12u1)
TRIPLET=x86_64-w64-mingw32
CC=$TRIPLET-gcc-posix
CXX=$TRIPLET-g++-posix

script="$(cd "$(dirname "$0")" && pwd)/$(basename "$0")"
repo_dir="$(cd "$(dirname "$0")/.." && pwd)"
command -v "$CXX" >/dev/null || { echo "windows_deps.sh: no $CXX (g++-mingw-w64-x86-64-posix)" >&2; exit 1; }
# Assimp finds this prefix's minizip through pkg-config only (without it, it asks for the bundled
# copy that Debian's source leaves out); dpkg-source unpacks what apt-get source fetches
for tool in pkg-config dpkg-source patch cmake; do
    command -v "$tool" >/dev/null || { echo "windows_deps.sh: no $tool (./build.sh windows installs what is needed)" >&2; exit 1; }
done
assimp_unity="$repo_dir/cmake/windows_assimp_unity.cmake"
key=$( { printf '%s\n' "${SOURCES[@]}"; "$CXX" --version | head -1; cat "$script" "$assimp_unity"; } |
      sha256sum | cut -c1-16)
cache="${PBR_WINDOWS_DEPS_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/pbr-samples/windows-deps}"
prefix="$cache/$key"
if [ -f "$prefix/complete" ]; then
    echo "$prefix"
    exit 0
fi
rm -rf "$prefix"
work="$prefix/build"
mkdir -p "$work"
log="$work/log.txt"
: >"$log"
step() {  # step WHAT COMMAND...: runs it, its output to the log; the log's tail on failure
    echo "windows_deps.sh: $1" >&2
    shift
    if ! "$@" >>"$log" 2>&1; then
        tail -n 40 "$log" >&2
        echo "windows_deps.sh: failed; the whole log: $log" >&2
        exit 1
    fi
}

# --- the sources, through apt with lists of its own ---------------------------------------------
apt="$work/apt"
mkdir -p "$apt/sources.list.d" "$apt/lists/partial" "$apt/cache/archives/partial"
: >"$apt/sources.list"
for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [ -f "$f" ] && sed -n 's/^deb \(.*\)/deb-src \1/p' "$f" >>"$apt/sources.list"
done
for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] && sed 's/^Types:.*/Types: deb-src/' "$f" >"$apt/sources.list.d/$(basename "$f")"
done
APT=(apt-get -q -o "Dir::Etc::SourceList=$apt/sources.list" -o "Dir::Etc::SourceParts=$apt/sources.list.d"
     -o "Dir::State::Lists=$apt/lists" -o "Dir::Cache=$apt/cache" -o Debug::NoLocking=1)
step "the source package lists (apt-get update, lists in $apt)" "${APT[@]}" update
src="$work/src"
mkdir -p "$src"
step "the sources: ${SOURCES[*]}" bash -c "cd '$src' && $(printf '%q ' "${APT[@]}") source ${SOURCES[*]}"
srcdir() { find "$src" -mindepth 1 -maxdepth 1 -type d -name "$1-*" | head -1; }

cmake_cross=(-DCMAKE_TOOLCHAIN_FILE="$repo_dir/cmake/mingw-w64.cmake" -DPBR_WINDOWS_DEPS="$prefix"
             -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$prefix" -DBUILD_SHARED_LIBS=OFF)

# --- header-only libraries, from the host's packages ----------------------------------------------
mkdir -p "$prefix/include" "$prefix/lib/cmake/glm"
cp -r /usr/include/glm "$prefix/include/"
cp -r /usr/include/stb "$prefix/include/"
cp -r /usr/include/utf8cpp "$prefix/include/"
cp -r /usr/include/rapidjson "$prefix/include/"
cat >"$prefix/lib/cmake/glm/glmConfig.cmake" <<'EOF'
# glm's headers (Debian's libglm-dev, copied by scripts/windows_deps.sh)
if(NOT TARGET glm::glm)
    add_library(glm::glm INTERFACE IMPORTED)
    set_target_properties(glm::glm PROPERTIES
        INTERFACE_INCLUDE_DIRECTORIES "${CMAKE_CURRENT_LIST_DIR}/../../../include")
endif()
set(glm_FOUND TRUE)
EOF

# --- GLFW ---------------------------------------------------------------------------------------
glfw=$(srcdir glfw3)
step "GLFW ($glfw)" cmake -S "$glfw" -B "$work/glfw" "${cmake_cross[@]}" -DGLFW_BUILD_DOCS=OFF \
    -DGLFW_BUILD_EXAMPLES=OFF -DGLFW_BUILD_TESTS=OFF
step "GLFW: build" cmake --build "$work/glfw" -j "$(nproc)" --target install

# --- minizip (Assimp reads zipped files through it) --------------------------------------------
minizip=$(srcdir minizip)
mkdir -p "$prefix/include/minizip" "$work/minizip"
(
    cd "$minizip"
    for f in ioapi unzip zip iowin32; do
        [ -f "$f.c" ] || continue
        $CC -O2 -c "$f.c" -o "$work/minizip/$f.o" -I. >>"$log" 2>&1
        cp "$f.h" "$prefix/include/minizip/"
    done
) || { tail -n 40 "$log" >&2; exit 1; }
step "minizip: archive" "$TRIPLET-ar" rcs "$prefix/lib/libminizip.a" "$work"/minizip/*.o
# Assimp asks pkg-config for minizip: this prefix's own, never the host's
mkdir -p "$prefix/lib/pkgconfig"
cat >"$prefix/lib/pkgconfig/minizip.pc" <<EOF
prefix=$prefix
libdir=\${prefix}/lib
includedir=\${prefix}/include
Name: minizip
Description: zip and unzip (Debian's minizip source, cross-built by scripts/windows_deps.sh)
Version: ${SOURCES[3]#minizip=}
Libs: -L\${libdir} -lminizip -lz
Cflags: -I\${includedir}/minizip
EOF

# --- Assimp, the glTF importer alone (what the samples read) -------------------------------------
# (at -O1, not CMake's Release -O3: the samples only read a few small models with it, and every
# picture of the windows tests is the same bytes; in one sitting its build took 90 s at -O2, 70 s
# at -O1 and 85 s at -O0. As a unity build but for the files that cannot share one,
# cmake/windows_assimp_unity.cmake: 23 s and 43 CPU-s against 38 s and 75 CPU-s, one sitting,
# 2026-12-08)
assimp=$(srcdir assimp)
# Debian's patch makes Draco (compressed glTF meshes) mandatory; the native build's libassimp has
# it, this one does not (the samples' models are not Draco-compressed)
step "Assimp: without Debian's use-system-libdraco.patch" \
    patch -d "$assimp" -R -p1 -i debian/patches/use-system-libdraco.patch
step "Assimp ($assimp)" env PKG_CONFIG_LIBDIR="$prefix/lib/pkgconfig" PKG_CONFIG_PATH= cmake -S "$assimp" -B "$work/assimp" "${cmake_cross[@]}" \
    -DASSIMP_BUILD_ALL_IMPORTERS_BY_DEFAULT=OFF -DASSIMP_BUILD_GLTF_IMPORTER=ON \
    -DASSIMP_BUILD_ALL_EXPORTERS_BY_DEFAULT=OFF -DASSIMP_NO_EXPORT=ON -DASSIMP_BUILD_TESTS=OFF \
    -DASSIMP_BUILD_ASSIMP_TOOLS=OFF -DASSIMP_BUILD_SAMPLES=OFF -DASSIMP_BUILD_ZLIB=OFF \
    -DASSIMP_WARNINGS_AS_ERRORS=OFF -DASSIMP_INSTALL_PDB=OFF -DASSIMP_BUILD_DRACO=OFF \
    -DCMAKE_CXX_FLAGS="-I$prefix/include -I$prefix/include/utf8cpp" -DCMAKE_C_FLAGS="-I$prefix/include" \
    -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" -DCMAKE_PROJECT_INCLUDE="$assimp_unity"
step "Assimp: build" cmake --build "$work/assimp" -j "$(nproc)" --target install

# --- Dear ImGui: its core, as Debian's libimgui.a, and the OpenGL 3 backend's source -------------
imgui=$(srcdir imgui)
mkdir -p "$prefix/include/imgui/backends" "$work/imgui"
# (its demo window left out: no sample shows it), the files side by side and at -O1 (the panel
# is a few hundred widgets a frame): 11 s instead of 33 s
step "Dear ImGui: imgui, imgui_draw, imgui_tables, imgui_widgets" \
    xargs -P "$(nproc)" -I{} "$CXX" -O1 -c "$imgui/{}.cpp" -o "$work/imgui/{}.o" -I"$imgui" \
        -I"$prefix/include/stb" < <(printf '%s\n' imgui_widgets imgui imgui_draw imgui_tables)
step "Dear ImGui: archive" "$TRIPLET-ar" rcs "$prefix/lib/libimgui.a" "$work"/imgui/*.o
cp "$imgui"/*.h "$prefix/include/imgui/"
cp "$imgui"/backends/imgui_impl_opengl3* "$prefix/include/imgui/backends/"

# the log stays; the sources and the objects go (about 150 MB)
rm -rf "$work/glfw" "$work/assimp" "$work/imgui" "$work/minizip" "$src" "$apt"
touch "$prefix/complete"
echo "$prefix"
