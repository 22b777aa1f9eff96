#pragma once
// Names that become files: what a recording, a ghost or a saved replay may
// be called. One rule set, so that a name accepted in one place is not
// refused (or spelled differently) in another.

#include <string>
#include <string_view>

namespace hemiroll::record {

// Letters, digits, '-', '_' and '.', not empty, not "." or "..": a name
// that cannot leave its folder (a trial id, TrialMeta).
bool isSafeFileName(std::string_view name);

// `text` with every character but ASCII letters, digits and those in
// `alsoKept` turned into '_'; `ifEmpty` when nothing is left.
std::string fileStemOf(std::string_view text, std::string_view alsoKept, std::string_view ifEmpty);

}  // namespace hemiroll::record
