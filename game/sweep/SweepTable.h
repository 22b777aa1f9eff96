#pragma once
// The sweep's CSV (docs/SWEEP.md, "The CSV"): one row per point, in point
// order, SI units in the column names. Numbers are the shortest text that
// reads back to the same double (std::to_chars), so a row is a function of
// the point's bits alone: the same on any thread count or shard split. A
// feature that was not found leaves its cells empty (its *_found cell says 0
// and `notes` says why); never NaN.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "game/sweep/PointMeasurement.h"
#include "game/sweep/SweepGrid.h"

namespace hemiroll::game {

const std::vector<std::string>& sweepColumns();
// The header line, with its '\n'.
std::string sweepHeader();
// The point's row, with its '\n' (RFC 4180 quoting where a field needs it).
std::string sweepRow(const SweepPoint& point, const PointMeasurement& m);

// The index of a column in sweepColumns(); throws std::out_of_range for a
// name that is not one.
std::size_t sweepColumn(std::string_view name);

// A sweep CSV's rows (fields as text, header checked against
// sweepColumns()). Throws SweepError naming the file: environment when it
// cannot be read, bad input when it is not this program's sweep CSV.
std::vector<std::vector<std::string>> readSweepRows(const std::filesystem::path& csv);

}  // namespace hemiroll::game
