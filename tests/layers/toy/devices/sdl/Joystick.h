// The toy's SDL device: a header of a library research may not link.
struct Joystick {};
