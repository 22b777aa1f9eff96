#include "engine/record/RecordingReader.h"

#include <string_view>

#include "engine/record/CsvRowFormat.h"
#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"

namespace hemiroll::record {

namespace {

std::string_view withoutCarriageReturn(std::string_view line) {
  return !line.empty() && line.back() == '\r' ? line.substr(0, line.size() - 1) : line;
}

}  // namespace

std::vector<haptics::RecordRow> RecordingReader::loadCsv(const std::filesystem::path& csvPath,
                                                         const ReadOptions& options, bool* truncatedTail) {
  const std::string text = readWholeFile(csvPath);
  const std::string where = csvPath.string() + ": line ";
  const std::size_t headerEnd = text.find('\n');
  if (headerEnd == std::string::npos)
    throw RecordError(where + "1: missing or incomplete header (an empty or cut-off file)");
  const std::string_view firstLine = withoutCarriageReturn(std::string_view(text).substr(0, headerEnd));
  const auto is = [&firstLine](const std::string& header) {
    return firstLine == std::string_view(header).substr(0, header.size() - 1);
  };
  if (!is(CsvRowFormat::header()) && !is(CsvRowFormat::headerBeforeGuidance()))
    throw RecordError(where + "1: the header is not this build's trial CSV header");

  std::vector<haptics::RecordRow> rows;
  if (truncatedTail) *truncatedTail = false;
  std::size_t lineNumber = 1;
  for (std::size_t start = headerEnd + 1; start < text.size();) {
    ++lineNumber;
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) {
      // No newline: the writer was interrupted in the middle of this row.
      if (!options.allowTruncatedTail)
        throw RecordError(where + std::to_string(lineNumber) +
                          ": incomplete last line (the file ends mid-row: an interrupted recording?)");
      if (truncatedTail) *truncatedTail = true;
      break;
    }
    haptics::RecordRow row;
    const std::string problem =
        CsvRowFormat::parse(withoutCarriageReturn(std::string_view(text).substr(start, end - start)), row);
    if (!problem.empty()) throw RecordError(where + std::to_string(lineNumber) + ": " + problem);
    rows.push_back(row);
    start = end + 1;
  }
  return rows;
}

Recording RecordingReader::load(const std::filesystem::path& csvPath, const ReadOptions& options) {
  Recording r;
  std::filesystem::path sidecarPath = csvPath;
  sidecarPath.replace_extension(".json");
  Sidecar::fromJson(readWholeFile(sidecarPath), sidecarPath.string(), r.meta, r.status);
  r.rows = loadCsv(csvPath, options, &r.truncatedTail);
  if (r.status.complete && r.status.rows != r.rows.size())
    throw RecordError(csvPath.string() + ": holds " + std::to_string(r.rows.size()) + " rows, its sidecar says " +
                      std::to_string(r.status.rows));
  return r;
}

}  // namespace hemiroll::record
