#include "rotlie/runs/lie_tables_io.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

namespace rotlie::runs {
namespace {

// The paper knows dim L_k of the free rigid body only up to order 5 (section 2.4).
constexpr int paper_known_rigid_dimension = 5;

std::string yes_no(bool b) { return b ? "yes" : "no"; }
std::string verdict(bool b) { return b ? "holds" : "FAILS"; }

nlohmann::json optional_json(const std::optional<std::int64_t>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); }

bool is_quote(const std::string& source) { return !source.empty() && source != "rule"; }
bool is_rigid(const lie::stage_block& b) { return b.name.rfind("rigid", 0) == 0; }

// The numbered literature sources quoted in the general blocks, in order of appearance.
std::vector<std::string> quote_sources(const std::vector<lie::stage_block>& blocks) {
  std::vector<std::string> sources;
  auto note = [&](const std::string& s) {
    if (is_quote(s) && std::find(sources.begin(), sources.end(), s) == sources.end()) sources.push_back(s);
  };
  for (const auto& b : blocks)
    for (const auto& r : b.rows) {
      note(r.stages_ns_source);
      note(r.stages_s_source);
    }
  return sources;
}

std::size_t source_index(const std::vector<std::string>& sources, const std::string& s) {
  return static_cast<std::size_t>(std::find(sources.begin(), sources.end(), s) - sources.begin()) + 1;
}

// One cell as text: empty, a number, or a quoted number with its source mark.
template <class Mark>
std::string cell(const std::optional<std::int64_t>& v, const std::string& source, Mark mark) {
  if (!v) return "";
  std::string s = std::to_string(*v);
  if (is_quote(source)) s += mark(source);
  return s;
}

std::string dim_cell(const lie::stage_block& b, const lie::stage_row& r, const std::string& computed_mark) {
  std::string s = r.dim ? std::to_string(*r.dim) : "";
  if (is_rigid(b) && r.order > paper_known_rigid_dimension) s += computed_mark;
  return s;
}

}  // namespace

nlohmann::json dims_json(const std::vector<lie::graded_piece>& pieces) {
  nlohmann::json orders = nlohmann::json::array();
  for (const auto& p : pieces) {
    orders.push_back({{"order", p.order},
                      {"dim", p.dimension},
                      {"theorem1", p.theorem1},
                      {"theorem2", p.theorem2 ? nlohmann::json(*p.theorem2) : nlohmann::json()},
                      {"bound", p.bound},
                      {"attained", p.bound_attained()},
                      {"method", lie::to_string(p.method)}});
  }
  return {{"orders", orders}};
}

std::string dims_text(const std::vector<lie::graded_piece>& pieces) {
  std::ostringstream out;
  char line[160];
  std::snprintf(line, sizeof line, "%5s %6s  %-9s %-9s %6s  %-8s %s\n", "order", "dim", "theorem1", "theorem2", "bound",
                "attained", "method");
  out << line;
  for (const auto& p : pieces) {
    std::snprintf(line, sizeof line, "%5d %6zu  %-9s %-9s %6zu  %-8s %s\n", p.order, p.dimension,
                  verdict(p.theorem1).c_str(), p.theorem2 ? verdict(*p.theorem2).c_str() : "-", p.bound,
                  yes_no(p.bound_attained()).c_str(), lie::to_string(p.method).c_str());
    out << line;
  }
  return out.str();
}

std::string dims_markdown(const std::vector<lie::graded_piece>& pieces) {
  std::ostringstream out;
  out << "| order k | dim L_k | Theorem 1 | Theorem 2 | Theorem 1–2 bound | bound attained | how the rank was established |\n"
      << "|---:|---:|:--|:--|---:|:--|:--|\n";
  for (const auto& p : pieces)
    out << "| " << p.order << " | " << p.dimension << " | " << verdict(p.theorem1) << " | "
        << (p.theorem2 ? verdict(*p.theorem2) : "—") << " | " << p.bound << " | " << yes_no(p.bound_attained()) << " | "
        << lie::to_string(p.method) << " |\n";
  return out.str();
}

nlohmann::json stages_json(const std::vector<lie::stage_block>& blocks) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& b : blocks) {
    nlohmann::json rows = nlohmann::json::array();
    for (const auto& r : b.rows) {
      nlohmann::json row = {{"order", r.order},
                            {"dim", optional_json(r.dim)},
                            {"equations_ns", optional_json(r.equations_ns)},
                            {"total_ns", optional_json(r.total_ns)},
                            {"equations_s", optional_json(r.equations_s)},
                            {"total_s", optional_json(r.total_s)},
                            {"stages_ns", optional_json(r.stages_ns)},
                            {"stages_s", optional_json(r.stages_s)}};
      if (is_quote(r.stages_ns_source)) row["stages_ns_quoted_from"] = r.stages_ns_source;
      if (is_quote(r.stages_s_source)) row["stages_s_quoted_from"] = r.stages_s_source;
      rows.push_back(std::move(row));
    }
    out.push_back({{"name", b.name}, {"title", b.title}, {"rows", rows}});
  }
  return {{"blocks", out}};
}

std::string stages_text(const std::vector<lie::stage_block>& blocks) {
  const auto sources = quote_sources(blocks);
  auto mark = [&](const std::string& s) { return "[" + std::to_string(source_index(sources, s)) + "]"; };
  std::ostringstream out;
  char line[200];
  for (const auto& b : blocks) {
    out << b.title << "\n";
    std::snprintf(line, sizeof line, "%5s %14s %10s %10s %10s %10s %10s %10s\n", "order", "dim", "eq NS", "total NS",
                  "eq S", "total S", "stages NS", "stages S");
    out << line;
    for (const auto& r : b.rows) {
      auto c = [&](const std::optional<std::int64_t>& v, const std::string& src = "") { return cell(v, src, mark); };
      std::snprintf(line, sizeof line, "%5d %14s %10s %10s %10s %10s %10s %10s\n", r.order,
                    dim_cell(b, r, "*").c_str(), c(r.equations_ns).c_str(), c(r.total_ns).c_str(),
                    c(r.equations_s).c_str(), c(r.total_s).c_str(), c(r.stages_ns, r.stages_ns_source).c_str(),
                    c(r.stages_s, r.stages_s_source).c_str());
      out << line;
    }
    out << "\n";
  }
  out << "*  dimension computed here; the paper leaves it empty (unknown beyond order 5)\n";
  for (std::size_t i = 0; i < sources.size(); ++i) out << "[" << i + 1 << "] " << sources[i] << "\n";
  return out.str();
}

std::string stages_markdown(const std::vector<lie::stage_block>& blocks) {
  const auto sources = quote_sources(blocks);
  auto mark = [&](const std::string& s) { return "<sup>q" + std::to_string(source_index(sources, s)) + "</sup>"; };
  std::ostringstream out;
  out << "| order | dimension | equations NS | total NS | equations S | total S | stages NS | stages S |\n"
      << "|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const auto& b : blocks) {
    out << "| **" << b.title << "** |||||||| \n";
    for (const auto& r : b.rows) {
      auto c = [&](const std::optional<std::int64_t>& v, const std::string& src = "") { return cell(v, src, mark); };
      out << "| " << r.order << " | " << dim_cell(b, r, "<sup>*</sup>") << " | " << c(r.equations_ns) << " | "
          << c(r.total_ns) << " | " << c(r.equations_s) << " | " << c(r.total_s) << " | "
          << c(r.stages_ns, r.stages_ns_source) << " | " << c(r.stages_s, r.stages_s_source) << " |\n";
    }
  }
  out << "\n<sup>*</sup> true dimension computed here; the paper leaves the cell empty and uses the "
         "Theorem 1–2 bound as the equation count.  \n";
  for (std::size_t i = 0; i < sources.size(); ++i)
    out << "<sup>q" << i + 1 << "</sup> literature value, not computed: " << sources[i] << "  \n";
  return out.str();
}

std::string stages_latex(const std::vector<lie::stage_block>& blocks) {
  const auto sources = quote_sources(blocks);
  auto mark = [&](const std::string& s) { return "$^{q" + std::to_string(source_index(sources, s)) + "}$"; };
  std::ostringstream out;
  out << "\\begin{tabular}{rrrrrrrr}\n\\hline\n"
      << "Order & Dimension & \\multicolumn{4}{c}{Number of equations} & \\multicolumn{2}{c}{Number of stages} \\\\\n"
      << " & & NS & Total & S & Total & NS & S \\\\\n\\hline\n";
  for (const auto& b : blocks) {
    out << "\\multicolumn{8}{l}{" << b.title << "} \\\\\n";
    for (const auto& r : b.rows) {
      auto c = [&](const std::optional<std::int64_t>& v, const std::string& src = "") { return cell(v, src, mark); };
      out << r.order << " & " << dim_cell(b, r, "$^{*}$") << " & " << c(r.equations_ns) << " & " << c(r.total_ns)
          << " & " << c(r.equations_s) << " & " << c(r.total_s) << " & " << c(r.stages_ns, r.stages_ns_source)
          << " & " << c(r.stages_s, r.stages_s_source) << " \\\\\n";
    }
    out << "\\hline\n";
  }
  out << "\\end{tabular}\n\n% $^{*}$ true dimension computed by rotlie; empty in the paper.\n";
  for (std::size_t i = 0; i < sources.size(); ++i) out << "% $^{q" << i + 1 << "}$ quoted: " << sources[i] << "\n";
  return out.str();
}

}  // namespace rotlie::runs
