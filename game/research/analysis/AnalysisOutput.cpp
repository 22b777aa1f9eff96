#include "game/research/analysis/AnalysisOutput.h"

#include <filesystem>
#include <system_error>

#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "game/research/analysis/FeaturesJson.h"
#include "game/research/analysis/TrialPlots.h"
#include "game/research/report/LinePlot.h"

namespace hemiroll::game {

OutputFiles analysisFiles(const std::vector<AnalysedTrial>& trials, bool plots) {
  OutputFiles files;
  for (const AnalysedTrial& t : trials) {
    const std::string& id = t.data.id;
    files.emplace_back(id + ".analysis.json", featuresJson(t.data, t.features, t.guidance));
    if (!plots) continue;
    files.emplace_back(id + ".overview.svg", overviewSheet(t.data, t.features));
    files.emplace_back(id + ".contact.svg", report::renderLinePlot(contactTracePlot(t.data, t.features)));
    files.emplace_back(id + ".mass_point.svg", report::renderLinePlot(massPointPlot(t.data, t.features)));
    files.emplace_back(id + ".psi.svg", report::renderLinePlot(precessionAnglePlot(t.data, t.features), 720, 420));
    files.emplace_back(id + ".channels.svg", report::renderLinePlot(channelsPlot(t.data), 720, 420));
  }
  files.emplace_back("analysis.csv", featureTableCsv(trials));
  files.emplace_back("analysis.md", featureTableMarkdown(trials));
  return files;
}

void writeOutputFiles(const std::string& dir, const OutputFiles& files) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir))
    throw record::RecordError(dir + ": cannot create the output folder (" + (ec ? ec.message() : "not a folder") + ")");
  for (const auto& [name, content] : files) record::writeFileAtomically(std::filesystem::path(dir) / name, content);
}

}  // namespace hemiroll::game
