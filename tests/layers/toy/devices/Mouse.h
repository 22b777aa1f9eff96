// The toy's headless devices: a header a research source may include.
struct Mouse {};
