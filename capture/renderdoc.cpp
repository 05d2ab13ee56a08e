#include "capture/renderdoc.h"

#include <dlfcn.h>

#include <renderdoc_app.h>

#include "renderer/common/error.h"

namespace ds::capture {
namespace {

RENDERDOC_API_1_4_1* api_of(void* api) {
    return static_cast<RENDERDOC_API_1_4_1*>(api);
}

}  // namespace

std::unique_ptr<RenderDoc> RenderDoc::attach() {
    // RTLD_NOLOAD: only find the library if RenderDoc injected it; never load it ourselves.
    void* lib = dlopen("librenderdoc.so", RTLD_NOW | RTLD_NOLOAD);
    if (!lib) return nullptr;
    auto get_api = reinterpret_cast<pRENDERDOC_GetAPI>(dlsym(lib, "RENDERDOC_GetAPI"));
    RENDERDOC_API_1_4_1* api = nullptr;
    if (!get_api || get_api(eRENDERDOC_API_Version_1_4_1, reinterpret_cast<void**>(&api)) != 1 ||
        !api) {
        return nullptr;
    }
    return std::unique_ptr<RenderDoc>(new RenderDoc(static_cast<void*>(api)));
}

void RenderDoc::start(void* device_pointer, const std::filesystem::path& path_template) {
    auto* api = api_of(api_);
    api->SetCaptureFilePathTemplate(path_template.c_str());
    api->StartFrameCapture(device_pointer, nullptr);
}

std::filesystem::path RenderDoc::end(void* device_pointer) {
    auto* api = api_of(api_);
    if (api->EndFrameCapture(device_pointer, nullptr) != 1) {
        throw Error("RenderDoc: the frame capture failed");
    }
    const uint32_t count = api->GetNumCaptures();
    if (count == 0) throw Error("RenderDoc: no capture was written");
    uint32_t length = 0;
    api->GetCapture(count - 1, nullptr, &length, nullptr);
    std::string path(length, '\0');
    api->GetCapture(count - 1, path.data(), &length, nullptr);
    path.resize(path.find('\0') == std::string::npos ? path.size() : path.find('\0'));
    return path;
}

}  // namespace ds::capture
