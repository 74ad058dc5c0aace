#pragma once
// The IBL maps on disk: each precomputed map is kept as a KTX 1 file (the format sample 06
// writes and the cookbook's tools read) whose metadata holds a key naming everything the map was
// made from: the input file's content hash, the parameters, the shader code and the GL renderer.
// A file is used only when it reads back whole and its key matches; a damaged or stale file is
// reported in one line, recomputed and replaced, never drawn.
#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "ibl.h"
#include "ktx.h"
#include "options.h"
#include "texture.h"

namespace pbr {

// The flags every IBL sample takes: --hdr FILE and --no-cache.
std::vector<FlagSpec> iblFlags();
// The environment --hdr names, else the project's (sunny_courtyard.hdr).
std::filesystem::path environmentFile(const Options& options);
// The cache folder to use: none with --no-cache, else defaultCacheDir().
std::optional<std::filesystem::path> cacheDir(const Options& options);

// Where the cache lives: $PBR_CACHE_DIR, else $XDG_CACHE_HOME/pbr-samples, else
// $HOME/.cache/pbr-samples; nullopt when none of them is set.
std::optional<std::filesystem::path> defaultCacheDir();

class IblCache {
public:
    // `dir` nullopt: no cache, everything is computed (what --no-cache asks for).
    explicit IblCache(std::optional<std::filesystem::path> dir);

    // <dir>/<file> when it holds a map made under `key`, else `compute()` (stored for next time).
    TextureCube cube(const std::string& file, const std::string& key,
                     const std::function<TextureCube()>& compute);
    Texture2D texture(const std::string& file, const std::string& key, KtxFormat format,
                      const std::function<Texture2D()>& compute);

    // Seconds spent computing maps (not loading them), GPU work finished.
    double computeSeconds() const { return computeSeconds_; }

private:
    std::optional<KtxImage> load(const std::filesystem::path& path, const std::string& key);
    void store(const std::filesystem::path& path, KtxImage image, const std::string& key);
    template <typename T>
    T timed(const std::function<T()>& compute);

    std::optional<std::filesystem::path> dir_;
    double computeSeconds_ = 0.0;
};

// A 64-bit FNV-1a hash as 16 hex digits: the content part of a cache key.
std::string contentHash(std::string_view bytes);

// One HDR environment and the maps image-based lighting derives from it, through the cache.
// The file is hashed at once (an unreadable file is an Error naming it); it is decoded only when
// a map has to be computed.
class IblEnvironment {
public:
    IblEnvironment(IblCache& cache, std::filesystem::path hdr);

    const TextureCube& environmentMap();  // 512^2, RGB16F, full mip chain
    TextureCube irradianceMap(int size = 32, float sampleDelta = kIrradianceSampleDelta);
    TextureCube prefilteredMap(int size = 128, int levels = 5, int samples = 1024);

private:
    std::string key(const std::string& what, const std::string& shaders) const;

    IblCache& cache_;
    std::filesystem::path hdr_;
    static constexpr int kEnvironmentSize = 512;
    std::string environmentKey_;  // what the environment cube is made from; every map's source
    std::optional<TextureCube> environment_;
};

// The BRDF LUT (see computeBrdfLut) through the cache.
Texture2D brdfLut(IblCache& cache, int size, int samples, BrdfLutChannels channels);

}  // namespace pbr
