#pragma once
// A user's text inside an error message: control characters escaped so that the message stays
// one line (DESIGN decision 8: one line `depthscope: error: …`). Header-only, so that every
// layer (vk's device choice too) can use it without linking another library.
#include <string>
#include <string_view>

namespace ds {

// `text` with \n, \t, \r and every other byte below 0x20 or equal to 0x7f written as an escape
// (\n, \t, \r, \xNN). Everything else, backslashes and UTF-8 included, stays as it is, so
// escaping twice changes nothing.
inline std::string escaped(std::string_view text) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte >= 0x20 && byte != 0x7f) {
            out += c;
        } else if (c == '\n') {
            out += "\\n";
        } else if (c == '\t') {
            out += "\\t";
        } else if (c == '\r') {
            out += "\\r";
        } else {
            out += "\\x";
            out += kHex[byte >> 4];
            out += kHex[byte & 0xf];
        }
    }
    return out;
}

// 'text', escaped: the form every message that echoes a value the user gave uses. (Not named
// `quoted`: for a std::string argument, argument-dependent lookup would pick std::quoted.)
inline std::string quote(std::string_view text) {
    return "'" + escaped(text) + "'";
}

}  // namespace ds
