#include "app/bench.h"

#include <algorithm>

#include "renderer/common/error.h"
#include "renderer/common/quoted.h"

namespace ds::app {
namespace {

std::vector<std::string> split(const std::string& text, char sep) {
    std::vector<std::string> parts;
    size_t start = 0;
    for (size_t i = 0; i <= text.size(); ++i) {
        if (i == text.size() || text[i] == sep) {
            parts.push_back(text.substr(start, i - start));
            start = i + 1;
        }
    }
    return parts;
}

}  // namespace

std::vector<std::vector<Assignment>> expand_matrix(const std::vector<std::string>& specs) {
    std::vector<std::vector<Assignment>> runs{{}};
    for (const std::string& spec : specs) {
        const size_t eq = spec.find('=');
        if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size()) {
            throw UsageError("--matrix expects name=value1,value2,..., got " + quote(spec));
        }
        const std::string name = spec.substr(0, eq);
        const std::vector<std::string> values = split(spec.substr(eq + 1), ',');
        if (std::any_of(values.begin(), values.end(), [](auto& v) { return v.empty(); })) {
            throw UsageError("--matrix " + quote(spec) + ": empty value");
        }
        std::vector<std::vector<Assignment>> next;
        for (const auto& run : runs) {
            for (const auto& value : values) {
                next.push_back(run);
                next.back().emplace_back(name, value);
            }
        }
        runs = std::move(next);
    }
    return runs;
}

Summary summarize(std::vector<double> values) {
    if (values.empty()) return {};
    std::sort(values.begin(), values.end());
    const size_t n = values.size();
    const double median = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
    return {median, values.front(), values.back()};
}

}  // namespace ds::app
