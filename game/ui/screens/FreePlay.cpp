#include "game/ui/screens/FreePlay.h"

#include "engine/record/ContentHash.h"
#include "engine/record/DataDirectory.h"
#include "game/ui/settings/Settings.h"
#include "game/ui/screens/ResultsScreen.h"
#include "game/ui/screens/ScreenHost.h"
#include "game/ui/screens/ScreenStack.h"

namespace hemiroll::game {

std::unique_ptr<PlaySession> FreePlay::begin(script::LoadedLevel& level, PlaySessionDef& def) {
  level = script::LevelLoader().loadFile(levelPath_);
  def.coupling = coupling(level.def);
  def.watchAutopilot = watch_;
  if (!host_.settings().overrideCoupling) {
    def.replayFile = record::dataDirectory() / "replays" / "last-trial.hrr";
    def.levelHash = record::fileContentHash(levelPath_);
  }
  return std::make_unique<PlaySession>(level, def);
}

physics::CouplingDef FreePlay::coupling(const task::LevelDef& level) const {
  return couplingFor(host_.settings(), level.coupling);
}

void FreePlay::finished(PlaySession& session, TrialResult result, const task::LevelDef& level,
                        TrialEnding ending) {
  std::string replayNote = session.replayError();
  if (host_.settings().overrideCoupling) replayNote = "no replay: the force method was overridden in the settings";
  auto results = std::make_unique<ResultsScreen>(host_, levelPath_, level.name, std::move(result), session.replayFile(),
                                                 replayNote, session.assisted(), std::move(ending));
  results->setPlaylist(playlist_);
  host_.screens().replace(std::move(results));
}

void FreePlay::leftWithoutTrial(const std::string& /*error*/) { host_.screens().pop(); }

}  // namespace hemiroll::game
