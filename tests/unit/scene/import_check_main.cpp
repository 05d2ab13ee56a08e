// ds_import_check FILE: loads one glTF file through the importer (built with ASan + UBSan by
// tests/unit/scene/CMakeLists.txt) and prints exactly one line. Exit 0: loaded; 1: InputError.
#include <cstdio>
#include <exception>

#include "renderer/common/error.h"
#include "renderer/scene/importer.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: ds_import_check FILE.gltf|FILE.glb\n");
        return 2;
    }
    try {
        const ds::scene::Scene scene = ds::scene::load_gltf(argv[1]);
        std::printf(
            "ok: %s: %zu meshes, %zu materials, %zu textures, %zu draw groups, "
            "%zu instances, %llu triangles\n",
            argv[1], scene.meshes.size(), scene.materials.size(), scene.textures.size(),
            scene.draw_groups.size(), scene.instances.size(),
            static_cast<unsigned long long>(scene.triangle_count()));
        return 0;
    } catch (const ds::InputError& e) {
        std::printf("depthscope: error: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        // Anything but InputError is a bug in the importer for this tool: a distinct code.
        std::printf("depthscope: internal error: %s\n", e.what());
        return 3;
    }
}
