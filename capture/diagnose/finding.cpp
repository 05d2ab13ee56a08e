#include "capture/diagnose/finding.h"

#include <algorithm>
#include <tuple>

namespace ds::diagnose {

const char* severity_name(Severity s) {
    switch (s) {
        case Severity::Error:
            return "error";
        case Severity::Warning:
            return "warning";
        case Severity::Info:
            return "info";
        case Severity::Hint:
            return "hint";
    }
    return "hint";
}

size_t Diagnosis::count(Severity s) const {
    return size_t(std::count_if(findings.begin(), findings.end(),
                                [s](const Finding& f) { return f.severity == s; }));
}

bool Diagnosis::has_at_least(Severity level) const {
    return std::any_of(findings.begin(), findings.end(),
                       [level](const Finding& f) { return int(f.severity) <= int(level); });
}

void rank(std::vector<Finding>& findings) {
    std::stable_sort(findings.begin(), findings.end(), [](const Finding& a, const Finding& b) {
        return std::tuple(int(a.severity), -a.magnitude.value, a.code, a.message) <
               std::tuple(int(b.severity), -b.magnitude.value, b.code, b.message);
    });
}

void normalise_pixels(std::vector<uint32_t>& pixels) {
    std::sort(pixels.begin(), pixels.end());
    pixels.erase(std::unique(pixels.begin(), pixels.end()), pixels.end());
}

}  // namespace ds::diagnose
