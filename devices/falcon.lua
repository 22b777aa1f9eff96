-- Novint Falcon, a device profile (docs/UDP_BRIDGE.md "Device profiles").
-- SI units; the key names say which.
--
-- Figures: Novint's Falcon product specifications ("4 x 4 x 4 in
-- workspace, > 2 lb force, > 400 dpi position resolution, 1 kHz"). Only
-- the 1 kHz update rate was found in the project's search corpora (a page
-- derived from Novint's own description: "the motors are updated 1000 times
-- per second (1 kHz)"); the others are the commonly published figures, NOT
-- CHECKED against a sheet here. Novint publishes no continuous force and
-- no stiffness: the two marked "chosen here" are conservative guesses of
-- this project, not the maker's; measure your unit before a study.
return {
  model = "Novint Falcon",
  maker = "Novint Technologies",
  sources = "Novint Falcon product specifications (commonly published figures; not checked here)",
  peak_force_N = 8.9,             -- "> 2 lbf"
  continuous_force_N = 3.0,       -- chosen here: not published by Novint
  max_stiffness_N_per_m = 1000,   -- chosen here: not published by Novint
  workspace_width_m = 0.1016,     -- 4 x 4 x 4 in
  workspace_depth_m = 0.1016,
  workspace_height_m = 0.1016,
  update_rate_Hz = 1000,          -- "1 kHz" (found, see above)
  position_resolution_m = 0.0000635,  -- "> 400 dpi"
  force_axes = 3,
  sensed_axes = 3,
}
