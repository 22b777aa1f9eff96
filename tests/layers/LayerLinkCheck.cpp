// Linked with every object of a layer's libraries (whole archive) and none of
// the libraries the layer may not use: an object that calls into them through
// a header, with no link declared, leaves an undefined symbol and the build
// stops. The configure-time rule (cmake/HemirollLayers.cmake) sees only the
// declared links; this sees the code. Nothing to run.
int main() { return 0; }
