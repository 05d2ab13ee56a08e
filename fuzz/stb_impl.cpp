// stb_image for the fuzz build only: depthscope links Debian's libstb, which the fuzzer could
// neither see into (coverage) nor check (ASan); here the decoders are compiled instrumented.
#define STB_IMAGE_IMPLEMENTATION
#define STBI_NO_STDIO
#include <stb/stb_image.h>
