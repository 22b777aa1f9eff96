#include "engine/record/TrialMeta.h"

#include <chrono>
#include <cstdio>
#include <ctime>

namespace hemiroll::record {

#ifndef HEMIROLL_VERSION
#define HEMIROLL_VERSION "unknown"
#endif

const char* softwareVersion() { return HEMIROLL_VERSION; }

std::string utcTimestamp() {
  const auto now = std::chrono::system_clock::now();
  const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
  std::tm tm{};
  gmtime_r(&seconds, &tm);
  char text[64];
  std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", tm.tm_year + 1900, tm.tm_mon + 1,
                tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec, static_cast<int>(ms));
  return text;
}

}  // namespace hemiroll::record
