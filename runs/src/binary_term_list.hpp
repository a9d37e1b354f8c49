// The registered force terms of the binary scene, one line each: ROTLIE_BINARY_TERM(NAME) names
// NAME_term(), defined in runs/src/binary_terms/NAME_term.cpp. Included twice by binary_terms.cpp.
ROTLIE_BINARY_TERM(sun)
ROTLIE_BINARY_TERM(tides)
ROTLIE_BINARY_TERM(flyby)
