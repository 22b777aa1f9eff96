// A research source that reaches a window header without linking it.
#include "tests/layers/toy/research/Reaching.h"
