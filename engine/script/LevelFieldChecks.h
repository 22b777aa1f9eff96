#pragma once
// Typed reads that level files need beyond LuaTableReader's: booleans,
// integers in a range, fixed-size number vectors, and an unknown-key check
// that points at the first unknown key (so its line can be found) and
// suggests the nearest allowed name ("did you mean 'tol'?").
//
// Every failure throws through LuaTableReader::fail: "source: path: message";
// DataFileLoader adds the line.

#include <array>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>

#include "engine/script/LuaTableReader.h"

namespace hemiroll::script {

// Throws at the first unknown key in sorted order (path = that key).
void rejectUnknownLevelKeys(const LuaTableReader& table, std::initializer_list<const char*> allowed);
// The same for a list built at run time (ProtocolLoader's keys with the overrides).
void rejectUnknownLevelKeys(const LuaTableReader& table, std::span<const char* const> allowed);

std::optional<bool> readBool(const LuaTableReader& table, const char* key);
// An integer-valued number in [lo, hi].
std::optional<int> readInteger(const LuaTableReader& table, const char* key, int lo, int hi);
// A number that must be > 0 (and finite).
std::optional<double> readPositive(const LuaTableReader& table, const char* key, const char* unit);
// A list of exactly N finite numbers {a, b[, c]}; `what` describes it for messages.
template <int N>
std::optional<std::array<double, N>> readVector(const LuaTableReader& table, const char* key, const char* what);

// "[n]", the path segment of a list position. Built by appending: GCC 12
// warns (-Wrestrict, a false positive) on "[" + std::string.
std::string positionKey(long long position);
// "[" + inner + "]" in the same way.
std::string bracketed(const std::string& inner);

// The closest name in `allowed` within edit distance 2, or nullptr.
const char* nearestName(std::string_view name, std::initializer_list<const char*> allowed);
const char* nearestName(std::string_view name, std::span<const char* const> allowed);

}  // namespace hemiroll::script
