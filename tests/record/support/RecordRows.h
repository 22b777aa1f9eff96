#pragma once
// Rows for record tests: random bit patterns (every finite double, with
// subnormals and -0.0, the hardest cases for text round trips) and a
// bit-for-bit comparison of rows (memcmp per field: RecordRow has padding,
// so the struct as a whole cannot be memcmp'ed).

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "engine/haptics/RecordRow.h"

namespace hemiroll::record::test {

inline double randomFiniteDouble(std::mt19937_64& rng) {
  for (;;) {
    const double d = std::bit_cast<double>(rng());
    if (std::isfinite(d)) return d;
  }
}

template <typename Visit>
void forEachRowDouble(haptics::RecordRow& r, Visit visit) {
  visit(r.time);
  for (auto& v : r.state) visit(v);
  for (auto* t : {&r.proxyPosition, &r.proxyVelocity, &r.handForce, &r.modelForce, &r.renderedForce, &r.guidanceForce})
    for (auto& v : *t) visit(v);
  visit(r.proxyDistance);
  visit(r.injectedEnergy);
  visit(r.rampScale);
  visit(r.lateness);
}

inline haptics::RecordRow randomRow(std::mt19937_64& rng, std::uint64_t tick) {
  haptics::RecordRow r;
  forEachRowDouble(r, [&rng](double& v) { v = randomFiniteDouble(rng); });
  r.tick = tick;
  r.event = static_cast<physics::DomainEvent>(rng() % 4);
  r.engagement = static_cast<haptics::Engagement>(rng() % 4);
  r.fault = static_cast<haptics::SafetyFault>(rng() % 9);
  r.paused = rng() % 2 == 1;
  r.forceClamped = rng() % 2 == 1;
  return r;
}

inline std::vector<haptics::RecordRow> randomRows(std::size_t n, std::uint64_t seed, int recordEvery = 10) {
  std::mt19937_64 rng(seed);
  std::vector<haptics::RecordRow> rows;
  for (std::size_t i = 0; i < n; ++i) rows.push_back(randomRow(rng, (i + 1) * static_cast<std::uint64_t>(recordEvery)));
  return rows;
}

inline bool sameBits(haptics::RecordRow a, haptics::RecordRow b) {
  std::vector<double> da, db;
  forEachRowDouble(a, [&da](double& v) { da.push_back(v); });
  forEachRowDouble(b, [&db](double& v) { db.push_back(v); });
  return std::memcmp(da.data(), db.data(), da.size() * sizeof(double)) == 0 && a.tick == b.tick &&
         a.event == b.event && a.engagement == b.engagement && a.fault == b.fault && a.paused == b.paused &&
         a.forceClamped == b.forceClamped;
}

}  // namespace hemiroll::record::test
