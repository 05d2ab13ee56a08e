#pragma once
// Runs an application with depthscope's Vulkan layer enabled for that process only: the layer's
// manifest folder is added to the loader's search (VK_ADD_LAYER_PATH, or VK_LAYER_PATH where
// that is set), the layer is enabled
// first, nearest the application (VK_INSTANCE_LAYERS, before any the environment names), and
// the layer's own settings travel as DEPTHSCOPE_LAYER_* variables (layer/config.h).
#include <map>
#include <string>
#include <vector>

namespace ds::app {

// The folder holding VkLayer_depthscope.json: $DEPTHSCOPE_LAYER_PATH, else the build tree's.
// Throws ds::Error when there is no manifest there.
std::string layer_manifest_dir();

// Starts `argv` with `env` added to this process's environment and waits for it. Returns its
// exit code (128 + the signal that ended it). Throws ds::Error when it cannot be started
// ("APP: not found").
int run_with_layer(const std::vector<std::string>& argv,
                   const std::map<std::string, std::string>& env);

}  // namespace ds::app
