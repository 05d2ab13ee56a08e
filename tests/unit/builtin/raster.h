#pragma once
// A tiny CPU rasteriser for facts about the built-in scenes: fragments per pixel with no depth
// test (depth complexity), and a depth-tested "which triangle is nearest" view for debug images.
#include <cstdint>
#include <vector>

#include "model_view.h"

namespace ds::test {

struct RasterOptions {
    int width = 160;
    int height = 90;
    bool cull_back_faces = true;  // single-sided triangles, as the GPU would rasterise them
};

struct Coverage {
    int width = 0;
    int height = 0;
    std::vector<uint32_t> fragments;  // per pixel, no depth test
    std::vector<int> nearest;         // index into the triangle list, -1 where empty
    std::vector<float> depth;         // linear depth of `nearest`

    uint64_t total_fragments() const;
    uint64_t covered_pixels() const;
    // Fragments per covered pixel: the average depth complexity of the view.
    double depth_complexity() const;
};

Coverage rasterise(const std::vector<WorldTriangle>& tris, const ViewCamera& cam,
                   const RasterOptions& opt = {});

}  // namespace ds::test
