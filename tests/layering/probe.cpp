// Compiled by tests/layering/CMakeLists.txt against one layer library with
// PROBE_HEADER naming a header of another layer: it builds only if that layer
// is visible from the first.
#include PROBE_HEADER

int drtLayeringProbe() { return 0; }
