#pragma once
// The renderer's device as reports name it: plain data, so the capture layer can take it
// without reaching up to the facade (renderer/device_info.h fills it).
#include <string>

namespace ds {

struct DeviceInfo {
    std::string name;         // "llvmpipe (LLVM 15.0.6, 256 bits)"
    std::string driver;       // driver name and info: "llvmpipe Mesa 22.3.6 (LLVM 15.0.6)"
    std::string api_version;  // "1.3.230"
};

}  // namespace ds
