#pragma once
// This build's version: `git describe --always --dirty --tags` of the source tree when it was
// built (cmake/version.cmake writes it on every build, the file changing only with the text),
// or "PROJECT_VERSION-unknown" outside a git checkout. Captures record it; replay compares it.
namespace ds {
const char* version();
}  // namespace ds
