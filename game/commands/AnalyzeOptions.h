#pragma once
// The flags of `hemiroll analyze`, parsed and checked before any file is read.

#include <optional>
#include <string>
#include <vector>

namespace hemiroll::game {

struct AnalyzeOptions {
  std::vector<std::string> inputs;        // trial CSVs, session folders, `hemiroll sim` CSVs
  std::optional<std::string> outDir;      // --out DIR
  bool plots = false;                     // --plots svg|none; svg by default when --out is given
  bool help = false;
};

struct AnalyzeOptionsResult {
  AnalyzeOptions options;
  std::string error;  // empty when the flags are good
};

AnalyzeOptionsResult parseAnalyzeOptions(const std::vector<std::string>& args);

const char* analyzeUsage();

}  // namespace hemiroll::game
