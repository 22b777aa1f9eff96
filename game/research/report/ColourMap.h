#pragma once
// Colour maps for heatmaps: a value in [0, 1] -> "#rrggbb". Viridis
// (perceptually uniform, readable in grey and by most colour-blind readers)
// for magnitudes; a blue-white-red diverging map for signed quantities.

#include <string>

namespace hemiroll::report {

enum class ColourMap { Viridis, Diverging };

// t is clamped to [0, 1]; a non-finite t gives the map's middle colour.
std::string colourAt(ColourMap map, double t);

}  // namespace hemiroll::report
