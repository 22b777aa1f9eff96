-- 3D Systems Touch X (formerly SensAble PHANTOM Desktop), a device profile
-- (docs/UDP_BRIDGE.md "Device profiles"). SI units; the key names say which.
--
-- Figures: the maker's "Touch X" specification sheet (3D Systems). NOT
-- CHECKED against the sheet here (no browsing on this machine, no copy in
-- the project's search corpora): these are the commonly published figures;
-- check them against your unit's sheet before a study.
return {
  model = "3D Systems Touch X",
  maker = "3D Systems",
  sources = "3D Systems Touch X specification sheet (commonly published figures; not checked here)",
  peak_force_N = 7.9,            -- "maximum exertable force at nominal position"
  continuous_force_N = 1.75,     -- "continuous exertable force (24 hrs)"
  max_stiffness_N_per_m = 1480,  -- the least stiff axis (z: 1.48 N/mm; x 1.86, y 2.35 N/mm)
  workspace_width_m = 0.160,     -- 160 W x 120 H x 120 D mm
  workspace_depth_m = 0.120,
  workspace_height_m = 0.120,
  update_rate_Hz = 1000,
  position_resolution_m = 0.000023,  -- "> 1100 dpi, ~0.023 mm"
  force_axes = 3,
  sensed_axes = 6,
}
