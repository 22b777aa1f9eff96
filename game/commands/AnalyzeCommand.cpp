#include "game/commands/AnalyzeCommand.h"

#include <iostream>
#include <utility>

#include "engine/record/RecordError.h"
#include "game/analysis/AnalysisInputError.h"
#include "game/analysis/AnalysisOutput.h"
#include "game/analysis/TrialLoader.h"
#include "game/commands/AnalyzeOptions.h"
#include "game/commands/CommandUsage.h"
#include "game/commands/ExitCode.h"

namespace hemiroll::game {

int runAnalyzeCommand(const std::vector<std::string>& args) {
  const AnalyzeOptionsResult parsed = parseAnalyzeOptions(args);
  if (const std::optional<int> exit = exitBeforeRunning("hemiroll analyze: ", parsed, analyzeUsage())) return *exit;
  const AnalyzeOptions& o = parsed.options;

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
