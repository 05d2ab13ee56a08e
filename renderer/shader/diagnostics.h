#pragma once
// Turns glslang's info log into depthscope's "FILE:LINE: message" lines.
#include <string>
#include <string_view>

namespace ds::shader {

// Keeps the ERROR lines of `log` (warnings and glslang's summary lines are dropped) as
// "FILE:LINE: message". glslang already names each location by the string name we gave the
// source or the include (relative to the shader root); a location without a name (the
// defines preamble) becomes "<defines>", a message without a location is given `main_name`.
// Never returns an empty string: a failure without a readable ERROR line still says so.
std::string format_info_log(std::string_view log, std::string_view main_name);

}  // namespace ds::shader
