#include "renderer/scene/gltf_material.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>

#include "renderer/scene/import_util.h"

namespace ds::scene::detail {
namespace {

// Each image becomes one 2D texture; 16384 is the largest 2D size lavapipe (our reference
// device) supports, and far beyond what real scenes use.
constexpr int kMaxImageSize = 16384;

std::string image_label(const tinygltf::Image& image, size_t index) {
    std::string label = "image " + std::to_string(index);
    if (!image.name.empty()) return label + " (" + image.name + ")";
    // data: URIs hold the whole image; only a file name is worth showing.
    if (!image.uri.empty() && !image.uri.starts_with("data:"))
        return label + " (" + image.uri + ")";
    return label;
}

uint8_t channel(const tinygltf::Image& image, size_t offset) {
    if (image.bits == 8) return image.image[offset];
    uint16_t v;  // 16-bit channels are stored in host byte order by tinygltf / stb_image
    std::memcpy(&v, image.image.data() + offset * 2, sizeof v);
    return static_cast<uint8_t>((v * 255u + 32767u) / 65535u);
}

Image import_image(const tinygltf::Image& source, size_t index) {
    const std::string what = image_label(source, index);
    if (source.image.empty()) fail(what + ": no pixel data (missing or undecodable image)");
    if (source.width <= 0 || source.height <= 0)
        fail(what + ": invalid size " + std::to_string(source.width) + "x" +
             std::to_string(source.height));
    if (source.width > kMaxImageSize || source.height > kMaxImageSize)
        fail(what + ": " + std::to_string(source.width) + "x" + std::to_string(source.height) +
             " is larger than " + std::to_string(kMaxImageSize));
    if (source.component < 1 || source.component > 4)
        fail(what + ": invalid component count " + std::to_string(source.component));
    if (source.bits != 8 && source.bits != 16)
        fail(what + ": unsupported bit depth " + std::to_string(source.bits));

    const size_t pixels = static_cast<size_t>(source.width) * static_cast<size_t>(source.height);
    const auto components = static_cast<size_t>(source.component);
    const size_t needed = pixels * components * static_cast<size_t>(source.bits / 8);
    if (source.image.size() < needed)
        fail(what + ": pixel data is " + std::to_string(source.image.size()) + " bytes, need " +
             std::to_string(needed));

    Image image;
    image.name = source.name;
    if (image.name.empty() && !source.uri.empty() && !source.uri.starts_with("data:"))
        image.name = source.uri;
    if (image.name.empty()) image.name = "image " + std::to_string(index);
    image.width = static_cast<uint32_t>(source.width);
    image.height = static_cast<uint32_t>(source.height);
    image.rgba8.resize(pixels * 4);
    for (size_t p = 0; p < pixels; ++p) {
        uint8_t c[4] = {0, 0, 0, 255};
        for (size_t k = 0; k < components; ++k) c[k] = channel(source, p * components + k);
        if (components <= 2) {  // grey (+ alpha): spread grey over RGB
            c[3] = components == 2 ? c[1] : uint8_t{255};
            c[1] = c[2] = c[0];
        }
        std::memcpy(&image.rgba8[p * 4], c, 4);
    }
    return image;
}

Filter mag_filter(int value, const std::string& what) {
    switch (value) {
        case -1:
        case TINYGLTF_TEXTURE_FILTER_LINEAR:
            return Filter::Linear;
        case TINYGLTF_TEXTURE_FILTER_NEAREST:
            return Filter::Nearest;
        default:
            fail(what + ": invalid magFilter " + std::to_string(value));
    }
}

void set_min_filter(Sampler& sampler, int value, const std::string& what) {
    using F = Filter;
    struct Mode {
        int value;
        F min;
        bool mipmaps;
        F mip;
    };
    static constexpr Mode kModes[] = {
        {-1, F::Linear, true, F::Linear},  // undefined: the best quality we can offer
        {TINYGLTF_TEXTURE_FILTER_NEAREST, F::Nearest, false, F::Nearest},
        {TINYGLTF_TEXTURE_FILTER_LINEAR, F::Linear, false, F::Linear},
        {TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST, F::Nearest, true, F::Nearest},
        {TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST, F::Linear, true, F::Nearest},
        {TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR, F::Nearest, true, F::Linear},
        {TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR, F::Linear, true, F::Linear},
    };
    for (const Mode& mode : kModes) {
        if (mode.value == value) {
            sampler.min = mode.min;
            sampler.mipmaps = mode.mipmaps;
            sampler.mip = mode.mip;
            return;
        }
    }
    fail(what + ": invalid minFilter " + std::to_string(value));
}

Wrap wrap_mode(int value, const std::string& what) {
    switch (value) {
        case TINYGLTF_TEXTURE_WRAP_REPEAT:
            return Wrap::Repeat;
        case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
            return Wrap::ClampToEdge;
        case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
            return Wrap::MirroredRepeat;
        default:
            fail(what + ": invalid wrap mode " + std::to_string(value));
    }
}

float finite_factor(double value, const std::string& what) {
    return to_float(value, what);
}

// `values` must hold N finite numbers; an empty vector (a model built in memory) means the
// glTF default.
template <int N>
glm::vec<N, float> factor_vector(const std::vector<double>& values, float fallback,
                                 const std::string& what) {
    glm::vec<N, float> out(fallback);
    if (values.empty()) return out;
    if (values.size() != N) fail(what + " must have " + std::to_string(N) + " numbers");
    for (int i = 0; i < N; ++i) out[i] = finite_factor(values[static_cast<size_t>(i)], what);
    return out;
}

// KHR_texture_transform's numbers: `count` finite numbers (1: a number, else an array).
std::vector<float> transform_numbers(const tinygltf::Value& t, const char* key, size_t count,
                                     const std::string& what) {
    const std::string name = what + ".KHR_texture_transform." + key;
    const tinygltf::Value& v = t.Get(key);
    std::vector<float> out;
    if (count == 1 && v.IsNumber()) out.push_back(to_float(v.GetNumberAsDouble(), name));
    if (count > 1 && v.IsArray() && v.ArrayLen() == count)
        for (size_t i = 0; i < count; ++i)
            if (v.Get(int(i)).IsNumber())
                out.push_back(to_float(v.Get(int(i)).GetNumberAsDouble(), name));
    if (out.size() != count)
        fail(name + " must be " + (count == 1 ? "a number" : std::to_string(count) + " numbers"));
    return out;
}

void apply_transform(TextureRef& ref, const tinygltf::ExtensionMap& extensions,
                     const std::string& what) {
    const auto found = extensions.find("KHR_texture_transform");
    if (found == extensions.end()) return;
    const tinygltf::Value& t = found->second;
    if (!t.IsObject()) fail(what + ".KHR_texture_transform must be an object");
    if (t.Has("offset")) {
        const std::vector<float> o = transform_numbers(t, "offset", 2, what);
        ref.offset = {o[0], o[1]};
    }
    if (t.Has("rotation")) ref.rotation = transform_numbers(t, "rotation", 1, what)[0];
    if (t.Has("scale")) {
        const std::vector<float> sc = transform_numbers(t, "scale", 2, what);
        ref.scale = {sc[0], sc[1]};
    }
    if (t.Has("texCoord")) {  // overrides the textureInfo's
        const tinygltf::Value& v = t.Get("texCoord");
        if (!v.IsInt() || v.GetNumberAsInt() < 0)
            fail(what + ".KHR_texture_transform.texCoord must be a non-negative integer");
        ref.uv_set = uint32_t(v.GetNumberAsInt());
    }
}

template <typename Info>
TextureRef texture_ref(const Info& info, size_t texture_count, const std::string& what) {
    if (info.index < 0) return {};
    if (static_cast<size_t>(info.index) >= texture_count)
        fail(what + ": texture " + std::to_string(info.index) + " out of range");
    if (info.texCoord < 0) fail(what + ": invalid texCoord " + std::to_string(info.texCoord));
    TextureRef ref{info.index, static_cast<uint32_t>(info.texCoord)};
    apply_transform(ref, info.extensions, what);
    return ref;
}

AlphaMode alpha_mode(const std::string& mode, const std::string& what) {
    if (mode == "OPAQUE" || mode.empty()) return AlphaMode::Opaque;
    if (mode == "MASK") return AlphaMode::Mask;
    if (mode == "BLEND") return AlphaMode::Blend;
    fail(what + ": unknown alphaMode \"" + one_line(mode) + "\"");
}

Material import_material(const tinygltf::Material& source, size_t index, size_t texture_count) {
    const std::string what = "material " + std::to_string(index);
    const auto& pbr = source.pbrMetallicRoughness;
    Material m;
    m.name = source.name.empty() ? what : source.name;
    m.base_color_factor = factor_vector<4>(pbr.baseColorFactor, 1.0f, what + " baseColorFactor");
    m.emissive_factor = factor_vector<3>(source.emissiveFactor, 0.0f, what + " emissiveFactor");
    // Out-of-range factors are clamped as the glTF BRDF does, not rejected.
    m.metallic_factor =
        std::clamp(finite_factor(pbr.metallicFactor, what + " metallicFactor"), 0.0f, 1.0f);
    m.roughness_factor =
        std::clamp(finite_factor(pbr.roughnessFactor, what + " roughnessFactor"), 0.0f, 1.0f);
    m.normal_scale = finite_factor(source.normalTexture.scale, what + " normalTexture.scale");
    m.occlusion_strength = std::clamp(
        finite_factor(source.occlusionTexture.strength, what + " occlusionTexture.strength"), 0.0f,
        1.0f);
    m.base_color = texture_ref(pbr.baseColorTexture, texture_count, what + " baseColorTexture");
    m.metallic_roughness = texture_ref(pbr.metallicRoughnessTexture, texture_count,
                                       what + " metallicRoughnessTexture");
    m.normal = texture_ref(source.normalTexture, texture_count, what + " normalTexture");
    m.occlusion = texture_ref(source.occlusionTexture, texture_count, what + " occlusionTexture");
    m.emissive = texture_ref(source.emissiveTexture, texture_count, what + " emissiveTexture");
    m.alpha_mode = alpha_mode(source.alphaMode, what);
    m.alpha_cutoff = finite_factor(source.alphaCutoff, what + " alphaCutoff");
    if (m.alpha_cutoff < 0.0f) fail(what + ": negative alphaCutoff");
    m.double_sided = source.doubleSided;
    return m;
}

}  // namespace

std::vector<Image> import_images(const tinygltf::Model& model,
                                 const std::map<size_t, std::string>& problems) {
    std::vector<Image> images;
    images.reserve(model.images.size());
    for (size_t i = 0; i < model.images.size(); ++i)
        images.push_back(problems.contains(i) ? placeholder_image(image_label(model.images[i], i))
                                              : import_image(model.images[i], i));
    return images;
}

Image placeholder_image(std::string name) {
    Image image;
    image.name = std::move(name);
    image.width = image.height = 1;
    image.rgba8 = {255, 255, 255, 255};
    return image;
}

std::vector<Sampler> import_samplers(const tinygltf::Model& model) {
    std::vector<Sampler> samplers;
    for (size_t i = 0; i < model.samplers.size(); ++i) {
        const tinygltf::Sampler& source = model.samplers[i];
        const std::string what = "sampler " + std::to_string(i);
        Sampler s;
        s.mag = mag_filter(source.magFilter, what);
        set_min_filter(s, source.minFilter, what);
        s.wrap_s = wrap_mode(source.wrapS, what);
        s.wrap_t = wrap_mode(source.wrapT, what);
        samplers.push_back(s);
    }
    samplers.push_back(Sampler{});  // the default sampler, always last
    return samplers;
}

std::vector<Texture> import_textures(const tinygltf::Model& model, uint32_t default_sampler,
                                     const TextureInput& in, std::vector<Image>& images,
                                     UnusableTextures& unusable) {
    std::vector<Texture> textures;
    for (size_t i = 0; i < model.textures.size(); ++i) {
        const tinygltf::Texture& source = model.textures[i];
        const std::string what = "texture " + std::to_string(i);
        if (source.source < 0 && (in.strict || source.extensions.empty()))
            fail(what + " has no image source" +
                 (source.extensions.empty() ? std::string()
                                            : " (its image is only in extension " +
                                                  source.extensions.begin()->first + ")"));
        if (source.source < 0) {  // KHR_texture_basisu, EXT_texture_webp ...: not decoded
            unusable[i] = what + ": its image is only in extension " +
                          source.extensions.begin()->first + ", which is not supported";
            images.push_back(placeholder_image(what + " (no image)"));
            textures.push_back({uint32_t(images.size() - 1), default_sampler});
            continue;
        }
        if (const auto problem = in.image_problems.find(size_t(source.source));
            problem != in.image_problems.end())
            unusable[i] = problem->second;
        if (static_cast<size_t>(source.source) >= model.images.size())
            fail(what + ": image " + std::to_string(source.source) + " out of range");
        if (source.sampler >= 0 && static_cast<size_t>(source.sampler) >= model.samplers.size())
            fail(what + ": sampler " + std::to_string(source.sampler) + " out of range");
        Texture t;
        t.image = static_cast<uint32_t>(source.source);
        t.sampler = source.sampler < 0 ? default_sampler : static_cast<uint32_t>(source.sampler);
        textures.push_back(t);
    }
    return textures;
}

std::vector<Material> import_materials(const tinygltf::Model& model) {
    std::vector<Material> materials;
    materials.reserve(model.materials.size());
    for (size_t i = 0; i < model.materials.size(); ++i)
        materials.push_back(import_material(model.materials[i], i, model.textures.size()));
    return materials;
}

void mark_srgb_images(const std::vector<Material>& materials, const std::vector<Texture>& textures,
                      std::vector<Image>& images) {
    auto mark = [&](const TextureRef& ref) {
        if (!ref.present() || static_cast<size_t>(ref.texture) >= textures.size()) return;
        const uint32_t image = textures[static_cast<size_t>(ref.texture)].image;
        if (image < images.size()) images[image].srgb = true;
    };
    for (const Material& m : materials) {
        mark(m.base_color);
        mark(m.emissive);
    }
}

}  // namespace ds::scene::detail
