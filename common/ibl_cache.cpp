#include "ibl_cache.h"

#include <cstdio>
#include <cstdlib>

#include "error.h"
#include "ibl.h"
#include "image.h"
#include "paths.h"
#include "shader.h"

namespace pbr {

namespace fs = std::filesystem;

namespace {

constexpr const char* kKeyName = "pbr.cacheKey";
// The C++ side of the maps (the HDR decoder, the face order, the sizes of the mip chain): the
// shaders are hashed into every key, this is counted by hand. Raise it when that code changes.
constexpr const char* kCodeVersion = "pbr ibl cache 2";

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

}  // namespace

std::vector<FlagSpec> iblFlags() {
    return {{"--hdr", "FILE", "an equirectangular .hdr environment (default: the project's)"},
            {"--no-cache", "", "compute the IBL maps even when the cache holds them"}};
}

fs::path environmentFile(const Options& options) {
    const auto hdr = options.sampleFlags.find("--hdr");
    return hdr != options.sampleFlags.end() ? fs::path(hdr->second)
                                            : environmentDir() / "sunny_courtyard.hdr";
}

std::optional<fs::path> cacheDir(const Options& options) {
    return options.has("--no-cache") ? std::nullopt : defaultCacheDir();
}

std::optional<fs::path> defaultCacheDir() {
    auto variable = [](const char* name) -> const char* {
        const char* value = std::getenv(name);
        return value && *value ? value : nullptr;
    };
    if (const char* dir = variable("PBR_CACHE_DIR")) return fs::path(dir);
    if (const char* dir = variable("XDG_CACHE_HOME")) return fs::path(dir) / "pbr-samples";
    if (const char* home = variable("HOME")) return fs::path(home) / ".cache" / "pbr-samples";
    return std::nullopt;
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

void IblCache::store(const fs::path& path, KtxImage image, const std::string& key) {
    image.metadata[kKeyName] = key;
    image.metadata["KTXorientation"] = "S=r,T=u";  // row 0 at t = 0, as GL uploads it
    try {
        writeKtx(path, image);
    } catch (const Error& error) {
        std::fprintf(stderr, "warning: %s; not cached\n", error.what());
    }
}

template <typename T>
T IblCache::timed(const std::function<T()>& compute) {
    const auto start = std::chrono::steady_clock::now();
    T result = compute();
    glFinish();
    computeSeconds_ +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

TextureCube IblCache::cube(const std::string& file, const std::string& key,
                           const std::function<TextureCube()>& compute) {
    if (!dir_) return timed(compute);
    const fs::path path = *dir_ / file;
    if (std::optional<KtxImage> image = load(path, key)) {
        try {
            TextureCube cube = TextureCube::fromKtx(*image);
            return cube;
        } catch (const Error& error) {
            std::fprintf(stderr, "note: %s: %s; recomputing\n", displayPath(path).c_str(),
                         error.what());
        }
    }
    TextureCube cube = timed(compute);
    store(path, cube.toKtx(), key);
    return cube;
}

Texture2D IblCache::texture(const std::string& file, const std::string& key, KtxFormat format,
                            const std::function<Texture2D()>& compute) {
    if (!dir_) return timed(compute);
    const fs::path path = *dir_ / file;
    if (std::optional<KtxImage> image = load(path, key)) {
        if (image->format == format && image->faces == 1) {
            return Texture2D::fromKtx(*image);
        }
        std::fprintf(stderr, "note: %s: not the expected format; recomputing\n",
                     displayPath(path).c_str());
    }
    Texture2D texture = timed(compute);
    store(path, texture.toKtx(format), key);
    return texture;
}

IblEnvironment::IblEnvironment(IblCache& cache, fs::path hdr)
    : cache_(cache), hdr_(std::move(hdr)) {
    environmentKey_ =
        std::string(kCodeVersion) + "; environment " + std::to_string(kEnvironmentSize) +
        " full mips; source " + hdr_.filename().string() + " " + contentHash(readTextFile(hdr_)) +
        "; shaders " + shaderCodeHash("ibl/cubemap.vert", "ibl/equirect_to_cube.frag") +
        "; renderer " + renderer();
}

std::string IblEnvironment::key(const std::string& what, const std::string& shaders) const {
    return what + "; shaders " + shaders + "; from " + environmentKey_;
}

const TextureCube& IblEnvironment::environmentMap() {
    if (!environment_) {
        environment_ = cache_.cube(hdr_.stem().string() + ".environment.ktx", environmentKey_, [&] {
            return equirectangularToCubemap(Texture2D(readHdr(hdr_)), kEnvironmentSize);
        });
    }
    return *environment_;
}

TextureCube IblEnvironment::irradianceMap(int size, float sampleDelta) {
    return cache_.cube(
        hdr_.stem().string() + ".irradiance.ktx",
        key("irradiance " + std::to_string(size) + " delta " + std::to_string(sampleDelta),
            shaderCodeHash("ibl/cubemap.vert", "ibl/irradiance.frag")),
        [&] { return convolveIrradiance(environmentMap(), size, sampleDelta); });
}

TextureCube IblEnvironment::prefilteredMap(int size, int levels, int samples) {
    return cache_.cube(hdr_.stem().string() + ".prefiltered.ktx",
                       key("prefiltered " + std::to_string(size) + " levels " +
                               std::to_string(levels) + " samples " + std::to_string(samples),
                           shaderCodeHash("ibl/cubemap.vert", "ibl/prefilter.frag")),
                       [&] { return prefilterSpecular(environmentMap(), size, levels, samples); });
}

Texture2D brdfLut(IblCache& cache, int size, int samples, BrdfLutChannels channels) {
    const bool sheen = channels == BrdfLutChannels::ScaleBiasSheen;
    const std::string name =
        std::string(sheen ? "brdf_lut_sheen_" : "brdf_lut_") + std::to_string(size);
    const std::string key = std::string(kCodeVersion) + "; " + name + " samples " +
                            std::to_string(samples) + "; shaders " +
                            shaderCodeHash("ibl/fullscreen.vert", "ibl/brdf_lut.frag") +
                            "; renderer " + renderer();
    return cache.texture(name + ".ktx", key, sheen ? KtxFormat::RGBA16F : KtxFormat::RG16F,
                         [&] { return computeBrdfLut(size, samples, channels); });
}

}  // namespace pbr
