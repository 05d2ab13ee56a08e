// The warning lines for unusable textures (renderer/scene/gltf_dropped.h): one per cause, the
// textures it takes, what each material that used them keeps.
#include <gtest/gtest.h>

#include "renderer/scene/gltf_dropped.h"

namespace ds::scene::detail {
namespace {

Material with(const std::string& name, int32_t base, int32_t normal, AlphaMode mode) {
    Material m;
    m.name = name;
    m.base_color.texture = base;
    m.normal.texture = normal;
    m.alpha_mode = mode;
    return m;
}

TEST(DroppedTextures, OneLinePerImageNamingEveryTextureAndMaterialItTakes) {
    std::vector<Material> materials = {with("ribs", -1, 3, AlphaMode::Opaque),
                                       with("ribs_too", -1, 4, AlphaMode::Opaque),
                                       with("leaves", 1, -1, AlphaMode::Mask)};
    const UnusableTextures unusable = {{1, "images[0] (\"leaves.png\"): no such file"},
                                       {3, "images[2] (\"ribs.png\"): no such file"},
                                       {4, "images[2] (\"ribs.png\"): no such file"},
                                       {7, "images[2] (\"ribs.png\"): no such file"},
                                       {9, "images[5] (\"unused.png\"): no such file"}};
    const std::vector<std::string> lines = drop_unusable_textures(materials, unusable);
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_EQ(lines[0],
              "images[0] (\"leaves.png\"): no such file: texture 1 dropped, factors only for "
              "material \"leaves\" baseColorTexture (masked: its alpha test now reads "
              "baseColorFactor's alpha 1)");
    EXPECT_EQ(lines[1],
              "images[2] (\"ribs.png\"): no such file: textures 3, 4 dropped, factors only for "
              "material \"ribs\" normalTexture, material \"ribs_too\" normalTexture; texture 7 "
              "used by no material");
    EXPECT_EQ(lines[2], "images[5] (\"unused.png\"): no such file: texture 9 used by no material");
    for (const Material& m : materials) {
        EXPECT_FALSE(m.base_color.present()) << m.name;
        EXPECT_FALSE(m.normal.present()) << m.name;
    }
}

}  // namespace
}  // namespace ds::scene::detail
