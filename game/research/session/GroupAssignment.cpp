#include "game/research/session/GroupAssignment.h"

#include <algorithm>
#include <map>
#include <optional>
#include <system_error>

#include "engine/files/FileKinds.h"
#include "engine/record/DurableFile.h"
#include "game/research/session/ParticipantsFile.h"
#include "game/research/session/SessionError.h"
#include "game/research/session/SessionFolder.h"
#include "game/research/session/SessionManifest.h"

namespace hemiroll::game {

namespace fs = std::filesystem;

namespace {

// The group and order of the first readable manifest among `participantDir`'s
// sessions (other than `skip`), if any.
std::optional<std::pair<std::string, int>> earlierAssignment(const fs::path& participantDir, const std::string& skip) {
  std::error_code ec;
  std::vector<fs::path> sessions;
  for (const auto& entry : fs::directory_iterator(participantDir, ec))
    if (entry.is_directory(ec) && entry.path().filename() != skip && fs::is_regular_file(entry.path() / kManifestFile, ec))
      sessions.push_back(entry.path());
  std::sort(sessions.begin(), sessions.end());
  for (const fs::path& s : sessions) {
    try {
      const SessionManifest m =
          SessionManifest::fromJson(record::readWholeFile(s / kManifestFile, files::kSessionManifest), s.string());
      return std::make_pair(m.group, m.blockOrder);
    } catch (const std::exception&) {
      // A manifest that does not read is the resume's concern, not this count's.
    }
  }
  return std::nullopt;
}

}  // namespace

ParticipantAssignment assignParticipant(const task::ProtocolDef& protocol, const fs::path& experimentFolder,
                                        const std::string& participant, const std::string& session) {
  ParticipantAssignment a;
  std::optional<ParticipantsTable> table;
  const ParticipantRow* row = nullptr;
  if (!protocol.participantsFile.empty()) {
    table = readParticipantsFile(protocol.participantsFile, protocol);
    row = table->find(participant);
    if (row == nullptr)
      throw SessionError(SessionError::Kind::BadInput,
                         "participant '" + participant + "' is not in " + protocol.participantsFile +
                             "; add a line for them (participant_id first, tab-separated) before their first session");
    a.info = row->columns;
  }
  const int orders = protocol.orderCount();
  if (protocol.groups.empty() && orders == 1) {
    a.how = "no groups";
    return a;
  }
  if (protocol.assignment == task::Assignment::ParticipantsFile) {
    a.group = row->group;
    a.order = row->order > 0 ? row->order : (row->rankInGroup - 1) % orders + 1;
    a.how = protocol.participantsFile + ", line " + std::to_string(row->line);
    // A participant keeps their group and order across sessions: a file
    // edited since their first session is refused, not followed.
    if (const auto earlier = earlierAssignment(experimentFolder / participant, session);
        earlier && (earlier->first != a.group || earlier->second != a.order))
      throw SessionError(SessionError::Kind::BadInput,
                         protocol.participantsFile + ":" + std::to_string(row->line) + ": participant '" + participant +
                             "' is in group '" + a.group + "' with block order " + std::to_string(a.order) +
                             " there, but an earlier session of theirs ran in group '" + earlier->first +
                             "' with block order " + std::to_string(earlier->second) +
                             "; a participant keeps their group: correct the file, or start a new participant id");
    return a;
  }
  if (const auto earlier = earlierAssignment(experimentFolder / participant, session)) {
    a.group = earlier->first;
    a.order = earlier->second;
    a.how = "kept from the participant's earlier session";
    return a;
  }
  // Balanced by arrival: the least filled group, then its least used order.
  std::map<std::string, int> perGroup;
  std::map<std::pair<std::string, int>, int> perCell;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(experimentFolder, ec)) {
    if (!entry.is_directory(ec) || entry.path().filename() == participant) continue;
    if (const auto other = earlierAssignment(entry.path(), "")) {
      ++perGroup[other->first];
      ++perCell[*other];
    }
  }
  const std::size_t groupCount = protocol.groups.empty() ? 1 : protocol.groups.size();
  int fewest = -1;
  for (std::size_t g = 0; g < groupCount; ++g) {
    const std::string name = protocol.groups.empty() ? "" : protocol.groups[g].name;
    if (fewest < 0 || perGroup[name] < fewest) {
      fewest = perGroup[name];
      a.group = name;
    }
  }
  fewest = -1;
  for (int o = 1; o <= orders; ++o)
    if (fewest < 0 || perCell[{a.group, o}] < fewest) {
      fewest = perCell[{a.group, o}];
      a.order = o;
    }
  int before = 0;
  for (const auto& [group, count] : perGroup) before += count;
  a.how = "balanced by arrival: participant " + std::to_string(before + 1) + " of the experiment";
  return a;
}

}  // namespace hemiroll::game
