// Included where Boost.Odeint's steppers are used, closed by odeint_warnings_restore.hpp (no include
// guard: each inclusion opens one region). GCC 12 sees Odeint's coefficient arrays as (maybe)
// uninitialized when a stepper is copied (they are set in its constructor): a false positive inside
// Boost, silenced in these regions only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#endif
