#include "game/research/session/SessionBotMemory.h"

#include <nlohmann/json.hpp>

#include <system_error>

#include "engine/files/FileKinds.h"
#include "engine/record/DurableFile.h"
#include "engine/record/RecordError.h"
#include "engine/script/ScriptError.h"
#include "game/research/session/SessionError.h"

namespace hemiroll::game {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

namespace {

constexpr const char* kFormat = "hemiroll-bot-memory";

json entriesOf(const script::BotMemory& memory) {
  json j = json::object();
  for (const auto& [name, value] : memory.entries()) j[name] = value;
  return j;
}

script::BotMemory memoryOf(const json& j) {
  script::BotMemory memory;
  for (const auto& [name, value] : j.items()) memory.set(name, value.get<double>());
  return memory;
}

[[noreturn]] void environment(const std::string& message) {
  throw SessionError(SessionError::Kind::Environment, message);
}

}  // namespace

void writeBotMemory(const fs::path& folder, int afterTrial, const script::BotMemory& after,
                    const script::BotMemory& before) {
  json j;
  j["format"] = kFormat;
  j["format_version"] = 1;
  j["after_trial"] = afterTrial;
  j["memory"] = entriesOf(after);
  j["before"] = entriesOf(before);
  try {
    record::writeFileAtomically(folder / kBotMemoryFile, j.dump(2) + "\n");
  } catch (const record::RecordError& e) {
    environment(e.what());
  }
}

script::BotMemory restoreBotMemory(const fs::path& folder, int done, std::string& note) {
  const fs::path path = folder / kBotMemoryFile;
  std::error_code ec;
  if (!fs::exists(path, ec)) {
    if (done > 0)
      note = "this session kept no bot memory before (begun by an earlier version, or its bot keeps none): the bot "
             "goes on with an empty memory";
    return {};
  }
  try {
    const json j = json::parse(record::readWholeFile(path, files::kBotMemory));
    if (j.at("format").get<std::string>() != kFormat || j.at("format_version").get<int>() != 1)
      environment(path.string() + ": not a bot memory of format version 1");
    const int after = j.at("after_trial").get<int>();
    if (after == done) return memoryOf(j.at("memory"));
    if (after == done + 1) return memoryOf(j.at("before"));  // that trial runs again
    environment(path.string() + ": holds the memory after trial " + std::to_string(after) + ", but " +
                std::to_string(done) + " trials are done: the folder was changed by hand");
  } catch (const json::exception& e) {
    environment(path.string() + ": not a readable bot memory (" + e.what() + ")");
  } catch (const record::RecordError& e) {
    environment(e.what());
  } catch (const script::ScriptError& e) {
    environment(path.string() + ": " + e.what());
  }
}

}  // namespace hemiroll::game
