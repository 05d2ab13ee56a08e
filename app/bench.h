#pragma once
// Pieces of `depthscope bench` that need no GPU: the settings matrix and the statistics.
#include <string>
#include <utility>
#include <vector>

namespace ds::app {

using Assignment = std::pair<std::string, std::string>;  // name, value

// "--matrix prepass=on,off --matrix msaa=1,4" -> every combination, first knob slowest,
// values in the order given. No matrix: one empty combination. Throws UsageError.
std::vector<std::vector<Assignment>> expand_matrix(const std::vector<std::string>& specs);

struct Summary {
    double median = 0, min = 0, max = 0;
};
Summary summarize(std::vector<double> values);  // empty -> zeros

}  // namespace ds::app
