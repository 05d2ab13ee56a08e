#include "container.h"

#include <cstring>
#include <string_view>

namespace ds::fuzz {

namespace {
constexpr std::string_view kMagic = "DSFZ";
}

Container unpack(const uint8_t* data, size_t size) {
    Container c;
    const std::string_view in(reinterpret_cast<const char*>(data), size);
    if (!in.starts_with(kMagic)) {
        c.document = std::string(in);
        return c;
    }
    size_t at = kMagic.size();
    bool first = true;
    while (at < in.size()) {  // a truncated entry keeps what is there
        const size_t name_length = static_cast<uint8_t>(in[at++]);
        const std::string name(in.substr(at, name_length));
        at = std::min(in.size(), at + name_length);
        uint32_t length = 0;
        for (int i = 0; i < 4 && at < in.size(); ++i, ++at)
            length |= uint32_t(static_cast<uint8_t>(in[at])) << (8 * i);
        std::string bytes(in.substr(at, length));
        at = std::min(in.size(), at + length);
        if (first) {
            // The name stands for a path: no NUL (the message would end there) and, as the
            // importer shows paths, control characters as '?'.
            if (!name.empty() && name.find('\0') == std::string::npos) c.name = name;
            for (char& ch : c.name)
                if (static_cast<unsigned char>(ch) < 0x20 || ch == 0x7f) ch = '?';
            c.document = std::move(bytes);
            first = false;
        } else {
            c.files[name] = std::move(bytes);
        }
    }
    return c;
}

std::string pack(const Container& c) {
    std::string out(kMagic);
    auto add = [&](const std::string& name, const std::string& bytes) {
        out.push_back(static_cast<char>(std::min<size_t>(name.size(), 255)));
        out += name.substr(0, 255);
        const auto length = static_cast<uint32_t>(bytes.size());
        for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>(length >> (8 * i)));
        out += bytes;
    };
    add(c.name, c.document);
    for (const auto& [name, bytes] : c.files) add(name, bytes);
    return out;
}

}  // namespace ds::fuzz
