# Generates the glad 2 loader (GL 3.3 core + the few extensions we use) into the build tree at
# configure time, from Debian's python3-glad. Nothing is downloaded: --reproducible uses the
# specification bundled with the package.
# The browser build takes an OpenGL ES 3.0 loader instead (WebGL 2 reports "OpenGL ES 3.0", and a
# 3.3 core loader would leave its entry points NULL), with float colour buffers (the IBL maps).
if(EMSCRIPTEN)
    set(PBR_GLAD_API "gles2=3.0")
    set(PBR_GLAD_EXTENSIONS "GL_EXT_color_buffer_float,GL_EXT_texture_filter_anisotropic")
    set(_glad_source gles2.c)
else()
    set(PBR_GLAD_API "gl:core=3.3")
    set(PBR_GLAD_EXTENSIONS "GL_KHR_debug,GL_EXT_texture_filter_anisotropic,GL_ARB_texture_filter_anisotropic")
    set(_glad_source gl.c)
endif()
set(PBR_GLAD_DIR "${CMAKE_BINARY_DIR}/glad")

# Debian installs the glad module for /usr/bin/python3 only; a python3 earlier on PATH (pyenv,
# a virtualenv) may not have it. Try /usr/bin/python3 first, then whatever else is found.
set(_glad_candidates /usr/bin/python3)
find_program(_path_python3 NAMES python3)
if(_path_python3)
    list(APPEND _glad_candidates "${_path_python3}")
endif()
set(PBR_GLAD_PYTHON "")
foreach(_py IN LISTS _glad_candidates)
    if(EXISTS "${_py}")
        execute_process(COMMAND "${_py}" -c "import glad" RESULT_VARIABLE _rc OUTPUT_QUIET ERROR_QUIET)
        if(_rc EQUAL 0)
            set(PBR_GLAD_PYTHON "${_py}")
            break()
        endif()
    endif()
endforeach()
if(NOT PBR_GLAD_PYTHON)
    message(FATAL_ERROR "glad: no python3 with the 'glad' module (tried: ${_glad_candidates}); "
                        "install Debian's python3-glad (apt-get install python3-glad)")
endif()

set(_glad_stamp "${PBR_GLAD_DIR}/stamp.txt")
set(_glad_key "${PBR_GLAD_PYTHON};${PBR_GLAD_API};${PBR_GLAD_EXTENSIONS}")
set(_glad_old "")
if(EXISTS "${_glad_stamp}")
    file(READ "${_glad_stamp}" _glad_old)
endif()
if(NOT _glad_old STREQUAL _glad_key OR NOT EXISTS "${PBR_GLAD_DIR}/src/${_glad_source}")
    message(STATUS "glad: generating the ${PBR_GLAD_API} loader with ${PBR_GLAD_PYTHON}")
    file(REMOVE_RECURSE "${PBR_GLAD_DIR}")
    execute_process(
        COMMAND "${PBR_GLAD_PYTHON}" -m glad --quiet --reproducible --api ${PBR_GLAD_API}
                --extensions "${PBR_GLAD_EXTENSIONS}" --out-path "${PBR_GLAD_DIR}" c
        RESULT_VARIABLE _glad_rc ERROR_VARIABLE _glad_err OUTPUT_QUIET)
    if(NOT _glad_rc EQUAL 0)
        message(FATAL_ERROR "glad: generation failed: ${_glad_err}")
    endif()
    file(WRITE "${_glad_stamp}" "${_glad_key}")
endif()

add_library(glad STATIC "${PBR_GLAD_DIR}/src/${_glad_source}")
target_include_directories(glad SYSTEM PUBLIC "${PBR_GLAD_DIR}/include")
set_target_properties(glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
