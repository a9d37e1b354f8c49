// Closes the region opened by odeint_warnings_off.hpp (no include guard).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
