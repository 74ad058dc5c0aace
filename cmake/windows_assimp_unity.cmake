# Assimp's library as a unity build, for the Windows build's libraries (scripts/windows_deps.sh
# passes this file as CMAKE_PROJECT_INCLUDE to Debian's Assimp source, which it leaves
# unchanged). It runs once Assimp's top-level CMakeLists.txt is read, when the target exists, and
# keeps out of the unity files the sources that cannot share one with others: the glTF 1 and
# glTF 2 importers and their registry (the same names in both formats' headers), and the files
# that include windows.h (its macros rename IOSystem's CreateDirectory and DeleteFile for every
# file after them: DefaultIOSystem.cpp, and DefaultLogger.cpp through Win32DebugLogStream.h) or
# that declare IOSystem again.
cmake_language(DEFER DIRECTORY "${CMAKE_SOURCE_DIR}" CALL pbr_assimp_unity_build)

function(pbr_assimp_unity_build)
    if(NOT TARGET assimp)
        message(FATAL_ERROR "windows_assimp_unity.cmake: Assimp's source has no target 'assimp'")
    endif()
    get_target_property(sources assimp SOURCES)
    get_target_property(source_dir assimp SOURCE_DIR)
    set(apart "")
    foreach(source IN LISTS sources)
        if(NOT IS_ABSOLUTE "${source}")
            set(source "${source_dir}/${source}")
        endif()
        if(source MATCHES "/glTF|/ImporterRegistry\\.cpp$|/DefaultIOSystem\\.cpp$|/DefaultLogger\\.cpp$|/Importer\\.cpp$|/IOSystem\\.cpp$")
            list(APPEND apart "${source}")
        endif()
    endforeach()
    set_source_files_properties(${apart} DIRECTORY "${source_dir}"
                                PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
    set_target_properties(assimp PROPERTIES UNITY_BUILD ON)
endfunction()
