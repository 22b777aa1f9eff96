#include "game/research/report/ColourMap.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace hemiroll::report {

namespace {

struct Rgb {
  double r, g, b;
};

// Nine evenly spaced stops of each map, interpolated linearly in sRGB.
constexpr std::array<Rgb, 9> kViridis{{{68, 1, 84}, {71, 45, 123}, {59, 82, 139}, {44, 114, 142}, {33, 145, 140},
                                       {40, 174, 128}, {94, 201, 98}, {173, 220, 48}, {253, 231, 37}}};
constexpr std::array<Rgb, 9> kDiverging{{{59, 76, 192}, {98, 130, 234}, {141, 176, 254}, {184, 208, 249},
                                         {247, 247, 247}, {244, 196, 173}, {244, 154, 123}, {222, 96, 77},
                                         {180, 4, 38}}};

}  // namespace

std::string colourAt(ColourMap map, double t) {
  const auto& stops = map == ColourMap::Viridis ? kViridis : kDiverging;
  if (!std::isfinite(t)) t = 0.5;
  const double at = std::clamp(t, 0.0, 1.0) * static_cast<double>(stops.size() - 1);
  const auto i = std::min(static_cast<std::size_t>(at), stops.size() - 2);
  const double w = at - static_cast<double>(i);
  auto channel = [&](double a, double b) { return static_cast<int>(std::lround(a + (b - a) * w)); };
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", channel(stops[i].r, stops[i + 1].r),
                channel(stops[i].g, stops[i + 1].g), channel(stops[i].b, stops[i + 1].b));
  return buffer;
}

}  // namespace hemiroll::report
