#pragma once
// Which group and block order a participant gets (docs/PROTOCOLS.md
// "Groups and counterbalancing"), decided once, when their first session
// starts, and kept in every session's manifest after that.
//
// - assignment = "participants_file": the participants file's `group`, and
//   its `order` or, where it gives none, the participant's rank among the
//   file's rows of that group, cycled through the orders.
// - assignment = "balanced" (by arrival): the group with the fewest
//   participants so far (ties: the first in the file), then that group's
//   least used order (ties: the first). The participants so far are those
//   with a session manifest in the experiment's folder. For participants
//   who arrive one after the other and all finish, the k-th (0-based) gets
//   group k mod G and order (k div G) mod R.
// A participant who already has a session of this experiment keeps its
// group and order.

#include <filesystem>
#include <string>

#include "engine/record/TrialMeta.h"
#include "engine/task/ProtocolDef.h"

namespace hemiroll::game {

struct ParticipantAssignment {
  std::string group;     // "" when the protocol has no groups
  int order = 1;         // 1-based block order (1 when nothing is counterbalanced)
  std::string how;       // one phrase: where the group came from
  record::Fields info;   // the participants file's own columns for this participant
};

// Throws SessionError (BadInput) for a participants file that does not
// check out or does not list the participant.
ParticipantAssignment assignParticipant(const task::ProtocolDef& protocol,
                                        const std::filesystem::path& experimentFolder,
                                        const std::string& participant, const std::string& session);

}  // namespace hemiroll::game
