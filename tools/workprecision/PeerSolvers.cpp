#include "tools/workprecision/PeerSolvers.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

// Boost 1.74's odeint copies a stepper's scratch buffers (std::array members)
// before their first use, as its own default argument; GCC reports that copy
// at our call site. The buffers are written before they are read.
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <boost/numeric/odeint.hpp>
#include <cstring>

namespace hemiroll::tools {

namespace {

template <int N>
struct Counted {
  const physics::OdeSystem<N>& system;
  long long evaluations = 0;
};

template <int N>
int cvodeRhs(sunrealtype t, N_Vector y, N_Vector ydot, void* data) {
  auto* c = static_cast<Counted<N>*>(data);
  physics::StateVector<N> x, dx;
  std::memcpy(x.data(), N_VGetArrayPointer(y), sizeof(double) * N);
  c->system.derivative(t, x, dx);
  std::memcpy(N_VGetArrayPointer(ydot), dx.data(), sizeof(double) * N);
  ++c->evaluations;
  return dx.allFinite() ? 0 : 1;  // 1: recoverable, CVODE retries smaller
}

template <int N>
PeerResult<N> runCvode(const physics::OdeSystem<N>& system, const physics::StateVector<N>& x0, double T, double tol) {
  PeerResult<N> result;
  Counted<N> counted{system};
  SUNContext ctx = nullptr;
  SUNContext_Create(nullptr, &ctx);
  N_Vector y = N_VNew_Serial(N, ctx);
  std::memcpy(N_VGetArrayPointer(y), x0.data(), sizeof(double) * N);
  void* mem = CVodeCreate(CV_ADAMS, ctx);
  CVodeInit(mem, cvodeRhs<N>, 0.0, y);
  CVodeSStolerances(mem, tol, tol);
  SUNNonlinearSolver nls = SUNNonlinSol_FixedPoint(y, 0, ctx);
  CVodeSetNonlinearSolver(mem, nls);
  CVodeSetUserData(mem, &counted);
  CVodeSetMaxNumSteps(mem, 100000000L);
  CVodeSetStopTime(mem, T);
  sunrealtype t = 0.0;
  const int flag = CVode(mem, T, y, &t, CV_NORMAL);
  result.ok = flag >= 0;
  std::memcpy(result.x.data(), N_VGetArrayPointer(y), sizeof(double) * N);
  CVodeFree(&mem);
  SUNNonlinSolFree(nls);
  N_VDestroy(y);
  SUNContext_Free(&ctx);
  result.evaluations = counted.evaluations;
  return result;
}

template <int N>
struct OdeintSystem {
  using State = std::array<double, N>;
  Counted<N>* counted;
  void operator()(const State& s, State& ds, double t) const {
    physics::StateVector<N> x, dx;
    std::memcpy(x.data(), s.data(), sizeof(double) * N);
    counted->system.derivative(t, x, dx);
    std::memcpy(ds.data(), dx.data(), sizeof(double) * N);
    ++counted->evaluations;
  }
};

template <int N, class Stepper>
PeerResult<N> runOdeint(const physics::OdeSystem<N>& system, const physics::StateVector<N>& x0,
                        double T, double tol) {
  namespace odeint = boost::numeric::odeint;
  PeerResult<N> result;
  Counted<N> counted{system};
  std::array<double, N> s;
  std::memcpy(s.data(), x0.data(), sizeof(double) * N);
  // What make_controlled(tol, tol, Stepper()) builds, constructed in place.
  using Checker = odeint::default_error_checker<double, typename Stepper::algebra_type, typename Stepper::operations_type>;
  odeint::controlled_runge_kutta<Stepper> controlled{Checker(tol, tol)};
  // Odeint's own step control takes it from here; 1e-4 s is a neutral start.
  odeint::integrate_adaptive(controlled, OdeintSystem<N>{&counted}, s, 0.0, T, 1e-4);
  std::memcpy(result.x.data(), s.data(), sizeof(double) * N);
  result.ok = result.x.allFinite();
  result.evaluations = counted.evaluations;
  return result;
}

}  // namespace

const char* peerName(Peer p) {
  switch (p) {
    case Peer::CvodeAdams: return "cvode-adams";
    case Peer::OdeintDopri5: return "odeint-dopri5";
    case Peer::OdeintFehlberg78: return "odeint-rkf78";
  }
  return "?";
}

template <int N>
PeerResult<N> runPeer(Peer peer, const physics::OdeSystem<N>& system, const physics::StateVector<N>& x0, double T,
                      double tol) {
  namespace odeint = boost::numeric::odeint;
  using State = std::array<double, N>;
  switch (peer) {
    case Peer::CvodeAdams: return runCvode<N>(system, x0, T, tol);
    case Peer::OdeintDopri5: return runOdeint<N, odeint::runge_kutta_dopri5<State>>(system, x0, T, tol);
    case Peer::OdeintFehlberg78: return runOdeint<N, odeint::runge_kutta_fehlberg78<State>>(system, x0, T, tol);
  }
  return {};
}

template PeerResult<8> runPeer<8>(Peer, const physics::OdeSystem<8>&, const physics::StateVector<8>&, double, double);
template PeerResult<12> runPeer<12>(Peer, const physics::OdeSystem<12>&, const physics::StateVector<12>&, double,
                                    double);

}  // namespace hemiroll::tools
