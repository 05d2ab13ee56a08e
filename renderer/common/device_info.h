#pragma once
// The renderer's device as reports name it: plain data, so the capture layer can take it
// without reaching up to the facade (renderer/device_info.h fills it).
#include <string>
#include <vector>

namespace ds {

struct DeviceInfo {
    std::string name;         // "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string driver;       // driver name and info: "llvmpipe Mesa 22.3.6 (LLVM 15.0.6)"
    std::string api_version;  // "1.3.230"
    // What the pipeline statistic fragment_shader_invocations counts on this driver (the
    // report's and the Passes panel's label for it).
    std::string fragment_statistic;
    // What the frame may ask of it (bench --soak's combinations): the msaa sample counts it
    // supports, and whether count_fragments, count_draws and surface_id / zfight can run.
    std::vector<int> msaa_counts;
    // VkPhysicalDeviceLimits::standardSampleLocations: samples lie where the spec's table puts
    // them (view/sample_positions.h); false: the sample view's positions are approximate.
    bool standard_sample_locations = false;
    bool fragment_counts = false;
    bool draw_counts = false;
    bool surface_ids = false;
    // Whether passes are timed (timestamps on the graphics queue): without, every gpu_ms and
    // gpu_start_ms is 0 and --trace is refused.
    bool timestamps = false;
};

}  // namespace ds
