#include "engine/analysis/TrialAnalyzer.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace hemiroll::analysis {

namespace {

// The rows whose time lies in [from, to].
std::pair<std::size_t, std::size_t> rowsWithin(std::span<const double> time, double from, double to) {
  std::size_t first = time.size(), last = 0;
  for (std::size_t i = 0; i < time.size(); ++i) {
    if (time[i] >= from && time[i] <= to) {
      first = std::min(first, i);
      last = i + 1;
    }
  }
  return first < last ? std::pair{first, last} : std::pair{std::size_t{0}, std::size_t{0}};
}

// Why a feature was measured over the whole trial: what the steady phase
// alone showed, without the detector's "no rose: " (the feature was found,
// over the whole trial).
std::string wholeTrialNote(const TimeInterval& steady, const std::string& reason) {
  const std::size_t colon = reason.find(": ");
  const std::string shown = reason.rfind("no ", 0) == 0 && colon != std::string::npos ? reason.substr(colon + 2) : reason;
  char window[64];
  std::snprintf(window, sizeof window, "%.1f-%.1f s", steady.start, steady.end);
  return "measured over the whole trial: the steady phase (" + std::string(window) + ") alone shows " + shown;
}

// The rose's and the helix's features over the same rows, their four
// channels resampled in one pass where that gives each detector the very
// series it would make alone (issue 32: the rows, gaps and median spacing
// were worked out twice): the same sampling, and no row dropped (a NaN in
// one channel drops its row for one detector only). Otherwise each alone.
template <typename Part>
std::pair<RoseFeatures, HelixFeatures> roseAndHelix(const TrialSamples& s, Part part, const TrialAnalysisDef& def) {
  if (def.rose.sampling == def.helix.sampling) {
    const std::span<const double> channels[] = {part(s.massX), part(s.massY), part(s.contactX), part(s.contactY)};
    UniformSeries joint = resampleUniform(part(s.time), channels, def.rose.sampling);
    if (joint.ok() && joint.droppedRows == 0) {
      UniformSeries mass{joint.t0, joint.dt, {}, 0, {}}, contact{joint.t0, joint.dt, {}, 0, {}};
      // Moved one by one: a braced list would copy them (its elements are const).
      for (std::size_t c = 0; c < 2; ++c) {
        mass.channels.push_back(std::move(joint.channels[c]));
        contact.channels.push_back(std::move(joint.channels[c + 2]));
      }
      return {detectRose(mass, def.rose), detectHelix(contact, def.helix)};
    }
  }
  return {detectRose(part(s.time), part(s.massX), part(s.massY), def.rose),
          detectHelix(part(s.time), part(s.contactX), part(s.contactY), def.helix)};
}

}  // namespace

TrialFeatures analyzeTrial(const TrialSamples& s, const TrialAnalysisDef& def) {
  TrialFeatures out;
  out.phases = segmentPhases(s.time, s.psi, def.phases);
  auto over = [&](std::size_t first, std::size_t last) {
    return [=](std::span<const double> column) {
      return column.size() >= last ? column.subspan(first, last - first) : std::span<const double>();
    };
  };
  const auto whole = over(0, s.time.size());
  auto rose = [&](auto part) { return detectRose(part(s.time), part(s.massX), part(s.massY), def.rose); };
  auto helix = [&](auto part) { return detectHelix(part(s.time), part(s.contactX), part(s.contactY), def.helix); };

  out.roseWindow = out.helixWindow = out.phases.trial;
  if (!out.phases.found) {
    out.roseNote = out.helixNote = "no steady precession phase: looked for over the whole trial";
    std::tie(out.rose, out.helix) = roseAndHelix(s, whole, def);
  } else {
    const auto [first, last] = rowsWithin(s.time, out.phases.steady.start, out.phases.steady.end);
    const auto steady = over(first, last);
    HelixFeatures helixSteady;
    std::tie(out.rose, helixSteady) = roseAndHelix(s, steady, def);
    out.roseWindow = out.phases.steady;
    if (!out.rose.found) {
      out.roseNote = wholeTrialNote(out.phases.steady, out.rose.reason);
      out.rose = rose(whole);
      out.roseWindow = out.phases.trial;
    }
    out.helix = std::move(helixSteady);
    out.helixWindow = out.phases.steady;
    if (!out.helix.arc.found || !out.helix.loops.found) {
      const std::string why = !out.helix.loops.found ? out.helix.loops.reason : out.helix.arc.reason;
      HelixFeatures wholeTrial = helix(whole);
      // Kept only where the whole trial shows more (the loops, or at least the arc).
      if ((wholeTrial.loops.found && !out.helix.loops.found) || (wholeTrial.arc.found && !out.helix.arc.found)) {
        out.helix = std::move(wholeTrial);
        out.helixWindow = out.phases.trial;
        out.helixNote = wholeTrialNote(out.phases.steady, why);
      }
    }
  }
  const bool sameWindow = out.roseWindow.start == out.helixWindow.start && out.roseWindow.end == out.helixWindow.end;
  if (sameWindow && out.rose.found && out.helix.loops.found && out.helix.loops.spacingTime.value > 0.0)
    out.loopsPerLeaf = out.rose.leafPeriod.value / out.helix.loops.spacingTime.value;
  return out;
}

}  // namespace hemiroll::analysis
