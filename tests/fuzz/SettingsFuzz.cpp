// Fuzz target: settings.json (game/ui/settings/SettingsFile): whatever the file
// holds, loading gives settings and notes, never an exception.
#include "game/ui/settings/SettingsFile.h"
#include "tests/fuzz/FuzzInput.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  hemiroll::game::loadSettings(hemiroll::fuzz::inputFile(data, size, ".json"));
  return 0;
}
