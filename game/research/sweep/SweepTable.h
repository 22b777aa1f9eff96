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

#include "game/research/sweep/PointMeasurement.h"
#include "game/research/sweep/SweepGrid.h"

namespace hemiroll::game {

const std::vector<std::string>& sweepColumns();
// A row is about 1.5 kB (numbers and a sentence of notes); a line longer
// than this is not one this program wrote.
inline constexpr std::size_t kMaxSweepLineBytes = 64 * 1024;
// The header line, with its '\n'.
std::string sweepHeader();
// The point's row, with its '\n' (RFC 4180 quoting where a field needs it).
std::string sweepRow(const SweepPoint& point, const PointMeasurement& m);

// The index of a column in sweepColumns(); throws std::out_of_range for a
// name that is not one.
std::size_t sweepColumn(std::string_view name);

// "" when `fields` is a row as this program writes it: every column, the
// text columns from their vocabularies, every other cell empty or a finite
// number (a NaN or an infinity edited in is refused: the CSV never holds
// one). Otherwise one sentence naming the column and the cell.
std::string sweepRowProblem(const std::vector<std::string>& fields);

// A sweep CSV's rows (fields as text, header checked against
// sweepColumns(), every row checked by sweepRowProblem as it is read; the
// file through the checked reader, files::kSweepTable). Throws SweepError
// naming the file and line: environment when it cannot be read, bad input
// when it is not this program's sweep CSV.
std::vector<std::vector<std::string>> readSweepRows(const std::filesystem::path& csv);

}  // namespace hemiroll::game
