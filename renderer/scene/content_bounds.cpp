// The part of a scene a camera should frame (scene.h: content_bounds).
#include <algorithm>
#include <numeric>

#include "renderer/scene/mesh_ops.h"
#include "renderer/scene/scene.h"

namespace ds::scene {
namespace {

float diagonal(const Bounds& b) {
    return b.valid() ? glm::length(b.extent()) : 0.0f;
}

}  // namespace

Bounds content_bounds(const Scene& scene) {
    const size_t n = scene.instances.size();
    std::vector<Bounds> boxes(n);
    for (size_t i = 0; i < n; ++i) {
        const Instance& instance = scene.instances[i];
        if (instance.mesh < scene.meshes.size())
            boxes[i] = detail::transform_bounds(scene.meshes[instance.mesh].bounds, instance.world);
    }
    std::vector<size_t> order(n);
    std::iota(order.begin(), order.end(), size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return diagonal(boxes[a]) > diagonal(boxes[b]); });
    // rest[k]: the box of every instance but the k largest.
    std::vector<Bounds> rest(n + 1);
    for (size_t k = n; k-- > 0;) {
        rest[k] = rest[k + 1];
        rest[k].extend(boxes[order[k]]);
    }
    const float whole = diagonal(rest[0]);
    const size_t most = std::min(std::max<size_t>(2, n / 10), n == 0 ? 0 : n - 1);
    for (size_t k = 1; k <= most; ++k)
        if (rest[k].valid() && diagonal(rest[k]) * kContentDwarf <= whole) return rest[k];
    return rest[0].valid() ? rest[0] : scene.bounds;
}

}  // namespace ds::scene
