#include "engine/record/ResultsFile.h"

#include <system_error>

#include "engine/files/CheckedFile.h"
#include "engine/files/FileReadError.h"
#include "engine/files/PrintableName.h"
#include "engine/record/CsvRowFormat.h"
#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"

namespace hemiroll::record {

namespace {

std::string number(double v) {
  std::string s;
  appendDouble(v, s);
  return s;
}

// Characters of RFC 4180 text, from a string or from a checked file a
// chunk at a time.
class CsvSource {
 public:
  explicit CsvSource(const std::string& text) : text_(&text) {}
  explicit CsvSource(files::CheckedFile& file) : file_(&file), chunk_(64 * 1024, '\0') {}
  // The next character, or -1 at the end.
  int get() {
    if (text_ != nullptr) return at_ < text_->size() ? static_cast<unsigned char>((*text_)[at_++]) : -1;
    if (at_ == filled_) {
      filled_ = file_->read(chunk_.data(), chunk_.size());
      at_ = 0;
      if (filled_ == 0) return -1;
    }
    return static_cast<unsigned char>(chunk_[at_++]);
  }
  int peek() {
    const int c = get();
    if (c >= 0) --at_;
    return c;
  }
  std::size_t position() const { return text_ != nullptr ? at_ : 0; }

 private:
  const std::string* text_ = nullptr;
  files::CheckedFile* file_ = nullptr;
  std::string chunk_;
  std::size_t at_ = 0, filled_ = 0;
};

enum class Record { Whole, Cut, None, TooLong };

// One record from `in`: its fields, the line count moved past its line
// end. None at the end of the text, Cut when the text ends before the line
// end, TooLong past maxBytes (the fields then hold what was read).
Record readRecord(CsvSource& in, std::vector<std::string>& fields, int& line, std::size_t maxBytes) {
  fields.assign(1, std::string());
  bool quoted = false;
  std::size_t bytes = 0;
  for (int c = in.get(); c >= 0; c = in.get()) {
    if (++bytes > maxBytes) return Record::TooLong;
    if (quoted) {
      if (c != '"') {
        line += c == '\n';
        fields.back() += static_cast<char>(c);
      } else if (in.peek() == '"') {
        fields.back() += '"';
        in.get();
      } else {
        quoted = false;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else if (c == '\n') {
      ++line;
      return Record::Whole;
    } else if (c != '\r') {
      fields.back() += static_cast<char>(c);
    }
  }
  return bytes == 0 ? Record::None : Record::Cut;
}

}  // namespace

std::optional<std::vector<std::string>> parseCsvLine(const std::string& line) {
  std::vector<std::string> fields;
  CsvSource in(line);
  int lineNumber = 1;
  if (readRecord(in, fields, lineNumber, line.size()) != Record::Whole || in.position() != line.size())
    return std::nullopt;
  return fields;
}

void ResultsFile::forEachRow(std::vector<std::string>& columns,
                             const std::function<void(const std::vector<std::string>&, int)>& row) const {
  columns.clear();
  std::error_code ec;
  if (!std::filesystem::exists(path_, ec) && !std::filesystem::is_symlink(path_, ec)) return;
  // Anything but a regular file in its place (a folder, a FIFO, a device) is
  // refused by the checked reader: read as empty, a resume would take every
  // finished trial for an interrupted one and move it aside.
  try {
    files::CheckedFile file(path_, kind_);
    CsvSource in(file);
    int line = 1;
    std::vector<std::string> fields;
    for (;;) {
      const int first = line;
      const Record r = readRecord(in, fields, line, kMaxRecordBytes);
      if (r == Record::None) break;
      if (r == Record::TooLong)
        throw RecordError(files::printablePath(path_) + ": line " + std::to_string(first) + ": a row longer than " +
                          files::describeSize(kMaxRecordBytes) + " (not a table this program wrote)");
      if (r == Record::Cut)
        throw RecordError(files::printablePath(path_) + ": line " + std::to_string(first) +
                          ": the last row has no line end (a write was cut short)");
      if (columns.empty()) {
        columns = fields;
      } else if (fields.size() != columns.size()) {
        throw RecordError(files::printablePath(path_) + ": line " + std::to_string(first) + ": " +
                          std::to_string(fields.size()) + " fields, the header has " + std::to_string(columns.size()));
      } else {
        row(fields, first);
      }
    }
  } catch (const files::FileReadError& e) {
    throw RecordError(std::string(e.what()) + "; move it away and run again");
  }
}

ResultsTable ResultsFile::read() const {
  ResultsTable table;
  forEachRow(table.columns, [&table](const std::vector<std::string>& fields, int) { table.rows.push_back(fields); });
  return table;
}

std::vector<std::string> ResultsFile::columns(const ResultsRow& r) {
  std::vector<std::string> c = {"participant", "session", "trial",     "level",        "level_hash",
                                "outcome",     "reason",  "duration_s", "score",       "rows",
                                "dropped_rows", "start_time"};
  for (const auto& [key, value] : r.extra) c.push_back(key);
  return c;
}

void ResultsFile::checkColumns(const ResultsRow& r) const {
  const std::string header = csvLine(columns(r));
  std::error_code ec;
  if (!std::filesystem::exists(path_, ec) && !std::filesystem::is_symlink(path_, ec)) return;
  // The header already there must be this row's: a session resumed with
  // other extra columns would otherwise misalign every later row. Only the
  // header's bytes are read.
  std::string existing(header.size(), '\0');
  try {
    files::CheckedFile file(path_, kind_);
    if (file.size() == 0) return;
    std::size_t filled = 0;
    while (filled < existing.size()) {
      const std::size_t n = file.read(existing.data() + filled, existing.size() - filled);
      if (n == 0) break;
      filled += n;
    }
    existing.resize(filled);
  } catch (const files::FileReadError& e) {
    throw RecordError(std::string(e.what()) + "; move it away and run again");
  }
  if (existing != header)
    throw RecordError(path_.string() + ": line 1: the header differs from this result's columns (" +
                      header.substr(0, header.size() - 1) + ")");
}

void ResultsFile::append(const ResultsRow& r) const {
  const std::string header = csvLine(columns(r));
  checkColumns(r);
  std::error_code ec;
  const bool fresh = !std::filesystem::exists(path_, ec) || std::filesystem::file_size(path_, ec) == 0;
  std::vector<std::string> fields = {r.participant, r.session,      r.trialId, r.level,
                                     r.levelHash,   r.outcome,      r.reason,  number(r.duration),
                                     number(r.score), std::to_string(r.rows), std::to_string(r.droppedRows),
                                     r.startTime};
  for (const auto& [key, value] : r.extra) fields.push_back(value);
  appendDurably(path_, (fresh ? header : std::string()) + csvLine(fields));
}

}  // namespace hemiroll::record
