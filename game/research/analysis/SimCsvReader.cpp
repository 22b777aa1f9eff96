#include "game/research/analysis/SimCsvReader.h"

#include <array>
#include <string_view>

#include "engine/files/CheckedFile.h"
#include "engine/files/FileReadError.h"
#include "engine/files/LineReader.h"
#include "engine/files/PrintableName.h"
#include "engine/record/CsvRowFormat.h"
#include "game/research/analysis/AnalysisInputError.h"

namespace hemiroll::game {

namespace {

constexpr std::array<const char*, 6> kNeeded = {"t", "x_p", "y_p", "u_a", "v_a", "psi"};

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (std::size_t comma = line.find(','); comma != std::string_view::npos; comma = line.find(',', start)) {
    out.push_back(line.substr(start, comma - start));
    start = comma + 1;
  }
  out.push_back(line.substr(start));
  return out;
}

// A sim CSV row is a few dozen numbers; a line longer than this is not one.
constexpr std::size_t kMaxSimLineBytes = 64 * 1024;

}  // namespace

bool isSimCsvHeader(const std::string& firstLine) {
  return std::string_view(firstLine).starts_with("t,x_p,y_p,");
}

// Read as a stream of bounded lines through the checked reader: memory
// holds the six columns, never the file.
TrialData readSimCsv(const std::filesystem::path& path) {
  const std::string where = files::printablePath(path) + ":";
  TrialData trial;
  trial.source = files::printablePath(path);
  trial.kind = "sim";
  try {
    files::CheckedFile file(path, files::kSampleTable);
    files::LineReader lines(file, kMaxSimLineBytes);
    std::string_view line;
    bool complete = false;
    if (!lines.next(line, complete) || !complete) throw AnalysisInputError(where + "1: missing or incomplete header");
    const std::vector<std::string_view> headerNames = split(line);
    const std::vector<std::string> names(headerNames.begin(), headerNames.end());
    std::array<std::size_t, kNeeded.size()> index{};
    for (std::size_t k = 0; k < kNeeded.size(); ++k) {
      index[k] = names.size();
      for (std::size_t c = 0; c < names.size(); ++c)
        if (names[c] == kNeeded[k]) index[k] = c;
      if (index[k] == names.size())
        throw AnalysisInputError(where + "1: no column '" + kNeeded[k] +
                                 "' (a `hemiroll sim` CSV has t, x_p, y_p, u_a, v_a, psi)");
    }
    std::array<std::vector<double>*, kNeeded.size()> columns = {&trial.time,     &trial.massX,    &trial.massY,
                                                                &trial.contactX, &trial.contactY, &trial.psi};
    while (lines.next(line, complete)) {
      const std::size_t lineNumber = lines.lineNumber();
      if (!complete) {
        trial.notes.push_back("line " + std::to_string(lineNumber) + ", the last, was cut off and is not used");
        break;
      }
      const std::vector<std::string_view> fields = split(line);
      if (fields.size() != names.size())
        throw AnalysisInputError(where + std::to_string(lineNumber) + ": " + std::to_string(fields.size()) +
                                 " fields, the header names " + std::to_string(names.size()));
      for (std::size_t k = 0; k < kNeeded.size(); ++k) {
        double value = 0.0;
        if (!record::parseDouble(fields[index[k]], value))
          throw AnalysisInputError(where + std::to_string(lineNumber) + ": column " + std::to_string(index[k] + 1) +
                                   " (" + kNeeded[k] + "): '" + std::string(fields[index[k]].substr(0, 40)) +
                                   "' is not a number");
        columns[k]->push_back(value);
      }
    }
  } catch (const files::FileReadError& e) {
    throw AnalysisInputError(e.what());
  }
  if (trial.time.empty()) throw AnalysisInputError(where + "2: no rows after the header");
  return trial;
}

}  // namespace hemiroll::game
