#pragma once
// The free rotors that need nothing but the body's moments, each known by its name: the one list a
// new rotor algorithm joins. A rotor R<T> has `static constexpr std::string_view rotor_name`, a
// constructor R(const vec3<T>& moments), moments() and advance(body_state<T>&, const T& t) const (the
// free_rotor contract of scene_contracts.hpp). Once listed it
// runs in every integrator with a free flight (SIER2/NAME, SIER4/NAME in md and spin, from Python)
// and as LAMMPS's `rotor NAME`. The table rotor (table_rotor.hpp) is the other kind: it needs a table.
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "rotlie/models/exact_free_rotation.hpp"
#include "rotlie/models/sej4_rotor.hpp"

namespace rotlie::models {

/// The list. A new rotor: its header, included above, and one entry here.
template <class T>
using closed_form_rotors = std::tuple<exact_free_rotation<T>, sej4_rotor<T>>;

/// The names of the listed rotors, in the list's order.
inline std::vector<std::string> closed_form_rotor_names() {
  using list = closed_form_rotors<double>;
  return []<std::size_t... I>(std::index_sequence<I...>) {
    return std::vector<std::string>{std::string(std::tuple_element_t<I, list>::rotor_name)...};
  }(std::make_index_sequence<std::tuple_size_v<list>>{});
}

/// Whether `name` is a listed rotor's.
inline bool is_closed_form_rotor(std::string_view name) {
  for (const auto& n : closed_form_rotor_names())
    if (n == name) return true;
  return false;
}

/// f(std::type_identity<R>{}) for the listed rotor R called `name` (every call of f must return the same
/// type); throws std::invalid_argument for a name not in the list.
template <class T, class F>
decltype(auto) with_closed_form_rotor(std::string_view name, F&& f) {
  using list = closed_form_rotors<T>;
  using result = decltype(f(std::type_identity<std::tuple_element_t<0, list>>{}));
  constexpr auto every = std::make_index_sequence<std::tuple_size_v<list>>{};
  const auto unknown = [&] { return std::invalid_argument("no free rotor is called '" + std::string(name) + "'"); };
  if constexpr (std::is_void_v<result>) {
    bool found = false;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      ((!found && std::tuple_element_t<I, list>::rotor_name == name ? (f(std::type_identity<std::tuple_element_t<I, list>>{}), found = true)
                                                                     : false),
       ...);
    }(every);
    if (!found) throw unknown();
  } else {
    std::optional<result> out;
    [&]<std::size_t... I>(std::index_sequence<I...>) {
      ((!out && std::tuple_element_t<I, list>::rotor_name == name ? (void)out.emplace(f(std::type_identity<std::tuple_element_t<I, list>>{}))
                                                                   : void()),
       ...);
    }(every);
    if (!out) throw unknown();
    return result(std::move(*out));
  }
}

}  // namespace rotlie::models
