#include "engine/record/RecordingReader.h"

#include <string_view>

#include "engine/files/CheckedFile.h"
#include "engine/files/FileReadError.h"
#include "engine/files/LineReader.h"
#include "engine/files/PrintableName.h"
#include "engine/record/CsvRowFormat.h"
#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"

namespace hemiroll::record {

bool RecordingReader::forEachRow(const std::filesystem::path& csvPath, const ReadOptions& options,
                                 const std::function<void(const haptics::RecordRow&)>& row) {
  const std::string where = files::printablePath(csvPath) + ": line ";
  try {
    files::CheckedFile file(csvPath, files::kSampleTable);
    files::LineReader lines(file, kMaxLineBytes);
    std::string_view line;
    bool complete = false;
    if (!lines.next(line, complete) || !complete)
      throw RecordError(where + "1: missing or incomplete header (an empty or cut-off file)");
    const auto is = [&line](const std::string& header) {
      return line == std::string_view(header).substr(0, header.size() - 1);
    };
    if (!is(CsvRowFormat::header()) && !is(CsvRowFormat::headerBeforeGuidance()))
      throw RecordError(where + "1: the header is not this build's trial CSV header");
    haptics::RecordRow parsed;
    while (lines.next(line, complete)) {
      if (!complete) {
        // No newline: the writer was interrupted in the middle of this row.
        if (!options.allowTruncatedTail)
          throw RecordError(where + std::to_string(lines.lineNumber()) +
                            ": incomplete last line (the file ends mid-row: an interrupted recording?)");
        return true;
      }
      parsed = haptics::RecordRow{};
      const std::string problem = CsvRowFormat::parse(line, parsed);
      if (!problem.empty()) throw RecordError(where + std::to_string(lines.lineNumber()) + ": " + problem);
      row(parsed);
    }
    return false;
  } catch (const files::FileReadError& e) {
    throw RecordError(e.what());
  }
}

std::vector<haptics::RecordRow> RecordingReader::loadCsv(const std::filesystem::path& csvPath,
                                                         const ReadOptions& options, bool* truncatedTail) {
  std::vector<haptics::RecordRow> rows;
  const bool cut = forEachRow(csvPath, options, [&rows](const haptics::RecordRow& r) { rows.push_back(r); });
  if (truncatedTail) *truncatedTail = cut;
  return rows;
}

void RecordingReader::loadSidecar(const std::filesystem::path& csvPath, TrialMeta& meta, SidecarStatus& status) {
  std::filesystem::path sidecarPath = csvPath;
  sidecarPath.replace_extension(".json");
  Sidecar::fromJson(readWholeFile(sidecarPath, files::kSidecar), files::printablePath(sidecarPath), meta, status);
}

Recording RecordingReader::load(const std::filesystem::path& csvPath, const ReadOptions& options) {
  Recording r;
  loadSidecar(csvPath, r.meta, r.status);
  r.rows = loadCsv(csvPath, options, &r.truncatedTail);
  if (r.status.complete && r.status.rows != r.rows.size())
    throw RecordError(files::printablePath(csvPath) + ": holds " + std::to_string(r.rows.size()) +
                      " rows, its sidecar says " + std::to_string(r.status.rows));
  return r;
}

}  // namespace hemiroll::record
