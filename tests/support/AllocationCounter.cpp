#include "tests/support/AllocationCounter.h"

#include <atomic>
#include <cstdlib>
#include <new>

namespace {
std::atomic<bool> gCounting{false};
std::atomic<long> gAllocations{0};
thread_local bool tCounting = false;
thread_local long tAllocations = 0;

void* allocate(std::size_t size) noexcept {
  if (gCounting.load(std::memory_order_relaxed)) gAllocations.fetch_add(1, std::memory_order_relaxed);
  if (tCounting) ++tAllocations;
  return std::malloc(size == 0 ? 1 : size);
}
void* allocateOrThrow(std::size_t size) {
  if (void* p = allocate(size)) return p;
  throw std::bad_alloc();
}
}  // namespace

// noinline: GCC otherwise inlines these into the standard containers and
// warns (falsely) that free() meets a pointer from operator new.
[[gnu::noinline]] void* operator new(std::size_t size) { return allocateOrThrow(size); }
[[gnu::noinline]] void* operator new[](std::size_t size) { return allocateOrThrow(size); }
[[gnu::noinline]] void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return allocate(size); }
[[gnu::noinline]] void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return allocate(size); }
[[gnu::noinline]] void operator delete(void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete[](void* p) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
[[gnu::noinline]] void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

namespace hemiroll::test {

AllocationCounter::AllocationCounter(Threads threads) : threads_(threads) {
  if (threads_ == Threads::All) {
    gAllocations.store(0);
  } else {
    tAllocations = 0;
  }
  resume();
}

AllocationCounter::~AllocationCounter() { pause(); }

void AllocationCounter::pause() {
  if (threads_ == Threads::All) gCounting.store(false);
  else tCounting = false;
}

void AllocationCounter::resume() {
  if (threads_ == Threads::All) gCounting.store(true);
  else tCounting = true;
}

long AllocationCounter::count() const { return threads_ == Threads::All ? gAllocations.load() : tAllocations; }

bool allocationCounterWorks() {
  for (const auto threads : {AllocationCounter::Threads::All, AllocationCounter::Threads::Calling}) {
    AllocationCounter counter(threads);
    void* volatile probe = ::operator new(16);
    counter.pause();
    ::operator delete(probe);
    if (counter.count() != 1) return false;
  }
  return true;
}

}  // namespace hemiroll::test
