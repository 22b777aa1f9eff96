#include "engine/record/FileNames.h"

namespace hemiroll::record {

bool isSafeFileName(std::string_view name) {
  if (name.empty() || name == "." || name == "..") return false;
  for (const char c : name)
    if (!isAsciiLetterOrDigit(c) && c != '-' && c != '_' && c != '.') return false;
  return true;
}

std::string fileStemOf(std::string_view text, std::string_view alsoKept, std::string_view ifEmpty) {
  std::string stem;
  for (const char c : text) stem += isAsciiLetterOrDigit(c) || alsoKept.find(c) != std::string_view::npos ? c : '_';
  return stem.empty() ? std::string(ifEmpty) : stem;
}

}  // namespace hemiroll::record
