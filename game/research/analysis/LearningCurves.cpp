#include "game/research/analysis/LearningCurves.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <tuple>

#include "engine/record/CsvRowFormat.h"
#include "game/research/report/LinePlot.h"

namespace hemiroll::game {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Spread {
  int n = 0;
  double mean = kNaN, sd = kNaN;
};

Spread spreadOf(const std::vector<double>& values) {
  Spread s;
  s.n = static_cast<int>(values.size());
  if (s.n == 0) return s;
  double sum = 0.0;
  for (const double v : values) sum += v;
  s.mean = sum / s.n;
  if (s.n < 2) return s;
  double squares = 0.0;
  for (const double v : values) squares += (v - s.mean) * (v - s.mean);
  s.sd = std::sqrt(squares / (s.n - 1));
  return s;
}

std::string number(double v) {
  if (!std::isfinite(v)) return "";
  std::string out;
  record::appendDouble(v, out);
  return out;
}

// Block names ranked in the file's order: as the participants with the
// lowest block order present meet them, then any others as met.
std::map<std::string, int> blockRanks(const std::vector<ExperimentTrial>& trials) {
  std::vector<const ExperimentTrial*> sorted;
  for (const ExperimentTrial& t : trials) sorted.push_back(&t);
  std::stable_sort(sorted.begin(), sorted.end(), [](const ExperimentTrial* a, const ExperimentTrial* b) {
    return std::tie(a->blockOrder, a->block, a->trialIndex) < std::tie(b->blockOrder, b->block, b->trialIndex);
  });
  std::map<std::string, int> ranks;
  for (const ExperimentTrial* t : sorted)
    if (!ranks.count(t->blockName)) {
      const int next = static_cast<int>(ranks.size()) + 1;
      ranks[t->blockName] = next;
    }
  return ranks;
}

std::string title(const std::string& measure) {
  if (measure == "success") return "success rate";
  return measure;
}

// The y axis: success as a rate in %, everything else as written.
report::AxisSpec yAxis(const std::string& measure) {
  report::AxisSpec y;
  if (measure == "success") {
    y.label = "success [%]";
    y.scale = 100.0;
    y.min = 0.0;
    y.max = 1.0;
  } else {
    y.label = measure;
  }
  return y;
}

}  // namespace

const std::vector<std::string>& defaultCurveMeasures() {
  static const std::vector<std::string> measures = {"success", "time_s", "final_margin", "contact_path_m"};
  return measures;
}

std::vector<CurvePoint> learningCurves(const std::vector<ExperimentTrial>& trials,
                                       const std::vector<std::string>& measures) {
  std::vector<CurvePoint> points;
  const std::map<std::string, int> ranks = blockRanks(trials);
  std::map<std::string, std::string> groupOf;  // participant -> group
  for (const ExperimentTrial& t : trials) groupOf.emplace(t.participant, t.group);
  for (const std::string& measure : measures) {
    // participant -> trial index -> values; participant -> block -> values
    std::map<std::string, std::map<int, std::vector<double>>> byTrial;
    std::map<std::string, std::map<std::string, std::vector<double>>> byBlock;
    for (const ExperimentTrial& t : trials) {
      const auto found = t.measures.find(measure);
      if (found == t.measures.end() || !std::isfinite(found->second)) continue;
      byTrial[t.participant][t.trialIndex].push_back(found->second);
      byBlock[t.participant][t.blockName].push_back(found->second);
    }
    std::map<std::string, std::map<int, std::vector<double>>> groupByTrial;
    std::map<std::string, std::map<std::string, std::vector<double>>> groupByBlock;
    for (const auto& [participant, perTrial] : byTrial)
      for (const auto& [index, values] : perTrial) {
        const Spread s = spreadOf(values);
        points.push_back({"participant", participant, groupOf[participant], "trial", static_cast<double>(index), "",
                          measure, s.n, s.mean, s.sd});
        groupByTrial[groupOf[participant]][index].push_back(s.mean);
      }
    for (const auto& [participant, perBlock] : byBlock)
      for (const auto& [name, values] : perBlock) {
        const Spread s = spreadOf(values);
        points.push_back({"participant", participant, groupOf[participant], "block",
                          static_cast<double>(ranks.at(name)), name, measure, s.n, s.mean, s.sd});
        groupByBlock[groupOf[participant]][name].push_back(s.mean);
      }
    for (const auto& [group, perTrial] : groupByTrial)
      for (const auto& [index, values] : perTrial) {
        const Spread s = spreadOf(values);
        points.push_back({"group", "", group, "trial", static_cast<double>(index), "", measure, s.n, s.mean, s.sd});
      }
    for (const auto& [group, perBlock] : groupByBlock)
      for (const auto& [name, values] : perBlock) {
        const Spread s = spreadOf(values);
        points.push_back({"group", "", group, "block", static_cast<double>(ranks.at(name)), name, measure, s.n, s.mean,
                          s.sd});
      }
  }
  return points;
}

std::string learningCurvesCsv(const std::vector<CurvePoint>& points) {
  std::string out =
      record::csvLine({"scope", "participant", "group", "by", "x", "block_name", "measure", "n", "mean", "sd"});
  for (const CurvePoint& p : points)
    out += record::csvLine({p.scope, p.participant, p.group, p.by, number(p.x), p.blockName, p.measure,
                            std::to_string(p.n), number(p.mean), number(p.sd)});
  return out;
}

OutputFiles learningCurvePlots(const std::vector<CurvePoint>& points, const std::vector<std::string>& measures) {
  OutputFiles files;
  std::vector<std::string> groups;
  for (const CurvePoint& p : points)
    if (std::find(groups.begin(), groups.end(), p.group) == groups.end()) groups.push_back(p.group);
  const auto colourOf = [&](const std::string& group) {
    return std::string(report::paletteColour(
        static_cast<std::size_t>(std::find(groups.begin(), groups.end(), group) - groups.begin())));
  };
  const auto shownGroup = [](const std::string& g) { return g.empty() ? std::string("all") : g; };
  for (const std::string& measure : measures) {
    for (const char* by : {"trial", "block"}) {
      report::LinePlotDef plot;
      plot.title = title(measure) + " by " + by + ", group mean and mean +- sd";
      plot.x.label = std::string(by) == "trial" ? "trial in session" : "block (the protocol's order)";
      plot.y = yAxis(measure);
      std::string blocks;
      for (const std::string& group : groups) {
        report::Series mean{shownGroup(group), {}, {}, colourOf(group)}, low{"", {}, {}, colourOf(group), 0.6},
            high{"", {}, {}, colourOf(group), 0.6};
        mean.markers = true;
        std::vector<const CurvePoint*> mine;
        for (const CurvePoint& p : points)
          if (p.scope == "group" && p.by == by && p.measure == measure && p.group == group) mine.push_back(&p);
        std::sort(mine.begin(), mine.end(), [](const CurvePoint* a, const CurvePoint* b) { return a->x < b->x; });
        for (const CurvePoint* p : mine) {
          mean.x.push_back(p->x);
          mean.y.push_back(p->mean);
          low.x.push_back(p->x);
          high.x.push_back(p->x);
          low.y.push_back(std::isfinite(p->sd) ? p->mean - p->sd : p->mean);
          high.y.push_back(std::isfinite(p->sd) ? p->mean + p->sd : p->mean);
          if (group == groups.front() && !p->blockName.empty())
            blocks += (blocks.empty() ? "" : ", ") + number(p->x) + " " + p->blockName;
        }
        report::Series line = mean;
        line.label.clear();
        line.markers = false;
        plot.series.push_back(std::move(line));
        plot.series.push_back(std::move(mean));
        plot.series.push_back(std::move(low));
        plot.series.push_back(std::move(high));
      }
      if (!blocks.empty()) plot.x.label += ": " + blocks;
      files.emplace_back("curves_" + measure + "_by_" + by + ".svg", report::renderLinePlot(plot));
    }
    report::LinePlotDef each;
    each.title = title(measure) + " by trial, every participant (colour: group)";
    each.x.label = "trial in session";
    each.y = yAxis(measure);
    std::set<std::string> labelled;
    std::map<std::string, report::Series> lines;
    for (const CurvePoint& p : points) {
      if (p.scope != "participant" || p.by != "trial" || p.measure != measure) continue;
      report::Series& s = lines[p.participant];
      if (s.x.empty()) {
        s.colour = colourOf(p.group);
        s.width = 0.8;
        if (labelled.insert(p.group).second) s.label = shownGroup(p.group);
      }
      s.x.push_back(p.x);
      s.y.push_back(p.mean);
    }
    for (auto& [participant, s] : lines) each.series.push_back(std::move(s));
    files.emplace_back("participants_" + measure + "_by_trial.svg", report::renderLinePlot(each));
  }
  return files;
}

}  // namespace hemiroll::game
