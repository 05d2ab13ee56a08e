// The command line's values: --size, --at, --look-at and whole numbers, each read exactly
// (no sign, spaces, hex or wrap-around where CLI11 alone would take them); usage errors name
// the option and quote what was given.
#include <charconv>
#include <cmath>
#include <limits>

#include <glm/glm.hpp>

#include "app/cli.h"
#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace ds::app {

std::optional<uint32_t> parse_digits(std::string_view text) {
    if (text.empty() || text.find_first_not_of("0123456789") != std::string_view::npos)
        return std::nullopt;
    uint32_t value = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || ptr != text.data() + text.size()) return std::nullopt;
    return value;
}

// Syntax and the tool's own bound only: whether the device can make images this large (and
// has the memory) is checked when rendering.
Size parse_size(const std::string& text) {
    const size_t x = text.find('x');
    const std::optional<uint32_t> w =
        x == std::string::npos ? std::nullopt : parse_digits(std::string_view(text).substr(0, x));
    const std::optional<uint32_t> h =
        x == std::string::npos ? std::nullopt : parse_digits(std::string_view(text).substr(x + 1));
    if (!w || !h || *w < 1 || *h < 1 || *w > kMaxSize || *h > kMaxSize) {
        throw UsageError("--size expects WIDTHxHEIGHT between 1x1 and " + std::to_string(kMaxSize) +
                         "x" + std::to_string(kMaxSize) + ", got " + quote(text));
    }
    return {*w, *h};
}

void parse_at(const std::string& text, uint32_t& x, uint32_t& y) {
    const size_t comma = text.find(',');
    const std::optional<uint32_t> px = comma == std::string::npos
                                           ? std::nullopt
                                           : parse_digits(std::string_view(text).substr(0, comma));
    const std::optional<uint32_t> py = comma == std::string::npos
                                           ? std::nullopt
                                           : parse_digits(std::string_view(text).substr(comma + 1));
    if (!px || !py || *px >= kMaxSize || *py >= kMaxSize) {
        throw UsageError("--at expects X,Y (two whole numbers below " + std::to_string(kMaxSize) +
                         ", 0,0 = top left), got " + quote(text));
    }
    x = *px;
    y = *py;
}

namespace {

// One decimal number of a --look-at text (minus, digits, point, exponent), finite; none else.
std::optional<float> parse_coordinate(std::string_view text) {
    float value = 0;
    const bool plain =
        !text.empty() && text.find_first_not_of("-0123456789.eE") == std::string_view::npos;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (!plain || ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(value))
        return std::nullopt;
    return value;
}

// "x,y,z" into out[3]; false when it is not three numbers.
bool parse_point(std::string_view text, float out[3]) {
    for (int i = 0; i < 3; ++i) {
        const size_t end = i < 2 ? text.find(',') : text.size();
        if (end == std::string_view::npos) return false;
        const std::optional<float> v = parse_coordinate(text.substr(0, end));
        if (!v) return false;
        out[i] = *v;
        if (i < 2) text.remove_prefix(end + 1);
    }
    return true;
}

// The eye and the target apart, giving a direction float can hold, not within 1 degree of
// straight up or down (up is +Y); throws UsageError quoting `text`.
void check_direction(const LookAt& l, const std::string& text) {
    const glm::vec3 d =
        glm::vec3(l.target[0], l.target[1], l.target[2]) - glm::vec3(l.eye[0], l.eye[1], l.eye[2]);
    const float length = glm::length(d);
    if (d == glm::vec3(0.0f))
        throw UsageError("--look-at: the eye and the point it looks at are the same, got " +
                         quote(text));
    if (!std::isfinite(length) || !(length > 0.0f))
        throw UsageError("--look-at: the eye and the point it looks at give no direction (too " +
                         std::string(std::isfinite(length) ? "close" : "far apart") + "), got " +
                         quote(text));
    if (std::fabs(d.y / length) > std::cos(glm::radians(1.0f)))
        throw UsageError(
            "--look-at: the view is within 1 degree of straight up or down (up is +Y: tilt it), "
            "got " +
            quote(text));
}

}  // namespace

LookAt parse_look_at(const std::string& text) {
    LookAt l;
    const std::string_view all(text);
    const size_t colon = all.find(':');
    const size_t second = colon == std::string::npos ? colon : all.find(':', colon + 1);
    const bool ok =
        colon != std::string::npos &&
        (second == std::string::npos || all.find(':', second + 1) == std::string::npos) &&
        parse_point(all.substr(0, colon), l.eye) &&
        parse_point(
            all.substr(colon + 1, second == std::string::npos ? second : second - colon - 1),
            l.target);
    if (!ok)
        throw UsageError(
            "--look-at expects EX,EY,EZ:TX,TY,TZ[:FOV] (six numbers: the eye, then the point it "
            "looks at; then the vertical field of view in degrees), got " +
            quote(text));
    if (second != std::string::npos) {
        const std::optional<float> fov = parse_coordinate(all.substr(second + 1));
        if (!fov || *fov < kMinFov || *fov > kMaxFov)
            throw UsageError(
                "--look-at: FOV expects a vertical field of view in degrees, 10..120, "
                "got " +
                quote(std::string(all.substr(second + 1))) + " in " + quote(text));
        l.fov = fov;
    }
    check_direction(l, text);
    return l;
}

}  // namespace ds::app
