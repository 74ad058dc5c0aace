#include "ibl/ibl_cache.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "app/app.h"
#include "base/error.h"
#include "base/paths.h"
#include "context/web.h"
#include "files/image.h"
#include "gl/shader.h"
#include "ibl/ibl.h"

namespace pbr {

namespace fs = std::filesystem;

namespace {

constexpr const char* kKeyName = "pbr.cacheKey";
// The C++ side of the maps (the HDR decoder, the face order, the sizes of the mip chain): the
// shaders are hashed into every key, this is counted by hand. Raise it when that code changes.
constexpr const char* kCodeVersion = "pbr ibl cache 5";

// The largest radiance the IBL maps carry. Their sums weight radiance by the GGX lobe (up to about
// 1e4 at roughness 0.25) over thousands of samples; in 32-bit floats (up to 3.4e38) that leaves
// room for 1e20, far above any real sky (a sun in absolute units is about 1.6e9).
constexpr float kMaxRadiance = 1.0e20f;

// The environment as the maps need it: values past kMaxRadiance lowered to it, and a line on
// stderr for that, and for a range past half floats (the maps then go to 32-bit floats).
// Values past kMaxRadiance in `count` texels lowered to it; returns how many texels had one.
// Called once a row: a browser swaps in its optimised code for a WebAssembly function at a later
// call only (see decodeHdrRow in image.cpp).
[[gnu::noinline]] int clampRadiance(float* rgb, size_t count) {
    int clamped = 0;
    for (size_t i = 0; i < count * 3; i += 3) {
        bool any = false;
        for (size_t c = i; c < i + 3; ++c) {
            if (rgb[c] > kMaxRadiance) {
                rgb[c] = kMaxRadiance;
                any = true;
            }
        }
        clamped += any ? 1 : 0;
    }
    return clamped;
}

HdrImage readEnvironment(const fs::path& path) {
    HdrImage image = readHdr(path);
    int clamped = 0;  // texels
    for (int y = 0; y < image.height; ++y) {
        clamped +=
            clampRadiance(&image.pixels[size_t(y) * size_t(image.width) * 3], size_t(image.width));
    }
    if (clamped > 0) {
        std::fprintf(stderr,
                     "note: %s: %d texels above %g lowered to %g (more than the IBL sums can carry "
                     "in 32-bit floats)\n",
                     displayPath(path).c_str(), clamped, double(kMaxRadiance),
                     double(kMaxRadiance));
    } else if (!fitsHalfFloat(image)) {
        std::fprintf(stderr,
                     "note: %s: values up to %g, past half-float range (%g): its IBL maps are kept "
                     "in 32-bit floats\n",
                     displayPath(path).c_str(), double(maxValue(image)), double(kMaxHalfFloat));
    }
    return image;
}

// The shader code a map is made with, so that editing a shader makes its cached maps stale.
std::string shaderCodeHash(const std::string& vertex, const std::string& fragment) {
    const fs::path includeDir = shaderDir() / "include";
    return contentHash(preprocessShader(shaderDir() / vertex, includeDir).text +
                       preprocessShader(shaderDir() / fragment, includeDir).text);
}

std::string renderer() {
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return name ? name : "unknown";
}

// A cube map's file: its key is the baked key with the renderer that computes it.
MapFile cubeMapFile(std::string name, std::string bakedKey, std::string contents) {
    return {std::move(name), bakedKey + "; renderer " + renderer(), std::move(contents), bakedKey};
}

}  // namespace

std::vector<FlagSpec> iblFlags() {
    return {FlagSpec::text("--hdr", "FILE",
                           "an equirectangular .hdr environment (default: the project's)"),
            FlagSpec::toggle("--no-cache",
                             "compute the IBL maps even when the cache holds them, and leave the "
                             "cache alone")};
}

std::vector<FlagSpec> iblGridFlags(bool splitSum) {
    std::vector<FlagSpec> flags = gridLightFlags();
    flags.push_back(FlagSpec::toggle("--no-ibl", "leave out the image-based light").asLive());
    if (!splitSum) {
        flags.push_back(FlagSpec::choice("--background", {"environment", "irradiance"},
                                         "what the sky shows: the environment (default) or its "
                                         "irradiance, the light the spheres' diffuse term reads")
                            .asLive());
        return flags;
    }
    flags.insert(flags.begin(),
                 FlagSpec::choice("--split-sum", {"text", "exact"},
                                  "the ambient term: the text's (F times the LUT's scale; default) "
                                  "or the split sum as its derivation has it (F0 times the scale, "
                                  "diffuse weighted by what the lobe leaves)")
                     .asLive());
    flags.push_back(FlagSpec::choice("--background", {"environment", "irradiance", "prefiltered"},
                                     "what the sky shows: the environment (default), its "
                                     "irradiance, or the prefiltered map at --background-lod")
                        .asLive());
    flags.push_back(FlagSpec::number("--background-lod", "L",
                                     "the sky's mip level: of the prefiltered map, roughness L / "
                                     "4; of the environment, its box-filtered mips",
                                     0.0, 4.0, 0.0)
                        .asLive());
    return flags;
}

fs::path environmentFile(const Options& options) {
    const auto hdr = options.sampleFlags.find("--hdr");
    return hdr != options.sampleFlags.end() ? pathFromUtf8(hdr->second)
                                            : environmentDir() / "sunny_courtyard.hdr";
}

std::optional<fs::path> cacheDir(const Options& options) {
    // A page's files live as long as the page: the browser build computes its maps every time.
    if (kWebGl) return std::nullopt;
    return options.has("--no-cache") ? std::nullopt : defaultCacheDir();
}

std::string contentHash(std::string_view bytes) {
    std::uint64_t hash = 14695981039346656037ull;
    for (const char byte : bytes) {
        hash ^= std::uint8_t(byte);
        hash *= 1099511628211ull;
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

IblCache::IblCache(std::optional<fs::path> dir) : dir_(std::move(dir)) {}

std::optional<KtxImage> IblCache::load(const fs::path& path, const std::string& key) {
    std::error_code ec;
    if (!fs::exists(path, ec)) return std::nullopt;
    try {
        KtxImage image = readKtx(path);
        const auto stored = image.metadata.find(kKeyName);
        if (stored == image.metadata.end() || stored->second != key) {
            std::fprintf(stderr,
                         "note: %s: stale (made from another input, parameters, shader code or "
                         "renderer); recomputing\n",
                         displayPath(path).c_str());
            return std::nullopt;
        }
        return image;
    } catch (const Error& error) {
        std::fprintf(stderr, "note: %s; recomputing\n", error.what());
        return std::nullopt;
    }
}

KtxImage MapFile::withMetadata(KtxImage image) const {
    image.metadata[kKeyName] = key;
    image.metadata["pbr.contents"] = contents;
    image.metadata["KTXorientation"] = "S=r,T=u";  // row 0 at t = 0, as GL uploads it
    return image;
}

void IblCache::store(const MapFile& file, KtxImage image) {
    try {
        std::error_code ec;
        fs::create_directories(*dir_, ec);  // the cache's own folder
        writeKtx(*dir_ / file.name, file.withMetadata(std::move(image)));
    } catch (const Error& error) {
        std::fprintf(stderr, "warning: %s; not cached\n", error.what());
    }
}

template <typename T>
T IblCache::timed(const MapFile& file, const std::function<T()>& compute) {
    web::status("computing " + file.name);  // a page says what it is doing (no-op natively)
    const auto start = std::chrono::steady_clock::now();
    T result = compute();
    finishGl();
    computeSeconds_ +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

TextureCube IblCache::cube(const MapFile& file, const std::function<TextureCube()>& compute) {
    if (kWebGl) {
        const fs::path baked = iblDir() / file.name;
        std::error_code ec;
        if (fs::exists(baked, ec)) {
            if (std::optional<KtxImage> image = load(baked, file.bakedKey)) {
                return TextureCube::fromKtx(*image);
            }
        }
    }
    if (!dir_) return timed(file, compute);
    const fs::path path = *dir_ / file.name;
    if (std::optional<KtxImage> image = load(path, file.key)) {
        try {
            return TextureCube::fromKtx(*image);
        } catch (const Error& error) {
            std::fprintf(stderr, "note: %s: %s; recomputing\n", displayPath(path).c_str(),
                         error.what());
        }
    }
    TextureCube cube = timed(file, compute);
    store(file, cube.toKtx());
    return cube;
}

std::optional<Texture2D> IblCache::loadTexture(const fs::path& path, const MapFile& file,
                                               KtxFormat format) {
    if (std::optional<KtxImage> image = load(path, file.bakedKey)) {
        if (image->format == format && !ktxShapeError(*image, false))
            return Texture2D::fromKtx(*image);
        std::fprintf(stderr, "note: %s: not the expected format; not used\n",
                     displayPath(path).c_str());
    }
    return std::nullopt;
}

Texture2D IblCache::texture(const MapFile& file, KtxFormat format,
                            const std::function<Texture2D()>& compute) {
    // What the build baked comes first: it depends on nothing a user can change at run time.
    if (std::optional<Texture2D> baked = loadTexture(iblDir() / file.name, file, format)) {
        return std::move(*baked);
    }
    if (!dir_) return timed(file, compute);
    if (std::optional<Texture2D> cached = loadTexture(*dir_ / file.name, file, format)) {
        return std::move(*cached);
    }
    Texture2D texture = timed(file, compute);
    store(file, texture.toKtx(format));
    return texture;
}

IblEnvironment::IblEnvironment(IblCache& cache, fs::path hdr)
    : cache_(cache), hdr_(std::move(hdr)) {
    environmentKey_ =
        std::string(kCodeVersion) + "; environment " + std::to_string(kEnvironmentSize) +
        " full mips; source " + hdr_.filename().string() + " " + contentHash(readTextFile(hdr_)) +
        "; shaders " + shaderCodeHash("ibl/cubemap.vert", "ibl/equirect_to_cube.frag");
}

MapFile IblEnvironment::environmentFile() const {
    return cubeMapFile(hdr_.stem().string() + ".environment.ktx", environmentKey_,
                       "environment cube map from " + hdr_.filename().string() + ", " +
                           std::to_string(kEnvironmentSize) + "^2, full mip chain");
}

MapFile IblEnvironment::irradianceFile(int size, float sampleDelta) const {
    return cubeMapFile(hdr_.stem().string() + ".irradiance.ktx",
                       "irradiance " + std::to_string(size) + " delta " +
                           std::to_string(sampleDelta) + "; shaders " +
                           shaderCodeHash("ibl/cubemap.vert", "ibl/irradiance.frag") + "; from " +
                           environmentKey_,
                       "diffuse irradiance / pi, " + std::to_string(size) + "^2 cube map");
}

MapFile IblEnvironment::prefilteredFile(int size, int levels, int samples) const {
    return cubeMapFile(hdr_.stem().string() + ".prefiltered.ktx",
                       "prefiltered " + std::to_string(size) + " levels " + std::to_string(levels) +
                           " samples " + std::to_string(samples) + "; shaders " +
                           shaderCodeHash("ibl/cubemap.vert", "ibl/prefilter.frag") + "; from " +
                           environmentKey_,
                       "GGX-prefiltered specular cube map, " + std::to_string(size) +
                           "^2, mip m for roughness m / " + std::to_string(levels - 1) + ", " +
                           std::to_string(samples) + " samples");
}

MapFile IblEnvironment::sheenFile(int size, int levels) const {
    return cubeMapFile(hdr_.stem().string() + ".sheen.ktx",
                       "sheen " + std::to_string(size) + " levels " + std::to_string(levels) +
                           "; shaders " +
                           shaderCodeHash("ibl/cubemap.vert", "ibl/prefilter_sheen.frag") +
                           "; from " + environmentKey_,
                       "Charlie-prefiltered sheen cube map, " + std::to_string(size) +
                           "^2, mip m for sheen roughness max(m / " + std::to_string(levels - 1) +
                           ", 0.1)");
}

TextureCube IblEnvironment::sheenMap(int size, int levels) {
    return cache_.cube(sheenFile(size, levels),
                       [&] { return prefilterSheen(environmentMap(), size, levels); });
}

const TextureCube& IblEnvironment::environmentMap() {
    if (!environment_) {
        environment_ = cache_.cube(environmentFile(), [&] {
            return equirectangularToCubemap(Texture2D(readEnvironment(hdr_)), kEnvironmentSize);
        });
    }
    return *environment_;
}

TextureCube IblEnvironment::irradianceMap(int size, float sampleDelta) {
    return cache_.cube(irradianceFile(size, sampleDelta),
                       [&] { return convolveIrradiance(environmentMap(), size, sampleDelta); });
}

TextureCube IblEnvironment::prefilteredMap(int size, int levels, int samples) {
    return cache_.cube(prefilteredFile(size, levels, samples),
                       [&] { return prefilterSpecular(environmentMap(), size, levels, samples); });
}

LutTexel lutTexel(const KtxImage& lut, float u, float v) {
    if (lut.images.empty() || lut.width <= 0 || lut.height <= 0) return {};
    const int x = std::clamp(int(u * float(lut.width)), 0, lut.width - 1);
    const int y = std::clamp(int(v * float(lut.height)), 0, lut.height - 1);  // row 0: v = 0
    const int channels = lut.channels(), bytes = lut.bytesPerChannel();
    const std::uint8_t* texel = lut.images[0].data() + (size_t(y) * size_t(lut.width) + size_t(x)) *
                                                           size_t(channels * bytes);
    auto channel = [&](int c) {
        if (c >= channels) return 0.0f;
        if (bytes == 2) {
            std::uint16_t half = 0;
            std::memcpy(&half, texel + 2 * c, 2);
            return halfToFloat(half);
        }
        float value = 0.0f;
        std::memcpy(&value, texel + 4 * c, 4);
        return value;
    };
    return {channel(0), channel(1), channel(2), channel(3)};
}

KtxFormat brdfLutFormat(BrdfLutChannels channels) {
    return channels == BrdfLutChannels::ScaleBiasSheen ? KtxFormat::RGBA16F : KtxFormat::RG16F;
}

MapFile brdfLutFile(int size, int samples, BrdfLutChannels channels) {
    const bool sheen = channels == BrdfLutChannels::ScaleBiasSheen,
               gltf = channels == BrdfLutChannels::GltfScaleBias;
    const std::string name = std::string(sheen  ? "brdf_lut_sheen_"
                                         : gltf ? "brdf_lut_gltf_"
                                                : "brdf_lut_") +
                             std::to_string(size);
    const std::string key = std::string(kCodeVersion) + "; " + name + " samples " +
                            std::to_string(samples) + "; shaders " +
                            shaderCodeHash("ibl/fullscreen.vert", "ibl/brdf_lut.frag");
    return {name + ".ktx", key,
            "BRDF LUT " + std::to_string(size) + "^2, " + std::to_string(samples) +
                " samples; x = NdotV, y = roughness at texel centres; R = GGX scale, G = GGX "
                "bias to F0" +
                (gltf ? " (height-correlated Smith visibility, glTF's V_GGX)"
                      : " (Schlick-GGX, k = roughness^2 / 2)") +
                (sheen ? ", B = Charlie sheen (Ashikhmin visibility), A = Charlie sheen (Charlie "
                         "visibility)"
                       : ""),
            key};
}

Texture2D brdfLut(IblCache& cache, int size, int samples, BrdfLutChannels channels) {
    return cache.texture(brdfLutFile(size, samples, channels), brdfLutFormat(channels),
                         [&] { return computeBrdfLut(size, samples, channels); });
}

SplitSumMaps::SplitSumMaps(IblCache& cache, const fs::path& hdr, BrdfLutChannels lut)
    : environment(cache, hdr),
      // the environment first (the sky draws it, and a frame should not make it)
      irradiance((environment.environmentMap(), environment.irradianceMap(32))),
      prefiltered(environment.prefilteredMap(128, 5, kPrefilterSamples)),
      brdfLut(pbr::brdfLut(cache, 512, 1024, lut)) {}

void SplitSumMaps::use(Shader& shader, int firstUnit) {
    useIblMaps(shader, environment.environmentMap(), irradiance, prefiltered, brdfLut, firstUnit);
}

}  // namespace pbr
