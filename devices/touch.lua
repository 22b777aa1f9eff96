-- 3D Systems Touch (formerly SensAble PHANTOM Omni), a device profile
-- (docs/UDP_BRIDGE.md "Device profiles"). SI units; the key names say which.
--
-- Figures: the maker's "Touch" specification sheet (3D Systems, "Touch
-- Haptic Device" product page and PDF). NOT CHECKED against the sheet here:
-- this machine cannot browse, and the project's search corpora hold no copy.
-- Every figure below is the one commonly published for this device (in the
-- sheet's tables as cited in papers and vendor pages); a lab should check
-- it against the sheet of its own unit before a study.
return {
  model = "3D Systems Touch",
  maker = "3D Systems",
  sources = "3D Systems Touch specification sheet (commonly published figures; not checked here)",
  peak_force_N = 3.3,            -- "maximum exertable force at nominal (orthogonal arms) position"
  continuous_force_N = 0.88,     -- "continuous exertable force (24 hrs)"
  max_stiffness_N_per_m = 1020,  -- the sheet's least stiff axis (z: 1.02 N/mm; x 1.26, y 2.31 N/mm)
  workspace_width_m = 0.160,     -- 160 W x 120 H x 70 D mm
  workspace_depth_m = 0.070,
  workspace_height_m = 0.120,
  update_rate_Hz = 1000,         -- the OpenHaptics servo loop's 1 kHz
  position_resolution_m = 0.000055,  -- "> 450 dpi, ~0.055 mm"
  force_axes = 3,                -- x, y, z
  sensed_axes = 6,               -- x, y, z and the stylus gimbal's roll, pitch, yaw
}
