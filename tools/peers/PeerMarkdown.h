#pragma once
// docs/PEERS.md from a study: what is compared, the settings, the targets
// (our RK4 at 1 ms against each engine's best setting), what it takes to
// reach 1 mm and 10 um, a table per scene, and what makes it unfair. Owns the
// wording; the numbers come from PeerReport's queries.

#include <string>

#include "tools/peers/PeerReport.h"

namespace hemiroll::tools::peers {

std::string peersMarkdown(const Study& study);

}  // namespace hemiroll::tools::peers
