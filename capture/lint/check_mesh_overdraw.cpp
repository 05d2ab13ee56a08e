// OVERDRAW (info), per mesh: meshoptimizer's meshopt_analyzeOverdraw (orthographic views of
// the mesh alone along its three axes at 256 x 256, in its index order, back faces counted as
// the view from the other side): a mesh whose own
// triangles shade each covered pixel more than Thresholds::mesh_overdraw times, whatever
// else the scene holds. What meshopt_optimizeOverdraw (a reordering) or the prepass can cut.
// Meshes no instance draws are left out.
#include <cmath>

#include <meshoptimizer.h>

#include "capture/diagnose/checks.h"
#include "capture/diagnose/finding_json.h"
#include "capture/lint/checks.h"

namespace ds::lint {
namespace {

Finding mesh_finding(const Input& in, uint32_t mesh, const meshopt_OverdrawStatistics& s,
                     uint32_t instance) {
    const scene::Mesh& m = in.scene.meshes[mesh];
    Finding f;
    f.code = "OVERDRAW";
    f.severity = Severity::Info;
    f.detector = "mesh_overdraw";
    f.pointer = "/meshes/" + std::to_string(m.gltf_mesh);
    f.magnitude = {std::round(double(s.overdraw) * 100.0) / 100.0, "x"};
    f.message = "mesh " + m.name + " overdraws itself " + diagnose::grouped(f.magnitude.value) +
                "x (meshoptimizer: " + diagnose::grouped(double(s.pixels_shaded)) +
                " pixels shaded for " + diagnose::grouped(double(s.pixels_covered)) +
                " covered, viewed along its axes from both sides)";
    f.fix = "meshopt_optimizeOverdraw (reorder its triangles), or keep the prepass";
    f.surfaces = {diagnose::surface_of(in.scene, instance)};
    return f;
}

}  // namespace

void check_mesh_overdraw(const Input& in, Output& out) {
    out.ran.push_back("mesh_overdraw");
    const std::vector<int64_t> first_instance = first_instances(in.scene);
    for (uint32_t m = 0; m < in.scene.meshes.size(); ++m) {
        const scene::Mesh& mesh = in.scene.meshes[m];
        if (first_instance[m] < 0 || mesh.indices.size() < 3 || mesh.vertices.empty()) continue;
        const meshopt_OverdrawStatistics s = meshopt_analyzeOverdraw(
            mesh.indices.data(), mesh.indices.size() / 3 * 3, &mesh.vertices[0].position.x,
            mesh.vertices.size(), sizeof(scene::Vertex));
        if (double(s.overdraw) > in.thresholds.mesh_overdraw)
            out.findings.push_back(mesh_finding(in, m, s, uint32_t(first_instance[m])));
    }
}

}  // namespace ds::lint
