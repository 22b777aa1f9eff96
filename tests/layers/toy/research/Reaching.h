#pragma once
// Its header: the include the rule must find.
  #  include "tests/layers/toy/window/Window.h"
