#pragma once
// One hidden SDL window with a GL 3.3 core context for a whole GL test
// binary (opening a context per test would cost ~0.1 s each under Xvfb).
// The binary runs under xvfb-run with Mesa's llvmpipe (CMakeLists.txt).

namespace hemiroll::test {

// Makes the shared context current (creating it on first use). Fails the
// calling test with SDL's message when no context can be made.
void useGlContext();

}  // namespace hemiroll::test
