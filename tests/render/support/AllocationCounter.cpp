#include "tests/render/support/AllocationCounter.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<bool> counting{false};
std::atomic<std::size_t> allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size ? size : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace hemiroll::test {

AllocationCounter::AllocationCounter() {
  allocations.store(0);
  counting.store(true);
}
AllocationCounter::~AllocationCounter() { counting.store(false); }
std::size_t AllocationCounter::count() const { return allocations.load(); }

}  // namespace hemiroll::test
