#pragma once
// Fits a circle to planar points (Taubin's algebraic fit, solved by Newton's
// method on its characteristic polynomial as in N. Chernov, "Circular and
// Linear Regression", 2010, Sec. 5.9). The circle is returned as
//   A (x^2 + y^2) + B x + C y + D = 0,  B^2 + C^2 - 4 A D = 1,
// whose curvature is 2 |A|. That form stays finite for points on a straight
// line (A = 0), where centre and radius do not: a nearly straight trace
// gives a curvature near zero instead of a radius of 1e15 m.

#include <span>

namespace hemiroll::analysis {

struct CircleFit {
  bool ok = false;             // false: fewer than 3 distinct points
  double curvature = 0.0;      // [1/m] >= 0 (the sign of a turn is the caller's: it knows the direction of travel)
  double centreX = 0.0, centreY = 0.0;  // [m] meaningful when curvature > 0
  double radius = 0.0;         // [m] 1 / curvature; 0 when curvature is 0 (a line)
  double rmsResidual = 0.0;    // [m] RMS geometric distance of the points from the circle (or line)
};

CircleFit fitCircle(std::span<const double> x, std::span<const double> y);

}  // namespace hemiroll::analysis
