#include "game/analysis/SimCsvReader.h"

#include <array>
#include <string_view>

#include "engine/record/CsvRowFormat.h"
#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "game/analysis/AnalysisInputError.h"

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

std::string_view withoutCarriageReturn(std::string_view line) {
  return !line.empty() && line.back() == '\r' ? line.substr(0, line.size() - 1) : line;
}

}  // namespace

bool isSimCsvHeader(const std::string& firstLine) {
  return std::string_view(firstLine).starts_with("t,x_p,y_p,");
}

TrialData readSimCsv(const std::filesystem::path& path) {
  std::string text;
  try {
    text = record::readWholeFile(path);
  } catch (const record::RecordError& e) {
    throw AnalysisInputError(e.what());
  }
  const std::string where = path.string() + ":";
  const std::size_t headerEnd = text.find('\n');
  if (headerEnd == std::string::npos) throw AnalysisInputError(where + "1: missing or incomplete header");
  const std::vector<std::string_view> names = split(withoutCarriageReturn(std::string_view(text).substr(0, headerEnd)));
  std::array<std::size_t, kNeeded.size()> index{};
  for (std::size_t k = 0; k < kNeeded.size(); ++k) {
    index[k] = names.size();
    for (std::size_t c = 0; c < names.size(); ++c)
      if (names[c] == kNeeded[k]) index[k] = c;
    if (index[k] == names.size())
      throw AnalysisInputError(where + "1: no column '" + kNeeded[k] + "' (a `hemiroll sim` CSV has t, x_p, y_p, u_a, v_a, psi)");
  }

  TrialData trial;
  trial.source = path.string();
  trial.kind = "sim";
  std::array<std::vector<double>*, kNeeded.size()> columns = {&trial.time,     &trial.massX,    &trial.massY,
                                                              &trial.contactX, &trial.contactY, &trial.psi};
  std::size_t lineNumber = 1;
  for (std::size_t start = headerEnd + 1; start < text.size();) {
    ++lineNumber;
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) {
      trial.notes.push_back("line " + std::to_string(lineNumber) + ", the last, was cut off and is not used");
      break;
    }
    const std::vector<std::string_view> fields = split(withoutCarriageReturn(std::string_view(text).substr(start, end - start)));
    if (fields.size() != names.size())
      throw AnalysisInputError(where + std::to_string(lineNumber) + ": " + std::to_string(fields.size()) +
                               " fields, the header names " + std::to_string(names.size()));
    for (std::size_t k = 0; k < kNeeded.size(); ++k) {
      double value = 0.0;
      if (!record::parseDouble(fields[index[k]], value))
        throw AnalysisInputError(where + std::to_string(lineNumber) + ": column " + std::to_string(index[k] + 1) + " (" +
                                 kNeeded[k] + "): '" + std::string(fields[index[k]]) + "' is not a number");
      columns[k]->push_back(value);
    }
    start = end + 1;
  }
  if (trial.time.empty()) throw AnalysisInputError(where + "2: no rows after the header");
  return trial;
}

}  // namespace hemiroll::game
