#include "capture/tune/reference_files.h"

#include "capture/exr_file.h"
#include "capture/image_writer.h"
#include "capture/tune/reference.h"
#include "capture/tune/score.h"

namespace ds::tune {
namespace {

capture::ExrImage hdr_exr(const Reference& ref) {
    capture::ExrImage exr{ref.width, ref.height, {}};
    const char* names[4] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c) {
        capture::ExrChannel ch{names[c], false, {}, {}};
        ch.floats.resize(size_t(ref.width) * ref.height);
        for (size_t p = 0; p < ch.floats.size(); ++p) ch.floats[p] = ref.hdr[p * 4 + size_t(c)];
        exr.channels.push_back(std::move(ch));
    }
    return exr;
}

std::vector<uint8_t> edges_rgba8(const Reference& ref) {
    std::vector<uint8_t> out(size_t(ref.width) * ref.height * 4, 0);
    for (size_t p = 0; p < ref.edges.size(); ++p) {
        const uint8_t v = ref.edges[p] ? 255 : 0;
        out[p * 4] = out[p * 4 + 1] = out[p * 4 + 2] = v;
        out[p * 4 + 3] = 255;
    }
    return out;
}

}  // namespace

nlohmann::json write_reference(Renderer& renderer, const scene::Scene& scene,
                               const scene::Camera& camera, const Settings& settings,
                               const FrameResult& frame,
                               const std::filesystem::path& resources_dir) {
    const Reference ref =
        render_reference(renderer, scene, camera, settings, {frame.width, frame.height});
    std::filesystem::create_directories(resources_dir);
    capture::write_png_rgba8(resources_dir / "reference.png", ref.width, ref.height, ref.rgba8);
    capture::write_exr(resources_dir / "reference.exr", hdr_exr(ref));
    nlohmann::json files = {"resources/reference.png", "resources/reference.exr"};
    if (!ref.edges.empty()) {
        capture::write_png_rgba8(resources_dir / "reference_edges.png", ref.width, ref.height,
                                 edges_rgba8(ref));
        files.push_back("resources/reference_edges.png");
    }
    // final.png's settings may hold gtao / contact_shadows: scored as it is, it says how far
    // the captured frame is from the reference, AO included.
    const ImageScore s = score_against(frame.rgba8, ref);
    return {{"factor", ref.factor},
            {"samples_per_pixel", ref.factor * ref.factor},
            {"ms", ref.ms},
            {"readback_bytes", ref.readback_bytes},
            {"edge_pixels", s.edge_pixels},
            {"files", files},
            {"final",
             {{"ssim", s.ssim},
              {"edge_error", s.edge_error},
              {"percent_over", s.percent_over},
              {"threshold", kScoreThreshold}}}};
}

}  // namespace ds::tune
