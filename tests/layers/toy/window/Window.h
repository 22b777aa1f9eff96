// The toy window library: its header.
struct Window {};
