#include "tests/fuzz/FuzzInput.h"

#include <unistd.h>

#include <fstream>
#include <stdexcept>

namespace hemiroll::fuzz {

std::filesystem::path inputFile(const std::uint8_t* data, std::size_t size, const std::string& extension) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("hemiroll-fuzz-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::filesystem::path file = dir / ("input" + extension);
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  if (!out) throw std::runtime_error("fuzz: cannot write " + file.string());  // the machine, not the input
  return file;
}

}  // namespace hemiroll::fuzz
