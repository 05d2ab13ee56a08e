#pragma once
// A capture::Plot (capture/plot.h, what `tune --plot` writes as PNG) drawn with ImGui's draw
// list: axes with their ranges, each series' markers and lines, a legend, and the hovered
// point's values and label as a tooltip.
#include "capture/plot.h"

namespace ds::ui {

void plot_widget(const char* id, const capture::Plot& plot, float height);

}  // namespace ds::ui
