// A research source that keeps to its layer.
#include <vector>
#include "tests/layers/toy/research/Reaching.h"
