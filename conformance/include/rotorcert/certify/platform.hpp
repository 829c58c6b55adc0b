// What the report records about where it ran (SPEC 1.3, NUM-1): operating system, CPU, compiler,
// MPFR, and the floating-point environment (MXCSR on x86: flush-to-zero, denormals-are-zero,
// rounding). The environment is observed twice: in the tool at start-up, and in each child after
// the implementation was loaded, because loading a library built with -ffast-math can switch
// FTZ/DAZ on for the whole process (crtfastmath).
#pragma once

#include <nlohmann/json.hpp>

namespace rotorcert::certify {

/// {"mxcsr": "0x1f80" | null, "flush_to_zero", "denormals_are_zero", "rounding"} of this thread now.
nlohmann::json fp_environment_json();

/// {"os", "machine", "cpu", "cores", "compiler", "mpfr", "reference_precision_bits", "fp_environment"}.
nlohmann::json platform_json();

}  // namespace rotorcert::certify
