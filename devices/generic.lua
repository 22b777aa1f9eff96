-- A generic desk haptic device: the limits hemiroll used before profiles
-- existed (3 N, 1000 N/m, a reach of 0.1 m about the origin). Not any
-- maker's figures: choose your device's own profile, or copy this file and
-- fill in its sheet (docs/UDP_BRIDGE.md "Device profiles").
return {
  model = "generic haptic device",
  maker = "",
  sources = "hemiroll's defaults (UdpBridgeDef::spec before issue 31); no maker's sheet",
  peak_force_N = 3.0,
  continuous_force_N = 3.0,       -- no separate rating: only a clamp held for long stops it
  max_stiffness_N_per_m = 1000,
  workspace_width_m = 0.2,        -- the 0.1 m reach each way
  workspace_depth_m = 0.2,
  workspace_height_m = 0.2,
  update_rate_Hz = 1000,
  force_axes = 3,
  sensed_axes = 3,
}
