#include "gltf/model_pack.h"

#include <cmath>
#include <cstring>
#include <map>
#include <type_traits>

#include "base/error.h"
#include "base/output.h"
#include "base/paths.h"

namespace pbr {

namespace fs = std::filesystem;

namespace {

constexpr char kMagic[8] = {'P', 'B', 'R', 'M', 'O', 'D', 'E', 'L'};
// Raise it whenever the layout below changes: a page never reads a pack of another layout.
constexpr std::uint32_t kVersion = 2;

// Little-endian on every machine the suite builds for (x86-64, arm64, wasm32): the values are
// copied as they lie in memory.
struct Out {
    std::string bytes;
    template <typename T>
    void value(const T& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes.append(reinterpret_cast<const char*>(&v), sizeof v);
    }
    void u32(std::uint64_t v) { value(std::uint32_t(v)); }
    void text(const std::string& s) {
        u32(s.size());
        bytes += s;
    }
    template <typename T>
    void array(const std::vector<T>& v) {
        static_assert(std::is_trivially_copyable_v<T>);
        u32(v.size());
        bytes.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
    }
    void texts(const std::vector<std::string>& v) {
        u32(v.size());
        for (const std::string& s : v) text(s);
    }
};

struct In {
    std::string_view bytes;
    std::string what;
    size_t at = 0;

    [[noreturn]] void fail(const std::string& why) const { throw Error(what + ": " + why); }
    const char* take(size_t size) {
        if (size > bytes.size() - at) fail("truncated (not a whole model pack)");
        const char* p = bytes.data() + at;
        at += size;
        return p;
    }
    template <typename T>
    T value() {
        T v;
        std::memcpy(&v, take(sizeof v), sizeof v);
        return v;
    }
    std::uint32_t u32() { return value<std::uint32_t>(); }
    // A count of items of `size` bytes each that the rest of the bytes can hold.
    size_t count(size_t size) {
        const std::uint32_t n = u32();
        if (size > 0 && n > (bytes.size() - at) / size) fail("truncated (not a whole model pack)");
        return n;
    }
    std::string text() {
        const size_t n = count(1);
        return std::string(take(n), n);
    }
    template <typename T>
    std::vector<T> array() {
        const size_t n = count(sizeof(T));
        std::vector<T> v(n);
        if (n) std::memcpy(v.data(), take(n * sizeof(T)), n * sizeof(T));
        return v;
    }
    std::vector<std::string> texts() {
        std::vector<std::string> v(count(4));
        for (std::string& s : v) s = text();
        return v;
    }
};

void writeTexture(Out& out, const TextureRef& ref, const std::map<fs::path, int>& files) {
    out.value(std::int32_t(ref.file.empty() ? ref.embedded : files.at(ref.file)));
    out.value(std::int32_t(ref.uvSet));
    for (const int v : {ref.wrapS, ref.wrapT, ref.magFilter, ref.minFilter})
        out.value(std::int32_t(v));
    out.value(ref.transform);
}

TextureRef readTexture(In& in, size_t images) {
    TextureRef ref;
    ref.embedded = in.value<std::int32_t>();
    if (ref.embedded < -1 || ref.embedded >= int(images)) in.fail("texture index out of range");
    ref.uvSet = in.value<std::int32_t>();
    if (ref.uvSet < 0 || ref.uvSet > 1) in.fail("texture coordinate set out of range");
    ref.wrapS = in.value<std::int32_t>();
    ref.wrapT = in.value<std::int32_t>();
    ref.magFilter = in.value<std::int32_t>();
    ref.minFilter = in.value<std::int32_t>();
    ref.transform = in.value<glm::mat3>();
    return ref;
}

// The factors of the advanced material's extensions, in the pack's order: one list that the
// writer and the reader both walk, so that they cannot disagree.
template <typename M, typename F>
void extensionFactors(M& m, F&& f) {
    f(m.clearcoat.factor);
    f(m.clearcoat.roughnessFactor);
    f(m.clearcoat.normalScale);
    f(m.sheen.colorFactor);
    f(m.sheen.roughnessFactor);
    f(m.transmission.factor);
    f(m.volume.thicknessFactor);
    f(m.volume.attenuationDistance);
    f(m.volume.attenuationColor);
    f(m.ior);
    f(m.khrSpecular.factor);
    f(m.khrSpecular.colorFactor);
    f(m.emissiveStrength);
}

// Every component finite: what loadModel promises of positions, normals, transforms, bounds
// and lights, and a pack stands for what it made.
template <typename V>
bool finite(const V& v) {
    for (int i = 0; i < V::length(); ++i) {
        if constexpr (std::is_floating_point_v<std::decay_t<decltype(v[i])>>) {
            if (!std::isfinite(v[i])) return false;
        } else if (!finite(v[i])) {
            return false;
        }
    }
    return true;
}

}  // namespace

fs::path packedModelPath(const fs::path& model) {
    return model.parent_path() / (model.filename().string() + ".pbrmodel");
}

std::string encodeModelPack(const Model& model) {
    // Texture files go inside, after the file's own embedded images, each file once.
    std::vector<EmbeddedImage> images = model.embeddedImages;
    std::map<fs::path, int> files;
    for (const Material& m : model.materials) {
        for (const TextureRef* ref : m.textures()) {
            if (ref->file.empty() || files.count(ref->file)) continue;
            const std::string bytes = readTextFile(ref->file);
            files[ref->file] = int(images.size());
            images.push_back({{bytes.begin(), bytes.end()}, 0, 0, ref->file.filename().string()});
        }
    }

    Out out;
    out.bytes.append(kMagic, sizeof kMagic);
    out.u32(kVersion);
    out.text(model.file.filename().string());
    out.texts(model.extensionsUsed);
    out.texts(model.extensionsRequired);
    out.texts(model.notes);
    out.u32(std::uint64_t(model.primitivesWithoutMaterial));
    out.value(model.boundsMin);
    out.value(model.boundsMax);
    out.u32(model.lights.size());
    for (const PunctualLight& light : model.lights) {
        out.u32(std::uint64_t(light.type));
        out.text(light.name);
        out.value(light.color);
        out.value(light.position);
        out.value(light.direction);
        out.value(light.range);
        out.value(light.innerConeAngle);
        out.value(light.outerConeAngle);
    }
    out.u32(images.size());
    for (const EmbeddedImage& image : images) {
        out.text(image.name);
        out.value(std::int32_t(image.width));
        out.value(std::int32_t(image.height));
        out.array(image.bytes);
    }
    out.u32(model.materials.size());
    for (const Material& m : model.materials) {
        out.text(m.name);
        for (const bool flag : {m.unlit, m.specularGlossiness, m.doubleSided, m.gltfDefault})
            out.value(std::uint8_t(flag));
        for (const TextureRef* ref : m.textures()) writeTexture(out, *ref, files);
        out.value(m.baseColorFactor);
        out.value(m.metallicFactor);
        out.value(m.roughnessFactor);
        out.value(m.normalScale);
        out.value(m.occlusionStrength);
        out.value(m.emissiveFactor);
        out.value(m.specularFactor);
        out.value(m.glossinessFactor);
        out.u32(std::uint64_t(m.alphaMode));
        out.value(m.alphaCutoff);
        extensionFactors(m, [&](const auto& value) { out.value(value); });
        out.texts(m.extensions);
    }
    out.u32(model.primitives.size());
    for (const ModelPrimitive& p : model.primitives) {
        out.u32(std::uint64_t(p.material));
        out.value(p.transform);
        out.u32(std::uint64_t(p.mesh.primitive));
        out.array(p.mesh.positions);
        out.array(p.mesh.normals);
        out.array(p.mesh.uvs);
        out.array(p.mesh.tangents);
        out.array(p.mesh.colors);
        out.array(p.mesh.uvs1);
        out.array(p.mesh.indices);
    }
    return std::move(out.bytes);
}

Model decodeModelPack(std::string_view bytes, const fs::path& file, const std::string& what) {
    In in{bytes, what};
    if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
        in.fail("not a model pack");
    in.take(sizeof kMagic);
    if (const std::uint32_t version = in.u32(); version != kVersion) {
        in.fail("a model pack of layout " + std::to_string(version) + ", not " +
                std::to_string(kVersion) + " (made by another version of the suite)");
    }
    Model model;
    model.file = file.parent_path() / in.text();
    model.extensionsUsed = in.texts();
    model.extensionsRequired = in.texts();
    model.notes = in.texts();
    model.primitivesWithoutMaterial = int(in.u32());
    model.boundsMin = in.value<glm::vec3>();
    model.boundsMax = in.value<glm::vec3>();
    if (!finite(model.boundsMin) || !finite(model.boundsMax)) in.fail("non-finite bounds");
    model.lights.resize(in.count(4));
    for (PunctualLight& light : model.lights) {
        const std::uint32_t type = in.u32();
        if (type > 2) in.fail("unknown light type");
        light.type = PunctualLight::Type(type);
        light.name = in.text();
        light.color = in.value<glm::vec3>();
        light.position = in.value<glm::vec3>();
        light.direction = in.value<glm::vec3>();
        light.range = in.value<float>();
        light.innerConeAngle = in.value<float>();
        light.outerConeAngle = in.value<float>();
        if (!finite(light.color) || !finite(light.position) || !finite(light.direction)) {
            in.fail("light '" + printable(light.name) +
                    "' has a non-finite colour, place or direction");
        }
    }
    model.embeddedImages.resize(in.count(4));
    for (EmbeddedImage& image : model.embeddedImages) {
        image.name = in.text();
        image.width = in.value<std::int32_t>();
        image.height = in.value<std::int32_t>();
        image.bytes = in.array<std::uint8_t>();
        // sizes checked before they multiply (a negative height wrapped the product, which
        // a crafted pack could make equal its byte count: the fuzz build's unsigned-overflow
        // check found it); at most 2^28 texels, as decodeImage takes
        if (image.width < 0 || image.height < 0 ||
            std::uint64_t(image.width) * std::uint64_t(image.height) > (std::uint64_t(1) << 28)) {
            in.fail("embedded image '" + printable(image.name) + "' has a size of " +
                    std::to_string(image.width) + " x " + std::to_string(image.height));
        }
        if (image.width > 0 &&
            image.bytes.size() != size_t(image.width) * size_t(image.height) * 4) {
            in.fail("embedded image '" + printable(image.name) +
                    "' is not width x height RGBA texels");
        }
    }
    model.materials.resize(in.count(4));
    for (Material& m : model.materials) {
        m.name = in.text();
        for (bool* flag : {&m.unlit, &m.specularGlossiness, &m.doubleSided, &m.gltfDefault})
            *flag = in.value<std::uint8_t>() != 0;
        for (TextureRef* ref : m.textures()) *ref = readTexture(in, model.embeddedImages.size());
        m.baseColorFactor = in.value<glm::vec4>();
        m.metallicFactor = in.value<float>();
        m.roughnessFactor = in.value<float>();
        m.normalScale = in.value<float>();
        m.occlusionStrength = in.value<float>();
        m.emissiveFactor = in.value<glm::vec3>();
        m.specularFactor = in.value<glm::vec3>();
        m.glossinessFactor = in.value<float>();
        const std::uint32_t alphaMode = in.u32();
        if (alphaMode > 2) in.fail("unknown alpha mode");
        m.alphaMode = AlphaMode(alphaMode);
        m.alphaCutoff = in.value<float>();
        extensionFactors(m, [&](auto& value) { value = in.value<std::remove_cvref_t<decltype(value)>>(); });
        m.extensions = in.texts();
    }
    model.primitives.resize(in.count(4));
    for (ModelPrimitive& p : model.primitives) {
        p.material = int(in.u32());
        if (size_t(p.material) >= model.materials.size()) in.fail("material index out of range");
        p.transform = in.value<glm::mat4>();
        if (!finite(p.transform)) in.fail("a non-finite node transform");
        const std::uint32_t primitive = in.u32();
        if (primitive > 1) in.fail("unknown primitive type");
        p.mesh.primitive = Primitive(primitive);
        p.mesh.positions = in.array<glm::vec3>();
        p.mesh.normals = in.array<glm::vec3>();
        p.mesh.uvs = in.array<glm::vec2>();
        p.mesh.tangents = in.array<glm::vec4>();
        p.mesh.colors = in.array<glm::vec4>();
        p.mesh.uvs1 = in.array<glm::vec2>();
        p.mesh.indices = in.array<std::uint32_t>();
        const size_t n = p.mesh.positions.size();
        for (const size_t size : {p.mesh.normals.size(), p.mesh.uvs.size(), p.mesh.tangents.size(),
                                  p.mesh.colors.size(), p.mesh.uvs1.size()}) {
            if (size != 0 && size != n)
                in.fail("a vertex attribute's count differs from the positions'");
        }
        for (const std::uint32_t index : p.mesh.indices) {
            if (index >= n) in.fail("vertex index out of range");
        }
        for (const auto* vectors : {&p.mesh.positions, &p.mesh.normals}) {
            for (const glm::vec3& v : *vectors) {
                if (!finite(v)) in.fail("a non-finite vertex position or normal");
            }
        }
    }
    if (in.at != bytes.size()) in.fail("bytes after the model (not a model pack of this layout)");
    if (model.primitives.empty()) in.fail("no triangles to draw");
    return model;
}

void writeModelPack(const Model& model, const fs::path& path) {
    writeFileAtomically(path, encodeModelPack(model));
}

}  // namespace pbr
