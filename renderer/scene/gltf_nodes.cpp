#include "renderer/scene/gltf_nodes.h"

#include <cfloat>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "renderer/scene/import_limits.h"
#include "renderer/scene/import_util.h"

namespace ds::scene::detail {
namespace {

constexpr float kPi = 3.14159265358979f;

bool finite(const glm::mat4& m) {
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 4; ++r)
            if (!std::isfinite(m[c][r])) return false;
    return true;
}

void check_numbers(const std::vector<double>& values, size_t count, const std::string& what) {
    if (!values.empty() && values.size() != count)
        fail(what + " must have " + std::to_string(count) + " numbers");
    for (double v : values) to_float(v, what);
}

void check_index(int index, size_t count, const std::string& what) {
    if (index != -1 && (index < 0 || static_cast<size_t>(index) >= count))
        fail(what + " " + std::to_string(index) + " out of range");
}

// Perspective parameters checked up front; zfar 0 means "infinite" (filled in from the scene
// bounds by the importer).
Camera camera_params(const tinygltf::Camera& source, size_t index) {
    const std::string what = "camera " + std::to_string(index);
    if (source.type == "orthographic") return {};
    if (source.type != "perspective")
        fail(what + ": unknown type \"" + one_line(source.type) + "\"");
    const auto& p = source.perspective;
    Camera c;
    c.yfov = to_float(p.yfov, what + " yfov");
    c.znear = to_float(p.znear, what + " znear");
    c.zfar = to_float(p.zfar, what + " zfar");
    if (!(c.yfov > 0.0f && c.yfov < kPi)) fail(what + ": yfov must be in (0, pi)");
    if (!(c.znear > 0.0f)) fail(what + ": znear must be > 0");
    if (c.zfar != 0.0f && !(c.zfar > c.znear)) fail(what + ": zfar must be > znear");
    return c;
}

// An orthographic camera's planes, as the file gives them: nothing renders through them, so a
// value beyond float range is shown as 0 rather than refusing the file.
float ortho_plane(double value) {
    return std::isfinite(value) && std::fabs(value) <= double{FLT_MAX} ? static_cast<float>(value)
                                                                       : 0.0f;
}

// Places `params` at a node: glTF cameras look down their local -Z with +Y up. Nothing when
// the node's transform collapses the view direction (e.g. zero scale).
std::optional<Camera> place_camera(Camera params, const glm::mat4& world) {
    const glm::vec3 forward = -glm::vec3(world[2]);
    const glm::vec3 up = glm::vec3(world[1]);
    if (!(glm::dot(forward, forward) > 1e-12f)) return std::nullopt;
    params.position = glm::vec3(world[3]);
    params.forward = glm::normalize(forward);
    glm::vec3 right = glm::cross(params.forward, up);
    if (!(glm::dot(right, right) > 1e-12f)) {
        const glm::vec3 axis =
            std::abs(params.forward.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
        right = glm::cross(params.forward, axis);
    }
    params.up = glm::normalize(glm::cross(glm::normalize(right), params.forward));
    return params;
}

// Checks every node (used or not) and returns their local transforms.
std::vector<glm::mat4> check_nodes(const tinygltf::Model& model) {
    std::vector<glm::mat4> locals;
    locals.reserve(model.nodes.size());
    for (size_t i = 0; i < model.nodes.size(); ++i) {
        const tinygltf::Node& node = model.nodes[i];
        const std::string what = "node " + std::to_string(i) + ":";
        check_index(node.mesh, model.meshes.size(), what + " mesh");
        check_index(node.camera, model.cameras.size(), what + " camera");
        check_index(node.skin, model.skins.size(), what + " skin");
        for (int child : node.children)
            if (child < 0 || static_cast<size_t>(child) >= model.nodes.size())
                fail(what + " child node " + std::to_string(child) + " out of range");
        locals.push_back(local_transform(node, i));
    }
    return locals;
}

// Camera node `index` placed by `world` into the walk's list (and as its camera when it is the
// first perspective one placed).
void add_camera(const tinygltf::Model& model, const std::vector<Camera>& params,
                const tinygltf::Node& node, int index, const glm::mat4& world, SceneWalk& walk) {
    const auto which = static_cast<size_t>(node.camera);
    const tinygltf::Camera& source = model.cameras[which];
    SceneCamera c;
    c.gltf_node = index;
    c.name = node.name;
    if (source.type == "perspective") {
        c.yfov = params[which].yfov;
        c.znear = params[which].znear;
        c.zfar = params[which].zfar;
        c.camera = place_camera(params[which], world);
        if (!walk.camera) walk.camera = c.camera;
    } else {
        c.type = SceneCamera::Type::Orthographic;
        c.znear = ortho_plane(source.orthographic.znear);
        c.zfar = ortho_plane(source.orthographic.zfar);
    }
    walk.cameras.push_back(std::move(c));
}

}  // namespace

int pick_scene(const tinygltf::Model& model) {
    if (model.scenes.empty()) fail("no scene");
    if (model.defaultScene == -1) return 0;
    if (model.defaultScene < 0 || static_cast<size_t>(model.defaultScene) >= model.scenes.size())
        fail("scene " + std::to_string(model.defaultScene) + " out of range (" +
             std::to_string(model.scenes.size()) + " scenes)");
    return model.defaultScene;
}

glm::mat4 local_transform(const tinygltf::Node& node, size_t index) {
    const std::string what = "node " + std::to_string(index);
    check_numbers(node.matrix, 16, what + " matrix");
    check_numbers(node.translation, 3, what + " translation");
    check_numbers(node.rotation, 4, what + " rotation");
    check_numbers(node.scale, 3, what + " scale");
    glm::mat4 m(1.0f);
    if (!node.matrix.empty()) {  // column-major, as glm
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r)
                m[c][r] = static_cast<float>(node.matrix[static_cast<size_t>(c * 4 + r)]);
        return m;
    }
    if (!node.translation.empty())
        m = glm::translate(
            m, glm::vec3(node.translation[0], node.translation[1], node.translation[2]));
    if (!node.rotation.empty()) {
        glm::quat q(static_cast<float>(node.rotation[3]), static_cast<float>(node.rotation[0]),
                    static_cast<float>(node.rotation[1]), static_cast<float>(node.rotation[2]));
        const float len = glm::length(q);
        // Exporters write slightly denormalised quaternions; only a zero one has no meaning.
        if (!(len > 1e-6f) || !std::isfinite(len))
            fail(what + " rotation is not a unit quaternion");
        m = m * glm::mat4_cast(q / len);
    }
    if (!node.scale.empty())
        m = glm::scale(m, glm::vec3(node.scale[0], node.scale[1], node.scale[2]));
    return m;
}

SceneWalk walk_scene(const tinygltf::Model& model, int scene_index) {
    std::vector<Camera> cameras;
    for (size_t i = 0; i < model.cameras.size(); ++i)
        cameras.push_back(camera_params(model.cameras[i], i));
    const std::vector<glm::mat4> locals = check_nodes(model);

    enum : uint8_t { kUnseen, kOnPath, kDone };
    std::vector<uint8_t> state(model.nodes.size(), kUnseen);
    struct Item {
        int node;
        glm::mat4 parent;
        bool exit;     // leaving the node's subtree: it is no longer on the current path
        size_t depth;  // 1 for a scene root
    };
    std::vector<Item> stack;
    auto push_children = [&](const std::vector<int>& nodes, const glm::mat4& parent,
                             const std::string& owner, size_t depth) {
        for (auto it = nodes.rbegin(); it != nodes.rend(); ++it) {
            if (*it < 0 || static_cast<size_t>(*it) >= model.nodes.size())
                fail(owner + ": node " + std::to_string(*it) + " out of range");
            stack.push_back({*it, parent, false, depth});
        }
    };
    const tinygltf::Scene& scene = model.scenes[static_cast<size_t>(scene_index)];
    push_children(scene.nodes, glm::mat4(1.0f), "scene " + std::to_string(scene_index), 1);

    SceneWalk walk;
    while (!stack.empty()) {
        const Item item = stack.back();
        stack.pop_back();
        const auto index = static_cast<size_t>(item.node);
        if (item.exit) {
            state[index] = kDone;
            continue;
        }
        const std::string what = "node " + std::to_string(index);
        if (state[index] == kOnPath) fail(what + " is its own ancestor (cycle in the hierarchy)");
        if (state[index] == kDone)
            fail(what + " is reached twice (two parents, or listed twice in the scene)");
        state[index] = kOnPath;
        if (item.depth > limits::kMaxHierarchyDepth)
            fail(what + ": the node hierarchy is more than " +
                 std::to_string(limits::kMaxHierarchyDepth) + " levels deep (the limit)");

        const tinygltf::Node& node = model.nodes[index];
        const glm::mat4 world = item.parent * locals[index];
        if (!finite(world)) fail(what + ": world transform is not finite");
        if (node.mesh >= 0)
            walk.placements.push_back(
                {node.mesh, world, node.name.empty() ? what : node.name, item.node});
        if (node.camera >= 0) add_camera(model, cameras, node, item.node, world, walk);
        stack.push_back({item.node, glm::mat4(1.0f), true, item.depth});
        push_children(node.children, world, what, item.depth + 1);
    }
    return walk;
}

}  // namespace ds::scene::detail
