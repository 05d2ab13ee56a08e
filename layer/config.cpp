#include "layer/config.h"

#include <cstdlib>
#include <sstream>

namespace ds::layer {

namespace {

std::string env(const char* name) {
    const char* v = std::getenv(name);
    return v ? v : "";
}

bool parse_frame(const std::string& text, uint64_t& frame) {
    if (text.empty() || text.size() > 12 || text.find_first_not_of("0123456789") != std::string::npos)
        return false;
    frame = std::stoull(text);
    return frame >= 1;
}

}  // namespace

Config Config::from_environment() {
    Config c;
    c.log = env("DEPTHSCOPE_LAYER_LOG") == "1";
    c.out = env("DEPTHSCOPE_LAYER_OUT");
    if (c.out.empty()) return c;
    const std::string mode = env("DEPTHSCOPE_LAYER_MODE");
    if (mode == "list") {
        c.mode = Mode::List;
    } else if (mode == "capture") {
        c.mode = Mode::Capture;
        if (!parse_frame(env("DEPTHSCOPE_LAYER_FRAME"), c.frame))
            c.error = "DEPTHSCOPE_LAYER_FRAME is not a frame number from 1";
    } else {
        c.error = "DEPTHSCOPE_LAYER_MODE is neither list nor capture";
    }
    std::map<std::string, std::string> settings;
    std::istringstream pairs(env("DEPTHSCOPE_LAYER_SETTINGS"));
    for (std::string pair; std::getline(pairs, pair, ';');) {
        const auto eq = pair.find('=');
        if (eq == std::string::npos || eq == 0) {
            c.error = "DEPTHSCOPE_LAYER_SETTINGS: '" + pair + "' is not k=v";
            continue;
        }
        settings[pair.substr(0, eq)] = pair.substr(eq + 1);
    }
    try {
        c.settings = parse_layer_settings(settings);
    } catch (const Error& e) {
        c.error = e.what();
    }
    if (!c.error.empty()) c.mode = Mode::Passive;
    return c;
}

}  // namespace ds::layer
