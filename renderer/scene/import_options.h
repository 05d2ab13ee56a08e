#pragma once
// How a scene file is loaded (load_scene, load_gltf): the one choice a command gives.

namespace ds::scene {

struct ImportOptions {
    // Refuse (one error, as before issue 27) what is otherwise a warning: an image file that is
    // missing or does not decode, a texture whose image only an unsupported extension holds.
    // Lenient, such a texture is dropped from its materials (gltf_dropped.h).
    bool strict = false;
};

}  // namespace ds::scene
