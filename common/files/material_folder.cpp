#include "files/material_folder.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <map>

#include "base/error.h"
#include "base/paths.h"

namespace pbr {

namespace fs = std::filesystem;

namespace {

struct MapNames {
    const char* map;
    std::vector<const char*> names;  // lower case
};

// The names each map goes by in the texture sets people download (see material_folder.h).
const std::array<MapNames, 6> kMaps = {{
    {"albedo",
     {"albedo", "basecolor", "base_color", "base-color", "basecolour", "base_colour", "diffuse",
      "diff", "color", "colour"}},
    {"normal",
     {"normal", "normalgl", "normal_gl", "normal-gl", "nor_gl", "normal-ogl", "normal_ogl",
      "normal_opengl"}},
    {"normal-directx",
     {"normaldx", "normal_dx", "normal-dx", "nor_dx", "normal_directx", "normal-directx"}},
    {"metallic", {"metallic", "metalness", "metal"}},
    {"roughness", {"roughness", "rough"}},
    {"ao", {"ao", "ambientocclusion", "ambient_occlusion", "ambient-occlusion", "occlusion"}},
}};

// Names of packed maps (several channels in one picture), which are none of the maps above.
constexpr std::array<const char*, 6> kPacked = {"metallic_roughness",
                                                "metallicroughness",
                                                "metalness_roughness",
                                                "occlusion_roughness_metallic",
                                                "orm",
                                                "arm"};

bool isSeparator(char c) {
    return c == '_' || c == '-' || c == '.' || c == ' ';
}

// `stem` is `name`, or ends in it right after a separator.
bool endsWithName(const std::string& stem, const std::string& name) {
    if (stem == name) return true;
    return stem.size() > name.size() && stem.ends_with(name) &&
           isSeparator(stem[stem.size() - name.size() - 1]);
}

std::string lower(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return text;
}

// "brick_wall_diff_4k" -> "brick_wall_diff": a trailing resolution tag is not part of the name.
std::string withoutResolution(const std::string& stem) {
    size_t end = stem.size();
    if (end < 3 || stem[end - 1] != 'k') return stem;
    size_t digits = end - 1;
    while (digits > 0 && std::isdigit(static_cast<unsigned char>(stem[digits - 1]))) --digits;
    if (digits == end - 1 || digits == 0 || !isSeparator(stem[digits - 1])) return stem;
    return stem.substr(0, digits - 1);
}

std::string namesOf(const char* map) {
    for (const MapNames& entry : kMaps) {
        if (std::string(entry.map) != map) continue;
        std::string list;
        for (size_t i = 0; i < entry.names.size(); ++i) {
            list += (i == 0 ? "" : i + 1 == entry.names.size() ? " or " : ", ");
            list += entry.names[i];
        }
        return list;
    }
    return map;
}

}  // namespace

std::optional<std::string> materialMapOf(const fs::path& file) {
    const std::string extension = lower(file.extension().string());
    if (extension != ".png" && extension != ".jpg" && extension != ".jpeg") return std::nullopt;
    const std::string stem = withoutResolution(lower(file.stem().string()));
    for (const char* packed : kPacked) {
        if (endsWithName(stem, packed)) return std::nullopt;
    }
    for (const MapNames& entry : kMaps) {
        for (const char* name : entry.names) {
            if (endsWithName(stem, name)) return entry.map;
        }
    }
    return std::nullopt;
}

MaterialFiles findMaterialFiles(const fs::path& dir) {
    std::error_code ec;
    if (!fs::is_directory(dir, ec)) {
        throw Error(displayPath(dir) + ": " +
                    (fs::exists(dir, ec) ? "not a folder" : "no such folder"));
    }
    std::vector<fs::path> names;
    for (const auto& entry : fs::directory_iterator(dir, ec)) {
        if (entry.is_regular_file(ec)) names.push_back(entry.path().filename());
    }
    if (ec) throw Error(displayPath(dir) + ": cannot list the folder: " + ec.message());
    return materialFilesOf(dir, names);
}

MaterialFiles materialFilesOf(const fs::path& dir, const std::vector<fs::path>& names) {
    std::map<std::string, std::vector<fs::path>> found;
    for (const fs::path& name : names) {
        if (const auto map = materialMapOf(name)) found[*map].push_back(dir / name);
    }

    auto one = [&](const char* map, bool required) -> std::optional<fs::path> {
        std::vector<fs::path>& files = found[map];
        std::sort(files.begin(), files.end());
        if (files.size() > 1) {
            std::string list;
            for (size_t i = 0; i < files.size(); ++i) {
                list += (i == 0 ? "" : i + 1 == files.size() ? " and " : ", ");
                list += printable(files[i].filename().string());
            }
            throw Error(displayPath(dir) + ": " + std::to_string(files.size()) + " files for the " +
                        map + " map (" + list + "); keep one");
        }
        if (files.empty()) {
            if (!required) return std::nullopt;
            throw Error(displayPath(dir) + ": missing the " + map + " map (a .png or .jpg named " +
                        namesOf(map) + ", after any prefix)");
        }
        return files.front();
    };

    MaterialFiles files;
    files.albedo = *one("albedo", true);
    if (const auto normal = one("normal", false)) {
        files.normal = *normal;  // an OpenGL map wins over a DirectX one beside it
    } else if (const auto directX = one("normal-directx", false)) {
        files.normal = *directX;
        files.normalConvention = NormalConvention::DirectX;
    } else {
        one("normal", true);  // throws: missing
    }
    files.metallic = *one("metallic", true);
    files.roughness = *one("roughness", true);
    files.ao = one("ao", false);
    return files;
}

}  // namespace pbr
