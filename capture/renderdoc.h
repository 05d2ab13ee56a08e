#pragma once
// RenderDoc's in-application API, when RenderDoc is already loaded in this process (started
// under `renderdoccmd capture`, or with its layer enabled). depthscope never loads it itself.
#include <filesystem>
#include <memory>
#include <string>

namespace ds::capture {

class RenderDoc {
  public:
    // Nullptr when RenderDoc is not loaded in the process.
    static std::unique_ptr<RenderDoc> attach();

    // `device_pointer` is RENDERDOC_DEVICEPOINTER_FROM_VKINSTANCE(instance). Captures are named
    // after `path_template` (a path without extension; RenderDoc appends a suffix and .rdc).
    void start(void* device_pointer, const std::filesystem::path& path_template);
    // Ends the capture; returns the .rdc's path (throws ds::Error if none was written).
    std::filesystem::path end(void* device_pointer);

  private:
    explicit RenderDoc(void* api) : api_(api) {}
    void* api_;  // RENDERDOC_API_1_4_1*, kept opaque so the header needs no RenderDoc include
};

}  // namespace ds::capture
