#pragma once
// The project's own PBR material sets, made from noise: rusted iron, gold, grass, plastic, wall.
// Each set is the tutorial's five maps: albedo (sRGB), normal (tangent space, OpenGL +Y),
// metallic, roughness and ao (linear).
#include <filesystem>
#include <string>
#include <vector>

#include "files/image.h"

namespace pbr::materials {

inline const std::vector<std::string> kSetNames = {"rusted_iron", "gold", "grass", "plastic",
                                                   "wall"};
inline const std::vector<std::string> kMapNames = {"albedo", "normal", "metallic", "roughness",
                                                   "ao"};

struct MaterialSet {
    std::string name;
    Image albedo, normal, metallic, roughness, ao;  // 3, 3, 1, 1, 1 channels
};

// Throws Error for an unknown name.
MaterialSet bake(const std::string& name, int size);

// Writes <dir>/<name>/{albedo,normal,metallic,roughness,ao}.png.
void write(const MaterialSet& set, const std::filesystem::path& dir);

// All sets side by side: a row per set, a column per map, `thumb` pixels each.
Image contactSheet(const std::vector<MaterialSet>& sets, int thumb);

}  // namespace pbr::materials
