#pragma once
// tune's results as a table (stdout), JSON (--json) and a plot (--plot, capture/plot.h).
#include <string>

#include <nlohmann/json.hpp>

#include "capture/plot.h"
#include "capture/tune/tune_alpha.h"
#include "capture/tune/tune_msaa.h"

namespace ds::tune {

using capture::Plot;
using capture::PlotSeries;

std::string msaa_text(const MsaaTune& t);
nlohmann::json msaa_json(const MsaaTune& t);
Plot msaa_plot(const MsaaTune& t);  // error against cost, the front as a line

std::string alpha_text(const AlphaTune& t);
nlohmann::json alpha_json(const AlphaTune& t);
Plot alpha_plot(const AlphaTune& t);  // coverage error against cutoff, a line per material

// "msaa=4 sample_shading=on …": what Apply sets, as --set arguments.
std::string assignments_text(const std::vector<std::string>& assignments);

}  // namespace ds::tune
