# Cross-compiling for 64-bit Windows with Debian's MinGW-w64 (g++-mingw-w64-x86-64-posix, the
# POSIX threads flavour: std::thread and std::mutex need it). The libraries come from
# PBR_WINDOWS_DEPS, a prefix that scripts/windows_deps.sh builds from Debian's own source packages
# (GLFW, Assimp, Dear ImGui, minizip) and fills with the header-only ones (glm, stb); nothing is
# looked for on the host. Everything links statically: the .exe files need no MinGW DLL beside
# them.
#
#     cmake --preset windows          (CMakePresets.json; ./build.sh windows makes the prefix first)
#
# A Windows user with MinGW (MSYS2) can use this file as it is, its compilers on PATH under these
# names or given with -DCMAKE_C_COMPILER/-DCMAKE_CXX_COMPILER, and PBR_WINDOWS_DEPS their prefix.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(PBR_MINGW_TRIPLET x86_64-w64-mingw32)
if(NOT CMAKE_C_COMPILER)
    set(CMAKE_C_COMPILER ${PBR_MINGW_TRIPLET}-gcc-posix)
endif()
if(NOT CMAKE_CXX_COMPILER)
    set(CMAKE_CXX_COMPILER ${PBR_MINGW_TRIPLET}-g++-posix)
endif()
set(CMAKE_RC_COMPILER ${PBR_MINGW_TRIPLET}-windres)

set(PBR_WINDOWS_DEPS "$ENV{PBR_WINDOWS_DEPS}" CACHE PATH
    "the prefix of the Windows libraries (scripts/windows_deps.sh prints it)")
if(NOT PBR_WINDOWS_DEPS)
    message(FATAL_ERROR "mingw-w64.cmake: set PBR_WINDOWS_DEPS to the prefix of the Windows "
                        "libraries (./build.sh windows makes it: scripts/windows_deps.sh)")
endif()
# try_compile projects see the toolchain file again, without the cache: pass the prefix on
list(APPEND CMAKE_TRY_COMPILE_PLATFORM_VARIABLES PBR_WINDOWS_DEPS)

set(CMAKE_FIND_ROOT_PATH "${PBR_WINDOWS_DEPS}" /usr/${PBR_MINGW_TRIPLET})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)

# No libgcc, libstdc++ or winpthread DLLs to carry along. The static Assimp names minizip and zlib
# by their bare names (-lminizip -lz): the prefix's lib/ is searched for them.
set(CMAKE_EXE_LINKER_FLAGS_INIT "-static -static-libgcc -static-libstdc++ -L${PBR_WINDOWS_DEPS}/lib")
