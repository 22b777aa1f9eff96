#pragma once
// Names that become files: what a recording, a ghost or a saved replay may
// be called. One rule set, so that a name accepted in one place is not
// refused (or spelled differently) in another. (An experiment's or a
// participant's id, which names a session folder, is checked where the
// protocol is read: task::isFolderName.)

#include <string>
#include <string_view>

namespace hemiroll::record {

// ASCII letters and digits only, whatever the locale: the same name on every
// machine. The BIDS labels keep just these.
inline bool isAsciiLetterOrDigit(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
}

// Letters, digits, '-', '_' and '.', not empty, not "." or "..": a name
// that cannot leave its folder (a trial id, TrialMeta).
bool isSafeFileName(std::string_view name);

// `text` with every character but ASCII letters, digits and those in
// `alsoKept` turned into '_'; `ifEmpty` when nothing is left.
std::string fileStemOf(std::string_view text, std::string_view alsoKept, std::string_view ifEmpty);

}  // namespace hemiroll::record
