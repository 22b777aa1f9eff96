#pragma once
// The peers of the work-precision study, on the same right-hand side
// (OdeSystem<N>::derivative, called through the same virtual function as our
// integrators call it):
//   cvode-adams   SUNDIALS CVODE 6.x (Debian 12: 6.4.1), variable-order Adams,
//                 fixed-point (functional) iteration, rtol = atol = tol
//   odeint-dopri5 Boost.Odeint runge_kutta_dopri5, controlled, atol = rtol = tol
//   odeint-rkf78  Boost.Odeint runge_kutta_fehlberg78, controlled, atol = rtol = tol
// Each integrates from (0, x0) to T exactly and returns x(T) and the number of
// right-hand side evaluations.

#include <array>
#include <string>

#include "engine/physics/OdeSystem.h"

namespace hemiroll::tools {

template <int N>
struct PeerResult {
  physics::StateVector<N> x;
  long long evaluations = 0;
  bool ok = true;
};

enum class Peer { CvodeAdams, OdeintDopri5, OdeintFehlberg78 };
const char* peerName(Peer p);

template <int N>
PeerResult<N> runPeer(Peer peer, const physics::OdeSystem<N>& system, const physics::StateVector<N>& x0, double T,
                      double tol);

}  // namespace hemiroll::tools
