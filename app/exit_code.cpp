#include "app/exit_code.h"

#include <cstdio>

namespace ds::app {

int validation_exit_code(Renderer& renderer, bool print_count, uint64_t other_messages) {
    renderer.shutdown();
    const uint64_t messages = renderer.validation_message_count() + other_messages;
    if (messages == 0) return 0;
    if (print_count)
        std::fprintf(stderr, "depthscope: %llu validation message(s)\n",
                     static_cast<unsigned long long>(messages));
    return 3;
}

}  // namespace ds::app
