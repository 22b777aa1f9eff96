#pragma once
// What a BIDS validator checks of a motion dataset that needs no schema
// files (the required files and their required columns and keys, the file
// names' entities, one channel per motion column): shared by the tests of
// `hemiroll bids` and of the whole study path.

#include <filesystem>
#include <string>
#include <vector>

namespace hemiroll::test {

std::string slurp(const std::filesystem::path& p);
std::vector<std::string> lines(const std::string& text);
// A TSV line's cells.
std::vector<std::string> cells(const std::string& line);

// gtest expectations on the dataset at `root` with `trials` motion recordings.
void expectValidBidsMotion(const std::filesystem::path& root, int trials);

}  // namespace hemiroll::test
