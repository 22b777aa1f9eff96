#pragma once
// A lab's participants file (docs/PROTOCOLS.md "Groups"): tab-separated,
// BIDS-like, one line per participant.
//
//   participant_id  group    order  age  handedness
//   p01             guided   1      24   right
//
// participant_id (first, required) is the id given to `session
// --participant`; group names one of the protocol's groups and order a
// block order (1 .. the protocol's order count), both only when the
// protocol assigns from the file; every other column is the lab's own and
// travels, as text, into the session's manifest and the BIDS export's
// participants.tsv. Empty cells and "n/a" are missing values.

#include <string>
#include <vector>

#include "engine/record/TrialMeta.h"
#include "engine/task/ProtocolDef.h"

namespace hemiroll::game {

struct ParticipantRow {
  int line = 0;              // 1-based line in the file
  std::string id;
  std::string group;         // "" without a group column
  int order = 0;             // 0 = no order column (or n/a)
  int rankInGroup = 0;       // 1-based: the how-manieth row of its group (of the file when no groups)
  record::Fields columns;    // the lab's own columns (not participant_id, group, order), in file order
};

struct ParticipantsTable {
  std::string source;
  std::vector<std::string> header;
  std::vector<ParticipantRow> rows;

  const ParticipantRow* find(const std::string& id) const;
};

// Reads and checks the file against `protocol` (its groups, assignment and
// order count). Throws SessionError (BadInput) with one sentence
// "FILE:LINE: column 'NAME': what is wrong" (or "FILE: ..." for the file).
ParticipantsTable readParticipantsFile(const std::string& path, const task::ProtocolDef& protocol);

}  // namespace hemiroll::game
