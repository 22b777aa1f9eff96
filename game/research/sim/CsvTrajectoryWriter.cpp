#include "game/research/sim/CsvTrajectoryWriter.h"

namespace hemiroll::game {

void CsvTrajectoryWriter::writeHeader() {
  // The first 14 names are a contract (design.md, "Contracts"); more may follow.
  std::fputs("t,x_p,y_p,xd_p,yd_p,w_x,w_y,w_z,u_a,v_a,u_o,v_o,psi,energy,f_x,f_y", out_);
  if (withHandForce_) std::fputs(",F_hx,F_hy,F_hz", out_);
  if (std::fputc('\n', out_) == EOF) good_ = false;
}

void CsvTrajectoryWriter::number(double value, bool last) {
  if (std::fprintf(out_, last ? "%.17g\n" : "%.17g,", value) < 0) good_ = false;
}

void CsvTrajectoryWriter::writeRow(const TrajectoryRow& row) {
  number(row.time, false);
  for (int i = 0; i < 12; ++i) number(row.state[i], false);
  number(row.energy, false);
  number(row.faceForce.x(), false);
  number(row.faceForce.y(), !withHandForce_);
  if (withHandForce_) {
    number(row.handForce.x(), false);
    number(row.handForce.y(), false);
    number(row.handForce.z(), true);
  }
  ++rows_;
}

}  // namespace hemiroll::game
