#include "rotlie/runs/lie_tables_io.hpp"

#include <algorithm>
#include <array>
#include <functional>
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

// A stage table's marks in one format: after a dimension computed here (the paper leaves it empty),
// and after a number quoted from literature source k (1-based).
struct table_marks {
  std::string computed;
  std::function<std::string(std::size_t)> quoted;
};

// One row's eight cells (order, dimension, equations and totals NS and S, stages NS and S) as text:
// empty, a number, or a number with its mark.
std::array<std::string, 8> row_cells(const lie::stage_block& b, const lie::stage_row& r, const std::vector<std::string>& sources,
                                     const table_marks& marks) {
  auto c = [&](const std::optional<std::int64_t>& v, const std::string& source = "") {
    if (!v) return std::string();
    std::string text = std::to_string(*v);
    if (is_quote(source)) text += marks.quoted(source_index(sources, source));
    return text;
  };
  std::string dim = r.dim ? std::to_string(*r.dim) : "";
  if (is_rigid(b) && r.order > paper_known_rigid_dimension) dim += marks.computed;
  return {std::to_string(r.order), dim, c(r.equations_ns), c(r.total_ns), c(r.equations_s), c(r.total_s),
          c(r.stages_ns, r.stages_ns_source), c(r.stages_s, r.stages_s_source)};
}

// The cells joined: open, the cells separated by sep, close.
std::string joined(const std::array<std::string, 8>& cells, const std::string& open, const std::string& sep, const std::string& close) {
  std::string line = open;
  for (std::size_t k = 0; k < cells.size(); ++k) line += (k ? sep : "") + cells[k];
  return line + close;
}

// A stage table in a format with delimiters (markdown, LaTeX): its marks, what comes before the first
// block, each block's title row, each row's delimiters, what ends a block, and the notes on the sources.
struct table_format {
  table_marks marks;
  std::string header;
  std::function<std::string(const std::string&)> block_title;
  std::string open, sep, close, block_end;
  std::function<std::string(const std::vector<std::string>&)> notes;
};

std::string stages_table(const std::vector<lie::stage_block>& blocks, const table_format& f) {
  const auto sources = quote_sources(blocks);
  std::string out = f.header;
  for (const auto& b : blocks) {
    out += f.block_title(b.title);
    for (const auto& r : b.rows) out += joined(row_cells(b, r, sources, f.marks), f.open, f.sep, f.close);
    out += f.block_end;
  }
  return out + f.notes(sources);
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
  const table_marks marks{"*", [](std::size_t k) { return "[" + std::to_string(k) + "]"; }};
  std::ostringstream out;
  char line[200];
  for (const auto& b : blocks) {
    out << b.title << "\n";
    std::snprintf(line, sizeof line, "%5s %14s %10s %10s %10s %10s %10s %10s\n", "order", "dim", "eq NS", "total NS",
                  "eq S", "total S", "stages NS", "stages S");
    out << line;
    for (const auto& r : b.rows) {
      const auto cells = row_cells(b, r, sources, marks);
      std::snprintf(line, sizeof line, "%5s %14s %10s %10s %10s %10s %10s %10s\n", cells[0].c_str(), cells[1].c_str(),
                    cells[2].c_str(), cells[3].c_str(), cells[4].c_str(), cells[5].c_str(), cells[6].c_str(), cells[7].c_str());
      out << line;
    }
    out << "\n";
  }
  out << "*  dimension computed here; the paper leaves it empty (unknown beyond order 5)\n";
  for (std::size_t i = 0; i < sources.size(); ++i) out << "[" << i + 1 << "] " << sources[i] << "\n";
  return out.str();
}

std::string stages_markdown(const std::vector<lie::stage_block>& blocks) {
  return stages_table(blocks, {{"<sup>*</sup>", [](std::size_t k) { return "<sup>q" + std::to_string(k) + "</sup>"; }},
                               "| order | dimension | equations NS | total NS | equations S | total S | stages NS | stages S |\n"
                               "|---:|---:|---:|---:|---:|---:|---:|---:|\n",
                               [](const std::string& title) { return "| **" + title + "** |||||||| \n"; },
                               "| ", " | ", " |\n", "",
                               [](const std::vector<std::string>& sources) {
                                 std::string notes = "\n<sup>*</sup> true dimension computed here; the paper leaves the cell empty "
                                                     "and uses the Theorem 1–2 bound as the equation count.  \n";
                                 for (std::size_t i = 0; i < sources.size(); ++i)
                                   notes += "<sup>q" + std::to_string(i + 1) + "</sup> literature value, not computed: " + sources[i] + "  \n";
                                 return notes;
                               }});
}

std::string stages_latex(const std::vector<lie::stage_block>& blocks) {
  return stages_table(blocks, {{"$^{*}$", [](std::size_t k) { return "$^{q" + std::to_string(k) + "}$"; }},
                               "\\begin{tabular}{rrrrrrrr}\n\\hline\n"
                               "Order & Dimension & \\multicolumn{4}{c}{Number of equations} & \\multicolumn{2}{c}{Number of stages} \\\\\n"
                               " & & NS & Total & S & Total & NS & S \\\\\n\\hline\n",
                               [](const std::string& title) { return "\\multicolumn{8}{l}{" + title + "} \\\\\n"; },
                               "", " & ", " \\\\\n", "\\hline\n",
                               [](const std::vector<std::string>& sources) {
                                 std::string notes = "\\end{tabular}\n\n% $^{*}$ true dimension computed by rotlie; empty in the paper.\n";
                                 for (std::size_t i = 0; i < sources.size(); ++i)
                                   notes += "% $^{q" + std::to_string(i + 1) + "}$ quoted: " + sources[i] + "\n";
                                 return notes;
                               }});
}

}  // namespace rotlie::runs
