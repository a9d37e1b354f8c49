#include "rotlie/solver/scheme_table.hpp"

#include <cln/dfloat.h>
#include <cln/rational_io.h>
#include <cln/real.h>

#include <algorithm>

#include <sstream>

#include "rotlie/lie/exact_number.hpp"

namespace rotlie::solver {

std::string scheme_table_name(const dedicated_solution& s) {
  return s.scheme + ":" + s.permutation + ":" + std::to_string(s.label);
}

std::string scheme_table_text(const dedicated_solution& s, const lie::moments_of_inertia& body, int digits) {
  std::ostringstream out;
  auto rational_text = [](const cln::cl_RA& x) {
    std::ostringstream t;
    t << x;
    return t.str();
  };
  out << "# rotlie scheme table: a splitting scheme dedicated to one rigid body\n"
      << "format_version 1\n"
      << "name " << scheme_table_name(s) << "\n"
      << "scheme " << s.scheme << "\n"
      << "split " << (s.layout.split == bch::splitting::abc ? "ABC" : "RS") << "\n"
      << "word " << s.layout.permuted << "\n"
      << "permutation " << s.permutation << "\n"
      << "label " << s.label << "\n"
      << "order 4\n"
      << "symmetric " << (s.layout.symmetric ? "true" : "false") << "\n"
      << "inertia " << rational_text(body.I[0]) << " " << rational_text(body.I[1]) << " " << rational_text(body.I[2]) << "\n"
      << "digits " << digits << "\n"
      << "residual " << lie::to_decimal(s.residual, 3) << "\n"
      << "analytic_remainder " << lie::to_decimal(cln::rational(cln::cl_DF(s.analytic_remainder)), 6) << "\n"
      << "source Laskar & Vaillant (2018), section 3; real solution " << s.label
      << " of H_R3 = 0 by ascending first free coefficient; rotlie solve\n"
      << "stages " << s.layout.stages.size() << "\n";
  for (const auto& st : s.layout.stages) {
    cln::cl_RA value = 0;
    for (const auto& [n, v] : s.coefficients)
      if (n == st.coefficient) value = v;
    out << "stage " << st.letter << " " << st.coefficient << " " << lie::to_decimal(value, digits);
    if (std::find(s.exact.begin(), s.exact.end(), st.coefficient) != s.exact.end()) out << " " << rational_text(value);
    out << "\n";
  }
  return out.str();
}

}  // namespace rotlie::solver
