#include "engine/task/LevelDef.h"

namespace hemiroll::task {

const char* medalName(Medal medal) {
  switch (medal) {
    case Medal::None: return "none";
    case Medal::Bronze: return "bronze";
    case Medal::Silver: return "silver";
    case Medal::Gold: return "gold";
  }
  return "none";
}

}  // namespace hemiroll::task
