#pragma once
// State vectors and the meaning of each slot. The names are the paper's
// (eq. 22), so that code, CSV columns and Lua tables read the same.

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace hemiroll::physics {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

template <int N>
using StateVector = Eigen::Matrix<double, N, 1>;

// 12-state force-driven model, eq. (22):
// x = {x_p, y_p, xd_p, yd_p, w_x, w_y, w_z, u_a, v_a, u_o, v_o, psi}.
// p is the mass point in face coordinates [m], w the angular velocity of the
// hemisphere in the base frame [rad/s], (u_a, v_a) the contact point on the
// plane [m], (u_o, v_o) the contact point on the sphere [rad], psi the
// contact angle [rad], kept continuous (never wrapped).
namespace force_slot {
inline constexpr int x_p = 0, y_p = 1, xd_p = 2, yd_p = 3;
inline constexpr int w_x = 4, w_y = 5, w_z = 6;
inline constexpr int u_a = 7, v_a = 8, u_o = 9, v_o = 10, psi = 11;
inline constexpr int body = 4;  // first slot of the hemisphere's own state
}  // namespace force_slot
using ForceDrivenState = StateVector<12>;

// 8-state prescribed drive, eq. (48): the hemisphere's own state, in the same
// order as slots 4..11 of the 12-state model, so that one is the tail of the
// other.
namespace body_slot {
inline constexpr int w_x = 0, w_y = 1, w_z = 2;
inline constexpr int u_a = 3, v_a = 4, u_o = 5, v_o = 6, psi = 7;
}  // namespace body_slot
using BodyState = StateVector<8>;

// The force-driven model with the orientation as a quaternion (BodyRotation.h):
// slots 0..8 as in the 12-state model, then q = (q_w, q_x, q_y, q_z) in
// place of (u_o, v_o, psi).
namespace rotation_slot {
inline constexpr int x_p = 0, y_p = 1, xd_p = 2, yd_p = 3;
inline constexpr int w_x = 4, w_y = 5, w_z = 6;
inline constexpr int u_a = 7, v_a = 8, q_w = 9, q_x = 10, q_y = 11, q_z = 12;
}  // namespace rotation_slot
using RotationState = StateVector<13>;

inline constexpr const char* kStateNames[12] = {"x_p", "y_p", "xd_p", "yd_p", "w_x", "w_y",
                                                "w_z", "u_a", "v_a",  "u_o",  "v_o", "psi"};

}  // namespace hemiroll::physics
