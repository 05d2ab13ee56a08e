#pragma once
// The validation exit code (3, main.cpp's list), decided here for every command that renders.
#include "renderer/renderer.h"

namespace ds::app {

// 3 when the renderer saw validation messages, else 0. The messages were printed as they came;
// `print_count` adds "depthscope: N validation message(s)" on stderr after them.
int validation_exit_code(const Renderer& renderer, bool print_count = true);

}  // namespace ds::app
