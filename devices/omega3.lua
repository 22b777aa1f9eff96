-- Force Dimension omega.3, a device profile (docs/UDP_BRIDGE.md "Device
-- profiles"). SI units; the key names say which.
--
-- Figures: Force Dimension's "omega.3" product specifications (omega.x
-- series data sheet). NOT CHECKED against the sheet here (no browsing on
-- this machine, no copy in the project's search corpora): these are the
-- commonly published figures; check them against your unit's sheet.
return {
  model = "Force Dimension omega.3",
  maker = "Force Dimension",
  sources = "Force Dimension omega.3 data sheet (commonly published figures; not checked here)",
  -- The sheet gives one force, "continuous 12.0 N"; no separate peak is
  -- published, so the clamp is that continuous figure.
  peak_force_N = 12.0,
  continuous_force_N = 12.0,
  max_stiffness_N_per_m = 14500,  -- "closed-loop stiffness 14.5 N/mm"
  -- "translation workspace: diameter 160 x length 110 mm": the cylinder's
  -- bounding box (width and height the diameter, depth its length).
  workspace_width_m = 0.160,
  workspace_depth_m = 0.110,
  workspace_height_m = 0.160,
  update_rate_Hz = 4000,          -- "refresh rate up to 4 kHz"
  position_resolution_m = 0.00001,  -- "translation resolution < 0.01 mm"
  force_axes = 3,
  sensed_axes = 3,
}
