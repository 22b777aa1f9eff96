// The toy window library.
#include "tests/layers/toy/window/Window.h"
