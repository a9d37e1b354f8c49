// The writers format what the libraries computed: a cell of Table 1 survives the round trip
// through JSON, quotes are marked in every format, LaTeX is well formed.
#include <boost/test/unit_test.hpp>

#include "rotlie/runs/lie_tables_io.hpp"

BOOST_AUTO_TEST_SUITE(lie_tables_io_test)

using namespace rotlie;

namespace {
std::vector<lie::stage_block> table(int k) {
  std::vector<std::size_t> dims;
  for (const auto& p : lie::lie_poisson_algebra(k)) dims.push_back(p.dimension);
  return lie::stage_table(k, dims);
}
std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (auto pos = s.find(what); pos != std::string::npos; pos = s.find(what, pos + 1)) ++n;
  return n;
}
}  // namespace

BOOST_AUTO_TEST_CASE(json_round_trip_of_every_cell) {
  const auto blocks = table(10);
  const auto j = runs::stages_json(blocks);
  for (std::size_t b = 0; b < blocks.size(); ++b)
    for (std::size_t i = 0; i < blocks[b].rows.size(); ++i) {
      const auto& row = j["blocks"][b]["rows"][i];
      const auto& r = blocks[b].rows[i];
      auto same = [&](const char* key, const std::optional<std::int64_t>& v) {
        BOOST_TEST((v ? row[key].get<std::int64_t>() == *v : row[key].is_null()), blocks[b].name << " " << key);
      };
      same("dim", r.dim);
      same("total_ns", r.total_ns);
      same("total_s", r.total_s);
      same("stages_s", r.stages_s);
    }
}

BOOST_AUTO_TEST_CASE(quotes_are_marked_in_every_format) {
  const auto blocks = table(10);
  // 4 + 4 quoted cells in the 2-letter block, 2 + 5 in the 3-letter block; footnotes (a)–(e) plus
  // the unreferenced 3-letter order 1–2 cells give 6 distinct sources.
  const std::string md = runs::stages_markdown(blocks);
  BOOST_TEST(count(md, "<sup>q") == 15u + 6u);  // 15 marked cells + 6 distinct sources
  const std::string tex = runs::stages_latex(blocks);
  BOOST_TEST(count(tex, "\\begin{tabular}") == 1u);
  BOOST_TEST(count(tex, "\\end{tabular}") == 1u);
  BOOST_TEST(count(tex, " \\\\\n") == 2u + 4u + 40u);  // header rows, block titles, data rows
}

BOOST_AUTO_TEST_CASE(dims_json_keeps_theorem2_null_at_even_orders) {
  const auto j = runs::dims_json(lie::lie_poisson_algebra(6));
  BOOST_TEST(j["orders"][1]["theorem2"].is_null());
  BOOST_TEST(j["orders"][4]["theorem2"].get<bool>());
  BOOST_TEST(j["orders"][5]["dim"].get<int>() == 6);
}

BOOST_AUTO_TEST_SUITE_END()  // lie_tables_io_test
