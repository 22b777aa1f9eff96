// Fuzz target: a bot file (engine/script/BotScript): loaded, initialised and
// asked for three ticks.
#include "engine/script/BotScript.h"
#include "engine/script/ScriptError.h"
#include "tests/fuzz/FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hemiroll::script;
  try {
    BotScript bot(hemiroll::fuzz::inputFile(data, size, ".lua").string());
    bot.init(BotLevelInfo{}, 0);
    BotObservation obs;
    for (int tick = 0; tick < 3; ++tick) {
      obs.time = 0.001 * tick;
      bot.act(obs);
    }
  } catch (const ScriptError&) {
  }
  return 0;
}
