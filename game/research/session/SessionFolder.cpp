#include "game/research/session/SessionFolder.h"

#include <cstdio>

#include "engine/record/DataDirectory.h"
#include "engine/task/ProtocolDef.h"

namespace hemiroll::game {

std::filesystem::path defaultSessionsRoot() { return record::dataDirectory() / "sessions"; }

std::string checkFolderId(const std::string& id, const char* what) {
  if (task::isFolderName(id)) return "";
  return std::string("the ") + what + " '" + id + "' must be 1 to 64 letters, digits, '-' or '_' (it names a folder)";
}

std::filesystem::path sessionFolder(const std::filesystem::path& dataRoot, const std::string& experiment,
                                    const std::string& participant, const std::string& session) {
  return dataRoot / experiment / participant / session;
}

std::string sessionTrialId(int index) {
  char text[32];
  std::snprintf(text, sizeof text, "trial-%03d", index);
  return text;
}

}  // namespace hemiroll::game
