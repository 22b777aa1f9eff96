#include "engine/record/TrialMeta.h"

namespace hemiroll::record {

#ifndef HEMIROLL_VERSION
#define HEMIROLL_VERSION "unknown"
#endif

const char* softwareVersion() { return HEMIROLL_VERSION; }

}  // namespace hemiroll::record
