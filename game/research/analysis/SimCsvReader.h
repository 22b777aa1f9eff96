#pragma once
// Reads the CSV that `hemiroll sim` writes (docs/SCENARIOS.md, "Output"):
// a header naming at least t, x_p, y_p, u_a, v_a and psi, then rows of
// numbers. An error names the file, the line and the column.

#include <filesystem>
#include <string>

#include "game/research/analysis/TrialData.h"

namespace hemiroll::game {

// True when the CSV's first line is a `hemiroll sim` header.
bool isSimCsvHeader(const std::string& firstLine);

// A partial last line (a run killed while writing) is dropped with a note.
// Throws AnalysisInputError.
TrialData readSimCsv(const std::filesystem::path& path);

}  // namespace hemiroll::game
