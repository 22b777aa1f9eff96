#pragma once
// The trial CSV's columns and the one code path that turns a RecordRow into a
// line and back. Column names carry their SI unit as a suffix (time_s,
// Fh_x_N, ...; see docs/RECORDING.md). Doubles are written in the shortest
// form that reads back to the identical bits (std::to_chars), so a reader
// gets exactly what the servo loop computed; enums are integer codes (names
// in the sidecar's "codes").

#include <string>
#include <string_view>
#include <vector>

#include "engine/haptics/RecordRow.h"

namespace hemiroll::record {

// How many codes each enum column has (the last enumerator + 1; the
// static_asserts in CsvRowFormat.cpp fail when an enum grows at the end).
inline constexpr int kEventCodes = 4;       // physics::DomainEvent
inline constexpr int kEngagementCodes = 4;  // haptics::Engagement
inline constexpr int kFaultCodes = 12;      // haptics::SafetyFault

// Files written before guidance (issue 14) end at force_clamped; they read
// back with a zero guidance force.
inline constexpr std::size_t kColumnsBeforeGuidance = 38;

class CsvRowFormat {
 public:
  static const std::vector<std::string>& columns();
  // The header line, with its '\n'.
  static std::string header();
  // The header of a file written before the guidance columns, with its '\n'.
  static std::string headerBeforeGuidance();
  // This build's columns, or the ones before guidance.
  static bool knownColumns(const std::vector<std::string>& names);
  // Appends the row as one line, with its '\n'.
  static void append(const haptics::RecordRow& row, std::string& out);
  // One line without its '\n' (this build's layout or the one before
  // guidance). Empty string when it parsed, else what is wrong (naming the column).
  static std::string parse(std::string_view line, haptics::RecordRow& row);
};

// RFC 4180: a field holding a comma, a quote or a line break is quoted,
// its quotes doubled; csvLine joins fields with commas and ends the line.
std::string csvField(const std::string& field);
std::string csvLine(const std::vector<std::string>& fields);

// Shortest round-trip text of a double (std::to_chars), appended.
void appendDouble(double value, std::string& out);
// Exactly one double filling the whole text; false otherwise.
bool parseDouble(std::string_view text, double& value);

}  // namespace hemiroll::record
