#include "engine/physics/IntegratorRegistry.h"

#include "engine/physics/DormandPrince54.h"
#include "engine/physics/DormandPrince853.h"
#include "engine/physics/GaussLegendre.h"
#include "engine/physics/Tsitouras54.h"
#include "engine/physics/Verner76.h"
#include "engine/physics/Verner98.h"

namespace hemiroll::physics {

const IntegratorRegistry& IntegratorRegistry::builtin() {
  // Built on first use (thread-safe static initialisation), never modified after.
  static const IntegratorRegistry registry = [] {
    IntegratorRegistry r;
    r.add<RungeKutta4>("rk4", "classical fourth-order Runge-Kutta, fixed step (the paper's choice at 1 ms)");
    r.add<GaussLegendre2>("gauss2", "Gauss-Legendre, 2 stages, implicit symmetric, fixed step: bounded energy error");
    r.add<GaussLegendre3>("gauss3", "Gauss-Legendre, 3 stages, implicit symmetric, fixed step: bounded energy error");
    r.add<DormandPrince54>("dopri5", "Dormand-Prince 5(4), adaptive (--tol), 4th-order dense output");
    r.add<Tsitouras54>("tsit5", "Tsitouras 5(4) (2011), adaptive (--tol), cubic Hermite dense output");
    r.add<Verner76>("vern7", "Verner's most efficient 7(6) pair (2010), adaptive (--tol), cubic Hermite dense output");
    r.add<Verner98>("vern9", "Verner's most efficient 9(8) pair (2010), adaptive (--tol), cubic Hermite dense output");
    r.add<DormandPrince853Double>("dop853", "Dormand-Prince 8(5,3) (HNW's DOP853), adaptive (--tol), 7th-order dense output");
    r.add<DormandPrince853LongDouble>("dop853ld",
                                      "DOP853 with the state kept in long double, for tight-tolerance references");
    return r;
  }();
  return registry;
}

std::vector<IntegratorInfo> IntegratorRegistry::list() const {
  std::vector<IntegratorInfo> out;
  out.reserve(entries_.size());
  for (const Entry& e : entries_) out.push_back(e.info);
  return out;
}

bool IntegratorRegistry::contains(std::string_view name) const { return find(name) != nullptr; }

const IntegratorRegistry::Entry* IntegratorRegistry::find(std::string_view name) const {
  for (const Entry& e : entries_)
    if (e.info.name == name) return &e;
  return nullptr;
}

std::unique_ptr<Integrator<12>> IntegratorRegistry::makeForceDriven(std::string_view name) const {
  const Entry* e = find(name);
  return e ? e->make12() : nullptr;
}

std::unique_ptr<Integrator<8>> IntegratorRegistry::makePrescribed(std::string_view name) const {
  const Entry* e = find(name);
  return e ? e->make8() : nullptr;
}

std::unique_ptr<Integrator<13>> IntegratorRegistry::makeRotation(std::string_view name) const {
  const Entry* e = find(name);
  return e ? e->make13() : nullptr;
}

}  // namespace hemiroll::physics
