#pragma once
// Counts C++ heap allocations (operator new) made on any thread while a
// scope is open; the binary's global operator new is replaced for this. The
// GL driver allocates through malloc and is not counted: the check is about
// our code (Renderer, sanitizer, geometry), which must not allocate per frame.

#include <cstddef>

namespace hemiroll::test {

class AllocationCounter {
 public:
  AllocationCounter();
  ~AllocationCounter();
  std::size_t count() const;
};

}  // namespace hemiroll::test
