-- Force Dimension omega.6, a device profile (docs/UDP_BRIDGE.md "Device
-- profiles"). SI units; the key names say which.
--
-- Figures: Force Dimension's "omega.6" product specifications (omega.x
-- series data sheet). NOT CHECKED against the sheet here (no browsing on
-- this machine, no copy in the project's search corpora): these are the
-- commonly published figures; check them against your unit's sheet.
return {
  model = "Force Dimension omega.6",
  maker = "Force Dimension",
  sources = "Force Dimension omega.6 data sheet (commonly published figures; not checked here)",
  peak_force_N = 12.0,             -- "continuous 12.0 N"; no separate peak published
  continuous_force_N = 12.0,
  max_stiffness_N_per_m = 14500,   -- "closed-loop stiffness 14.5 N/mm"
  workspace_width_m = 0.160,       -- translation: diameter 160 x length 110 mm (bounding box)
  workspace_depth_m = 0.110,
  workspace_height_m = 0.160,
  update_rate_Hz = 4000,           -- "refresh rate up to 4 kHz"
  position_resolution_m = 0.00001, -- "translation resolution < 0.01 mm"
  force_axes = 3,                  -- forces only; the wrist (240 x 140 x 320 deg) is passive
  sensed_axes = 6,
}
