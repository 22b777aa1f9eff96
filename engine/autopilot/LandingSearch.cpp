#include "engine/autopilot/LandingSearch.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>
#include <vector>

#include "engine/physics/NormalDraws.h"

namespace hemiroll::autopilot {

std::optional<LandingShape> searchLandingShape(const LandingSearchDef& def, const ScoreShapes& score) {
  constexpr int n = 2 * LandingShape::kKnots;
  using Vector = std::array<double, n>;
  const int elites = std::clamp(def.elites, 1, def.population);
  const std::size_t batch = static_cast<std::size_t>(std::max(1, def.batch));
  Vector mean{}, spread{};
  spread.fill(def.spread);
  physics::NormalDraws normal(def.seed);
  std::vector<std::pair<double, Vector>> samples(static_cast<std::size_t>(def.population));
  const auto shapeOf = [](const Vector& theta) {
    LandingShape shape;
    for (std::size_t j = 0; j < LandingShape::kKnots; ++j) shape.knots[j] = physics::Vec2(theta[2 * j], theta[2 * j + 1]);
    return shape;
  };
  std::vector<LandingShape> shapes;
  for (int round = 0; round < def.rounds; ++round) {
    for (std::size_t first = 0; first < samples.size(); first += batch) {
      const std::size_t end = std::min(samples.size(), first + batch);
      shapes.clear();
      for (std::size_t k = first; k < end; ++k) {
        Vector& theta = samples[k].second;
        for (std::size_t i = 0; i < n; ++i) theta[i] = mean[i] + (k == 0 ? 0.0 : spread[i] * normal());
        shapes.push_back(shapeOf(theta));
      }
      if (def.outOfTime && def.outOfTime()) return std::nullopt;
      const std::vector<ShapeScore> scores = score(shapes);
      for (std::size_t k = first; k < end; ++k) {
        if (scores[k - first].success) return shapes[k - first];
        samples[k].first = scores[k - first].cost;
      }
    }
    std::partial_sort(samples.begin(), samples.begin() + elites, samples.end(),
                      [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t i = 0; i < n; ++i) {
      double m = 0.0, v = 0.0;
      for (int e = 0; e < elites; ++e) m += samples[static_cast<std::size_t>(e)].second[i];
      m /= elites;
      for (int e = 0; e < elites; ++e) {
        const double d = samples[static_cast<std::size_t>(e)].second[i] - m;
        v += d * d;
      }
      mean[i] = m;
      spread[i] = std::sqrt(v / elites) + 1e-5;  // never quite zero: keep searching
    }
  }
  return std::nullopt;
}

std::optional<LandingShape> searchLandingShape(const LandingSearchDef& def, const ScoreShape& score) {
  LandingSearchDef single = def;
  single.batch = 1;
  return searchLandingShape(single, [&score](const std::vector<LandingShape>& shapes) {
    return std::vector<ShapeScore>{score(shapes.front())};
  });
}

}  // namespace hemiroll::autopilot
