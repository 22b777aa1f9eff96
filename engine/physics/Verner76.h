#pragma once
// Verner's "most efficient" 7(6) pair: J. H. Verner, "Numerically optimal
// Runge-Kutta pairs with interpolants", Numer. Algorithms 53 (2010) 383-396,
// the 10-stage pair whose coefficients Verner publishes as
// RKV76.IIa.Efficient.00001675585.081206 (sfu.ca/~jverner), rounded to
// double. It propagates the 7th-order solution and estimates the error with
// the embedded 6th-order one (TableauPair.h steps it).
// tests/physics/Verner76Test.cpp checks the typed table against all 85 order
// conditions up to the 7th (the embedded weights against the 37 up to the
// 6th).
//
// Measured in docs/WORK_PRECISION.md: the fastest of ours at 2 of its 35
// error levels (1e-5 on free motion and on the heavy rose); Verner98.h and
// DOP853 take the rest. Near-ties there move between runs.
//
// Dense output: ExplicitPair.h's cubic Hermite (third order between the
// steps, exact at their ends), not Verner's 16-stage interpolant.

#include "engine/physics/TableauPair.h"

namespace hemiroll::physics {

struct Vern7Tableau {
  static constexpr std::string_view kName = "vern7";
  static constexpr int kOrder = 7, kStages = 10;
  // As printed to 17 significant digits (each names one double).
  static constexpr double c[10] = {0.0,
                                   5.0000000000000001e-03,
                                   1.0888888888888888e-01,
                                   1.6333333333333333e-01,
                                   4.5550000000000002e-01,
                                   6.0950944899783810e-01,
                                   8.8400000000000001e-01,
                                   9.2500000000000004e-01,
                                   1.0,
                                   1.0};
  // Row i holds a_ij, j < i (a_i2 = 0 from row 4 on).
  static constexpr double a[10][10] = {
      {},
      {5.0000000000000001e-03},
      {-1.0767901234567900e+00, 1.1856790123456791e+00},
      {4.0833333333333333e-02, 0.0, 1.2250000000000000e-01},
      {6.3891392362557264e-01, 0.0, -2.4556726382236569e+00, 2.2722587145980842e+00},
      {-2.6615773750187572e+00, 0.0, 1.0804513886456137e+01, -8.3539146573961993e+00, 8.2048759495665702e-01},
      {6.0677414346967709e+00, 0.0, -2.4711273635911084e+01,
       2.0427517930788895e+01, -1.9061579788166472e+00, 1.0061722492420679e+00},
      {1.2054670076253203e+01, 0.0, -4.9754784950468988e+01,
       4.1142888638604674e+01, -4.4617601499740038e+00, 2.0423348222391748e+00, -9.8348436654061080e-02},
      {1.0138146522881808e+01, 0.0, -4.2641136031717501e+01, 3.5763840039922570e+01,
       -4.3480228403929075e+00, 2.0098622683770357e+00, 3.4874904603382723e-01, -2.7143900510483127e-01},
      {-4.5030072034298676e+01, 0.0, 1.8732724376545889e+02, -1.5402882369350186e+02,
       1.8564653063475362e+01, -7.1418096792950791e+00, 1.3088085781613785e+00, 0.0, 0.0},
  };
  // The 7th-order weights (propagated) and the 6th-order ones.
  static constexpr double b[10] = {4.7155618486272220e-02,  0.0, 0.0, 2.5750564298434153e-01, 2.6216653977412618e-01,
                                   1.5216092656738558e-01,  4.9399691700324844e-01, -2.9430311714032503e-01,
                                   8.1317472324951096e-02,  0.0};
  static constexpr double bHat[10] = {4.4608606606341174e-02, 0.0, 0.0, 2.6716403785713727e-01, 2.2010183001772929e-01,
                                      2.1884317031431569e-01, 2.2898717054112028e-01, 0.0, 0.0, 2.0295184663356284e-02};
};

template <int N>
using Verner76 = TableauPair<N, Vern7Tableau>;

}  // namespace hemiroll::physics
