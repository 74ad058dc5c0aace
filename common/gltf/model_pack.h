#pragma once
// The compact form of a pbr::Model: what loadModel (Assimp, model_assimp.cpp) made of a glTF
// file, written by the native build (resources/models/pack_model.cpp) for the pages, which have
// no Assimp (Debian has none for WebAssembly). Reading it applies no glTF rules: every primitive,
// material, light and note is as the native loader left it, and the textures the file named are
// inside, as embedded images (each file once). Little-endian, our own layout (model_pack.cpp).
#include <filesystem>
#include <string>

#include "gltf/model.h"

namespace pbr {

// <model>.pbrmodel beside the model: pbr_showcase.gltf -> pbr_showcase.gltf.pbrmodel.
std::filesystem::path packedModelPath(const std::filesystem::path& model);

// The bytes of the compact form. Texture files are read (an unreadable one is an Error naming it).
std::string encodeModelPack(const Model& model);
// Back to a Model, its file `file` (the glTF path the pack stands for). Throws
// Error("<what>: <reason>") for bytes that are not a whole pack of this version.
Model decodeModelPack(std::string_view bytes, const std::filesystem::path& file,
                      const std::string& what);

// Written whole or not at all (base/output.h).
void writeModelPack(const Model& model, const std::filesystem::path& path);

}  // namespace pbr
