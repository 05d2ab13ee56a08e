#include "renderer/scene/gltf_dropped.h"

#include <cstdio>
#include <map>

namespace ds::scene::detail {
namespace {

std::string factor_text(float v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", double(v));
    return text;
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
    std::vector<std::string> lines;
    for (const auto& [texture, why] : unusable) {
        std::string line = why + ": texture " + std::to_string(texture);
        const auto found = uses.find(texture);
        if (found == uses.end()) {
            lines.push_back(line + " is used by no material");
            continue;
        }
        line += " dropped, factors only for";
        for (size_t i = 0; i < found->second.size(); ++i)
            line += (i ? ", " : " ") + found->second[i];
        lines.push_back(line);
    }
    return lines;
}

}  // namespace ds::scene::detail
