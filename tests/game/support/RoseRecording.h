#pragma once
// A trial recording (engine/record's CSV + sidecar) of the paper's rose on
// the face, a trochoid on the plane and psi = -0.1 t, at 100 Hz: for the
// analysis glue's tests without running a level.

#include <filesystem>
#include <string>

namespace hemiroll::test {

// Writes <dir>/<id>.csv and .json with `rows` rows; `finished` false leaves
// the sidecar saying "complete": false (an interrupted trial). Returns the CSV.
std::filesystem::path writeRoseRecording(const std::filesystem::path& dir, const std::string& id, int rows,
                                         bool finished);

}  // namespace hemiroll::test
