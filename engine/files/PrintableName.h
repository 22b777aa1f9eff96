#pragma once
// File names are bytes on Linux; messages, JSON and CSV want UTF-8 text.
// The one rule (docs/RECORDING.md): a name is shown as it is when it is
// valid UTF-8 without control characters; otherwise each byte that breaks
// that is written as \xNN (two hex digits), so the text is valid UTF-8,
// still points at the file, and JSON writers never see invalid bytes.

#include <filesystem>
#include <string>
#include <string_view>

namespace hemiroll::files {

// True when `text` is valid UTF-8 (no overlong forms, surrogates or code
// points past U+10FFFF) and holds no control character (< 0x20, 0x7F).
bool isPrintableUtf8(std::string_view text);

// `text` with every byte that is not part of a valid, printable UTF-8
// sequence written as \xNN.
std::string printable(std::string_view text);
// `text` with every byte that is not part of a valid UTF-8 sequence written
// as \xNN; control characters are kept (a JSON writer escapes those its
// own way).
std::string validUtf8(std::string_view text);
inline std::string printablePath(const std::filesystem::path& path) { return printable(path.native()); }

}  // namespace hemiroll::files
