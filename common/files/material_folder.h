#pragma once
// Which file of a PBR material folder is which map, under the names real texture sets use:
// "albedo.png" (the tutorial's), "rustediron2_basecolor.png" (freepbr), "Bricks076C_1K_Color.jpg"
// (ambientCG), "brick_wall_diff_4k.png" and so on. Pure: no GL, no decoding.
//
// A file is a map when its name, in any case, without its extension (.png, .jpg, .jpeg), is one
// of the map's names, alone or after any prefix ending in '_', '-', '.' or ' ', optionally
// followed by a resolution tag such as "_2k":
//   albedo     albedo, basecolor, base_color, base-color, basecolour, base_colour, diffuse,
//              diff, color, colour
//   normal     normal, nor, normalgl, normal_gl, nor_gl, normal-ogl, normal_opengl (OpenGL:
//              green up); normaldx, normal_dx, nor_dx, normal-dx, normal_directx (DirectX:
//              green down, flipped on load)
//   metallic   metallic, metalness, metal
//   roughness  roughness, rough
//   ao         ao, ambientocclusion, ambient_occlusion, occlusion
// Two files for one map (albedo.png and basecolor.png, or normal.png and normal.jpg) are an
// error naming both. An OpenGL and a DirectX normal map side by side is not: the OpenGL one is
// taken. Packed maps (metallic_roughness, orm, arm) are not read as either channel.
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace pbr {

enum class NormalConvention { OpenGL, DirectX };

struct MaterialFiles {
    std::filesystem::path albedo, normal, metallic, roughness;
    std::optional<std::filesystem::path> ao;  // optional: white when absent
    NormalConvention normalConvention = NormalConvention::OpenGL;
};

// The map a file name stands for ("albedo", "normal", "normal-directx", "metallic",
// "roughness", "ao"), or nullopt when it is none of them (a height map, a preview, a readme).
std::optional<std::string> materialMapOf(const std::filesystem::path& file);

// The maps of `dir`. Throws Error naming the folder or file and the reason: no such folder, a
// required map missing (saying which names were looked for), two files for one map.
MaterialFiles findMaterialFiles(const std::filesystem::path& dir);
// The choice findMaterialFiles makes once it has listed the folder: the maps among `names` (the
// names of the regular files in `dir`, in any order), each returned as dir / name. The same
// errors, naming `dir`, except the folder's own (none is read).
MaterialFiles materialFilesOf(const std::filesystem::path& dir,
                              const std::vector<std::filesystem::path>& names);

}  // namespace pbr
