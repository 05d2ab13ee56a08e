#pragma once
// The renderer's device as reports name it: plain data, so the capture layer can take it
// without reaching up to the facade (renderer/device_info.h fills it).
#include <string>

namespace ds {

struct DeviceInfo {
    std::string name;         // "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string driver;       // driver name and info: "llvmpipe Mesa 22.3.6 (LLVM 15.0.6)"
    std::string api_version;  // "1.3.230"
    // What the pipeline statistic fragment_shader_invocations counts on this driver (the
    // report's and the Passes panel's label for it).
    std::string fragment_statistic;
};

}  // namespace ds
