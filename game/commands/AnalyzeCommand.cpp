#include "game/commands/AnalyzeCommand.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <utility>

#include "engine/record/RecordError.h"
#include "game/research/analysis/AnalysisInputError.h"
#include "game/research/analysis/AnalysisOutput.h"
#include "game/research/analysis/ExperimentTable.h"
#include "game/research/analysis/LearningCurves.h"
#include "game/research/analysis/TrialLoader.h"
#include "game/commands/AnalyzeOptions.h"
#include "game/commands/CommandUsage.h"
#include "game/commands/ExitCode.h"

namespace hemiroll::game {

namespace {

// Per group: participants, trials, success rate, mean time of the trials.
std::string groupSummary(const ExperimentTable& table) {
  struct Tally {
    std::map<std::string, int> participants;
    int trials = 0, successes = 0;
    double time = 0.0;
  };
  std::map<std::string, Tally> groups;
  for (const ExperimentTrial& t : table.trials) {
    Tally& g = groups[t.group];
    g.participants[t.participant] = 1;
    ++g.trials;
    const auto success = t.measures.find("success");
    g.successes += success != t.measures.end() && success->second == 1.0;
    const auto time = t.measures.find("time_s");
    if (time != t.measures.end()) g.time += time->second;
  }
  std::string out = "| group | participants | trials | success [%] | mean time [s] |\n|---|---|---|---|---|\n";
  for (const auto& [name, g] : groups) {
    char line[256];
    std::snprintf(line, sizeof line, "| %s | %zu | %d | %.1f | %.2f |\n", name.empty() ? "(none)" : name.c_str(),
                  g.participants.size(), g.trials, 100.0 * g.successes / g.trials, g.time / g.trials);
    out += line;
  }
  return out;
}

// `hemiroll analyze EXPERIMENT_FOLDER`: the long table and the learning curves.
int analyzeExperiment(const AnalyzeOptions& o) {
  ExperimentTable table;
  try {
    table = readExperiment(o.inputs.front());
  } catch (const AnalysisInputError& e) {
    std::cerr << "hemiroll analyze: " << e.what() << "\n";
    return kExitUsage;
  }
  for (const std::string& note : table.notes) std::cerr << "hemiroll analyze: " << note << "\n";
  if (o.outDir) {
    const std::vector<CurvePoint> curves = learningCurves(table.trials, defaultCurveMeasures());
    OutputFiles files = {{"trials.csv", table.csv()}, {"learning_curves.csv", learningCurvesCsv(curves)}};
    if (o.plots)
      for (auto& plot : learningCurvePlots(curves, defaultCurveMeasures())) files.push_back(std::move(plot));
    try {
      writeOutputFiles(*o.outDir, files);
    } catch (const record::RecordError& e) {
      std::cerr << "hemiroll analyze: " << e.what() << "\n";
      return kExitFailure;
    }
    std::cerr << "hemiroll analyze: " << table.sessions << (table.sessions == 1 ? " session, " : " sessions, ")
              << table.trials.size() << (table.trials.size() == 1 ? " trial, " : " trials, ")
              << files.size() << " files written to " << *o.outDir << "\n";
  }
  std::cout << groupSummary(table);
  return kExitOk;
}

}  // namespace

int runAnalyzeCommand(const std::vector<std::string>& args) {
  const AnalyzeOptionsResult parsed = parseAnalyzeOptions(args);
  if (const std::optional<int> exit = exitBeforeRunning("hemiroll analyze: ", parsed, analyzeUsage())) return *exit;
  const AnalyzeOptions& o = parsed.options;
  if (o.inputs.size() == 1 && isExperimentFolder(o.inputs.front())) return analyzeExperiment(o);

  // Everything is read and measured before anything is written: bad input
  // leaves no output behind.
  std::vector<AnalysedTrial> trials;
  try {
    for (TrialData& data : loadTrials(o.inputs)) {
      analysis::TrialFeatures features = analysis::analyzeTrial(data.samples());
      const analysis::GuidanceWork guidance = analysis::guidanceWork(data.guidanceSamples());
      trials.push_back({std::move(data), std::move(features), guidance});
    }
  } catch (const AnalysisInputError& e) {
    std::cerr << "hemiroll analyze: " << e.what() << "\n";
    return kExitUsage;
  }
  const std::string table = featureTableMarkdown(trials);

  if (o.outDir) {
    const OutputFiles files = analysisFiles(trials, o.plots);
    try {
      writeOutputFiles(*o.outDir, files);
    } catch (const record::RecordError& e) {
      std::cerr << "hemiroll analyze: " << e.what() << "\n";
      return kExitFailure;
    }
    std::cerr << "hemiroll analyze: " << trials.size() << (trials.size() == 1 ? " trial" : " trials") << ", "
              << files.size() << " files written to " << *o.outDir << "\n";
  }
  std::cout << table;
  return kExitOk;
}

}  // namespace hemiroll::game
