#pragma once
// What every fuzz target shares: the libFuzzer entry point it defines, the
// input as text, and the input as a file for the loaders that read one.
//
// A target feeds its bytes to one parser or loader and catches exactly the
// errors that parser documents (its sentence for bad input). Anything else
// - another exception, a crash, a sanitizer report, a hang - is a finding:
// the exception escapes and aborts, which libFuzzer and the corpus runner
// both report with the input that did it.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace hemiroll::fuzz {

inline std::string_view textOf(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// The input written to a file of this process's own (rewritten per input),
// named with `extension` for loaders that care.
std::filesystem::path inputFile(const std::uint8_t* data, std::size_t size, const std::string& extension);

}  // namespace hemiroll::fuzz
