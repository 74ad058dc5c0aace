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

#include "app/options.h"
#include "files/ktx.h"
#include "gl/texture.h"
#include "ibl/ibl.h"

namespace pbr {

// The flags every IBL sample takes: --hdr FILE and --no-cache.
std::vector<FlagSpec> iblFlags();
// The grid IBL samples' flags (04; 05 with `splitSum`), read every frame: the point lights
// (gridLightFlags), --no-ibl, and what the sky shows (--background: the environment or its
// irradiance); with `splitSum`, the ambient term's form first (--split-sum) and the sky's
// prefiltered map too, at --background-lod.
std::vector<FlagSpec> iblGridFlags(bool splitSum);
// The environment --hdr names, else the project's (sunny_courtyard.hdr).
std::filesystem::path environmentFile(const Options& options);
// The cache folder to use: none with --no-cache, else defaultCacheDir() (paths.h).
std::optional<std::filesystem::path> cacheDir(const Options& options);

// A precomputed map as a file: the name it has in the cache (and in 06's output folder), the key
// it is made under, and what it holds. The cache and 06 write it with the same metadata, so the
// two files are the same bytes.
struct MapFile {
    std::string name;      // "sunny_courtyard.irradiance.ktx"
    std::string key;       // input hash, parameters, shader code, renderer
    std::string contents;  // one line for people: sizes, what each channel holds
    // The key without the renderer: what a map the build baked is stored under (a page reads
    // those, made on the build's renderer; see IblCache::cube). The same as `key` for a LUT.
    std::string bakedKey;

    // `image` with this map's metadata: pbr.cacheKey, pbr.contents and its orientation.
    KtxImage withMetadata(KtxImage image) const;
};

class IblCache {
public:
    // `dir` nullopt: no cache, everything is computed (what --no-cache asks for).
    explicit IblCache(std::optional<std::filesystem::path> dir);

    // <dir>/<file.name> when it holds a map made under `file.key`, else `compute()` (stored for
    // next time). What the build baked into iblDir() comes first, cache or no cache, under
    // `file.bakedKey`: a texture (a BRDF LUT) everywhere; a cube map (the default environment's
    // irradiance and prefiltered maps) in a page only, which has no cache to keep what it
    // computes (natively the cache does that job, keyed by the renderer too).
    TextureCube cube(const MapFile& file, const std::function<TextureCube()>& compute);
    Texture2D texture(const MapFile& file, KtxFormat format,
                      const std::function<Texture2D()>& compute);

    // Seconds spent computing maps (not loading them), GPU work finished.
    double computeSeconds() const { return computeSeconds_; }

private:
    std::optional<KtxImage> load(const std::filesystem::path& path, const std::string& key);
    std::optional<Texture2D> loadTexture(const std::filesystem::path& path, const MapFile& file,
                                         KtxFormat format);
    void store(const MapFile& file, KtxImage image);
    template <typename T>
    T timed(const MapFile& file, const std::function<T()>& compute);

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
    TextureCube prefilteredMap(int size = 128, int levels = 5, int samples = kPrefilterSamples);
    // prefiltered by the sheen's lobe (prefilterSheen): sample 10's image-based sheen
    TextureCube sheenMap(int size = 32, int levels = 5);

    // What each map is as a file (see MapFile): 06 writes the maps under these names.
    MapFile environmentFile() const;
    MapFile irradianceFile(int size = 32, float sampleDelta = kIrradianceSampleDelta) const;
    MapFile prefilteredFile(int size = 128, int levels = 5, int samples = kPrefilterSamples) const;
    MapFile sheenFile(int size = 32, int levels = 5) const;

private:
    IblCache& cache_;
    std::filesystem::path hdr_;
    static constexpr int kEnvironmentSize = 512;
    // what the environment cube is made from (the renderer left out); every map's source
    std::string environmentKey_;
    std::optional<TextureCube> environment_;
};

// The split sum's maps as 05, 07 and 08 use them (LearnOpenGL's sizes), through the cache: the
// environment cube, its irradiance (32^2), the prefiltered map (128^2, 5 levels, roughness
// level / 4, kPrefilterSamples a texel) and the BRDF LUT (512^2 from 1024 samples, scale and
// bias: `lut` ScaleBias, the texts' table, for 05; GltfScaleBias, the glTF BRDF's, for 07, 08
// and 10). Made again (emplace) after a shader reload: the cache's keys hold the shaders' code.
struct SplitSumMaps {  // irradiance 32, prefiltered 128 x 5 levels, LUT 512 from 1024 samples
    SplitSumMaps(IblCache& cache, const std::filesystem::path& hdr,
                 BrdfLutChannels lut = BrdfLutChannels::ScaleBias);
    IblEnvironment environment;
    TextureCube irradiance, prefiltered;
    Texture2D brdfLut;
    // useIblMaps with these maps, from unit `firstUnit`.
    void use(Shader& shader, int firstUnit);
};

// The BRDF LUT (see computeBrdfLut) through the cache, and what it is as a file: RG16F for
// ScaleBias, RGBA16F for ScaleBiasSheen. It depends on no input, so the build bakes the ones the
// samples use into iblDir() (resources/ibl) and a start reads them from there. Its key names no
// renderer: a table made on one GL implementation serves every other.
Texture2D brdfLut(IblCache& cache, int size, int samples, BrdfLutChannels channels);
MapFile brdfLutFile(int size, int samples, BrdfLutChannels channels);
KtxFormat brdfLutFormat(BrdfLutChannels channels);

// One texel of a BRDF LUT read back (nearest to u = NdotV, v = roughness, both in [0, 1]): the
// split sum's scale and bias, and the sheen where the table has it (else 0).
struct LutTexel {
    float scale = 0.0f, bias = 0.0f, sheen = 0.0f;
    float sheenAlbedo = 0.0f;  // A: the sheen's albedo with Charlie's visibility
};
LutTexel lutTexel(const KtxImage& lut, float u, float v);

}  // namespace pbr
