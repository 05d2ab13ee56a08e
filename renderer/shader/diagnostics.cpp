#include "renderer/shader/diagnostics.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <vector>

namespace ds::shader {

namespace {

constexpr std::string_view kErrorPrefix = "ERROR: ";

bool all_digits(std::string_view text) {
    return !text.empty() && std::all_of(text.begin(), text.end(),
                                        [](unsigned char c) { return std::isdigit(c) != 0; });
}

std::string_view trim(std::string_view text) {
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) {
        text.remove_suffix(1);
    }
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) {
        text.remove_prefix(1);
    }
    return text;
}

// glslang's own bookkeeping lines, which repeat what the real errors already say.
bool is_noise(std::string_view message) {
    return message.find("compilation terminated") != std::string_view::npos ||
           message.find("compilation errors.  No code generated") != std::string_view::npos;
}

struct Location {
    std::string_view file, line, message;
};

// Splits "FILE:LINE: message"; the first ":<digits>: " ends FILE, so a name may hold ':'.
std::optional<Location> split_location(std::string_view text) {
    for (size_t colon = text.find(':'); colon != std::string_view::npos;
         colon = text.find(':', colon + 1)) {
        const size_t digits_end = text.find(':', colon + 1);
        if (digits_end == std::string_view::npos) return std::nullopt;
        const std::string_view line = text.substr(colon + 1, digits_end - colon - 1);
        if (all_digits(line) && colon > 0) {
            return Location{text.substr(0, colon), line, trim(text.substr(digits_end + 1))};
        }
    }
    return std::nullopt;
}

std::string format_error(std::string_view text, std::string_view main_name) {
    if (auto loc = split_location(text)) {
        std::string file = all_digits(loc->file) ? "<defines>" : std::string(loc->file);
        return file + ":" + std::string(loc->line) + ": " + std::string(loc->message);
    }
    return std::string(main_name) + ": " + std::string(trim(text));
}

}  // namespace

std::string format_info_log(std::string_view log, std::string_view main_name) {
    std::vector<std::string> lines;
    size_t start = 0;
    while (start < log.size()) {
        size_t end = log.find('\n', start);
        if (end == std::string_view::npos) end = log.size();
        std::string_view line = trim(log.substr(start, end - start));
        start = end + 1;
        const size_t prefix = line.find(kErrorPrefix);  // also "INTERNAL ERROR: "
        if (prefix == std::string_view::npos ||
            (prefix > 0 && line.substr(0, prefix) != "INTERNAL ")) {
            continue;
        }
        const std::string_view body = line.substr(prefix + kErrorPrefix.size());
        if (is_noise(body)) continue;
        std::string formatted = format_error(body, main_name);
        if (std::find(lines.begin(), lines.end(), formatted) == lines.end()) {
            lines.push_back(std::move(formatted));
        }
    }
    if (lines.empty()) {
        const std::string_view raw = trim(log);
        return std::string(main_name) + ": compilation failed" +
               (raw.empty() ? "" : " (" + std::string(raw) + ")");
    }
    std::string out;
    for (const std::string& line : lines) {
        if (!out.empty()) out += '\n';
        out += line;
    }
    return out;
}

}  // namespace ds::shader
