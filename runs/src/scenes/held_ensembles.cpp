// The ensemble scenes held (held_ensemble.hpp) in each scalar: the integrators compiled here once.
#include <type_traits>

#include "held_ensemble.hpp"

namespace rotlie::runs::scene_support {
namespace {

template <class T>
models::vec3<double> ensemble_double(const models::vec3<T>& v) {
  return {static_cast<double>(v[0]), static_cast<double>(v[1]), static_cast<double>(v[2])};
}

template <class Composition>
class held_ensemble_run final : public held_md_run {
 public:
  using T = typename Composition::scalar;
  using state = typename Composition::state;

  held_ensemble_run(const Composition& method, std::vector<state> states, const T& h) : method_(method), x_(std::move(states)), h_(h) {}

  void step() override {
    for (auto& x : x_) method_.step(x, h_);
    ++k_;
  }
  long steps() const override { return k_; }
  long systems() const override { return static_cast<long>(x_.size()); }
  long bodies() const override { return x_.empty() ? 0 : static_cast<long>(x_[0].bodies.size()); }
  md_body body(long system, long i) const override {
    const auto& b = x_[static_cast<std::size_t>(system)].bodies[static_cast<std::size_t>(i)];
    md_body out;
    out.q = ensemble_double(b.q), out.p = ensemble_double(b.p), out.G = ensemble_double(b.rot.G);
    for (std::size_t j = 0; j < 9; ++j) out.Q.a[j] = static_cast<double>(b.rot.Q.a[j]);
    return out;
  }
  double energy(long system) const override {
    const auto s = current(system);
    return static_cast<double>(method_.system().kinetic_energy(s) + s.potential);  // as the trajectory's energy
  }
  double potential(long system) const override { return static_cast<double>(current(system).potential); }
  long force_evaluations() const override {
    long n = 0;
    for (const auto& x : x_) n += x.force_evaluations;
    return n;
  }

 private:
  // the state with its forces at the current configuration, evaluated on a copy if stale
  state current(long system) const {
    state s = x_[static_cast<std::size_t>(system)];
    method_.system().ensure_forces(s);
    return s;
  }

  Composition method_;
  std::vector<state> x_;
  T h_;
  long k_ = 0;
};

}  // namespace

template <class Scene>
std::unique_ptr<held_md_run> held_ensemble(const Scene& scene, const models::md_run_options& o, bool prepare_forces) {
  using T = std::decay_t<decltype(scene.mass)>;
  return models::with_scene_integrator<T>(scene, o, [&](const auto& method) -> std::unique_ptr<held_md_run> {
    using C = std::decay_t<decltype(method)>;
    std::vector<typename C::state> states;
    for (long run = 0; run < o.runs; ++run) {
      states.push_back(scene.initial(o.seed, static_cast<std::uint64_t>(run)));
      if (prepare_forces) method.system().ensure_forces(states.back());
    }
    return std::make_unique<held_ensemble_run<C>>(method, std::move(states), T(o.h_fs));
  });
}

template std::unique_ptr<held_md_run> held_ensemble(const models::free_water<double>&, const models::md_run_options&, bool);
template std::unique_ptr<held_md_run> held_ensemble(const models::free_water<long double>&, const models::md_run_options&, bool);
template std::unique_ptr<held_md_run> held_ensemble(const models::free_water<quad>&, const models::md_run_options&, bool);
template std::unique_ptr<held_md_run> held_ensemble(const models::dipole_field<double>&, const models::md_run_options&, bool);
template std::unique_ptr<held_md_run> held_ensemble(const models::dipole_field<long double>&, const models::md_run_options&, bool);
template std::unique_ptr<held_md_run> held_ensemble(const models::dipole_field<quad>&, const models::md_run_options&, bool);

}  // namespace rotlie::runs::scene_support
