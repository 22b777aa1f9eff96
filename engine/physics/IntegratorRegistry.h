#pragma once
// Integrators by name, so that command-line flags, tools and levels select
// them with a string ("rk4") and a new method becomes available everywhere by
// registering it once in IntegratorRegistry.cpp. Each entry makes the method
// for every state size in use: the 12-state force-driven model, its 13-state
// quaternion form (RotationDrivenSystem.h) and the 8-state prescribed drive.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "engine/physics/AdaptiveIntegrator.h"

namespace hemiroll::physics {

struct IntegratorInfo {
  std::string name;         // the name flags and files use, e.g. "rk4"
  std::string description;  // one line for `--integrator list`
  int order = 0;            // classical order of accuracy
  bool adaptive = false;    // step-size controlled: takes a tolerance (--tol), not a step
};

class IntegratorRegistry {
 public:
  // Every built-in integrator, in the order they are listed.
  static const IntegratorRegistry& builtin();

  std::vector<IntegratorInfo> list() const;
  bool contains(std::string_view name) const;

  // A fresh integrator of that name, or nullptr if there is none.
  std::unique_ptr<Integrator<12>> makeForceDriven(std::string_view name) const;
  std::unique_ptr<Integrator<8>> makePrescribed(std::string_view name) const;
  std::unique_ptr<Integrator<13>> makeRotation(std::string_view name) const;

  template <int N>
  std::unique_ptr<Integrator<N>> make(std::string_view name) const {
    static_assert(N == 12 || N == 13 || N == 8, "only the 12-, 13- and 8-state models exist");
    if constexpr (N == 12) {
      return makeForceDriven(name);
    } else if constexpr (N == 13) {
      return makeRotation(name);
    } else {
      return makePrescribed(name);
    }
  }

  // Adds a method implemented as a class template Method<N>.
  template <template <int> class Method>
  void add(std::string name, std::string description) {
    Method<12> probe;
    const int order = probe.order();
    const bool adaptive = probe.adaptive() != nullptr;
    entries_.push_back(Entry{IntegratorInfo{std::move(name), std::move(description), order, adaptive},
                             [] { return std::unique_ptr<Integrator<12>>(new Method<12>()); },
                             [] { return std::unique_ptr<Integrator<8>>(new Method<8>()); },
                             [] { return std::unique_ptr<Integrator<13>>(new Method<13>()); }});
  }

 private:
  struct Entry {
    IntegratorInfo info;
    std::unique_ptr<Integrator<12>> (*make12)();
    std::unique_ptr<Integrator<8>> (*make8)();
    std::unique_ptr<Integrator<13>> (*make13)();
  };
  const Entry* find(std::string_view name) const;

  std::vector<Entry> entries_;
};

}  // namespace hemiroll::physics
