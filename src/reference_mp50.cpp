// The MPFR reference sweep at 50 digits (src/reference_mp.hxx).
#include "reference_mp.hxx"

ROLLKIN_INSTANTIATE_REFERENCE(50)
