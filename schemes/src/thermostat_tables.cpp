#include "rotlie/schemes/thermostat_tables.hpp"

#include <stdexcept>

#include "rotlie/schemes/printable_text.hpp"
#include "rotlie/schemes/quad.hpp"

namespace rotlie::schemes {
namespace {

std::string half_of(const std::string& value) { return (quad(value) / 2).str(36, std::ios_base::scientific); }

const char* suffix(thermostat_placement p) {
  switch (p) {
    case thermostat_placement::middle: return "+BAOAB";
    case thermostat_placement::ends: return "+OBABO";
    case thermostat_placement::chain: return "+NHC";
  }
  return "";
}

}  // namespace

char thermostat_letter(thermostat_placement p) { return p == thermostat_placement::chain ? 'N' : 'O'; }

scheme_table thermostatted_table(const scheme_table& tv, thermostat_placement placement) {
  if (tv.splitting != split::tv) throw std::invalid_argument("scheme table " + printable_text(tv.name) + " is not a TV table: no thermostat to add");
  for (const auto& s : tv.stages)
    if (is_thermostat_letter(s.part)) throw std::invalid_argument("scheme table " + printable_text(tv.name) + " already has a thermostat");
  scheme_table t = tv;
  t.name = tv.name + suffix(placement);
  t.stages.clear();
  const char letter = thermostat_letter(placement);
  if (placement == thermostat_placement::middle) {
    // an odd number of stages has one in the middle, split in halves around O; an even number has O between its halves
    const std::size_t n = tv.stages.size(), mid = n / 2;
    for (std::size_t k = 0; k < n; ++k) {
      const stage& s = tv.stages[k];
      if (n % 2 == 1 && k == mid) {
        t.stages.push_back({s.part, s.name + "a", half_of(s.value)});
        t.stages.push_back({letter, "o", "1"});
        t.stages.push_back({s.part, s.name + "b", half_of(s.value)});
        continue;
      }
      if (n % 2 == 0 && k == mid) t.stages.push_back({letter, "o", "1"});
      t.stages.push_back(s);
    }
  } else {
    t.stages.push_back({letter, "o1", "0.5"});
    for (const auto& s : tv.stages) t.stages.push_back(s);
    t.stages.push_back({letter, "o2", "0.5"});
  }
  t.word.clear();
  for (const auto& s : t.stages) t.word += s.part;
  t.source = tv.source + (placement == thermostat_placement::chain ? "; a Nose-Hoover chain for h/2 at both ends (Kamberaj, Low & Neal 2005)"
                          : placement == thermostat_placement::ends ? "; the exact Ornstein-Uhlenbeck step for h/2 at both ends (OBABO)"
                                                                     : "; the exact Ornstein-Uhlenbeck step for h in the middle (BAOAB)");
  check_scheme_table(t);
  return t;
}

}  // namespace rotlie::schemes
