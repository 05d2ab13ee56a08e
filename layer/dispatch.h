#pragma once
// The next layer's entry points, per instance and per device, loaded once at creation. The
// X-lists name every function the layer calls or intercepts (core Vulkan 1.3 and the
// extensions it records); a function the driver lacks stays null.
#include <vulkan/vulkan.h>

#define DS_LAYER_INSTANCE_FUNCTIONS(X)                                                        \
    X(DestroyInstance)                                                                        \
    X(GetInstanceProcAddr)                                                                    \
    X(EnumerateDeviceExtensionProperties)                                                     \
    X(GetPhysicalDeviceProperties)                                                            \
    X(GetPhysicalDeviceProperties2)                                                           \
    X(GetPhysicalDeviceProperties2KHR)                                                        \
    X(GetPhysicalDeviceFeatures)                                                              \
    X(GetPhysicalDeviceFeatures2)                                                             \
    X(GetPhysicalDeviceMemoryProperties)                                                      \
    X(GetPhysicalDeviceQueueFamilyProperties)

// Commands the layer records (a copy of each, to replay the captured frame) and forwards.
#define DS_LAYER_RECORDED_COMMANDS(X)                                                         \
    X(CmdBindPipeline)                                                                        \
    X(CmdSetViewport)                                                                         \
    X(CmdSetScissor)                                                                          \
    X(CmdSetLineWidth)                                                                        \
    X(CmdSetDepthBias)                                                                        \
    X(CmdSetBlendConstants)                                                                   \
    X(CmdSetDepthBounds)                                                                      \
    X(CmdSetStencilCompareMask)                                                               \
    X(CmdSetStencilWriteMask)                                                                 \
    X(CmdSetStencilReference)                                                                 \
    X(CmdBindDescriptorSets)                                                                  \
    X(CmdBindIndexBuffer)                                                                     \
    X(CmdBindVertexBuffers)                                                                   \
    X(CmdDraw)                                                                                \
    X(CmdDrawIndexed)                                                                         \
    X(CmdDrawIndirect)                                                                        \
    X(CmdDrawIndexedIndirect)                                                                 \
    X(CmdDispatch)                                                                            \
    X(CmdDispatchIndirect)                                                                    \
    X(CmdCopyBuffer)                                                                          \
    X(CmdCopyImage)                                                                           \
    X(CmdBlitImage)                                                                           \
    X(CmdCopyBufferToImage)                                                                   \
    X(CmdCopyImageToBuffer)                                                                   \
    X(CmdUpdateBuffer)                                                                        \
    X(CmdFillBuffer)                                                                          \
    X(CmdClearColorImage)                                                                     \
    X(CmdClearDepthStencilImage)                                                              \
    X(CmdClearAttachments)                                                                    \
    X(CmdResolveImage)                                                                        \
    X(CmdSetEvent)                                                                            \
    X(CmdResetEvent)                                                                          \
    X(CmdWaitEvents)                                                                          \
    X(CmdPipelineBarrier)                                                                     \
    X(CmdBeginQuery)                                                                          \
    X(CmdEndQuery)                                                                            \
    X(CmdResetQueryPool)                                                                      \
    X(CmdWriteTimestamp)                                                                      \
    X(CmdCopyQueryPoolResults)                                                                \
    X(CmdPushConstants)                                                                       \
    X(CmdBeginRenderPass)                                                                     \
    X(CmdNextSubpass)                                                                         \
    X(CmdEndRenderPass)                                                                       \
    X(CmdExecuteCommands)                                                                     \
    X(CmdSetDeviceMask)                                                                       \
    X(CmdDispatchBase)                                                                        \
    X(CmdDrawIndirectCount)                                                                   \
    X(CmdDrawIndexedIndirectCount)                                                            \
    X(CmdBeginRenderPass2)                                                                    \
    X(CmdNextSubpass2)                                                                        \
    X(CmdEndRenderPass2)                                                                      \
    X(CmdSetEvent2)                                                                           \
    X(CmdResetEvent2)                                                                         \
    X(CmdWaitEvents2)                                                                         \
    X(CmdPipelineBarrier2)                                                                    \
    X(CmdWriteTimestamp2)                                                                     \
    X(CmdCopyBuffer2)                                                                         \
    X(CmdCopyImage2)                                                                          \
    X(CmdCopyBufferToImage2)                                                                  \
    X(CmdCopyImageToBuffer2)                                                                  \
    X(CmdBlitImage2)                                                                          \
    X(CmdResolveImage2)                                                                       \
    X(CmdBeginRendering)                                                                      \
    X(CmdEndRendering)                                                                        \
    X(CmdSetCullMode)                                                                         \
    X(CmdSetFrontFace)                                                                        \
    X(CmdSetPrimitiveTopology)                                                                \
    X(CmdSetViewportWithCount)                                                                \
    X(CmdSetScissorWithCount)                                                                 \
    X(CmdBindVertexBuffers2)                                                                  \
    X(CmdSetDepthTestEnable)                                                                  \
    X(CmdSetDepthWriteEnable)                                                                 \
    X(CmdSetDepthCompareOp)                                                                   \
    X(CmdSetDepthBoundsTestEnable)                                                            \
    X(CmdSetStencilTestEnable)                                                                \
    X(CmdSetStencilOp)                                                                        \
    X(CmdSetRasterizerDiscardEnable)                                                          \
    X(CmdSetDepthBiasEnable)                                                                  \
    X(CmdSetPrimitiveRestartEnable)                                                           \
    X(CmdBeginDebugUtilsLabelEXT)                                                             \
    X(CmdEndDebugUtilsLabelEXT)                                                               \
    X(CmdInsertDebugUtilsLabelEXT)

// Extension names of core commands: the same function, recorded the same way.
#define DS_LAYER_COMMAND_ALIASES(X)                                                           \
    X(CmdBeginRenderingKHR, CmdBeginRendering)                                                \
    X(CmdEndRenderingKHR, CmdEndRendering)                                                    \
    X(CmdBeginRenderPass2KHR, CmdBeginRenderPass2)                                            \
    X(CmdNextSubpass2KHR, CmdNextSubpass2)                                                    \
    X(CmdEndRenderPass2KHR, CmdEndRenderPass2)                                                \
    X(CmdDrawIndirectCountKHR, CmdDrawIndirectCount)                                          \
    X(CmdDrawIndexedIndirectCountKHR, CmdDrawIndexedIndirectCount)                            \
    X(CmdSetEvent2KHR, CmdSetEvent2)                                                          \
    X(CmdResetEvent2KHR, CmdResetEvent2)                                                      \
    X(CmdWaitEvents2KHR, CmdWaitEvents2)                                                      \
    X(CmdPipelineBarrier2KHR, CmdPipelineBarrier2)                                            \
    X(CmdWriteTimestamp2KHR, CmdWriteTimestamp2)                                              \
    X(CmdCopyBuffer2KHR, CmdCopyBuffer2)                                                      \
    X(CmdCopyImage2KHR, CmdCopyImage2)                                                        \
    X(CmdCopyBufferToImage2KHR, CmdCopyBufferToImage2)                                        \
    X(CmdCopyImageToBuffer2KHR, CmdCopyImageToBuffer2)                                        \
    X(CmdBlitImage2KHR, CmdBlitImage2)                                                        \
    X(CmdResolveImage2KHR, CmdResolveImage2)                                                  \
    X(CmdSetDeviceMaskKHR, CmdSetDeviceMask)                                                  \
    X(CmdDispatchBaseKHR, CmdDispatchBase)                                                    \
    X(CmdSetCullModeEXT, CmdSetCullMode)                                                      \
    X(CmdSetFrontFaceEXT, CmdSetFrontFace)                                                    \
    X(CmdSetPrimitiveTopologyEXT, CmdSetPrimitiveTopology)                                    \
    X(CmdSetViewportWithCountEXT, CmdSetViewportWithCount)                                    \
    X(CmdSetScissorWithCountEXT, CmdSetScissorWithCount)                                      \
    X(CmdBindVertexBuffers2EXT, CmdBindVertexBuffers2)                                        \
    X(CmdSetDepthTestEnableEXT, CmdSetDepthTestEnable)                                        \
    X(CmdSetDepthWriteEnableEXT, CmdSetDepthWriteEnable)                                      \
    X(CmdSetDepthCompareOpEXT, CmdSetDepthCompareOp)                                          \
    X(CmdSetDepthBoundsTestEnableEXT, CmdSetDepthBoundsTestEnable)                            \
    X(CmdSetStencilTestEnableEXT, CmdSetStencilTestEnable)                                    \
    X(CmdSetStencilOpEXT, CmdSetStencilOp)                                                    \
    X(CmdSetRasterizerDiscardEnableEXT, CmdSetRasterizerDiscardEnable)                        \
    X(CmdSetDepthBiasEnableEXT, CmdSetDepthBiasEnable)                                        \
    X(CmdSetPrimitiveRestartEnableEXT, CmdSetPrimitiveRestartEnable)

// Other device functions the layer intercepts or calls.
#define DS_LAYER_DEVICE_FUNCTIONS(X)                                                          \
    X(GetDeviceProcAddr)                                                                      \
    X(DestroyDevice)                                                                          \
    X(GetDeviceQueue)                                                                         \
    X(GetDeviceQueue2)                                                                        \
    X(QueueSubmit)                                                                            \
    X(QueueSubmit2)                                                                           \
    X(QueueSubmit2KHR)                                                                        \
    X(QueueWaitIdle)                                                                          \
    X(QueuePresentKHR)                                                                        \
    X(DeviceWaitIdle)                                                                         \
    X(CreateSwapchainKHR)                                                                     \
    X(AllocateCommandBuffers)                                                                 \
    X(FreeCommandBuffers)                                                                     \
    X(BeginCommandBuffer)                                                                     \
    X(EndCommandBuffer)                                                                       \
    X(ResetCommandBuffer)                                                                     \
    X(CreateCommandPool)                                                                      \
    X(DestroyCommandPool)                                                                     \
    X(ResetCommandPool)                                                                       \
    X(CreateRenderPass)                                                                       \
    X(CreateRenderPass2)                                                                      \
    X(CreateRenderPass2KHR)                                                                   \
    X(DestroyRenderPass)                                                                      \
    X(CreateFramebuffer)                                                                      \
    X(DestroyFramebuffer)                                                                     \
    X(CreateImageView)                                                                        \
    X(DestroyImageView)                                                                       \
    X(CreateShaderModule)                                                                     \
    X(DestroyShaderModule)                                                                    \
    X(CreatePipelineLayout)                                                                   \
    X(DestroyPipelineLayout)                                                                  \
    X(CreateDescriptorSetLayout)                                                              \
    X(DestroyDescriptorSetLayout)                                                             \
    X(CreateGraphicsPipelines)                                                                \
    X(DestroyPipeline)                                                                        \
    X(SetDebugUtilsObjectNameEXT)                                                             \
    X(CreateBuffer)                                                                           \
    X(DestroyBuffer)                                                                          \
    X(GetBufferMemoryRequirements)                                                            \
    X(AllocateMemory)                                                                         \
    X(FreeMemory)                                                                             \
    X(BindBufferMemory)                                                                       \
    X(MapMemory)                                                                              \
    X(UnmapMemory)                                                                            \
    X(CreateQueryPool)                                                                        \
    X(DestroyQueryPool)                                                                       \
    X(GetQueryPoolResults)                                                                    \
    X(CreateDescriptorPool)                                                                   \
    X(DestroyDescriptorPool)                                                                  \
    X(AllocateDescriptorSets)                                                                 \
    X(UpdateDescriptorSets)                                                                   \
    X(CreateFence)                                                                            \
    X(DestroyFence)                                                                           \
    X(WaitForFences)

namespace ds::layer {

struct InstanceTable {
#define DS_X(name) PFN_vk##name name = nullptr;
    DS_LAYER_INSTANCE_FUNCTIONS(DS_X)
#undef DS_X
    PFN_vkCreateDevice CreateDevice = nullptr;  // from the next layer's GetInstanceProcAddr
    void load(VkInstance instance, PFN_vkGetInstanceProcAddr next);
};

struct DeviceTable {
#define DS_X(name) PFN_vk##name name = nullptr;
    DS_LAYER_RECORDED_COMMANDS(DS_X)
    DS_LAYER_DEVICE_FUNCTIONS(DS_X)
#undef DS_X
    void load(VkDevice device, PFN_vkGetDeviceProcAddr next);
};

}  // namespace ds::layer
