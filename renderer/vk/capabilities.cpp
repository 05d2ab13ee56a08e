#include "renderer/vk/capabilities.h"
#include "renderer/vk/features.h"

#include <algorithm>
#include <cstdlib>
#include <sstream>
#include <string_view>

#include "renderer/common/error.h"
#include "renderer/format/format.h"
#include "renderer/vk/check.h"

namespace ds::vk {

std::vector<VkFormat> supported_formats(std::span<const VkFormat> candidates,
                                        VkFormatFeatureFlags required, const FormatQuery& query) {
    std::vector<VkFormat> out;
    for (VkFormat format : candidates) {
        // Depth attachments are always optimal tiling; linear-tiling support is irrelevant.
        if ((query(format).optimalTilingFeatures & required) == required) out.push_back(format);
    }
    return out;
}

VkFormat choose_depth_format(std::span<const VkFormat> candidates, VkFormatFeatureFlags required,
                             const FormatQuery& query) {
    std::vector<VkFormat> ok = supported_formats(candidates, required, query);
    if (!ok.empty()) return ok.front();
    std::string names;
    for (VkFormat f : candidates) names += std::string(names.empty() ? "" : ", ") + format::name(f);
    throw Error("no supported depth format (depth attachment + sampled, optimal tiling) among: " +
                (names.empty() ? std::string("(no candidates)") : names));
}

std::string device_type_name(VkPhysicalDeviceType type) {
    switch (type) {
        case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
            return "integrated-gpu";
        case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
            return "discrete-gpu";
        case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
            return "virtual-gpu";
        case VK_PHYSICAL_DEVICE_TYPE_CPU:
            return "cpu";
        default:
            return "other";
    }
}

std::string version_string(uint32_t v) {
    return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) +
           "." + std::to_string(VK_API_VERSION_PATCH(v));
}

std::string sample_counts_text(VkSampleCountFlags counts) {
    std::string out;
    for (uint32_t n = 1; n <= 64; n *= 2)
        if (counts & n) out += (out.empty() ? "" : " ") + std::to_string(n);
    return out.empty() ? "none" : out;
}

std::string resolve_modes_text(VkResolveModeFlags modes) {
    std::string out;
    auto add = [&](VkResolveModeFlagBits bit, const char* name) {
        if (modes & bit) out += std::string(out.empty() ? "" : " ") + name;
    };
    add(VK_RESOLVE_MODE_SAMPLE_ZERO_BIT, "SAMPLE_ZERO");
    add(VK_RESOLVE_MODE_AVERAGE_BIT, "AVERAGE");
    add(VK_RESOLVE_MODE_MIN_BIT, "MIN");
    add(VK_RESOLVE_MODE_MAX_BIT, "MAX");
    return out.empty() ? "none" : out;
}

namespace {

// Fills the queue facts; returns the first family with GRAPHICS and COMPUTE.
void probe_queues(VkPhysicalDevice device, DeviceReport& r) {
    uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    const VkQueueFlags want = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    for (uint32_t i = 0; i < count; ++i) {
        if ((families[i].queueFlags & want) != want) continue;
        r.queue_family = i;
        r.timestamp_valid_bits = families[i].timestampValidBits;
        r.candidate.graphics_compute_queue = true;
        return;
    }
}

void probe_features(VkPhysicalDevice device, DeviceReport& r) {
    // Feature structs of 1.2 and later are only valid on devices of that version.
    if (r.candidate.api_version < VK_API_VERSION_1_2) {
        VkPhysicalDeviceFeatures f{};
        vkGetPhysicalDeviceFeatures(device, &f);
        r.pipeline_statistics = f.pipelineStatisticsQuery;
        r.occlusion_query_precise = f.occlusionQueryPrecise;
        r.fragment_stores_and_atomics = f.fragmentStoresAndAtomics;
        r.sample_rate_shading = f.sampleRateShading;
        r.geometry_shader = f.geometryShader;
        return;
    }
    r.candidate.via_extensions =
        r.candidate.api_version < VK_API_VERSION_1_3 && has_promoted_extensions(device);
    if (r.candidate.api_version < VK_API_VERSION_1_3 && !r.candidate.via_extensions) {
        // Without the extensions their feature structs must not be chained.
        FeatureChain chain;
        chain.v12.pNext = nullptr;
        vkGetPhysicalDeviceFeatures2(device, &chain.base);
        r.pipeline_statistics = chain.base.features.pipelineStatisticsQuery;
        r.occlusion_query_precise = chain.base.features.occlusionQueryPrecise;
        r.fragment_stores_and_atomics = chain.base.features.fragmentStoresAndAtomics;
        r.sample_rate_shading = chain.base.features.sampleRateShading;
        r.geometry_shader = chain.base.features.geometryShader;
        r.descriptor_indexing = chain.v12.runtimeDescriptorArray;
        return;
    }
    FeatureChain chain;
    vkGetPhysicalDeviceFeatures2(device, &chain.base);
    r.candidate.dynamic_rendering = chain.dynamic_rendering.dynamicRendering;
    r.candidate.synchronization2 = chain.synchronization2.synchronization2;
    r.candidate.extended_dynamic_state = chain.extended_dynamic_state.extendedDynamicState;
    r.pipeline_statistics = chain.base.features.pipelineStatisticsQuery;
    r.occlusion_query_precise = chain.base.features.occlusionQueryPrecise;
    r.fragment_stores_and_atomics = chain.base.features.fragmentStoresAndAtomics;
    r.sample_rate_shading = chain.base.features.sampleRateShading;
    r.geometry_shader = chain.base.features.geometryShader;
    r.descriptor_indexing = chain.v12.runtimeDescriptorArray;
}

void probe_properties(VkPhysicalDevice device, DeviceReport& r) {
    VkPhysicalDeviceProperties base{};
    vkGetPhysicalDeviceProperties(device, &base);
    r.candidate.name = base.deviceName;
    r.candidate.type = device_type_name(base.deviceType);
    r.candidate.api_version = base.apiVersion;
    r.vendor_id = base.vendorID;
    r.device_id = base.deviceID;
    r.color_sample_counts = base.limits.framebufferColorSampleCounts;
    r.depth_sample_counts = base.limits.framebufferDepthSampleCounts;
    r.standard_sample_locations = base.limits.standardSampleLocations;
    r.timestamps = base.limits.timestampComputeAndGraphics;
    r.timestamp_period_ns = base.limits.timestampPeriod;
    if (base.apiVersion < VK_API_VERSION_1_2) return;
    auto v11 = make<VkPhysicalDeviceVulkan11Properties>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_PROPERTIES);
    auto resolve = make<VkPhysicalDeviceDepthStencilResolveProperties>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DEPTH_STENCIL_RESOLVE_PROPERTIES, &v11);
    auto driver = make<VkPhysicalDeviceDriverProperties>(
        VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES, &resolve);
    auto p2 =
        make<VkPhysicalDeviceProperties2>(VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &driver);
    vkGetPhysicalDeviceProperties2(device, &p2);
    r.driver_name = driver.driverName;
    r.driver_info = driver.driverInfo;
    r.driver_id = driver.driverID;
    r.depth_resolve_modes = resolve.supportedDepthResolveModes;
    r.stencil_resolve_modes = resolve.supportedStencilResolveModes;
    r.fragment_quad_operations = (v11.subgroupSupportedStages & VK_SHADER_STAGE_FRAGMENT_BIT) &&
                                 (v11.subgroupSupportedOperations & VK_SUBGROUP_FEATURE_QUAD_BIT);
}

// DEPTHSCOPE_HIDE_DEPTH_FORMATS="D24_UNORM_S8_UINT X8_D24_UNORM_PACK32" (names as `info`
// prints them, separated by spaces or commas): depth formats probed as unsupported, to see
// what a device without them does (lavapipe has every one).
bool hidden_depth_format(VkFormat format) {
    const char* env = std::getenv("DEPTHSCOPE_HIDE_DEPTH_FORMATS");
    if (!env) return false;
    const std::string name = format::name(format);
    std::string_view list = env;
    while (!list.empty()) {
        const size_t end = std::min(list.find_first_of(" ,"), list.size());
        if (list.substr(0, end) == name) return true;
        list.remove_prefix(std::min(end + 1, list.size()));
    }
    return false;
}

}  // namespace

DeviceReport probe_device(VkPhysicalDevice device, uint32_t index) {
    DeviceReport r;
    r.candidate.index = index;
    probe_properties(device, r);
    probe_features(device, r);
    probe_queues(device, r);
    r.unmet = unmet_requirements(r.candidate);

    auto query = [device](VkFormat format) {
        VkFormatProperties props{};
        if (!hidden_depth_format(format))
            vkGetPhysicalDeviceFormatProperties(device, format, &props);
        return props;
    };
    r.depth_formats = supported_formats(kDepthFormatCandidates, kDepthFormatFeatures, query);
    if (!r.depth_formats.empty())
        r.depth_format = r.depth_formats.front();
    else
        r.unmet.push_back("no usable depth format");

    VkPhysicalDeviceMemoryProperties mem{};
    vkGetPhysicalDeviceMemoryProperties(device, &mem);
    for (uint32_t i = 0; i < mem.memoryHeapCount; ++i)
        if (mem.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
            r.device_local_bytes += mem.memoryHeaps[i].size;
    r.limits = probe_limits(device, r.candidate.api_version);
    return r;
}

std::vector<DeviceReport> probe_all_devices() {
    auto app = make<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
    app.pApplicationName = "depthscope info";
    app.apiVersion = VK_API_VERSION_1_3;
    auto info = make<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
    info.pApplicationInfo = &app;
    VkInstance instance = VK_NULL_HANDLE;
    check(vkCreateInstance(&info, nullptr, &instance), "vkCreateInstance");

    std::vector<DeviceReport> reports;
    try {
        uint32_t count = 0;
        check(vkEnumeratePhysicalDevices(instance, &count, nullptr), "vkEnumeratePhysicalDevices");
        std::vector<VkPhysicalDevice> devices(count);
        check(vkEnumeratePhysicalDevices(instance, &count, devices.data()),
              "vkEnumeratePhysicalDevices");
        for (uint32_t i = 0; i < count; ++i) reports.push_back(probe_device(devices[i], i));
    } catch (...) {
        vkDestroyInstance(instance, nullptr);
        throw;
    }
    vkDestroyInstance(instance, nullptr);
    return reports;
}

std::string format_report(const DeviceReport& r) {
    std::ostringstream out;
    auto yes = [](bool b) { return b ? "yes" : "no"; };
    out << "device " << r.candidate.index << ": " << r.candidate.name << "\n";
    out << "  type:                 " << r.candidate.type << "\n";
    out << "  api version:          " << version_string(r.candidate.api_version)
        << (r.candidate.via_extensions ? " (1.3 features through KHR/EXT extensions)" : "") << "\n";
    out << "  driver:               " << r.driver_name << " (" << r.driver_info << ")\n";
    std::string unmet;
    for (const std::string& u : r.unmet) unmet += (unmet.empty() ? "" : ", ") + u;
    out << "  suitable:             " << (unmet.empty() ? "yes" : "no (" + unmet + ")") << "\n";
    out << "  depth formats:        ";
    for (VkFormat f : r.depth_formats) out << format::name(f) << " ";
    out << "(using " << format::name(r.depth_format) << ")\n";
    out << "  colour sample counts: " << sample_counts_text(r.color_sample_counts) << "\n";
    out << "  standard sample locations: " << (r.standard_sample_locations ? "yes" : "no") << "\n";
    out << "  depth sample counts:  " << sample_counts_text(r.depth_sample_counts) << "\n";
    out << "  depth resolve modes:  " << resolve_modes_text(r.depth_resolve_modes)
        << ((r.depth_resolve_modes & VK_RESOLVE_MODE_MAX_BIT) ? "" : " (MAX: shader fallback)")
        << "\n";
    out << "  timestamps:           " << yes(r.timestamps) << " (period " << r.timestamp_period_ns
        << " ns, " << r.timestamp_valid_bits << " valid bits)\n";
    out << "  pipeline statistics:  " << yes(r.pipeline_statistics) << "\n";
    out << "  precise occlusion:    " << yes(r.occlusion_query_precise) << "\n";
    out << "  descriptor indexing:  " << yes(r.descriptor_indexing) << "\n";
    out << "  fragment quad ops:    " << yes(r.fragment_quad_operations) << "\n";
    out << "  device-local memory:  " << (r.device_local_bytes >> 20) << " MiB\n";
    const DeviceLimits& l = r.limits;
    out << "  image size limit:     " << l.max_image_dimension_2d << " (framebuffer "
        << l.max_framebuffer_width << "x" << l.max_framebuffer_height << ")\n";
    out << "  largest allocation:   "
        << (l.max_memory_allocation_size ? bytes_text(l.max_memory_allocation_size) : "?") << "\n";
    out << "  frame memory limit:   " << bytes_text(l.heap_bytes) << " (heap " << l.heap_index
        << (l.memory_budget ? ", or VK_EXT_memory_budget's budget when lower" : "") << ")"
        << (l.lowered ? " (lowered by DEPTHSCOPE_DEVICE_LIMITS)" : "") << "\n";
    return out.str();
}

}  // namespace ds::vk
