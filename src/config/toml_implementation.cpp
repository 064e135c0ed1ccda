/// toml++'s implementation, compiled once into geardyn (toml++'s documented non-header-only
/// mode: TOML_HEADER_ONLY=0 everywhere, TOML_IMPLEMENTATION in one translation unit) instead of
/// linking Debian's libtomlplusplus.so: one shared library and its symbol lookups less at every
/// start (issue 22).
#define TOML_IMPLEMENTATION
#include <toml++/toml.h>
