#pragma once
// `hemiroll bids SESSION_OR_EXPERIMENT... --out DIR [--name NAME]`: session
// folders as a BIDS motion dataset (game/research/session/BidsDataset, RECORDING.md).

#include <string>
#include <vector>

namespace hemiroll::game {

int runBidsCommand(const std::vector<std::string>& args);

}  // namespace hemiroll::game
