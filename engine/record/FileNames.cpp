#include "engine/record/FileNames.h"

namespace hemiroll::record {

namespace {

// ASCII only, whatever the locale: the same name on every machine.
bool isLetterOrDigit(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'); }

}  // namespace

bool isSafeFileName(std::string_view name) {
  if (name.empty() || name == "." || name == "..") return false;
  for (const char c : name)
    if (!isLetterOrDigit(c) && c != '-' && c != '_' && c != '.') return false;
  return true;
}

std::string fileStemOf(std::string_view text, std::string_view alsoKept, std::string_view ifEmpty) {
  std::string stem;
  for (const char c : text) stem += isLetterOrDigit(c) || alsoKept.find(c) != std::string_view::npos ? c : '_';
  return stem.empty() ? std::string(ifEmpty) : stem;
}

}  // namespace hemiroll::record
