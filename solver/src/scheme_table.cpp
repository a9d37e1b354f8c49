#include "rotlie/solver/scheme_table.hpp"

#include <cln/dfloat.h>
#include <cln/rational_io.h>
#include <cln/real.h>

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "rotlie/lie/exact_number.hpp"

namespace rotlie::solver {

std::string scheme_table_name(const dedicated_solution& s) {
  return s.scheme + ":" + s.permutation + ":" + std::to_string(s.label);
}

std::map<std::string, cln::cl_RA> written_coefficients(const dedicated_solution& s, int digits) {
  std::map<std::string, cln::cl_RA> out;
  for (const auto& [name, value] : s.coefficients) out[name] = written_value(value, digits);
  return out;
}

std::string scheme_table_text(const dedicated_solution& s, const lie::moments_of_inertia& body, int digits) {
  const auto written = written_coefficients(s, digits);
  const order_certificate certificate = certify_order_four(s.layout, body, written, digits);
  std::ostringstream out;
  auto rational_text = [](const cln::cl_RA& x) {
    std::ostringstream t;
    t << x;
    return t.str();
  };
  out << "# rotlie scheme table: a splitting scheme dedicated to one rigid body\n";
  if (certificate.order < 4)
    out << "# not order 4 at these digits: " << certificate.failure << "\n";
  out << "format_version 1\n"
      << "name " << scheme_table_name(s) << "\n"
      << "scheme " << s.scheme << "\n"
      << "split " << (s.layout.split == bch::splitting::abc ? "ABC" : "RS") << "\n"
      << "word " << s.layout.permuted << "\n"
      << "permutation " << s.permutation << "\n"
      << "label " << s.label << "\n"
      << "order " << certificate.order << "\n"
      << "symmetric " << (s.layout.symmetric ? "true" : "false") << "\n"
      << "inertia " << rational_text(body.I[0]) << " " << rational_text(body.I[1]) << " " << rational_text(body.I[2]) << "\n"
      << "digits " << digits << "\n"
      << "residual " << lie::to_decimal(certificate.residual, 3) << "\n"
      << "analytic_remainder " << lie::to_decimal(cln::rational(cln::cl_DF(s.analytic_remainder)), 6) << "\n"
      << "source Laskar & Vaillant (2018), section 3; real solution " << s.label
      << " of H_R3 = 0 by ascending first free coefficient; rotlie solve\n"
      << "stages " << s.layout.stages.size() << "\n";
  for (const auto& st : s.layout.stages) {
    cln::cl_RA value = 0;
    for (const auto& [n, v] : s.coefficients)
      if (n == st.coefficient) value = v;
    // The same text that written_coefficients read back and the certificate judged.
    out << "stage " << st.letter << " " << st.coefficient << " " << lie::to_decimal(value, digits);
    if (std::find(s.exact.begin(), s.exact.end(), st.coefficient) != s.exact.end()) out << " " << rational_text(value);
    out << "\n";
  }
  return out.str();
}

bch::splitting splitting_of(schemes::split split) {
  switch (split) {
    case schemes::split::abc: return bch::splitting::abc;
    case schemes::split::rs: return bch::splitting::rs;
    case schemes::split::tv: break;
  }
  throw std::invalid_argument("a TV table (free flight and kick) has no splitting of the free rigid body");
}

schemes::scheme_table scheme_table_of(const dedicated_solution& s, const lie::moments_of_inertia& body, int digits) {
  return schemes::parse_scheme_table(scheme_table_text(s, body, digits));
}

std::string searched_table_text(const bch::scheme_layout& layout, const lie::moments_of_inertia& body,
                                const std::map<std::string, cln::cl_RA>& values, const searched_table_lines& lines) {
  std::ostringstream out;
  out << "format_version 1\n"
      << "name " << lines.name << "\n"
      << "scheme " << layout.word << "\n"
      << "split " << (layout.split == bch::splitting::abc ? "ABC" : "RS") << "\n"
      << "word " << layout.permuted << "\n"
      << "permutation " << layout.permutation << "\n"
      << "order " << lines.order << "\n"
      << "symmetric true\n"
      << "inertia " << lie::inertia_text(body) << "\n"
      << "digits " << lines.digits << "\n"
      << "residual " << lie::to_decimal(lines.residual, 3) << "\n"
      << "#" << lines.comment << "\n"
      << "analytic_remainder " << lines.analytic_remainder << "\n"
      << "source " << lines.source << "\n"
      << "stages " << layout.stages.size() << "\n";
  for (const auto& st : layout.stages)
    out << "stage " << st.letter << " " << st.coefficient << " " << lie::to_decimal(values.at(st.coefficient), lines.digits) << "\n";
  return out.str();
}

}  // namespace rotlie::solver
