#pragma once
// Writes trajectory rows as CSV (docs/SCENARIOS.md, "Output"):
//   t,x_p,y_p,xd_p,yd_p,w_x,w_y,w_z,u_a,v_a,u_o,v_o,psi,energy,f_x,f_y[,F_hx,F_hy,F_hz]
// Every number with %.17g, so that a double survives the round trip through
// text exactly and equal runs give byte-identical files.

#include <cstdio>

#include "game/research/sim/TrajectoryRow.h"

namespace hemiroll::game {

class CsvTrajectoryWriter {
 public:
  // Does not own `out`. withHandForce adds the F_h columns (proxy drives).
  CsvTrajectoryWriter(std::FILE* out, bool withHandForce) : out_(out), withHandForce_(withHandForce) {}

  void writeHeader();
  void writeRow(const TrajectoryRow& row);
  long long rowsWritten() const { return rows_; }
  // False once any write failed (disk full, closed pipe).
  bool good() const { return good_ && std::ferror(out_) == 0; }

 private:
  void number(double value, bool last);

  std::FILE* out_;
  bool withHandForce_;
  long long rows_ = 0;
  bool good_ = true;
};

}  // namespace hemiroll::game
