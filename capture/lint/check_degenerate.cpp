// DEGENERATE_TRIANGLE (info): per mesh, its triangles degenerate by area, not only by index
// (renderer/scene/surface_pairs.h's rule: a repeated or out-of-range index, or an area at
// most 1e-7 of the longest edge squared): they cover no pixel and cost vertex work. Counted in
// the mesh's own space, once however many nodes place it; meshes no node draws are left out.
#include "capture/diagnose/checks.h"
#include "capture/lint/checks.h"
#include "renderer/scene/surface_pairs.h"

namespace ds::lint {

void check_degenerate(const Input& in, Output& out) {
    out.ran.push_back("degenerate");
    const std::vector<int64_t> instance_of = first_instances(in.scene);
    for (const scene::DegenerateTriangles& d : scene::find_degenerate_triangles(in.scene.meshes)) {
        if (instance_of[d.mesh] < 0) continue;  // a mesh no node draws
        const scene::Mesh& m = in.scene.meshes.at(d.mesh);
        Finding f;
        f.code = "DEGENERATE_TRIANGLE";
        f.severity = Severity::Info;
        f.detector = "degenerate";
        f.pointer = "/meshes/" + std::to_string(m.gltf_mesh);
        f.magnitude = {double(d.count), "triangles"};
        f.message = "mesh " + m.name + " has " + std::to_string(d.count) + " of " +
                    std::to_string(m.indices.size() / 3) +
                    " triangles with no area (the first: triangle " + std::to_string(d.first) + ")";
        f.fix = "remove them (meshopt or the exporter's cleanup): they cover no pixel";
        f.surfaces = {diagnose::surface_of(in.scene, uint32_t(instance_of[d.mesh]))};
        out.findings.push_back(std::move(f));
    }
}

}  // namespace ds::lint
