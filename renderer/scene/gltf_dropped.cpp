#include "renderer/scene/gltf_dropped.h"

#include <algorithm>
#include <cstdio>
#include <map>

namespace ds::scene::detail {
namespace {

std::string factor_text(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(v));
    return text;
}

// "texture 3" or "textures 3, 4, 6".
std::string texture_list(const std::vector<size_t>& textures) {
    std::string out = textures.size() == 1 ? "texture" : "textures";
    for (size_t i = 0; i < textures.size(); ++i)
        out += (i ? ", " : " ") + std::to_string(textures[i]);
    return out;
}

std::string joined(const std::vector<std::string>& items) {
    std::string out;
    for (size_t i = 0; i < items.size(); ++i) out += (i ? ", " : " ") + items[i];
    return out;
}

}  // namespace

std::vector<std::string> drop_unusable_textures(std::vector<Material>& materials,
                                                const UnusableTextures& unusable) {
    std::map<size_t, std::vector<std::string>> uses;  // texture -> what lost it
    for (Material& m : materials) {
        const std::pair<TextureRef*, const char*> slots[] = {
            {&m.base_color, "baseColorTexture"},
            {&m.metallic_roughness, "metallicRoughnessTexture"},
            {&m.normal, "normalTexture"},
            {&m.occlusion, "occlusionTexture"},
            {&m.emissive, "emissiveTexture"}};
        for (auto& [ref, slot] : slots) {
            if (!ref->present() || !unusable.contains(size_t(ref->texture))) continue;
            std::string use = "material \"" + m.name + "\" " + slot;
            if (ref == &m.base_color && m.alpha_mode == AlphaMode::Mask)
                use += " (masked: its alpha test now reads baseColorFactor's alpha " +
                       factor_text(m.base_color_factor.a) + ")";
            uses[size_t(ref->texture)].push_back(use);
            *ref = TextureRef{};
        }
    }
    // One line per cause (an image file, an extension): textures that share an image share it.
    std::vector<std::pair<std::string, std::vector<size_t>>> causes;
    for (const auto& entry : unusable) {  // (not a structured binding: a lambda reads it)
        auto it = std::find_if(causes.begin(), causes.end(),
                               [&](const auto& c) { return c.first == entry.second; });
        if (it == causes.end()) it = causes.insert(causes.end(), {entry.second, {}});
        it->second.push_back(entry.first);
    }
    std::vector<std::string> lines;
    for (const auto& [why, textures] : causes) {
        std::vector<size_t> used, unused;
        std::vector<std::string> lost;
        for (const size_t t : textures) {
            const auto found = uses.find(t);
            (found == uses.end() ? unused : used).push_back(t);
            if (found != uses.end())
                lost.insert(lost.end(), found->second.begin(), found->second.end());
        }
        std::string line = why + ":";
        if (!used.empty())
            line += " " + texture_list(used) + " dropped, factors only for" + joined(lost);
        if (!unused.empty())
            line += std::string(used.empty() ? " " : "; ") + texture_list(unused) +
                    " used by no material";
        lines.push_back(line);
    }
    return lines;
}

}  // namespace ds::scene::detail
