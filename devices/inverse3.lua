-- Haply Inverse3, a device profile (docs/UDP_BRIDGE.md "Device profiles").
-- SI units; the key names say which.
--
-- Figures: Haply Robotics' "Inverse3" technical specifications page. NOT
-- CHECKED against it here: no browsing on this machine, and the project's
-- search corpora hold only integration guides that name the device (3 DOF
-- position and force) without its figures. The numbers below are the ones
-- commonly quoted for the device and are the least certain of the shipped
-- profiles: check every one against Haply's current sheet before a study.
return {
  model = "Haply Inverse3",
  maker = "Haply Robotics",
  sources = "Haply Inverse3 technical specifications (commonly quoted figures; not checked here)",
  peak_force_N = 9.0,
  continuous_force_N = 3.0,
  max_stiffness_N_per_m = 3000,
  workspace_width_m = 0.40,
  workspace_depth_m = 0.25,
  workspace_height_m = 0.25,
  update_rate_Hz = 4000,
  force_axes = 3,
  sensed_axes = 3,
}
