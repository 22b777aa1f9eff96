# Tests that open a real window run under a virtual X display with Mesa's
# software OpenGL (llvmpipe), so `make test` works on a machine with no
# display or GPU: xvfb-run -a (a free display number) around the whole test
# binary, LIBGL_ALWAYS_SOFTWARE=1 so every machine draws with the same
# rasteriser the reference images were made with. One ctest per binary: one
# Xvfb start (~0.5 s) instead of one per test. RESOURCE_LOCK keeps two such
# binaries from racing for the same display number under `ctest -j`.
find_program(HEMIROLL_XVFB_RUN xvfb-run)

function(hemiroll_add_display_test name target labels)
  if(HEMIROLL_XVFB_RUN)
    set(command ${HEMIROLL_XVFB_RUN} -a -s "-screen 0 1280x1024x24" $<TARGET_FILE:${target}>)
  else()
    message(WARNING "xvfb-run not found (tools/install-deps.sh installs xvfb): ${name} needs a display")
    set(command $<TARGET_FILE:${target}>)
  endif()
  set(environment "LIBGL_ALWAYS_SOFTWARE=1;SDL_AUDIODRIVER=dummy")
  if(HEMIROLL_SANITIZE)
    list(APPEND environment "LSAN_OPTIONS=suppressions=${PROJECT_SOURCE_DIR}/cmake/lsan.supp")
  endif()
  if(HEMIROLL_TSAN)
    # Races are looked for as in every other test; lock-order checking is off
    # here. The uninstrumented X11/xcb and Mesa libraries take locks TSan sees
    # taken but never released, and after a few dozen windows in one process
    # its deadlock detector stops at its own limit of 64 held locks
    # (sanitizer_deadlock_detector.h CHECK, inside glXSwapBuffers). Measured
    # with the 21 window tests of screens.window: no race reported.
    list(APPEND environment
         "TSAN_OPTIONS=halt_on_error=1 detect_deadlocks=0 suppressions=${PROJECT_SOURCE_DIR}/cmake/tsan.supp")
  endif()
  add_test(NAME ${name} COMMAND ${command} --gtest_brief=1)
  set_tests_properties(${name} PROPERTIES
    LABELS "${labels}" TIMEOUT 120 RESOURCE_LOCK xvfb
    ENVIRONMENT "${environment}")
endfunction()
