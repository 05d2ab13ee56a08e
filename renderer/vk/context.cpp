#include "renderer/vk/context.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "renderer/common/error.h"
#include "renderer/vk/check.h"
#include "renderer/vk/features.h"
#include "renderer/vk/functions.h"

namespace ds::vk {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

VKAPI_ATTR VkBool32 VKAPI_CALL on_debug_message(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                                VkDebugUtilsMessageTypeFlagsEXT type,
                                                const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                void* user) {
    // One line per message so logs and tests can grep them.
    std::string text = data && data->pMessage ? data->pMessage : "(no message)";
    std::replace(text.begin(), text.end(), '\n', ' ');
    // GENERAL messages come from the loader and the driver (Mesa reports SPIR-V it frowns on,
    // e.g. the Invariant member decoration glslang emits for `invariant gl_Position` on every
    // run): shown only with DEPTHSCOPE_VK_LOG=1; only the validation layer's findings count.
    if (!(type & (VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                  VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT))) {
        static const bool show_general = [] {
            const char* env = std::getenv("DEPTHSCOPE_VK_LOG");
            return env && std::strcmp(env, "1") == 0;
        }();
        if (show_general) std::fprintf(stderr, "vulkan: %s\n", text.c_str());
        return VK_FALSE;
    }
    std::fprintf(stderr, "validation: %s\n", text.c_str());
    static_cast<std::atomic<uint64_t>*>(user)->fetch_add(1);
    return VK_FALSE;  // never abort the call: the count fails the run instead
}

bool has_layer(const char* name) {
    uint32_t count = 0;
    check(vkEnumerateInstanceLayerProperties(&count, nullptr),
          "vkEnumerateInstanceLayerProperties");
    std::vector<VkLayerProperties> layers(count);
    check(vkEnumerateInstanceLayerProperties(&count, layers.data()),
          "vkEnumerateInstanceLayerProperties");
    return std::any_of(layers.begin(), layers.end(), [&](const VkLayerProperties& l) {
        return std::strcmp(l.layerName, name) == 0;
    });
}

// Extensions of the implementation (layer == nullptr) or of one layer.
bool has_instance_extension(const char* layer, const char* name) {
    uint32_t count = 0;
    check(vkEnumerateInstanceExtensionProperties(layer, &count, nullptr),
          "vkEnumerateInstanceExtensionProperties");
    std::vector<VkExtensionProperties> exts(count);
    check(vkEnumerateInstanceExtensionProperties(layer, &count, exts.data()),
          "vkEnumerateInstanceExtensionProperties");
    return std::any_of(exts.begin(), exts.end(), [&](const VkExtensionProperties& e) {
        return std::strcmp(e.extensionName, name) == 0;
    });
}

VkDebugUtilsMessengerCreateInfoEXT messenger_info(std::atomic<uint64_t>* counter) {
    auto info = make<VkDebugUtilsMessengerCreateInfoEXT>(
        VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT);
    info.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                           VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = on_debug_message;
    info.pUserData = counter;
    return info;
}

}  // namespace

Context::Context(const ContextOptions& options) : swapchain_(options.swapchain) {
    try {
        create_instance(options);
        pick_physical_device(options.device);
        create_device();
    } catch (...) {
        destroy();  // the destructor does not run for a half-built object
        throw;
    }
}

Context::~Context() {
    destroy();
}

// The messenger outlives the device: the validation layer reports objects still alive at
// vkDestroyDevice, and those messages count like any other.
void Context::destroy() {
    if (device_) vkDeviceWaitIdle(device_);  // teardown: an error here has nowhere to go
    allocator_.reset();
    if (once_fence_) vkDestroyFence(device_, once_fence_, nullptr);
    if (once_pool_) vkDestroyCommandPool(device_, once_pool_, nullptr);  // frees once_cmd_
    if (device_) vkDestroyDevice(device_, nullptr);
    if (messenger_) {
        auto destroy_messenger = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy_messenger) destroy_messenger(instance_, messenger_, nullptr);
    }
    if (instance_) vkDestroyInstance(instance_, nullptr);
    once_pool_ = VK_NULL_HANDLE;
    device_ = VK_NULL_HANDLE;
    messenger_ = VK_NULL_HANDLE;
    instance_ = VK_NULL_HANDLE;
}

void Context::create_instance(const ContextOptions& options) {
    std::vector<const char*> layers;
    std::vector<const char*> extensions;
    const bool validate = options.validate;
    if (validate && !has_layer(kValidationLayer))
        throw Error(std::string("validation requested but ") + kValidationLayer +
                    " is not installed (Debian: vulkan-validationlayers)");
    if (validate) layers.push_back(kValidationLayer);

    const char* layer = validate ? kValidationLayer : nullptr;
    const bool debug_utils =
        has_instance_extension(nullptr, VK_EXT_DEBUG_UTILS_EXTENSION_NAME) ||
        (layer && has_instance_extension(layer, VK_EXT_DEBUG_UTILS_EXTENSION_NAME));
    if (debug_utils) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    if (validate && !debug_utils)
        throw Error("validation requested but VK_EXT_debug_utils is not available");
    const bool sync = validate && options.sync_validation &&
                      has_instance_extension(layer, VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    if (sync) extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
    for (const std::string& name : options.instance_extensions) {
        if (!has_instance_extension(nullptr, name.c_str()))
            throw Error("the Vulkan loader has no " + name + " (needed for a window)");
        extensions.push_back(name.c_str());
    }

    auto app = make<VkApplicationInfo>(VK_STRUCTURE_TYPE_APPLICATION_INFO);
    app.pApplicationName = "depthscope";
    app.pEngineName = "depthscope";
    app.apiVersion = VK_API_VERSION_1_3;

    // The messenger in pNext also reports problems inside vkCreateInstance/vkDestroyInstance.
    VkDebugUtilsMessengerCreateInfoEXT messenger = messenger_info(validation_messages_.get());
    const VkValidationFeatureEnableEXT enables[] = {
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT};
    auto features =
        make<VkValidationFeaturesEXT>(VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT, &messenger);
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = enables;

    auto info = make<VkInstanceCreateInfo>(VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO);
    info.pNext = validate ? (sync ? static_cast<const void*>(&features) : &messenger) : nullptr;
    info.pApplicationInfo = &app;
    info.enabledLayerCount = uint32_t(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    check(vkCreateInstance(&info, nullptr, &instance_), "vkCreateInstance");

    if (debug_utils) debug_.load(instance_);
    if (validate) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
        if (!create) throw Error("vkCreateDebugUtilsMessengerEXT is missing");
        check(create(instance_, &messenger, nullptr, &messenger_),
              "vkCreateDebugUtilsMessengerEXT");
    }
}

void Context::pick_physical_device(const std::string& request) {
    uint32_t count = 0;
    check(vkEnumeratePhysicalDevices(instance_, &count, nullptr), "vkEnumeratePhysicalDevices");
    std::vector<VkPhysicalDevice> devices(count);
    check(vkEnumeratePhysicalDevices(instance_, &count, devices.data()),
          "vkEnumeratePhysicalDevices");

    std::vector<DeviceReport> reports;
    std::vector<DeviceCandidate> candidates;
    for (uint32_t i = 0; i < count; ++i) {
        reports.push_back(probe_device(devices[i], i));
        candidates.push_back(reports.back().candidate);
    }
    const uint32_t chosen = select_device(candidates, request);
    // Selection covers the API; the depth format is the one remaining hard requirement.
    if (reports[chosen].depth_format == VK_FORMAT_UNDEFINED)
        throw Error("device " + std::to_string(chosen) + " (" + reports[chosen].candidate.name +
                    ") has no usable depth format");
    physical_device_ = devices[chosen];
    report_ = reports[chosen];
    VkPhysicalDeviceProperties props{};
    vkGetPhysicalDeviceProperties(physical_device_, &props);
    limits_ = props.limits;
    // As probed, with DEPTHSCOPE_DEVICE_LIMITS applied: every check sees the same numbers.
    limits_.maxImageDimension2D = report_.limits.max_image_dimension_2d;
    limits_.maxFramebufferWidth = report_.limits.max_framebuffer_width;
    limits_.maxFramebufferHeight = report_.limits.max_framebuffer_height;
}

// A window needs VK_KHR_swapchain on the chosen device.
void Context::require_swapchain() const {
    uint32_t count = 0;
    check(vkEnumerateDeviceExtensionProperties(physical_device_, nullptr, &count, nullptr),
          "vkEnumerateDeviceExtensionProperties");
    std::vector<VkExtensionProperties> exts(count);
    check(vkEnumerateDeviceExtensionProperties(physical_device_, nullptr, &count, exts.data()),
          "vkEnumerateDeviceExtensionProperties");
    if (std::none_of(exts.begin(), exts.end(), [](const VkExtensionProperties& e) {
            return std::strcmp(e.extensionName, VK_KHR_SWAPCHAIN_EXTENSION_NAME) == 0;
        }))
        throw Error(report_.candidate.name + " has no " VK_KHR_SWAPCHAIN_EXTENSION_NAME
                                             " (needed for a window)");
}

void Context::create_device() {
    if (swapchain_) require_swapchain();
    const float priority = 1.0f;
    auto queue = make<VkDeviceQueueCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO);
    queue.queueFamilyIndex = report_.queue_family;
    queue.queueCount = 1;
    queue.pQueuePriorities = &priority;

    FeatureChain features;
    features.dynamic_rendering.dynamicRendering = VK_TRUE;
    features.synchronization2.synchronization2 = VK_TRUE;
    features.extended_dynamic_state.extendedDynamicState = VK_TRUE;
    // Optional features: on when present, so the graph can measure with them later.
    features.base.features.pipelineStatisticsQuery = report_.pipeline_statistics;
    features.base.features.occlusionQueryPrecise = report_.occlusion_query_precise;
    // Storage images of R8 / R16F / RG16F (the screen-space compute passes write AO and contact
    // shadows as such): optional in Vulkan, present on lavapipe and every desktop driver.
    VkPhysicalDeviceFeatures supported{};
    vkGetPhysicalDeviceFeatures(physical_device_, &supported);
    features.base.features.shaderStorageImageExtendedFormats =
        supported.shaderStorageImageExtendedFormats;
    features.base.features.fragmentStoresAndAtomics = report_.fragment_stores_and_atomics;
    features.base.features.sampleRateShading = report_.sample_rate_shading;
    features.base.features.geometryShader = report_.geometry_shader;

    auto info = make<VkDeviceCreateInfo>(VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &features.base);
    info.queueCreateInfoCount = 1;
    info.pQueueCreateInfos = &queue;
    std::vector<const char*> extensions;
    if (report_.candidate.via_extensions)
        extensions.assign(kPromotedExtensions.begin(), kPromotedExtensions.end());
    if (swapchain_) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    info.enabledExtensionCount = uint32_t(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    check(vkCreateDevice(physical_device_, &info, nullptr, &device_), "vkCreateDevice");
    load_device_functions(device_, report_.candidate.via_extensions);
    vkGetDeviceQueue(device_, report_.queue_family, 0, &queue_);
    create_once_objects();
}

// submit_once()'s command buffer and fence, and the memory allocator.
void Context::create_once_objects() {
    auto pool = make<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
    pool.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pool.queueFamilyIndex = report_.queue_family;
    check(vkCreateCommandPool(device_, &pool, nullptr, &once_pool_), "vkCreateCommandPool");
    auto alloc = make<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    alloc.commandPool = once_pool_;
    alloc.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    alloc.commandBufferCount = 1;
    check(vkAllocateCommandBuffers(device_, &alloc, &once_cmd_), "vkAllocateCommandBuffers");
    auto fence_info = make<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
    check(vkCreateFence(device_, &fence_info, nullptr, &once_fence_), "vkCreateFence");
    allocator_ =
        std::make_unique<Allocator>(physical_device_, device_, Allocator::kDefaultBlockSize,
                                    report_.limits.max_memory_allocation_size);
}

VkFormatProperties Context::format_properties(VkFormat format) const {
    VkFormatProperties props{};
    vkGetPhysicalDeviceFormatProperties(physical_device_, format, &props);
    return props;
}

void Context::submit_once(const std::function<void(VkCommandBuffer)>& record) {
    std::lock_guard lock(once_mutex_);
    struct Reset {  // a throw from `record` leaves the buffer recording: reset it for the next
        Context& c;
        bool recorded = false;
        ~Reset() {
            if (!recorded) vkResetCommandBuffer(c.once_cmd_, 0);
        }
    } reset{*this};
    auto begin = make<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(once_cmd_, &begin), "vkBeginCommandBuffer");  // resets it
    record(once_cmd_);
    check(vkEndCommandBuffer(once_cmd_), "vkEndCommandBuffer");
    reset.recorded = true;

    check(vkResetFences(device_, 1, &once_fence_), "vkResetFences");
    auto cmd_info = make<VkCommandBufferSubmitInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO);
    cmd_info.commandBuffer = once_cmd_;
    auto submit = make<VkSubmitInfo2>(VK_STRUCTURE_TYPE_SUBMIT_INFO_2);
    submit.commandBufferInfoCount = 1;
    submit.pCommandBufferInfos = &cmd_info;
    this->submit(submit, once_fence_);
    check(vkWaitForFences(device_, 1, &once_fence_, VK_TRUE, UINT64_MAX), "vkWaitForFences");
}

void Context::submit(const VkSubmitInfo2& submit, VkFence fence) const {
    std::lock_guard lock(queue_mutex_);
    check(fn().queue_submit2(queue_, 1, &submit, fence), "vkQueueSubmit2");
}

VkResult Context::present(const VkPresentInfoKHR& info) const {
    std::lock_guard lock(queue_mutex_);
    return vkQueuePresentKHR(queue_, &info);
}

void Context::wait_idle() const {
    std::lock_guard lock(queue_mutex_);
    check(vkDeviceWaitIdle(device_), "vkDeviceWaitIdle");
}

void Context::drain() const noexcept {
    std::lock_guard lock(queue_mutex_);
    vkDeviceWaitIdle(device_);
}

}  // namespace ds::vk
