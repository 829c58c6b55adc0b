// A certificate for a terminal: one line per clause that needs a reader's eye, then the levels.
#pragma once

#include <ostream>

#include <rotorcert/certify/certificate.hpp>

namespace rotorcert::certify {

/// Without `verbose`, PASSes and unclaimed NOT_SUPPORTED clauses are left out.
void print_certificate(std::ostream& out, const Certificate& c, bool verbose);

}  // namespace rotorcert::certify
