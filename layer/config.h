#pragma once
// The layer's settings, from the environment `depthscope layer` gives the application:
//   DEPTHSCOPE_LAYER_OUT       the folder it writes (none: the layer only passes calls on)
//   DEPTHSCOPE_LAYER_MODE      list | capture
//   DEPTHSCOPE_LAYER_FRAME     the frame to capture (from 1)
//   DEPTHSCOPE_LAYER_SETTINGS  k=v pairs separated by ';' (renderer/common/layer_settings.h)
//   DEPTHSCOPE_LAYER_LOG       1: a line on stderr per device and submission (debugging)
#include <cstdint>
#include <map>
#include <string>

#include <cstdio>

#include "renderer/common/layer_settings.h"

namespace ds::layer {

struct Config {
    enum class Mode { Passive, List, Capture };
    Mode mode = Mode::Passive;
    std::string out;
    uint64_t frame = 0;
    LayerSettings settings;
    std::string error;  // what was wrong with the environment (the layer then stays passive)
    bool log = false;

    static Config from_environment();
};

// A line on stderr when DEPTHSCOPE_LAYER_LOG=1.
#define DS_LAYER_LOG(...)                                      \
    do {                                                       \
        if (::ds::layer::config().log) {                       \
            std::fprintf(stderr, "depthscope layer: " __VA_ARGS__); \
            std::fputc('\n', stderr);                          \
        }                                                      \
    } while (0)

const Config& config();

}  // namespace ds::layer
