#include "game/research/session/ParticipantsFile.h"

#include <algorithm>
#include <charconv>
#include <iterator>

#include "engine/files/FileKinds.h"
#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "game/research/session/SessionError.h"

namespace hemiroll::game {

namespace {

[[noreturn]] void badInput(const std::string& message) { throw SessionError(SessionError::Kind::BadInput, message); }

std::vector<std::string> splitTabs(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t tab = line.find('\t', start);
    cells.push_back(line.substr(start, tab == std::string::npos ? std::string::npos : tab - start));
    if (tab == std::string::npos) return cells;
    start = tab + 1;
  }
}

bool missing(const std::string& cell) { return cell.empty() || cell == "n/a"; }

std::string groupNames(const task::ProtocolDef& protocol) {
  std::string names;
  for (const task::GroupDef& g : protocol.groups) names += (names.empty() ? "'" : ", '") + g.name + "'";
  return names;
}

}  // namespace

const ParticipantRow* ParticipantsTable::find(const std::string& id) const {
  for (const ParticipantRow& row : rows)
    if (row.id == id) return &row;
  return nullptr;
}

namespace {

// The file's lines without their line ends ('\n' or "\r\n"), the trailing
// empty lines dropped.
std::vector<std::string> participantsFileLines(const std::string& path) {
  std::string text;
  try {
    text = record::readWholeFile(path, files::kParticipants);
  } catch (const record::RecordError& e) {
    badInput(e.what());
  }
  std::vector<std::string> lines;
  for (std::size_t start = 0; start < text.size();) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
    start = end + 1;
  }
  while (!lines.empty() && lines.back().empty()) lines.pop_back();
  if (lines.empty()) badInput(path + ": empty; the first line names the columns, starting with participant_id");
  return lines;
}

std::string columnAt(const std::string& path, int line, const std::string& column) {
  return path + ":" + std::to_string(line) + ": column '" + column + "': ";
}

// Where the header puts the columns hemiroll reads (-1: absent).
struct KnownColumns {
  int group = -1, order = -1;
};

// The header's columns into table.header, each name checked; the group and
// order columns held to the protocol's way of assigning.
KnownColumns readHeader(const std::string& firstLine, const task::ProtocolDef& protocol, ParticipantsTable& table) {
  const std::string& path = table.source;
  const bool fromFile = protocol.assignment == task::Assignment::ParticipantsFile;
  table.header = splitTabs(firstLine);
  // A file saved by a spreadsheet may start with a byte-order mark: not part
  // of the first column's name.
  if (table.header[0].rfind("\xEF\xBB\xBF", 0) == 0) table.header[0].erase(0, 3);
  if (table.header[0] != "participant_id")
    badInput(columnAt(path, 1, table.header[0]) + "the first column must be participant_id (tab-separated columns)");
  KnownColumns known;
  for (std::size_t c = 0; c < table.header.size(); ++c) {
    const std::string& name = table.header[c];
    if (name.empty()) badInput(path + ":1: column " + std::to_string(c + 1) + " has no name");
    if (std::count(table.header.begin(), table.header.end(), name) > 1)
      badInput(columnAt(path, 1, name) + "named twice");
    // The names hemiroll writes beside the lab's columns (BIDS participants,
    // analyze's trials.csv): a lab column so named would clash with them.
    static const char* const kReserved[] = {"participant", "session", "block_order", "assigned_by", "trial",
                                            "trial_index", "trial_id", "block", "block_name", "trial_in_block",
                                            "condition", "condition_label", "outcome", "success", "time_s",
                                            "score", "level", "level_file", "seed", "guidance"};
    if (std::find(std::begin(kReserved), std::end(kReserved), name) != std::end(kReserved))
      badInput(columnAt(path, 1, name) + "a name hemiroll writes itself (in BIDS participants.tsv and analyze's trials.csv); "
               "rename the column (e.g. 'lab_" + name + "')");
    if (name == "group") known.group = static_cast<int>(c);
    if (name == "order") known.order = static_cast<int>(c);
  }
  if (fromFile && known.group < 0)
    badInput(path + ":1: no 'group' column; the protocol assigns groups from this file (assignment = "
                    "\"participants_file\"): add a group column with one of " + groupNames(protocol));
  if (!fromFile && (known.group >= 0 || known.order >= 0))
    badInput(columnAt(path, 1, known.group >= 0 ? "group" : "order") +
             "the protocol assigns groups and orders by arrival (assignment = \"balanced\"): remove the column, or "
             "give the protocol assignment = \"participants_file\"");
  return known;
}

// One participant's line (lineNo counts from 1), checked against the
// protocol and the rows before it; perGroup counts the rows per group so far
// (the last entry: no group column).
ParticipantRow readRow(const std::string& line, int lineNo, KnownColumns known, const task::ProtocolDef& protocol,
                       const ParticipantsTable& table, std::vector<int>& perGroup) {
  const std::string& path = table.source;
  if (line.empty()) badInput(path + ":" + std::to_string(lineNo) + ": an empty line (remove it)");
  const std::vector<std::string> cells = splitTabs(line);
  if (cells.size() != table.header.size())
    badInput(path + ":" + std::to_string(lineNo) + ": " + std::to_string(cells.size()) + " columns, the header has " +
             std::to_string(table.header.size()) + " (columns are separated by tabs)");
  ParticipantRow row;
  row.line = lineNo;
  row.id = cells[0];
  if (!task::isFolderName(row.id))
    badInput(columnAt(path, lineNo, "participant_id") + "'" + row.id +
             "' is not a participant id: use 1 to 64 letters, digits, '-' or '_' (the id given to --participant)");
  if (const ParticipantRow* other = table.find(row.id))
    badInput(columnAt(path, lineNo, "participant_id") + "'" + row.id + "' is listed twice (also on line " +
             std::to_string(other->line) + ")");
  std::size_t groupIndex = protocol.groups.size();
  if (known.group >= 0) {
    row.group = cells[static_cast<std::size_t>(known.group)];
    if (missing(row.group)) badInput(columnAt(path, lineNo, "group") + "missing; one of " + groupNames(protocol));
    const auto found = std::find_if(protocol.groups.begin(), protocol.groups.end(),
                                    [&](const task::GroupDef& g) { return g.name == row.group; });
    if (found == protocol.groups.end())
      badInput(columnAt(path, lineNo, "group") + "no group '" + row.group + "' in the protocol (its groups: " +
               groupNames(protocol) + ")");
    groupIndex = static_cast<std::size_t>(found - protocol.groups.begin());
  }
  if (known.order >= 0) {
    const std::string& text = cells[static_cast<std::size_t>(known.order)];
    if (!missing(text)) {
      int value = 0;
      const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
      if (error != std::errc() || end != text.data() + text.size() || value < 1 || value > protocol.orderCount())
        badInput(columnAt(path, lineNo, "order") + "'" + text + "' is not a block order: a whole number from 1 to " +
                 std::to_string(protocol.orderCount()) + " (the protocol's counterbalanced orders)");
      row.order = value;
    }
  }
  row.rankInGroup = ++perGroup[groupIndex];
  for (std::size_t c = 1; c < cells.size(); ++c)
    if (static_cast<int>(c) != known.group && static_cast<int>(c) != known.order)
      row.columns.emplace_back(table.header[c], missing(cells[c]) ? std::string() : cells[c]);
  return row;
}

}  // namespace

ParticipantsTable readParticipantsFile(const std::string& path, const task::ProtocolDef& protocol) {
  ParticipantsTable table;
  table.source = path;
  const std::vector<std::string> lines = participantsFileLines(path);
  const KnownColumns known = readHeader(lines[0], protocol, table);
  std::vector<int> perGroup(protocol.groups.size() + 1, 0);
  for (std::size_t i = 1; i < lines.size(); ++i)
    table.rows.push_back(readRow(lines[i], static_cast<int>(i) + 1, known, protocol, table, perGroup));
  return table;
}

}  // namespace hemiroll::game
