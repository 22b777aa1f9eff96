#pragma once
// DOP853: the explicit Runge-Kutta method of order 8 of Dormand & Prince
// (Prince & Dormand 1981, "High order embedded Runge-Kutta formulae"), with
// the error estimator "5(3)" and the 7th-order dense output of Hairer,
// Norsett & Wanner, Solving ODEs I, 2nd ed., Sec. II.10 (DOP853). 12 stages per
// step plus one (the derivative at the step's end, reused as the next step's
// first); 3 more for the dense output, only in steps whose dense output is
// asked for (computed on the first interpolate() after the step). The
// coefficients were typed from the published tableau (HNW I, Sec. II.10;
// decimal expansions to 30 digits) and are checked in
// tests/physics/DormandPrince853Test.cpp against the order conditions.
//
// Real = long double keeps the state and each step's update in extended
// precision (the right-hand side still runs in double): over the 1e5 and more
// steps of a tight-tolerance reference this removes the round-off of adding a
// small increment to a large state, the part of round-off that accumulates.

#include "engine/physics/AdaptiveIntegrator.h"

namespace hemiroll::physics {

namespace dop853 {
// Nodes (c2..c5 are irrational: they involve sqrt(6)).
inline constexpr double c2 = 0.526001519587677318785587544488e-01;
inline constexpr double c3 = 0.789002279381515978178381316732e-01;
inline constexpr double c4 = 0.118350341907227396726757197510e+00;
inline constexpr double c5 = 0.281649658092772603273242802490e+00;
inline constexpr double c6 = 0.333333333333333333333333333333e+00;
inline constexpr double c7 = 0.25e+00;
inline constexpr double c8 = 0.307692307692307692307692307692e+00;
inline constexpr double c9 = 0.651282051282051282051282051282e+00;
inline constexpr double c10 = 0.6e+00;
inline constexpr double c11 = 0.857142857142857142857142857142e+00;
inline constexpr double c14 = 0.1e+00;
inline constexpr double c15 = 0.2e+00;
inline constexpr double c16 = 0.777777777777777777777777777778e+00;

// 8th-order weights (stages 2..5 have weight zero).
inline constexpr double b1 = 5.42937341165687622380535766363e-2;
inline constexpr double b6 = 4.45031289275240888144113950566e0;
inline constexpr double b7 = 1.89151789931450038304281599044e0;
inline constexpr double b8 = -5.8012039600105847814672114227e0;
inline constexpr double b9 = 3.1116436695781989440891606237e-1;
inline constexpr double b10 = -1.52160949662516078556178806805e-1;
inline constexpr double b11 = 2.01365400804030348374776537501e-1;
inline constexpr double b12 = 4.47106157277725905176885569043e-2;

// The 3rd-order estimator: err3 = sum b k - (bhh1 k1 + bhh2 k9 + bhh3 k12).
inline constexpr double bhh1 = 0.244094488188976377952755905512e+00;
inline constexpr double bhh2 = 0.733846688281611857341361741547e+00;
inline constexpr double bhh3 = 0.220588235294117647058823529412e-01;

// The 5th-order estimator: err5 = sum er k.
inline constexpr double er1 = 0.1312004499419488073250102996e-01;
inline constexpr double er6 = -0.1225156446376204440720569753e+01;
inline constexpr double er7 = -0.4957589496572501915214079952e+00;
inline constexpr double er8 = 0.1664377182454986536961530415e+01;
inline constexpr double er9 = -0.3503288487499736816886487290e+00;
inline constexpr double er10 = 0.3341791187130174790297318841e+00;
inline constexpr double er11 = 0.8192320648511571246570742613e-01;
inline constexpr double er12 = -0.2235530786388629525884427845e-01;

inline constexpr double a21 = 5.26001519587677318785587544488e-2;
inline constexpr double a31 = 1.97250569845378994544595329183e-2;
inline constexpr double a32 = 5.91751709536136983633785987549e-2;
inline constexpr double a41 = 2.95875854768068491816892993775e-2;
inline constexpr double a43 = 8.87627564304205475450678981324e-2;
inline constexpr double a51 = 2.41365134159266685502369798665e-1;
inline constexpr double a53 = -8.84549479328286085344864962717e-1;
inline constexpr double a54 = 9.24834003261792003115737966543e-1;
inline constexpr double a61 = 3.7037037037037037037037037037e-2;
inline constexpr double a64 = 1.70828608729473871279604482173e-1;
inline constexpr double a65 = 1.25467687566822425016691814123e-1;
inline constexpr double a71 = 3.7109375e-2;
inline constexpr double a74 = 1.70252211019544039314978060272e-1;
inline constexpr double a75 = 6.02165389804559606850219397283e-2;
inline constexpr double a76 = -1.7578125e-2;
inline constexpr double a81 = 3.70920001185047927108779319836e-2;
inline constexpr double a84 = 1.70383925712239993810214054705e-1;
inline constexpr double a85 = 1.07262030446373284651809199168e-1;
inline constexpr double a86 = -1.53194377486244017527936158236e-2;
inline constexpr double a87 = 8.27378916381402288758473766002e-3;
inline constexpr double a91 = 6.24110958716075717114429577812e-1;
inline constexpr double a94 = -3.36089262944694129406857109825e0;
inline constexpr double a95 = -8.68219346841726006818189891453e-1;
inline constexpr double a96 = 2.75920996994467083049415600797e1;
inline constexpr double a97 = 2.01540675504778934086186788979e1;
inline constexpr double a98 = -4.34898841810699588477366255144e1;
inline constexpr double a101 = 4.77662536438264365890433908527e-1;
inline constexpr double a104 = -2.48811461997166764192642586468e0;
inline constexpr double a105 = -5.90290826836842996371446475743e-1;
inline constexpr double a106 = 2.12300514481811942347288949897e1;
inline constexpr double a107 = 1.52792336328824235832596922938e1;
inline constexpr double a108 = -3.32882109689848629194453265587e1;
inline constexpr double a109 = -2.03312017085086261358222928593e-2;
inline constexpr double a111 = -9.3714243008598732571704021658e-1;
inline constexpr double a114 = 5.18637242884406370830023853209e0;
inline constexpr double a115 = 1.09143734899672957818500254654e0;
inline constexpr double a116 = -8.14978701074692612513997267357e0;
inline constexpr double a117 = -1.85200656599969598641566180701e1;
inline constexpr double a118 = 2.27394870993505042818970056734e1;
inline constexpr double a119 = 2.49360555267965238987089396762e0;
inline constexpr double a1110 = -3.0467644718982195003823669022e0;
inline constexpr double a121 = 2.27331014751653820792359768449e0;
inline constexpr double a124 = -1.05344954667372501984066689879e1;
inline constexpr double a125 = -2.00087205822486249909675718444e0;
inline constexpr double a126 = -1.79589318631187989172765950534e1;
inline constexpr double a127 = 2.79488845294199600508499808837e1;
inline constexpr double a128 = -2.85899827713502369474065508674e0;
inline constexpr double a129 = -8.87285693353062954433549289258e0;
inline constexpr double a1210 = 1.23605671757943030647266201528e1;
inline constexpr double a1211 = 6.43392746015763530355970484046e-1;

// The three extra stages of the dense output (k13 = f(t + h, x1)).
inline constexpr double a141 = 5.61675022830479523392909219681e-2;
inline constexpr double a147 = 2.53500210216624811088794765333e-1;
inline constexpr double a148 = -2.46239037470802489917441475441e-1;
inline constexpr double a149 = -1.24191423263816360469010140626e-1;
inline constexpr double a1410 = 1.5329179827876569731206322685e-1;
inline constexpr double a1411 = 8.20105229563468988491666602057e-3;
inline constexpr double a1412 = 7.56789766054569976138603589584e-3;
inline constexpr double a1413 = -8.298e-3;
inline constexpr double a151 = 3.18346481635021405060768473261e-2;
inline constexpr double a156 = 2.83009096723667755288322961402e-2;
inline constexpr double a157 = 5.35419883074385676223797384372e-2;
inline constexpr double a158 = -5.49237485713909884646569340306e-2;
inline constexpr double a1511 = -1.08347328697249322858509316994e-4;
inline constexpr double a1512 = 3.82571090835658412954920192323e-4;
inline constexpr double a1513 = -3.40465008687404560802977114492e-4;
inline constexpr double a1514 = 1.41312443674632500278074618366e-1;
inline constexpr double a161 = -4.28896301583791923408573538692e-1;
inline constexpr double a166 = -4.69762141536116384314449447206e0;
inline constexpr double a167 = 7.68342119606259904184240953878e0;
inline constexpr double a168 = 4.06898981839711007970213554331e0;
inline constexpr double a169 = 3.56727187455281109270669543021e-1;
inline constexpr double a1613 = -1.39902416515901462129418009734e-3;
inline constexpr double a1614 = 2.9475147891527723389556272149e0;
inline constexpr double a1615 = -9.15095847217987001081870187138e0;

// Dense output: the coefficients of the 4th..7th terms of the continuous
// extension, rows d4, d5, d6, d7 over the stages 1, 6..16.
inline constexpr double d41 = -0.84289382761090128651353491142e+01, d46 = 0.56671495351937776962531783590e+00,
                        d47 = -0.30689499459498916912797304727e+01, d48 = 0.23846676565120698287728149680e+01,
                        d49 = 0.21170345824450282767155149946e+01, d410 = -0.87139158377797299206789907490e+00,
                        d411 = 0.22404374302607882758541771650e+01, d412 = 0.63157877876946881815570249290e+00,
                        d413 = -0.88990336451333310820698117400e-01, d414 = 0.18148505520854727256656404962e+02,
                        d415 = -0.91946323924783554000451984436e+01, d416 = -0.44360363875948939664310572000e+01;
inline constexpr double d51 = 0.10427508642579134603413151009e+02, d56 = 0.24228349177525818288430175319e+03,
                        d57 = 0.16520045171727028198505394887e+03, d58 = -0.37454675472269020279518312152e+03,
                        d59 = -0.22113666853125306036270938578e+02, d510 = 0.77334326684722638389603898808e+01,
                        d511 = -0.30674084731089398182061213626e+02, d512 = -0.93321305264302278729567221706e+01,
                        d513 = 0.15697238121770843886131091075e+02, d514 = -0.31139403219565177677282850411e+02,
                        d515 = -0.93529243588444783865713862664e+01, d516 = 0.35816841486394083752465898540e+02;
inline constexpr double d61 = 0.19985053242002433820987653617e+02, d66 = -0.38703730874935176555105901742e+03,
                        d67 = -0.18917813819516756882830838328e+03, d68 = 0.52780815920542364900561016686e+03,
                        d69 = -0.11573902539959630126141871134e+02, d610 = 0.68812326946963000169666922661e+01,
                        d611 = -0.10006050966910838403183860980e+01, d612 = 0.77771377980534432092869265740e+00,
                        d613 = -0.27782057523535084065932004339e+01, d614 = -0.60196695231264120758267380846e+02,
                        d615 = 0.84320405506677161018159903784e+02, d616 = 0.11992291136182789328035130030e+02;
inline constexpr double d71 = -0.25693933462703749003312586129e+02, d76 = -0.15418974869023643374053993627e+03,
                        d77 = -0.23152937917604549567536039109e+03, d78 = 0.35763911791061412378285349910e+03,
                        d79 = 0.93405324183624310003907691704e+02, d710 = -0.37458323136451633156875139351e+02,
                        d711 = 0.10409964950896230045147246184e+03, d712 = 0.29840293426660503123344363579e+02,
                        d713 = -0.43533456590011143754432175058e+02, d714 = 0.96324553959188282948394950600e+02,
                        d715 = -0.39177261675615439165231486172e+02, d716 = -0.14972683625798562581422125276e+03;
}  // namespace dop853

template <int N, class Real = double>
class DormandPrince853 final : public AdaptiveIntegrator<N> {
 public:
  using RealVector = Eigen::Matrix<Real, N, 1>;

  std::string_view name() const override { return sizeof(Real) > sizeof(double) ? "dop853ld" : "dop853"; }
  int order() const override { return 8; }
  const StateVector<N>& state() const override { return x_; }

  // x(t) = r1 + s (r2 + s1 (r3 + s (r4 + s1 (r5 + s (r6 + s1 (r7 + s r8)))))),
  // s = (t - t0) / h, s1 = 1 - s (HNW I, Sec. II.10, DOP853's CONTD8). The
  // three extra stages and r2..r8 are computed here, on the first call after
  // a step, so that steps nobody interpolates cost 12 evaluations, not 15.
  void interpolate(double t, StateVector<N>& x) override {
    if (!denseReady_) prepareDense();
    const double s = (t - this->stepBegin()) / hDone_, s1 = 1.0 - s;
    const StateVector<N> inner =
        r2_ + s1 * (r3_ + s * (r4_ + s1 * (r5_ + s * (r6_ + s1 * (r7_ + s * r8_)))));
    x = (xPrev_ + (Real(s) * inner.template cast<Real>())).template cast<double>();
  }

 protected:
  int controlOrder() const override { return 8; }
  // The stabilized (PI) control that DOP853 offers as an option (HNW I,
  // Sec. IV.2; beta = 0.04, as our DOPRI5): Hairer's default beta = 0 rejected
  // 8 to 22% of the steps on the work-precision scenarios, each rejection
  // 11 evaluations thrown away; with beta = 0.04 it is 1 to 10%.
  double controlBeta() const override { return 0.04; }

  void restart(const OdeSystem<N>& f, double t0, const StateVector<N>& x0) override {
    xr_ = x0.template cast<Real>();
    x_ = x0;
    this->setTime(t0);
    f.derivative(t0, x_, k_[cur_][1]);
    this->countEvaluations(1);
    denseReady_ = false;
    hDone_ = 0.0;
  }

  double attempt(const OdeSystem<N>& f, double h) override {
    using namespace dop853;
    const double t = this->time();
    StateVector<N>* k = k_[cur_];  // 1-based: k[1]..k[13] as in the published tableau
    // Each stage's state x + h * sum_j a_ij k_j in one pass over the
    // components (the sum in double, left to right, the state in Real).
    stage(f, t + c2 * h, h, k[2], [&](int i) { return a21 * k[1][i]; });
    stage(f, t + c3 * h, h, k[3], [&](int i) { return a31 * k[1][i] + a32 * k[2][i]; });
    stage(f, t + c4 * h, h, k[4], [&](int i) { return a41 * k[1][i] + a43 * k[3][i]; });
    stage(f, t + c5 * h, h, k[5], [&](int i) { return a51 * k[1][i] + a53 * k[3][i] + a54 * k[4][i]; });
    stage(f, t + c6 * h, h, k[6], [&](int i) { return a61 * k[1][i] + a64 * k[4][i] + a65 * k[5][i]; });
    stage(f, t + c7 * h, h, k[7],
          [&](int i) { return a71 * k[1][i] + a74 * k[4][i] + a75 * k[5][i] + a76 * k[6][i]; });
    stage(f, t + c8 * h, h, k[8],
          [&](int i) { return a81 * k[1][i] + a84 * k[4][i] + a85 * k[5][i] + a86 * k[6][i] + a87 * k[7][i]; });
    stage(f, t + c9 * h, h, k[9], [&](int i) {
      return a91 * k[1][i] + a94 * k[4][i] + a95 * k[5][i] + a96 * k[6][i] + a97 * k[7][i] + a98 * k[8][i];
    });
    stage(f, t + c10 * h, h, k[10], [&](int i) {
      return a101 * k[1][i] + a104 * k[4][i] + a105 * k[5][i] + a106 * k[6][i] + a107 * k[7][i] + a108 * k[8][i] +
             a109 * k[9][i];
    });
    stage(f, t + c11 * h, h, k[11], [&](int i) {
      return a111 * k[1][i] + a114 * k[4][i] + a115 * k[5][i] + a116 * k[6][i] + a117 * k[7][i] + a118 * k[8][i] +
             a119 * k[9][i] + a1110 * k[10][i];
    });
    stage(f, t + h, h, k[12], [&](int i) {
      return a121 * k[1][i] + a124 * k[4][i] + a125 * k[5][i] + a126 * k[6][i] + a127 * k[7][i] + a128 * k[8][i] +
             a129 * k[9][i] + a1210 * k[10][i] + a1211 * k[11][i];
    });
    this->countEvaluations(11);

    // The new state and the combined estimate of DOP853 (HNW I, Sec. II.10,
    // eq. 10.17): the 5th-order difference, damped where the 3rd-order one
    // shows it is not yet asymptotic. Weights sk_i = tol + tol max(|x_i|, |x1_i|).
    const double tol = this->tolerance();
    double e5 = 0.0, e3 = 0.0;
    bool finite = true;
    RealVector xr1;
    StateVector<N> x1;
    for (int i = 0; i < N; ++i) {
      const double inc = b1 * k[1][i] + b6 * k[6][i] + b7 * k[7][i] + b8 * k[8][i] + b9 * k[9][i] +
                         b10 * k[10][i] + b11 * k[11][i] + b12 * k[12][i];
      xr1[i] = xr_[i] + Real(h) * Real(inc);
      const double xn = static_cast<double>(xr1[i]);
      x1[i] = xn;
      finite = finite && std::isfinite(xn);
      const double sk = tol + tol * std::max(std::abs(x_[i]), std::abs(xn));
      const double d5 = (er1 * k[1][i] + er6 * k[6][i] + er7 * k[7][i] + er8 * k[8][i] + er9 * k[9][i] +
                         er10 * k[10][i] + er11 * k[11][i] + er12 * k[12][i]) /
                        sk;
      const double d3 = (inc - (bhh1 * k[1][i] + bhh2 * k[9][i] + bhh3 * k[12][i])) / sk;
      e5 += d5 * d5;
      e3 += d3 * d3;
    }
    xrNew_ = xr1;
    xNew_ = x1;
    hTry_ = h;
    double denominator = e5 + 0.01 * e3;
    if (denominator <= 0.0) denominator = 1.0;
    const double err = std::abs(h) * e5 / std::sqrt(N * denominator);
    return std::isfinite(err) && finite ? err : std::numeric_limits<double>::infinity();
  }

  void accept(const OdeSystem<N>& f) override {
    xPrev_ = xr_;
    xr_ = xrNew_;
    x_ = xNew_;
    hDone_ = hTry_;
    tPrev_ = this->time();
    this->setTime(tPrev_ + hTry_);
    system_ = &f;
    // k13: the derivative at the new point, for the next step and the dense
    // output. The stages of the accepted step stay where they are (the bank
    // becomes the dense output's); the next attempt writes the other bank,
    // whose k1 is this k13 (first same as last).
    f.derivative(this->time(), x_, k_[cur_][13]);
    this->countEvaluations(1);
    cur_ ^= 1;
    k_[cur_][1] = k_[cur_ ^ 1][13];
    denseReady_ = false;
  }

 private:
  // out = f(t, x + h * sum(i)), component by component.
  template <class Sum>
  [[gnu::always_inline]] inline void stage(const OdeSystem<N>& f, double t, double h, StateVector<N>& out,
                                           const Sum& sum) {
    // A local vector: the compiler may assume it aliases no stage (members).
    StateVector<N> y;
    for (int i = 0; i < N; ++i) y[i] = static_cast<double>(xr_[i] + Real(h) * Real(sum(i)));
    f.derivative(t, y, out);
  }

  void prepareDense() {
    using namespace dop853;
    const StateVector<N>* k = k_[cur_ ^ 1];  // the accepted step's stages
    const double h = hDone_;
    const double t = tPrev_;
    StateVector<N> k14, k15, k16;
    auto extra = [&](double c, const StateVector<N>& sum, StateVector<N>& out) {
      stage_ = (xPrev_ + Real(h) * sum.template cast<Real>()).template cast<double>();
      system_->derivative(t + c * h, stage_, out);
    };
    extra(c14, a141 * k[1] + a147 * k[7] + a148 * k[8] + a149 * k[9] + a1410 * k[10] + a1411 * k[11] +
                   a1412 * k[12] + a1413 * k[13],
          k14);
    extra(c15, a151 * k[1] + a156 * k[6] + a157 * k[7] + a158 * k[8] + a1511 * k[11] + a1512 * k[12] +
                   a1513 * k[13] + a1514 * k14,
          k15);
    extra(c16, a161 * k[1] + a166 * k[6] + a167 * k[7] + a168 * k[8] + a169 * k[9] + a1613 * k[13] +
                   a1614 * k14 + a1615 * k15,
          k16);
    this->countEvaluations(3);
    r2_ = (xr_ - xPrev_).template cast<double>();
    r3_ = h * k[1] - r2_;
    r4_ = r2_ - h * k[13] - r3_;
    r5_ = h * (d41 * k[1] + d46 * k[6] + d47 * k[7] + d48 * k[8] + d49 * k[9] + d410 * k[10] + d411 * k[11] +
               d412 * k[12] + d413 * k[13] + d414 * k14 + d415 * k15 + d416 * k16);
    r6_ = h * (d51 * k[1] + d56 * k[6] + d57 * k[7] + d58 * k[8] + d59 * k[9] + d510 * k[10] + d511 * k[11] +
               d512 * k[12] + d513 * k[13] + d514 * k14 + d515 * k15 + d516 * k16);
    r7_ = h * (d61 * k[1] + d66 * k[6] + d67 * k[7] + d68 * k[8] + d69 * k[9] + d610 * k[10] + d611 * k[11] +
               d612 * k[12] + d613 * k[13] + d614 * k14 + d615 * k15 + d616 * k16);
    r8_ = h * (d71 * k[1] + d76 * k[6] + d77 * k[7] + d78 * k[8] + d79 * k[9] + d710 * k[10] + d711 * k[11] +
               d712 * k[12] + d713 * k[13] + d714 * k14 + d715 * k15 + d716 * k16);
    denseReady_ = true;
  }

  RealVector xr_, xrNew_, xPrev_;
  StateVector<N> x_, xNew_, stage_;
  // Two banks of stages, 1-based k[1]..k[13]: k_[cur_] for the attempt in
  // progress, k_[cur_ ^ 1] holds the last accepted step's (dense output).
  StateVector<N> k_[2][14];
  int cur_ = 0;
  StateVector<N> r2_, r3_, r4_, r5_, r6_, r7_, r8_;
  const OdeSystem<N>* system_ = nullptr;
  double hTry_ = 0.0, hDone_ = 0.0, tPrev_ = 0.0;
  bool denseReady_ = false;
};

// Both variants as one-parameter templates, for the registry's template
// template parameter (clang does not match a template with a defaulted
// second parameter to `template <int> class` before C++20's P0522 is on).
template <int N>
using DormandPrince853Double = DormandPrince853<N, double>;
template <int N>
using DormandPrince853LongDouble = DormandPrince853<N, long double>;

}  // namespace hemiroll::physics
