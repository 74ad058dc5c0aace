# The seed corpus of the fuzz targets, collected at build time into OUT/<target>/: the files the
# Release build baked (RESOURCES: environments, textures, the IBL maps, our glTF models and their
# packs) and Debian's glTF test models (MODELS), each up to 64 KB (larger ones slow every run
# down and reach nothing the small ones do not). Either source may be absent: the committed
# seeds (tests/fuzz/seeds) still start every target.
#   cmake -DRESOURCES=<baked resources/> -DMODELS=<assimp test models> -DOUT=<folder>
#         -P collect_seeds.cmake
set(kMaxSeedBytes 65536)

# Copies the files matching `patterns` under `root` into OUT/<target>, named after their path
# below `root` (two models of one name in different folders stay two seeds).
function(collect target root)
    if(NOT root OR NOT IS_DIRECTORY "${root}")
        return()
    endif()
    file(MAKE_DIRECTORY "${OUT}/${target}")
    set(patterns ${ARGN})
    list(TRANSFORM patterns PREPEND "${root}/")
    file(GLOB_RECURSE files ${patterns})
    foreach(file IN LISTS files)
        file(SIZE "${file}" size)
        if(size GREATER kMaxSeedBytes)
            continue()
        endif()
        file(RELATIVE_PATH name "${root}" "${file}")
        string(REPLACE "/" "_" name "${name}")
        file(COPY_FILE "${file}" "${OUT}/${target}/${name}" ONLY_IF_DIFFERENT)
    endforeach()
endfunction()

collect(hdr "${RESOURCES}" "*.hdr")
collect(png "${RESOURCES}" "*.png" "*.jpg")
collect(ktx "${RESOURCES}" "*.ktx")
collect(ibl_cache "${RESOURCES}/ibl" "*.ktx")
collect(gltf_json "${RESOURCES}/models" "*.gltf" "*.glb")
collect(gltf_json "${MODELS}/glTF2" "*.gltf" "*.glb")
collect(gltf_json "${MODELS}/glTF" "*.gltf" "*.glb")
collect(model "${RESOURCES}/models" "*.gltf" "*.glb")
collect(model "${MODELS}/glTF2" "*.gltf" "*.glb")
collect(model "${MODELS}/glTF" "*.gltf" "*.glb")
collect(model_pack "${RESOURCES}/models" "*.pbrmodel")
