#pragma once
// The validation exit code (3, main.cpp's list), decided here for every command that renders.
#include <cstdint>

#include "renderer/renderer.h"

namespace ds::app {

// Shuts the renderer down first (Renderer::shutdown(): the layer's leak report at
// vkDestroyDevice counts too), so nothing may use it afterwards; then 3 when it saw validation
// messages, else 0. The messages were printed as they came; `print_count` adds
// "depthscope: N validation message(s)" on stderr after them. `other_messages`: those of
// another device the command used (the inspector's UI device), counted alike.
int validation_exit_code(Renderer& renderer, bool print_count = true, uint64_t other_messages = 0);

}  // namespace ds::app
